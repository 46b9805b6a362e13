//! @file Interface ownership of a marker run: the marker lines, the configuration array
//! (cell -> object), the index array (object -> material), the interface normals, the owner
//! update after each step and the per-material mass renormalisation (docs/tvd.md).
#pragma once
#include <array>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/geometry.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd {

//! Cell volumes of a grid: planar dx dz (per cm of depth), r-z 2 pi r dx dz with r the cell
//! centre. One definition for the solver, the ownership and the totals.
struct CellVolumes {
  GridSpec grid;
  bool rz = false;
  std::vector<double> cellX;  //!< x (r) of the cell centres
  [[nodiscard]] double operator()(long cell) const;
};

//! Which object owns each cell of a marker run, and the bookkeeping that goes with it. The
//! solver owns the flow state and calls in once per step (update) with it.
class Ownership {
 public:
  //! Initial state of an object: the state a changed cell takes when its new owner has no
  //! material left near it or anywhere.
  struct ObjectState {
    double rho, vx, vz, e;
  };

  //! Marker lines around the scene's bodies (object = body), rasterised into the owner array;
  //! `material` is each object's material. Honours a stop request (hvi::throwIfStopRequested).
  void setUp(const cases::Scene& scene, const CellVolumes& cells, std::vector<int> material,
             std::vector<ObjectState> initial, int materials, int threads);
  //! Each material's mass in `U` becomes its target (call once the initial state is set).
  void startTargets(const Conserved& U);

  //! After a flow step of `dt`: moves the marker lines with the time-centred velocity (the
  //! start-of-step velocity in startVelocity(), the end-of-step one from `U`), rebuilds the
  //! owner array, re-initialises the cells whose owner changed and renormalises each
  //! material's mass; what that adds to the domain is booked in `booked`.
  void update(Conserved& U, double dt, Budget& booked);

  //! Conservative cut-cell mode (docs/tvd.md): the marker lines only give the geometry. The
  //! rasterisation keeps every object's cell fractions (fractions()), and the markers move with
  //! the velocity of every cell that holds material, owned or not.
  void setCutCells(bool on) { cutCells_ = on; }
  //! Cut-cell mode with Options::closedOutflow: the outflow sides (xmin, xmax, zmin, zmax)
  //! beyond which the marker lines stay put (MarkerSet::advect); none by default.
  void setOpenSides(std::array<bool, 4> open) { open_ = open; }
  //! Cut-cell mode with Options::closedOutflow and cutOutflowLines: the outflow sides at which
  //! the lines are cut after each move (MarkerSet::clipToSides). None by default.
  void setCutSides(std::array<bool, 4> cut) { cut_ = cut; }
  //! Cut-cell mode: removes the lines of object `o` (a body whose material has all left through
  //! the outflow sides; TvdSolver::dropEmptiedLines). Returns how many.
  long dropLines(int o) { return markers_.removeObject(o); }
  //! Whether any side cuts the lines (setCutSides).
  [[nodiscard]] bool cutsLines() const { return cut_[0] || cut_[1] || cut_[2] || cut_[3]; }
  //! Cut cells: markers on a wall stay on it, none crosses one (Options::markerWalls).
  void setMarkerWalls(bool on) { markerWalls_ = on; }
  //! Cut-cell mode: each line reads its own body's cells' velocity where its stencil holds one
  //! (MarkerSet::advect's `own`; Options::ownBodyVelocity).
  void setOwnVelocity(bool on) { ownVelocity_ = on; }
  //! The marker step of the cut-cell mode: moves and redistributes the lines, rebuilds the
  //! owner array and the fractions (into the buffers lent, lendFractions); the flow state is
  //! not touched. The material
  //! and the lines lie within grid rows [rowLo, rowHi), at least two rows from their ends (or
  //! at the grid's edge), and so does every velocity this mode ever set (Phases::rowLo): only
  //! those rows are visited. The flow state is the mixture of the `count` phase states `parts`
  //! (Phases::q: summed per cell in phase order, as Phases::mixture sums them), taken where it
  //! is read instead of through a mixture array written for it.
  void move(const Conserved* parts, int count, double dt, int rowLo, int rowHi);
  //! Per object o and cell c (fractions()[o][c]): the part of the cell the object covers, as
  //! the last rasterisation (setUp, move, remeasure) left it, until taken.
  [[nodiscard]] const std::vector<std::vector<double>>& fractions() const { return fraction_; }
  //! Hands the fractions over (the phases' volume fractions are computed from them in place),
  //! leaving none here: the next rasterisation writes into the buffers lent before it.
  [[nodiscard]] std::vector<std::vector<double>> takeFractions();
  //! Buffers for the next rasterisation's fractions (per object, zero outside the rows move
  //! is given), so that the fractions need no array of their own between steps.
  void lendFractions(std::vector<std::vector<double>> buffers) { fraction_ = std::move(buffers); }
  //! Rasterises the current lines again (after a restart) into owner, normals and fractions.
  void remeasure();

  //! Mass that came in through the domain boundary for material `m` (sweeps), g.
  void addBoundaryMass(int m, double mass) { target_[static_cast<std::size_t>(m)] += mass; }

  [[nodiscard]] const std::vector<int>& owner() const { return owner_; }
  //! The marker normals per cell; empty in the cut-cell mode, which reads none.
  [[nodiscard]] const std::vector<Vec2>& normal() const { return normal_; }
  //! Cut-cell mode, for its checkpoint: the normals of the current lines (MarkerSet::rasterize),
  //! computed on demand (16 B per cell less between checkpoints).
  [[nodiscard]] std::vector<Vec2> cutCellNormals() const;
  [[nodiscard]] const std::vector<int>& objectMaterial() const { return objectMaterial_; }
  [[nodiscard]] const MarkerSet& markers() const { return markers_; }
  [[nodiscard]] const std::vector<double>& targets() const { return target_; }
  [[nodiscard]] long changes() const { return changeCount_; }
  //! Material of a cell, -1 vacuum.
  [[nodiscard]] int cellMaterial(long cell) const {
    const int o = owner_[static_cast<std::size_t>(cell)];
    return o < 0 ? -1 : objectMaterial_[static_cast<std::size_t>(o)];
  }
  //! Velocity at the start of the step (cm/us), filled by the solver's time-step pass.
  double* startVelocityX() { return vxOld_.data(); }
  double* startVelocityZ() { return vzOld_.data(); }

  //! The state a checkpoint holds (sizes checked by the caller).
  void restore(std::vector<int> owner, std::vector<Vec2> normal, std::vector<double> targets,
               MarkerSet markers, long changes);

 private:
  struct Change {
    long cell;
    double rho, mx, mz, E;
  };
  struct ObjectSum {  // sums of an object's non-empty cells, for the last-resort fill
    double rho = 0.0, mx = 0.0, mz = 0.0, E = 0.0;
    long count = 0;
  };
  // Moves the lines with the time-centred velocity and redistributes them (both modes).
  void advanceLines(const Conserved* parts, int count, double dt, int rowLo, int rowHi);
  void centredVelocity(const Conserved* parts, int count, double dt, int rowLo, int rowHi);
  void extendIntoVacuum(int layers, int rowLo, int rowHi);
  [[nodiscard]] Change fillFor(long cell, int to, const Conserved& U,
                               std::vector<ObjectSum>& sums) const;
  [[nodiscard]] std::vector<ObjectSum> sumObjects(const Conserved& U) const;
  void measure(const Conserved& U);  // mass_ and band_ of the current state
  void renormalise(Conserved& U, Budget& booked);

  CellVolumes cells_;
  int threads_ = 1;
  MarkerSet markers_;
  std::vector<int> owner_, ownerNew_, objectMaterial_;
  std::vector<Vec2> normal_, normalNew_;
  std::vector<ObjectState> initial_;
  long changeCount_ = 0;
  // Per material: the mass it must have, its initial mass plus what crossed the domain boundary
  // (docs/tvd.md "Mass renormalisation"); its mass now and its interface band.
  std::vector<double> target_, mass_, band_, scale_;
  // Scratch, sized once.
  std::vector<double> vxOld_, vzOld_, vxMid_, vzMid_;
  // The time-centred velocity: in the cut-cell mode in place of the start velocity (setUp).
  double* midX() { return cutCells_ ? vxOld_.data() : vxMid_.data(); }
  double* midZ() { return cutCells_ ? vzOld_.data() : vzMid_.data(); }
  std::vector<Change> changes_;
  std::vector<signed char> known_;        // cell has a velocity for the markers
  std::vector<long> fresh_;               // cells given a velocity in this ring
  std::vector<unsigned char> nearKnown_;  // per column of a row: a known cell within a row
  std::vector<double> normalLength_;      // marker length per cell
  bool cutCells_ = false;
  std::array<bool, 4> open_{};  // cut-cell mode: the outflow sides (MarkerSet::advect)
  std::array<bool, 4> cut_{};   // cut-cell mode: lines cut there (MarkerSet::clipToSides)
  bool markerWalls_ = true;
  bool ownVelocity_ = true;
  std::array<bool, 4> walls_{};  //!< xmin, xmax, zmin, zmax hold the markers (cut cells)
  std::vector<std::vector<double>> fraction_;  // cut-cell mode: object fractions per cell
};

}  // namespace hvi::tvd
