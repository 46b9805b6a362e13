//! @file Harten-Yee upwind TVD numerical flux at one face (semi-discrete form).
#pragma once
#include <cmath>

#include "hvi/tvd/characteristics.hpp"

namespace hvi::tvd {

//! Harten's entropy fix: |z| away from 0, a parabola of half-width delta near 0, so that a
//! transonic rarefaction does not keep a stationary expansion shock.
inline double entropyFixedAbs(double z, double delta) {
  const double a = std::abs(z);
  return a >= delta ? a : (z * z + delta * delta) / (2.0 * delta);
}

//! Numerical flux of Harten-Yee's upwind TVD scheme (Yee 1989, eq. 4.33 with the method-of-
//! lines choice sigma(z) = psi(z) / 2):
//!   F = 1/2 [F_L + F_R + sum_l r_l phi_l],
//!   phi_l = sigma(a_l) (g_l,L + g_l,R) - psi(a_l + gamma_l) alpha_l,
//!   gamma_l = sigma(a_l) (g_l,R - g_l,L) / alpha_l   (0 where alpha_l = 0),
//! with a_l the characteristic speeds (u - c, u, u, u + c, u) of the averaged state, alpha_l the
//! characteristic jumps at this face and g_l,L / g_l,R the limited jumps of the cells left and
//! right of it. psi has Harten's entropy fix (half-width `delta`) on the two acoustic fields
//! only: the linearly degenerate fields use |a| so that a contact at rest stays exactly at rest
//! (a free body in vacuum does not leak mass). With g = 0 this is Roe's first-order flux.
inline void hartenYeeFlux(const FaceEigen& f, const double gL[kFields], const double gR[kFields],
                          const double FL[4], const double FR[4], double delta, double out[4]) {
  const double a[kFields] = {f.u - f.c, f.u, f.u, f.u + f.c, f.u};
  double phi[kFields];
  for (int l = 0; l < kFields; ++l) {
    const bool acoustic = (l == 0 || l == 3);
    const double psiA = acoustic ? entropyFixedAbs(a[l], delta) : std::abs(a[l]);
    const double sigma = 0.5 * psiA;
    const double al = f.alpha[l];
    const bool zero = al == 0.0;  // select, not branch: alpha = 0 is common and unpredictable
    const double gamma = (zero ? 0.0 : sigma * (gR[l] - gL[l])) / (zero ? 1.0 : al);
    const double z = a[l] + gamma;
    const double psiZ = acoustic ? entropyFixedAbs(z, delta) : std::abs(z);
    phi[l] = sigma * (gL[l] + gR[l]) - psiZ * al;
  }
  double d[4];
  applyRight(f, phi, d);
  for (int k = 0; k < 4; ++k) out[k] = 0.5 * ((FL[k] + FR[k]) + d[k]);
}

//! Local Lax-Friedrichs (Rusanov) flux: first order and positivity preserving for CFL <= 1/2,
//! used only where the TVD flux would leave a cell with rho <= 0 or e < 0.
inline void rusanovFlux(const double UL[4], const double UR[4], const double FL[4],
                        const double FR[4], double smax, double out[4]) {
  for (int k = 0; k < 4; ++k) out[k] = 0.5 * ((FL[k] + FR[k]) - smax * (UR[k] - UL[k]));
}

}  // namespace hvi::tvd
