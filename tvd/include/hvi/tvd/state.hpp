//! @file The TVD solver's state and budgets: conserved arrays, Budget, Ledger.
#pragma once
#include <vector>

namespace hvi::tvd {

//! Conserved state per cell (index k * nx + i) per unit volume: density g/cm^3, momentum
//! density g/(cm^2 us) along x (or r) and z, total energy density rho (e + |v|^2/2), Mbar.
struct Conserved {
  std::vector<double> rho, mx, mz, E;
};

//! Component `part` (&Conserved::rho, ...) of the mixture of `count` phase states at cell c:
//! their sum in phase order, which is Phases::mixture's value bit for bit (one phase: its own),
//! for the passes that read the mixture without forming it.
inline double mixtureAt(const Conserved* parts, int count, std::vector<double> Conserved::*part,
                        std::size_t c) {
  double s = (parts[0].*part)[c];
  for (int p = 1; p < count; ++p) s += (parts[p].*part)[c];
  return s;
}

//! Mass (g), momentum (g cm/us) and energy (g cm^2/us^2) that one mechanism added to the domain
//! (negative: removed). Planar amounts are per cm of depth; r-z amounts include the 2 pi r.
//! The line kernel books into the same type, per unit line length (Budget::add).
struct Budget {
  double mass = 0.0, momentumX = 0.0, momentumZ = 0.0, energy = 0.0;
  Budget& operator+=(const Budget& o) {
    mass += o.mass;
    momentumX += o.momentumX;
    momentumZ += o.momentumZ;
    energy += o.energy;
    return *this;
  }
  //! Adds amounts given in the coordinates of a sweep line along `axis` (0: x, 1: z): normal
  //! momentum `pn` along the line, tangential `pt` across it.
  void add(double m, double pn, double pt, double e, int axis) {
    mass += m;
    (axis == 0 ? momentumX : momentumZ) += pn;
    (axis == 0 ? momentumZ : momentumX) += pt;
    energy += e;
  }
  //! `scale` times this budget (line amounts to the solver's units).
  [[nodiscard]] Budget scaled(double scale) const {
    return {scale * mass, scale * momentumX, scale * momentumZ, scale * energy};
  }
};

//! Every way the totals change. totals() (the domain plus what left through outflow sides)
//! now minus totals() at the start equals sum() to round-off (momentumX excepted in r-z, where
//! the radial momentum has the P/r source).
struct Ledger {
  Budget boundary;      //!< impulse of the walls and the axis (normal momentum only)
  Budget interfaces;    //!< two-sided fluxes at object/object and object/vacuum faces (markers)
  Budget ownerChanges;  //!< cells re-initialised or emptied when the configuration changes
  Budget floors;        //!< velocity reset below the vacuum density, internal-energy floor
  //! What left through the outflow sides (outflow positive; inflow negative): part of the
  //! totals, not a change of them (Solver::outflow).
  Budget outflow;
  [[nodiscard]] Budget sum() const {
    Budget s = boundary;
    s += interfaces;
    s += ownerChanges;
    s += floors;
    return s;
  }
};

//! Grids smaller than this run their loops on one thread: a parallel region's barrier costs
//! more than the work (and much more when the cores are shared).
inline constexpr long kParallelCells = 16384;
//! Cells below which a streaming pass (a copy or sum of a few arrays, a mask, a fit of the
//! fractions: a few operations per cell) runs on one thread. Such a pass over the ~1e5 cells of
//! variant 1's rows takes tens of microseconds, about what waking the threads costs with a
//! passive wait policy on two cores; with ~50 parallel regions per step the conservative mode
//! gained nothing from a second thread (docs/performance.md, "TVD: thread wake-ups").
inline constexpr long kParallelStream = 1L << 20;

}  // namespace hvi::tvd
