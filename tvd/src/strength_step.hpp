//! @file TVD with the effect `strength` (docs/strength.md, "TVD"): the per-cell strength state,
//! its conservative advection with the mass fluxes of a sweep line, and the strength sub-step.
#pragma once
#include <array>
#include <vector>

#include "hvi/strength/strength.hpp"
#include "line_work.hpp"

namespace hvi::tvd::detail {

//! Strength scalars carried per unit volume (rho q), so that the sweeps advect them with the
//! mass: the deviator's three stored components and the equivalent plastic strain.
enum StrengthComponent : int { kSxx = 0, kSzz = 1, kSxz = 2, kEps = 3, kStrengthFields = 4 };

//! The strength state of a single-material TVD run (exists only when the scene names
//! `strength`). `rq[k][c]` is rho times the component k of cell c.
struct StrengthState {
  strength::Material material;  //!< of the run's material
  bool solid = false;           //!< false: a fluid (no strength table), s stays 0
  double rho0 = 0.0;            //!< reference density (eta = rho / rho0)
  std::array<std::vector<double>, kStrengthFields> rq;
  // Sub-step scratch, one value per cell: velocity, live (above the vacuum density) and the
  // specific deviator after the update.
  std::vector<double> u, w;
  std::vector<unsigned char> live;
  std::array<std::vector<double>, 3> s;
  //! Conservative interfaces (docs/strength.md, "TVD with interfaces"): per phase (body) its
  //! strength table and rho_p q per unit CELL volume (the phase's mass in the cell times q, as
  //! the phase's conserved state), empty for a fluid phase; `rq` above is then unused, and `s`
  //! holds the cell's volume-fraction-weighted deviator.
  struct Phase {
    strength::Material material;
    bool solid = false;
    double rho0 = 0.0;
    std::array<std::vector<double>, kStrengthFields> rq;
  };
  std::vector<Phase> phases;
  //! Cut-cell scratch: the cell's velocity gradient (dvx/dx, dvx/dz, dvz/dx, dvz/dz, hoop).
  std::array<std::vector<double>, 5> grad;
};

//! Per-thread scratch of the advection along one line.
struct StrengthLineWork {
  explicit StrengthLineWork(int capacity)
      : rhoOld(static_cast<std::size_t>(capacity) + 4),
        massFlux(static_cast<std::size_t>(capacity) + 5),
        q(static_cast<std::size_t>(capacity) + 4),
        cells(static_cast<std::size_t>(capacity) + 4),
        rhoNew(static_cast<std::size_t>(capacity) + 4),
        invVol(static_cast<std::size_t>(capacity) + 4),
        lanes(static_cast<std::size_t>(capacity + 4) * 8) {}
  std::vector<double> rhoOld;    //!< the line's density before the sweep (buffer positions)
  std::vector<double> massFlux;  //!< time-integrated mass through face f (line units)
  std::vector<double> q;         //!< specific value of one component
  std::vector<long> cells;       //!< grid cell of each buffer position 2..n+1
  std::vector<double> rhoNew;    //!< a batch lane's density after the sweep
  std::vector<double> invVol;    //!< a batch lane's inverse cell volumes (line units)
  std::vector<double> lanes;  //!< a batch's density before the sweep, as its buffers (<= 8 lanes)
};

//! Advects the strength scalars of one swept line (cells `cells[j]` at buffer positions
//! 2..n+1) with the line's own mass fluxes. The sweep changes a cell's density by its face
//! fluxes only, so the time-integrated mass flux through each face follows from the density
//! change, starting from the low end (a wall or the axis: none; an outflow side: the edge
//! budget `edgeMassLow`, inflow positive). rho q then changes by those fluxes times the
//! upwind value of q (second order, minmod-limited, Courant-corrected), so a uniform q stays
//! uniform exactly and sum rho q V changes only through the domain's edges.
void advectStrengthLine(StrengthState& st, StrengthLineWork& sw, const LineWork& w, int n,
                        double edgeMassLow, double rhoCut);
//! The same with the density after the sweep and the inverse volumes given as buffers
//! (positions 2..n+1): a lane of the four-line batches.
void advectStrengthLine(StrengthState& st, StrengthLineWork& sw, const double* rhoNew,
                        const double* invVol, int n, double edgeMassLow, double rhoCut);
//! The same for the given arrays `rq` (a phase's, in the cut-cell mode: `rhoOld` and `rhoNew`
//! are then that phase's mass per unit cell volume before and after the sweep).
void advectStrengthLine(std::array<std::vector<double>, kStrengthFields>& rq, StrengthLineWork& sw,
                        const double* rhoNew, const double* invVol, int n, double edgeMassLow,
                        double rhoCut);

}  // namespace hvi::tvd::detail
