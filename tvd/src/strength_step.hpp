//! @file TVD with the effect `strength` (docs/strength.md, "TVD"): the per-cell strength state,
//! its conservative advection with the mass fluxes of a sweep line, and the strength sub-step.
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "hvi/strength/strength.hpp"
#include "hvi/tvd/characteristics.hpp"
#include "line_work.hpp"

namespace hvi::tvd::detail {

//! Strength scalars carried per unit volume (rho q), so that the sweeps advect them with the
//! mass: the deviator's three stored components, the equivalent plastic strain and, with the
//! effect fracture only, the damage D (its array is empty without fracture, and every loop over
//! the components skips an empty one, so a run without fracture does the same arithmetic).
enum StrengthComponent : int {
  kSxx = 0,
  kSzz = 1,
  kSxz = 2,
  kEps = 3,
  kDamage = 4,
  kStrengthFields = 5
};
//! The components a run without fracture carries (and its checkpoint holds).
inline constexpr int kStrengthFieldsWithoutDamage = 4;

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
  //! Effect fracture (docs/strength.md, "TVD fracture"): rq[kDamage] exists (single material,
  //! or each solid phase's); per material (phase) its spall strength (-1: a fluid, or a material
  //! the single-material run does not use: no limit) and the density below which it counts as
  //! torn (kStrengthDensityFraction rho0), for the sweeps.
  bool fracture = false;
  std::vector<double> spall, rhoIntact;
  //! Cut-cell scratch: the cell's velocity gradient (dvx/dx, dvx/dz, dvz/dx, dvz/dz, hoop).
  std::array<std::vector<double>, 5> grad;
};

//! Failed material (effect fracture: D = 1, to the round-off of the advected ratio rho D / rho)
//! returns to a zero yield every step and carries no deviator: no shear wave, so its c_L in the
//! time step is the bulk sound speed (docs/strength.md, "TVD fracture"). `rhoD` is the damage
//! component of rq (empty without fracture), `rho` the cell's (phase's) density of the same
//! normalisation.
inline bool failedMaterial(const std::vector<double>& rhoD, std::size_t c, double rho) {
  return !rhoD.empty() && rhoD[c] >= (1.0 - 1e-12) * rho;
}

//! The sub-step's boundary sides (xmin, xmax, zmin, zmax): true where the side mirrors (a wall
//! or the axis), false for an outflow side.
using StrengthSides = std::array<bool, 4>;

//! d(u, w)/d(along `axis`: 0 = x, 1 = z) of the sub-step's velocity (st.u, st.w) at cell
//! c = k nx + i, from its neighbours: a mirror side reflects the normal velocity, an outflow
//! side repeats the cell, a cell that is not live is left out (one-sided difference).
inline void strengthVelocityDerivative(const StrengthState& st, const StrengthSides& reflect,
                                       int nx, int nz, double h, long c, int i, int k, int axis,
                                       double& du, double& dw) {
  const auto cc = static_cast<std::size_t>(c);
  const bool lowEdge = axis == 0 ? i == 0 : k == 0;
  const bool highEdge = axis == 0 ? i == nx - 1 : k == nz - 1;
  const long stride = axis == 0 ? 1 : nx;
  const double u0 = st.u[cc], w0 = st.w[cc];
  double uL = u0, wL = w0, uR = u0, wR = w0;
  bool hasL = true, hasR = true;
  if (lowEdge) {
    if (reflect[axis == 0 ? 0 : 2]) {
      uL = axis == 0 ? -u0 : u0;
      wL = axis == 0 ? w0 : -w0;
    }
  } else {
    const auto l = static_cast<std::size_t>(c - stride);
    hasL = st.live[l] != 0;
    uL = st.u[l];
    wL = st.w[l];
  }
  if (highEdge) {
    if (reflect[axis == 0 ? 1 : 3]) {
      uR = axis == 0 ? -u0 : u0;
      wR = axis == 0 ? w0 : -w0;
    }
  } else {
    const auto r = static_cast<std::size_t>(c + stride);
    hasR = st.live[r] != 0;
    uR = st.u[r];
    wR = st.w[r];
  }
  if (hasL && hasR) {
    du = (uR - uL) / (2.0 * h);
    dw = (wR - wL) / (2.0 * h);
  } else if (hasR) {
    du = (uR - u0) / h;
    dw = (wR - w0) / h;
  } else if (hasL) {
    du = (u0 - uL) / h;
    dw = (w0 - wL) / h;
  } else {
    du = dw = 0.0;
  }
}

//! Traction (tx, tz) and its power pe on a face, per unit face area.
struct StrengthFaceFlux {
  double tx = 0.0, tz = 0.0, pe = 0.0;
};
//! The face value along `axis` between cells a (low) and b (high) of the sub-step's deviator
//! st.s and velocity; a or b < 0: the domain's edge, whose ghost is a mirror (wall, axis: the
//! normal velocity and the shear traction vanish on the face) or a copy (outflow). A face next
//! to a cell that is not live carries nothing.
inline StrengthFaceFlux strengthFaceFlux(const StrengthState& st, const StrengthSides& reflect,
                                         int axis, long a, long b, bool lowEdgeFace) {
  using Flux = StrengthFaceFlux;
  const bool edge = a < 0 || b < 0;
  const long c = a < 0 ? b : a;
  const auto cc = static_cast<std::size_t>(c);
  if (!st.live[cc]) return {};
  double sxx = st.s[0][cc], szz = st.s[1][cc], sxz = st.s[2][cc], u = st.u[cc], w = st.w[cc];
  if (edge) {
    const int side = axis == 0 ? (lowEdgeFace ? 0 : 1) : (lowEdgeFace ? 2 : 3);
    if (reflect[side]) return axis == 0 ? Flux{sxx, 0.0, 0.0} : Flux{0.0, szz, 0.0};
    return axis == 0 ? Flux{sxx, sxz, sxx * u + sxz * w} : Flux{sxz, szz, sxz * u + szz * w};
  }
  const auto bb = static_cast<std::size_t>(b);
  if (!st.live[bb]) return {};
  sxx = 0.5 * (sxx + st.s[0][bb]);
  szz = 0.5 * (szz + st.s[1][bb]);
  sxz = 0.5 * (sxz + st.s[2][bb]);
  u = 0.5 * (u + st.u[bb]);
  w = 0.5 * (w + st.w[bb]);
  return axis == 0 ? Flux{sxx, sxz, sxx * u + sxz * w} : Flux{sxz, szz, sxz * u + szz * w};
}

//! Effect fracture inside the sweeps' EOS calls (docs/strength.md, "TVD fracture"):
//! a solid phase's pressure becomes strength::effectivePressure(P, D, spall), as SPH
//! applies it after every EOS evaluation; below kStrengthDensityFraction rho0 (`intact` false:
//! torn material, which the failure rule has met on the way there) it carries no tension at all.
//! Capped, the pressure no longer follows the state (both derivatives 0, as the EOS's own
//! cut-off); scaled by 1 - D, so are they. H follows P; the sound speed is the EOS's (it only sets
//! wave speeds and the face's floor, and never falls below the material's).
inline void limitTension(CellState& s, double damage, double spall, bool intact) {
  if (!(s.p < 0.0)) return;
  const double d = intact ? std::clamp(damage, 0.0, 1.0) : 1.0;
  const double p = strength::effectivePressure(s.p, d, spall);
  if (p == s.p) return;
  if (s.p < -spall || d >= 1.0) {
    s.prho = 0.0;
    s.gam = 0.0;
  } else {
    s.prho *= 1.0 - d;
    s.gam *= 1.0 - d;
  }
  s.H += (p - s.p) / s.rho;
  s.p = p;
}

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
