//! @file Rear-wall failure of a shield, detected in a snapshot (docs/shield.md, "Failure"):
//! perforation is a through-hole in the rear wall or a detached spall behind it.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hvi/cases/scene.hpp"
#include "hvi/common/snapshot.hpp"

namespace hvi::shield {

//! Which body is the rear wall, where it was at t = 0, and the thresholds. Lengths cm.
struct RearWallConfig {
  std::string name = "rear_wall";  //!< object name in the snapshot
  double zMin = 0.0, zMax = 0.0;   //!< initial faces
  double radius = 0.0;             //!< the plate's radius (columns beyond it are not looked at)
  double rho0 = 0.0;               //!< g/cm^3
  int direction = -1;              //!< impact direction along z (-1: towards -z)
  //! A column (radius bin) of the wall whose areal mass, in the wall's main piece, falls below
  //! this fraction of rho0 * thickness is open: light passes through the wall there.
  double holeArealFraction = 0.1;
  //! A piece of rear-wall material is a fragment when it holds at least this many cells.
  int minFragmentCells = 3;
};

//! The config of a scene's body named "rear_wall" (a rect); nullopt if it has none.
std::optional<RearWallConfig> rearWallConfigFromScene(const cases::Scene& scene);
//! Every plate of an r-z scene, in body order: each rect body at rest that starts at the axis
//! (a shield scene's bumper, intermediate walls and rear wall; the study's plate). A
//! RearWallConfig measures any plate. Empty for a planar scene.
std::vector<RearWallConfig> plateConfigsFromScene(const cases::Scene& scene);

//! A connected piece of rear-wall material separated from the wall's main piece.
struct Fragment {
  double mass = 0.0;  //!< g (whole ring in r-z, per cm of depth in planar)
  double centroidR = 0.0, centroidZ = 0.0;
  double zLow = 0.0, zHigh = 0.0;  //!< extent along z (cell faces)
  double rOuter = 0.0;             //!< outer radius (cell face)
  double velocityZ = 0.0;          //!< mass-weighted, cm/us
  int cells = 0;
};

//! An open radial band [rInner, rOuter] of the wall (a disk at the axis when rInner = 0).
struct Hole {
  double rInner = 0.0, rOuter = 0.0;
  double area = 0.0;  //!< cm^2, pi (rOuter^2 - rInner^2) in r-z
};

struct RearWallState {
  double time = 0.0;      //!< us
  double cellSize = 0.0;  //!< cm, the grid the state was measured on
  std::vector<Hole> holes;
  std::vector<Fragment> spall;    //!< detached pieces moving away from the wall, downrange
  double thinnestFraction = 1.0;  //!< smallest column areal mass / (rho0 t) of the main piece
  double thinnestRadius = 0.0;    //!< where (cm)
  double mainVelocityZ = 0.0;     //!< mass-weighted velocity of the main piece, cm/us
  [[nodiscard]] bool throughHole() const { return !holes.empty(); }
  [[nodiscard]] bool detachedSpall() const { return !spall.empty(); }
  [[nodiscard]] bool perforated() const { return throughHole() || detachedSpall(); }
  //! The aperture on the axis: rOuter of the opening that starts at r = 0 (0: the plate is
  //! closed at the axis; a ring tear elsewhere is in `holes` only).
  [[nodiscard]] double holeRadius() const;
  //! "intact", "through_hole", "detached_spall" or "through_hole_and_spall".
  [[nodiscard]] std::string mode() const;
};

//! Measures the rear wall in `s` on its own grid (particles: a covering grid of their spacing,
//! or `spacing` if > 0). Needs the "object" and "velocity" fields; throws InputError naming
//! what is missing.
RearWallState measureRearWall(const Snapshot& s, const RearWallConfig& cfg, double spacing = 0.0);
//! Several plates of one snapshot, measured on one resampled grid (each as measureRearWall).
std::vector<RearWallState> measurePlates(const Snapshot& s,
                                         const std::vector<RearWallConfig>& plates,
                                         double spacing = 0.0);
//! From an hvi HDF5 snapshot: the config from the scene stored in the file.
RearWallState measureRearWall(const std::filesystem::path& h5);

nlohmann::json toJson(const RearWallState& s);
//! toJson plus the plate's `name`, its `hole_radius_cm` (holeRadius()) and `spalled`
//! (detachedSpall()): one entry of a snapshot's `plates` (docs/output.md).
nlohmann::json plateJson(const std::string& name, const RearWallState& s);
//! Per plate over a run, from its snapshots' `plates` arrays (time order): the last hole radius
//! and the largest, the failure verdict (failureVerdict), and the spall flag with the first
//! snapshot that shows a detached spall and its pieces.
nlohmann::json platesSummary(const nlohmann::json& perSnapshot);
//! The run's verdict from its per-snapshot states (as toJson wrote them, in time order): failed
//! at the first snapshot that shows perforation, with that snapshot's evidence; else the last.
nlohmann::json failureVerdict(const nlohmann::json& states);

}  // namespace hvi::shield
