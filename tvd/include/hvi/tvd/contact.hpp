//! @file Two-sided (ghost-fluid) fluxes at faces between different objects or next to vacuum.
#pragma once
#include <algorithm>
#include <cmath>

#include "hvi/tvd/characteristics.hpp"

namespace hvi::tvd {

// A face whose two cells belong to different marker objects (or one to vacuum) is a piece of a
// material interface that the grid resolves only to whole cells. Its true orientation is the
// unit normal n of the marker lines in the cut cells (line coordinates: n = (nn, nt), nn >= 0,
// pointing from the left cell to the right one). Across a face between two objects:
//  - the two sides exchange momentum only through the interface pressure p*, from a contact
//    Riemann problem ALONG n (two-shock approximation), so tangential velocity slips freely;
//  - each side sees the Euler flux of its own state with the velocity component along n
//    replaced by the interface velocity u* (ghost-fluid method): material slides along a
//    staircase interface instead of being stopped at each step, and no mass of one object
//    enters the other's cells.
// Across a face between an object and vacuum (a free surface) the material side sees the Euler
// flux of its own state with P = 0: no work is done on vacuum, and its mass moves out at its
// own velocity, the velocity the marker line moves with, so what leaves through the face is
// what the moving boundary gives back when the next cell is filled.
// The two sides' fluxes differ: the scheme is not conservative at the interface (the solver
// books the difference); cells that change owner when the markers move by a whole cell restore
// the balance on average (docs/tvd.md).

//! Interface pressure and the interface normal velocity each side moves with (equal unless
//! the sides separate, when p* = 0 and each surface moves at its own release velocity).
struct ContactStar {
  double p = 0.0;
  double uL = 0.0, uR = 0.0;
};

//! Slope s of the linear shock-speed fit U_s = c + s |du| used for each side's shock impedance,
//! from the EOS's Gruneisen coefficient: s = 1 + Gamma/2 is exact for the strong-shock limit of
//! an ideal gas ((gamma + 1)/2); clamped to [1, 2] (solids: 1.2-1.6). It only shapes the first
//! steps after two objects meet; afterwards the cells next to the contact carry the star state.
inline double shockSlope(const CellState& s) { return std::clamp(1.0 + 0.5 * s.gam, 1.0, 2.0); }

//! Acoustic impedance rho c; the tiny offset keeps cold gas (c = 0, P = 0) finite, where every
//! product with it is zero anyway.
inline double impedance(const CellState& s) { return s.rho * (s.c + 1e-30); }

//! Two-shock Riemann problem along n between material states L and R (normal velocities uL,
//! uR): the star pressure p, tension included, and the star velocity u.
struct TwoShock {
  double p = 0.0, u = 0.0;
};
inline TwoShock twoShock(const CellState& L, const CellState& R, double uL, double uR,
                         int iterations) {
  double zL = impedance(L), zR = impedance(R);
  TwoShock s;
  for (int it = 0;; ++it) {
    const double inv = 1.0 / (zL + zR);
    s.p = ((zR * L.p + zL * R.p) + zL * zR * (uL - uR)) * inv;
    s.u = ((zL * uL + zR * uR) + (L.p - R.p)) * inv;
    if (it == iterations) break;
    zL = L.rho * ((L.c + 1e-30) + shockSlope(L) * std::max(uL - s.u, 0.0));
    zR = R.rho * ((R.c + 1e-30) + shockSlope(R) * std::max(s.u - uR, 0.0));
  }
  return s;
}

//! Two-shock contact Riemann problem along n between material states L and R.
inline ContactStar contactStar(const CellState& L, const CellState& R, double nn, double nt,
                               int iterations = 2) {
  const double uL = L.u * nn + L.w * nt, uR = R.u * nn + R.w * nt;
  const TwoShock t = twoShock(L, R, uL, uR, iterations);
  ContactStar s;
  if (t.p > 0.0) {
    s.p = t.p;
    s.uL = s.uR = t.u;
  } else {
    // No tension across an interface: the sides separate, each released to P = 0.
    s.p = 0.0;
    s.uL = uL + L.p / impedance(L);
    s.uR = uR - R.p / impedance(R);
  }
  return s;
}

//! Pressure on a face inside one material, for the r-z hoop source P/r: the two-shock p* of
//! contactStar, which may be tension where the cells themselves carry it. contactStar's
//! separation (p* >= 0) is right at an interface or a wall, which cannot pull; inside a body
//! that carries tension (strength, a spall strength) the clamp left the hoop source at 0 while
//! the flux difference carried the tension, a net outward force on the cells next to the axis
//! that expanded them without bound (the Taylor rod's axis, docs/tvd.md "Tension at the
//! axis"). Bounded below by the cells' own tension, and equal to contactStar's p* where neither
//! cell is in tension (the tension cut-off, gases: bit for bit as before).
inline double facePressure(const CellState& L, const CellState& R, int iterations) {
  const double p = twoShock(L, R, L.u, R.u, iterations).p;
  const double floor = std::min({0.0, L.p, R.p});
  if (!(floor < 0.0)) return p > 0.0 ? p : 0.0;  // contactStar's p*
  return std::max(p, floor);
}

//! Euler flux of side K's state with its velocity component along n set to uStar and the
//! pressure set to pStar.
inline void starFlux(const CellState& K, double pStar, double uStar, double nn, double nt,
                     double F[4]) {
  const double un = K.u * nn + K.w * nt;
  const double du = uStar - un;
  const double vn = K.u + du * nn, vt = K.w + du * nt;
  const double E = K.rho * (K.e + 0.5 * (vn * vn + vt * vt));
  F[0] = K.rho * vn;
  F[1] = F[0] * vn + pStar;
  F[2] = F[0] * vt;
  F[3] = (E + pStar) * vn;
}

//! Free surface: the Euler flux of side K's own state with the pressure set to 0.
inline void freeSurfaceFlux(const CellState& K, double F[4]) {
  F[0] = K.rho * K.u;
  F[1] = F[0] * K.u;
  F[2] = F[0] * K.w;
  F[3] = K.rho * (K.e + 0.5 * (K.u * K.u + K.w * K.w)) * K.u;
}

}  // namespace hvi::tvd
