//! @file State and geometry of the conservative cut-cell interface mode (docs/tvd.md,
//! "Conservative interfaces"): every body (phase) keeps its own conserved state in every
//! cell it occupies, on the part of the cell the marker lines give it.
#pragma once
#include <cstdint>
#include <vector>

#include "hvi/common/snapshot.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd {

struct CellVolumes;

//! Below this volume fraction a phase is absent from a cell: the round-off of the exact polygon
//! coverage (docs/markers.md) is ~1e-13 of a cell, and a sliver of 1e-9 of a cell holds no state
//! worth a flux. Material stranded in such a cell is handed to a neighbour (Phases::repair).
inline constexpr double kPhaseAbsent = 1e-9;

struct Phases;

//! Each phase's volume fractions before a marker step, where nonzero (cells in increasing
//! order): the repair reads them only where a phase is left with no neighbour, so a sparse copy
//! replaces a second array of every phase's fractions (8 B per phase and cell).
struct OldFractions {
  std::vector<std::vector<long>> cell;
  std::vector<std::vector<double>> value;
  //! Keeps the nonzero fractions of phases.alpha (all lie in rows [rowLo, rowHi)).
  void keep(const Phases& phases);
  //! Phase p's kept fraction of cell c (0 where none was kept).
  [[nodiscard]] double at(int p, long c) const;
};

//! Per phase p (body index; the solver keeps each body's material) and cell c: the volume
//! fraction alpha (from the marker lines), the conserved state per unit CELL volume q = alpha U
//! (U the phase's own state per unit phase volume), and the one-sided face apertures of the
//! phase (MarkerSet::faceApertures).
struct Phases {
  int count = 0;
  GridSpec grid;
  std::vector<Conserved> q;
  std::vector<std::vector<double>> alpha;
  //! Per phase: its material's reference density, for the volume of an orphan whose kept
  //! volume packs it beyond any state of the material (repair); 0 (the rule off) until set.
  std::vector<double> rho0;
  //! Further per-unit-cell-volume quantities of each phase that move with its mass wherever
  //! the repair moves it (effect strength: rho_p times the deviator and the plastic strain,
  //! docs/strength.md "TVD with interfaces"); carried[p] may be empty. Not owned.
  std::vector<std::vector<std::vector<double>*>> carried;
  //! Working fractions within a step: alpha at its start, then moved by each sweep with the
  //! phases' velocities (docs/tvd.md); the marker lines give alpha again after the step.
  std::vector<std::vector<double>> volume;
  //! One-sided face apertures per phase (FaceApertures, one slot per body).
  FaceApertures faces;
  //! Grid rows [rowLo, rowHi) that can hold material or geometry: the union, over the run, of
  //! the rows the marker lines span, widened by kRowMargin. Every phase array (q, alpha,
  //! volume, the apertures) and the mixture are zero outside, so the per-step passes visit these
  //! rows only; any wider range gives the same results (docs/tvd.md, "Cost").
  int rowLo = 0, rowHi = 0;
  //! Rows beyond the lines' span: the markers' velocity reaches two cells into vacuum
  //! (Ownership), and a z face row lies one above its cells.
  static constexpr int kRowMargin = 3;
  [[nodiscard]] long cellLo() const { return static_cast<long>(rowLo) * grid.nx; }
  [[nodiscard]] long cellHi() const { return static_cast<long>(rowHi) * grid.nx; }
  //! Widens [rowLo, rowHi) to hold rows [lo, hi) (clamped to the grid).
  void coverRows(int lo, int hi);
  //! Widens the rows to every row where some phase has a fraction or material (after a
  //! restart: orphan cells may lie outside the lines' span).
  void coverOccupied();

  [[nodiscard]] double apertureX(int p, int side, int i, int k) const {
    return faces.ax(p, side, i, k);
  }
  [[nodiscard]] double apertureZ(int p, int side, int i, int k) const {
    return faces.az(p, side, i, k);
  }

  //! Sizes every array for `phases` bodies on `grid`, all empty.
  void resize(int phases, const GridSpec& grid);
  //! Volume fractions and face apertures from the marker lines; phase p is body p. `alpha`
  //! holds every body's cell fractions (MarkerSet::rasterizeFractions, zero outside the lines'
  //! rows) on entry and the volume fractions on return: where two bodies' lines overlap by
  //! round-off so that the phases together cover more than a cell or a face, each is scaled to
  //! fit, and a fraction below kPhaseAbsent is 0.
  void measure(const MarkerSet& markers);
  //! After the volume fractions change: material left in a cell its phase no longer occupies
  //! goes to the neighbour of that phase with the largest fraction, and a cell the phase newly
  //! occupies shares the state of that neighbour (conservative averages of the integrals,
  //! Hu et al. 2006, section 2.5). `oldAlpha` is the fraction before the change; a phase with
  //! no neighbour within two rings keeps its old fraction there (an orphan, counted).
  long repair(const CellVolumes& volumes, const OldFractions& oldAlpha);
  //! First part of repair for phase p: material the sweeps carried ahead of the marker lines
  //! goes to the neighbouring cells the lines give it (working fraction `volume` against alpha).
  void settle(const CellVolumes& volumes, int p);
  //! Second part of settle: a deficit the two rings could not fill takes from the nearest
  //! cells with an excess along a path of face neighbours holding the phase, each hop moving the
  //! volume at its own cell's state (docs/tvd.md, "Uniform motion").
  void route(const CellVolumes& volumes, int p);
  //! Mixture state: the sum of the phases' q (rows [rowLo, rowHi); U is zero outside).
  void mixture(Conserved& U) const;

 private:
  // Repair scratch: the scan's offsets, compacted per chunk; the phase's mismatch band, the
  // repair's seeds, the cells route's hops changed, their merge, the cells a pass visits.
  std::vector<std::uint32_t> found_, foundB_;
  std::vector<long> band_, seeds_, hopped_, merged_, todo_;
  std::vector<unsigned> stamp_;  // route scratch: BFS visit stamps and parents per cell
  std::vector<long> parent_, queue_;
  std::vector<int> depth_;
  unsigned epoch_ = 0;
};

}  // namespace hvi::tvd
