//! @file Eulerian second-order TVD finite-volume solver with marker lines (METHOD.md section 4).
#pragma once
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/common/solver.hpp"
#include "hvi/tvd/markers.hpp"

namespace hvi::tvd {

//! The solver the `hvi` command drives for `solver = "tvd"` scenes. Throws hvi::InputError for
//! a scene the solver cannot run (see TvdSolver).
std::unique_ptr<Solver> createSolver(const cases::Scene& scene);

//! Conserved state per cell (index k * nx + i) per unit volume: density g/cm^3, momentum
//! density g/(cm^2 us) along x (or r) and z, total energy density rho (e + |v|^2/2), Mbar.
struct Conserved {
  std::vector<double> rho, mx, mz, E;
};

//! Mass (g), momentum (g cm/us) and energy (g cm^2/us^2) that one mechanism added to the domain
//! (negative: removed). Planar amounts are per cm of depth; r-z amounts include the 2 pi r.
struct Budget {
  double mass = 0.0, momentumX = 0.0, momentumZ = 0.0, energy = 0.0;
  Budget& operator+=(const Budget& o) {
    mass += o.mass;
    momentumX += o.momentumX;
    momentumZ += o.momentumZ;
    energy += o.energy;
    return *this;
  }
};

//! Every way the totals change. totals() now minus totals() at the start equals sum() to
//! round-off (momentumX excepted in r-z, where the radial momentum has the P/r source).
struct Ledger {
  Budget boundary;      //!< fluxes through the domain boundary (inflow positive)
  Budget interfaces;    //!< two-sided fluxes at object/object and object/vacuum faces (markers)
  Budget ownerChanges;  //!< cells re-initialised or emptied when the configuration changes
  Budget floors;        //!< velocity reset below the vacuum density, internal-energy floor
  [[nodiscard]] Budget sum() const {
    Budget s = boundary;
    s += interfaces;
    s += ownerChanges;
    s += floors;
    return s;
  }
};

//! Settings the scene does not carry (defaults are those documented in docs/tvd.md).
struct Options {
  double entropyFix = 0.1;    //!< Harten's delta as a fraction of |u| + c at the face
  int contactIterations = 2;  //!< two-shock impedance updates at object/object faces
  int threads = 0;            //!< OpenMP threads for the sweeps; 0: omp_get_max_threads()
};

//! Eulerian TVD solver (the scheme is specified in docs/tvd.md):
//! - uniform grid over scene.domain with dx = dz = scene.tvd.cellSize (the domain is rounded to
//!   whole cells from xmin, zmin); planar x-z or r-z (x = r >= 0);
//! - Strang-alternated dimensional splitting (x then z on even steps, z then x on odd), each
//!   1-D sweep integrated by Heun's two-stage predictor-corrector with Harten-Yee upwind TVD
//!   fluxes, limiter scene.tvd.limiter, CFL scene.tvd.cfl;
//! - with the `material_interfaces` effect: marker lines (MarkerSet) around every body, a
//!   configuration array (cell -> object) and an index array (object -> material), ghost-fluid
//!   fluxes at interfaces and vacuum (P = 0); without it the scene must have one material and
//!   vacuum is that material below scene.tvd.vacuumDensity * rho0.
//! Throws hvi::InputError for an empty domain, a non-positive cell size or CFL, a CFL above
//! 0.5, several materials without `material_interfaces`, or an r-z domain with xmin < 0.
class TvdSolver final : public Solver {
 public:
  explicit TvdSolver(const cases::Scene& scene, Options options = {});
  ~TvdSolver() override;
  TvdSolver(const TvdSolver&) = delete;
  TvdSolver& operator=(const TvdSolver&) = delete;

  [[nodiscard]] std::string name() const override { return "tvd"; }
  [[nodiscard]] double time() const override { return time_; }
  [[nodiscard]] long step() const override { return step_; }
  [[nodiscard]] long workItems() const override { return grid_.cells(); }
  double advance(double tStop) override;
  [[nodiscard]] Snapshot snapshot() const override;
  [[nodiscard]] Totals totals() const override;
  void writeCheckpoint(std::ostream& out) const override;
  void readCheckpoint(std::istream& in) override;

  // Lower-level access (tests, tools).
  [[nodiscard]] const GridSpec& grid() const { return grid_; }
  [[nodiscard]] Geometry geometry() const { return geometry_; }
  [[nodiscard]] const Conserved& conserved() const { return U_; }
  //! Mutable state for tests that set up states the scene cannot express. The caller keeps it
  //! physical (rho > 0 in material cells, zero in vacuum cells of a marker run).
  Conserved& conservedForTesting() { return U_; }
  [[nodiscard]] bool markersActive() const { return markersOn_; }
  [[nodiscard]] const MarkerSet& markers() const { return markerSet_; }
  //! Configuration array: owning object per cell, -1 vacuum (markers only; empty otherwise).
  [[nodiscard]] const std::vector<int>& owner() const { return owner_; }
  //! Index array: material of each object.
  [[nodiscard]] const std::vector<int>& objectMaterial() const { return objectMaterial_; }
  [[nodiscard]] const Ledger& ledger() const { return ledger_; }
  //! Largest stable step of the current state, us.
  [[nodiscard]] double stableTimeStep() const;
  //! Cells whose owner changed since the start (markers only).
  [[nodiscard]] long ownerChanges() const { return ownerChangeCount_; }
  //! Cell volume (planar: cm^2 per cm of depth; r-z: 2 pi r dr dz, cm^3).
  [[nodiscard]] double cellVolume(long cell) const;

 private:
  struct Workspace;
  struct LineRecord;
  void setUpGrid(const cases::Scene& scene);
  void setUpMaterials(const cases::Scene& scene);
  void initialiseState(const cases::Scene& scene);
  void sweep(int direction, double dt);
  void updateMarkers(double dt);
  double signalSpeedPass(bool keepVelocity, long* worstCell) const;
  void checkState() const;

  GridSpec grid_;
  Geometry geometry_ = Geometry::Planar;
  cases::Domain domain_;
  cases::TvdParams params_;
  Options options_;
  std::vector<cases::Material> materials_;
  std::vector<std::string> bodyNames_;
  struct BodyState {
    double rho, vx, vz, e;
  };
  std::vector<BodyState> bodyStates_;  // initial state of each body (object)
  std::vector<double> rhoCut_;         // per material: below this density a cell is vacuum
  // Per material: below kThinFraction * rho0 a cell is nearly empty; if the positivity fallback
  // cannot keep it physical it is reset to vacuum (booked in the ledger) instead of aborting.
  static constexpr double kThinFraction = 1e-3;
  std::vector<double> rhoThin_;
  int singleMaterial_ = 0;  // the material of a run without markers

  Conserved U_;
  double time_ = 0.0;
  long step_ = 0;
  double dt0_ = 0.0;  // first step's dt: the reference of the dt-collapse check
  Ledger ledger_;
  long ownerChangeCount_ = 0;

  // Radii (r-z) of the x faces and cell centres.
  std::vector<double> faceX_, cellX_;

  // Markers (material_interfaces only).
  bool markersOn_ = false;
  bool phaseOn_ = false;  // effect phase_bookkeeping: vapour fraction and phase in snapshots
  MarkerSet markerSet_;
  std::vector<int> owner_, ownerNew_, objectMaterial_;
  std::vector<Vec2> normal_, normalNew_;
  mutable std::vector<double> vxOld_, vzOld_, vxMid_, vzMid_;
  struct Change {
    long cell;
    double rho, mx, mz, E;
  };
  // Per material: the mass it must have, its initial mass plus what crossed the domain boundary
  // (renormaliseMaterials, docs/tvd.md "Mass renormalisation").
  std::vector<double> materialTarget_, materialMass_, materialBand_;
  void measureMaterials();  // materialMass_ and materialBand_ of the current state
  void renormaliseMaterials();
  [[nodiscard]] int cellMaterial(long cell) const {
    const int o = owner_[static_cast<std::size_t>(cell)];
    return o < 0 ? -1 : objectMaterial_[static_cast<std::size_t>(o)];
  }
  std::vector<Change> changes_;       // scratch of updateMarkers
  std::vector<signed char> known_;    // scratch: cell has a velocity for the markers
  std::vector<long> fresh_;           // scratch: cells given a velocity in this ring
  std::vector<double> normalLength_;  // scratch: marker length per cell

  int threads_ = 1;
  // Grids smaller than this run their loops on one thread: a parallel region's barrier costs
  // more than the work (and much more when the cores are shared).
  static constexpr long kParallelCells = 16384;
  std::vector<std::unique_ptr<Workspace>> work_;
  // Per sweep line: what it booked to the ledger, summed in line order after the sweep so the
  // totals (and the material targets they feed) do not depend on which thread ran which line.
  std::vector<LineRecord> lineRecords_;
};

}  // namespace hvi::tvd
