//! @file Eulerian second-order TVD finite-volume solver with marker lines (docs/tvd.md).
#pragma once
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/common/solver.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/ownership.hpp"
#include "hvi/tvd/phases.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd {
namespace detail {
struct StrengthState;
}

//! The solver the `hvi` command drives for `solver = "tvd"` scenes. Throws hvi::InputError for
//! a scene the solver cannot run (see TvdSolver).
std::unique_ptr<Solver> createSolver(const cases::Scene& scene);

//! Settings the scene does not carry (defaults are those documented in docs/tvd.md).
struct Options {
  double entropyFix = 0.1;    //!< Harten's delta as a fraction of |u| + c at the face
  int contactIterations = 2;  //!< two-shock impedance updates at object/object faces
  int threads = 0;            //!< OpenMP threads for the sweeps; 0: omp_get_max_threads()
  //! Without markers, sweep detail::kBatch lines at a time (vectorised across lines); false:
  //! one line at a time, the reference the batches reproduce bit for bit (tests).
  bool lineBatches = true;
  //! Cut-cell mode, an experiment (off): a phase cell's negative internal energy is floored
  //! (raised to e = 0, booked) only where its EOS cannot take it (P < 0 or not finite, c not
  //! positive). It removes the Whipple d = 1 cm run's floors but makes a thin-cell outflow scene
  //! collapse (docs/tvd.md, "The energy floor in cold compressed cells").
  bool keepColdStates = false;
  //! Cut-cell mode (docs/tvd.md "Outflow sides: no re-entry"; off in Options, on in scenes):
  //! nothing re-enters through an outflow side. A face there where the edge cell's phase moves
  //! inwards is a wall for that phase (no mass, tangential momentum or energy; the normal momentum
  //! of the contact pressure with the cell's mirror image), and marker lines beyond the side stay
  //! put. Without it the zero-gradient ghost lets the phase in and the lines beyond follow the edge
  //! cells' velocity back in (variant 1 at 0.0075 cm took 0.16 of its 0.28 energy in through its
  //! top side). The scene key tvd.outflow sets it ("auto", the default, and "no_reentry"); a
  //! library user's Options keep it off unless set.
  bool closedOutflow = false;
  //! Cut-cell mode with closedOutflow, an experiment (off; the scene key tvd.outflow =
  //! "no_reentry_cut" sets both): the marker lines are cut at the outflow sides after every
  //! move (MarkerSet::clipToSides), so no line holds material that left, and a body whose mass
  //! has all left loses its lines (docs/tvd.md "Cutting the lines at outflow sides"). false: the
  //! earlier lines, whose markers beyond an outflow side stay put. The open outflow (the
  //! default) keeps its lines: cut there, they either let the ghost's inflow be packed into the
  //! edge cells or, held at the side, grew a jet (measured, same section).
  bool cutOutflowLines = false;
  //! Cut-cell mode: a marker on a wall keeps its normal coordinate and none crosses a wall, so a
  //! body's side on a wall stays there (docs/markers.md; the spall scene's lateral tension
  //! pulled the phases off the walls, docs/strength.md "TVD fracture"). false: the earlier
  //! motion with the field clamped to the outermost cell centres.
  bool markerWalls = true;
  //! Cut-cell mode: where a body fills a cell of a marker's interpolation stencil or of the ring
  //! around it, its line moves with the velocity of the stencil's cells that hold the body (or
  //! that the bodies together fill) only (docs/tvd.md
  //! "Marker velocity: each line its own body's"; MarkerSet::advect's `own`). false, and always
  //! with tvd.outflow = "open": every cell's, vacuum cells taking their neighbours' mean, so that
  //! a body's free surface moved with a body a cell away (before 2026-12-04).
  bool ownBodyVelocity = true;
  //! Cut-cell mode with closedOutflow: a phase in an edge cell of an outflow side that moves
  //! out, holds less of the cell than leaves in one step at its speed and no longer reaches the
  //! cell's inner face is released through the side, booked as outflow (docs/tvd.md "Slivers at
  //! outflow sides"). false: it stays (the side holds it as a wall while its lines, beyond the
  //! side, give it a vanishing fraction).
  bool releaseSlivers = true;
};

//! Eulerian TVD solver (the scheme is specified in docs/tvd.md):
//! - uniform grid over scene.domain with dx = dz = scene.tvd.cellSize (the domain is rounded to
//!   whole cells from xmin, zmin); planar x-z or r-z (x = r >= 0);
//! - Strang-alternated dimensional splitting (x then z on even steps, z then x on odd), each
//!   1-D sweep integrated by Heun's two-stage predictor-corrector with Harten-Yee upwind TVD
//!   fluxes, limiter scene.tvd.limiter, CFL scene.tvd.cfl;
//! - with the `material_interfaces` effect: interface ownership (Ownership: marker lines
//!   around every body, a configuration array cell -> object, an index array object ->
//!   material), ghost-fluid fluxes at interfaces and vacuum (P = 0); without it the scene must
//!   have one material and vacuum is that material below scene.tvd.vacuumDensity * rho0.
//! The solver holds the grid, the settings, the conserved state and the ledger, and conducts a
//! step: the time step, the sweeps (sweep.cpp), then Ownership::update.
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
  [[nodiscard]] Totals totals() const override;  //!< in the domain plus outflow()
  [[nodiscard]] Totals outflow() const override;
  void writeCheckpoint(std::ostream& out) const override;
  void readCheckpoint(std::istream& in) override;

  // Lower-level access (tests, tools).
  [[nodiscard]] const GridSpec& grid() const { return grid_; }
  [[nodiscard]] Geometry geometry() const { return geometry_; }
  [[nodiscard]] const Conserved& conserved() const {
    syncMixture();
    return U_;
  }
  //! Mutable state for tests that set up states the scene cannot express. The caller keeps it
  //! physical (rho > 0 in material cells, zero in vacuum cells of a marker run).
  Conserved& conservedForTesting() {
    syncMixture();
    return U_;
  }
  [[nodiscard]] bool markersActive() const { return markersOn_; }
  //! Conservative cut-cell interfaces (each phase its own state on its part of the cells).
  [[nodiscard]] bool cutCells() const { return cut_; }
  [[nodiscard]] const Phases& phases() const { return phases_; }  //!< cut-cell mode only
  Phases& phasesForTesting() { return phases_; }
  [[nodiscard]] const Ownership& ownership() const { return ownership_; }  //!< markers only
  [[nodiscard]] const MarkerSet& markers() const { return ownership_.markers(); }
  //! Configuration array: owning object per cell, -1 vacuum (markers only; empty otherwise).
  [[nodiscard]] const std::vector<int>& owner() const { return ownership_.owner(); }
  //! Index array: material of each object.
  [[nodiscard]] const std::vector<int>& objectMaterial() const { return objectMaterial_; }
  [[nodiscard]] const Ledger& ledger() const { return ledger_; }
  //! Effect strength: rho times component k of the strength state per cell (0: s_xx, 1: s_zz,
  //! 2: s_xz, 3: the equivalent plastic strain), for tests that set up a state the scene cannot
  //! express. Throws std::logic_error without the effect.
  std::vector<double>& strengthStateForTesting(int k);
  //! The same per phase p of the conservative interfaces (rho_p times the component per unit
  //! cell volume). Throws std::logic_error without the effect or for a fluid phase.
  std::vector<double>& phaseStrengthStateForTesting(int p, int k);
  //! Largest stable step of the current state, us.
  [[nodiscard]] double stableTimeStep() const;
  //! Cells whose owner changed since the start (markers only).
  [[nodiscard]] long ownerChanges() const { return ownership_.changes(); }
  //! Lines of a line batch that needed the positivity fallback and were redone one at a time.
  [[nodiscard]] long linesRedone() const;
  //! Cell volume (planar: cm^2 per cm of depth; r-z: 2 pi r dr dz, cm^3).
  [[nodiscard]] double cellVolume(long cell) const { return cellVolumes_(cell); }
  //! Cut-cell mode: cell-stages whose phases took one velocity (stiff exchange, docs/tvd.md
  //! "The thin film"), counted since this solver was built (a diagnostic; not checkpointed).
  [[nodiscard]] long relaxations() const { return relaxations_; }
  //! Cut-cell mode: deficits the limiter could not reach, mixed with a neighbour (docs/tvd.md
  //! "The thin film"), counted since this solver was built (a diagnostic; not checkpointed).
  [[nodiscard]] long deficitMixings() const { return mixings_; }
  //! Cut-cell mode: cell-stages of a phase below the vacuum density pooled with a neighbour
  //! instead of put at rest (docs/tvd.md, "The vacuum cut-off"); a diagnostic, not checkpointed.
  [[nodiscard]] long thinPoolings() const { return poolings_; }
  //! The vacuum density in use, a fraction of rho0: scene.tvd.vacuumDensity, or where the scene
  //! leaves it 0 the mode's default (docs/tvd.md "The vacuum cut-off: pooled, not discarded"):
  //! 1e-6, the study's, without markers and in the whole-cell mode; 1e-9 in the conservative
  //! mode, where the cut-off discards a phase's momentum and energy, and 1e-6 discarded 1.5e-5
  //! of variant 1's energy at 0.0075 cm.
  [[nodiscard]] double vacuumDensity() const {
    if (params_.vacuumDensity > 0.0) return params_.vacuumDensity;
    return cut_ ? 1e-9 : 1e-6;
  }
  //! Cut-cell mode: mass of each phase (body, Phases) that left through the outflow sides since
  //! the start (inflow negative; checkpointed): with it every body's mass closes to round-off.
  [[nodiscard]] const std::vector<double>& phaseOutflowMass() const { return phaseOutflow_; }

 private:
  struct Workspace;
  struct LineRecord;
  void setUpGrid(const cases::Scene& scene);
  void setUpMaterials(const cases::Scene& scene);
  void initialiseState(const cases::Scene& scene);
  void sweep(int direction, double dt);
  void sweepCut(int direction, double dt);
  void finishSweep(int lines);  // failure report or the line records into the ledger
  void initialiseCut(const cases::Scene& scene);
  // Effect strength (strength_step.cpp, docs/strength.md "TVD"): the state, the sub-step after
  // the sweeps, and the shear modulus of a cell's state (the time step's c_L).
  void setUpStrength(const cases::Scene& scene);
  void strengthStep(double dt);
  [[nodiscard]] double strengthShearModulus(double rho, double e, double p) const;
  // The same with conservative interfaces (strength_cut.cpp): per solid phase, the cell's
  // deviator the volume-fraction-weighted one; phase p's shear modulus at its own state.
  void strengthStepCut(double dt);
  [[nodiscard]] double phaseShearModulus(int p, double rho, double e, double pressure) const;
  // Body `body`'s initial state at the centre of `cell` (a radial velocity field sampled there).
  [[nodiscard]] Ownership::ObjectState stateAtCentre(const cases::Scene& scene, std::size_t body,
                                                     std::size_t cell) const;
  // Adds `weight` times the conserved form of state `b` to cell c of U.
  static void addState(Conserved& U, std::size_t c, const Ownership::ObjectState& b, double weight);
  void measurePhases();            // phases_ geometry from the marker lines (cut-cell mode)
  void markOwnCells();             // cut-cell mode: the cells each line reads its velocity from
  void releaseSlivers(double dt);  // cut-cell mode, no re-entry: slivers leave through the side
  void dropEmptiedLines();         // cut-cell mode: the lines of bodies that have all left
  double signalSpeedCut(double* vx, double* vz, long* worstCell) const;
  // Cut cells: each velocity component of a phase cell below the time-step density limited to
  // one cell per step (docs/tvd.md, "Thin cells faster than the step"), booked under floors.
  void limitThinVelocities(double dt);
  // Largest signal speed over the material cells (and the check that each is physical); with
  // vx/vz given, each material cell's velocity is stored there (the markers' start velocity).
  double signalSpeedPass(double* vx, double* vz, long* worstCell) const;

  // Grid.
  GridSpec grid_;
  Geometry geometry_ = Geometry::Planar;
  cases::Domain domain_;
  std::vector<double> faceX_, cellX_;  // radii (r-z) of the x faces and cell centres
  CellVolumes cellVolumes_;

  // Scene and settings.
  cases::TvdParams params_;
  Options options_;
  // Per phase: the conservative mode gives every body its own phase (a copy of its material),
  // so that the line between two bodies of one material is a material interface, not a tracer
  // that the phase's mass flows across; elsewhere one per scene material.
  std::vector<cases::Material> materials_;
  std::vector<cases::Material> sceneMaterials_;  // the scene's materials
  std::vector<int> sceneMaterialOf_;             // per entry of materials_: its scene material
  std::vector<std::string> bodyNames_;
  std::vector<int> objectMaterial_;                 // material of each body (object)
  std::vector<Ownership::ObjectState> bodyStates_;  // initial state of each body (object)
  std::vector<double> rhoCut_;  // per material: below this density a cell is vacuum
  // Per material: below kThinFraction * rho0 a cell is nearly empty; if the positivity fallback
  // cannot keep it physical it is reset to vacuum (booked in the ledger) instead of aborting.
  static constexpr double kThinFraction = 1e-3;
  std::vector<double> rhoThin_;
  // Cut-cell mode: a phase cell below kStepDensityFraction * rho0 does not set the time step
  // (Autodyn's minimum density factor for the time step, 1e-4): far-expanded vapour whose EOS
  // sound speed grows without bound (Tillotson, 2e4 cm/us at 1e-5 rho0) would stop the run for
  // a negligible mass; its state stays bounded by the positivity treatment (docs/tvd.md "The
  // thin film"). Its mass is still conserved exactly.
  static constexpr double kStepDensityFraction = 1e-4;
  std::vector<double> rhoStep_;
  // Effect strength: below kStrengthDensityFraction * rho0 a cell carries no deviator. Intact
  // solid never stretches that far (aluminium would need some -15 GPa); what does is a free
  // surface's partly filled cell (the single material's average with the vacuum beside it) or
  // material torn apart, and a deviator there would push a nearly empty cell at any speed.
  static constexpr double kStrengthDensityFraction = 0.8;
  int singleMaterial_ = 0;  // the material of a run without markers
  bool markersOn_ = false;  // effect material_interfaces: marker lines and ownership_
  bool phaseOn_ = false;    // effect phase_bookkeeping: vapour fraction and phase in snapshots

  // State. In the cut-cell mode U_ is the mixture of the phases (Phases::mixture), formed when
  // something reads it (syncMixture) rather than after every step: the step's own readers
  // (the signal speed's velocities, totals) sum the phases where they read them, to the same
  // bits. mixtureStale_: the phases changed since U_ was formed.
  void syncMixture() const {
    if (!mixtureStale_) return;
    phases_.mixture(U_);
    mixtureStale_ = false;
  }
  mutable Conserved U_;
  mutable bool mixtureStale_ = false;
  double time_ = 0.0;
  long step_ = 0;
  double dt0_ = 0.0;  // first step's dt: the reference of the dt-collapse check
  Ledger ledger_;
  Ownership ownership_;    // markers only
  bool cut_ = false;       // conservative cut-cell interfaces (markers only)
  Phases phases_;          // cut-cell mode: per material fractions, apertures and states
  OldFractions alphaOld_;  // cut-cell mode: fractions before the marker step (nonzero ones)
  long relaxations_ = 0;   // cut-cell mode: relaxed cell-stages (diagnostic)
  long mixings_ = 0;       // cut-cell mode: deficits mixed (diagnostic)
  long poolings_ = 0;      // cut-cell mode: thin cells pooled (diagnostic)
  long orphans_ = 0;       // cut-cell mode: cells kept off the geometry
  std::vector<double> phaseOutflow_;  // cut-cell mode: each phase's mass out through outflow sides
  std::vector<double> phaseEdge_;     // cut-cell mode: the same per line and sweep (line order)
  // Cut-cell mode: each phase's first and last occupied position along each line of the sweep
  // (-1 where none), from one pass over the fractions in memory order: the line windows
  // without a strided search from both ends of every line.
  std::vector<int> phaseSpan_;
  std::vector<double> columnSpan_;  // scratch of that pass for the z lines: each column's rows
  // Cut-cell mode: the same for the lines of the step's second sweep, recorded per thread by the
  // first as it writes its lines back (valid while spanNextValid_).
  std::vector<int> spanNext_;
  bool spanNextValid_ = false;
  // Cut-cell mode: the working fractions equal alpha (the first sweep of a step reads alpha and
  // writes phases_.volume; every occupied cell lies in its line's window, so all are written).
  bool volumeFresh_ = true;

  // Sweep scratch, one per thread, and the per-line ledger records (summed in line order after
  // the sweep so the totals and the material targets do not depend on the schedule).
  int threads_ = 1;
  std::vector<std::unique_ptr<Workspace>> work_;
  std::vector<LineRecord> lineRecords_;
  // Effect strength: rho times the deviator and the plastic strain per cell (null without it).
  std::unique_ptr<detail::StrengthState> strength_;
};

}  // namespace hvi::tvd
