//! @file Harten-Yee upwind TVD numerical flux at one face (semi-discrete form).
#pragma once
#include <cmath>

#include "hvi/tvd/characteristics.hpp"

namespace hvi::tvd {

//! Harten's entropy fix: |z| away from 0, a parabola of half-width delta near 0, so that a
//! transonic rarefaction does not keep a stationary expansion shock.
//! Both branches are computed and one selected, so that a loop over faces vectorises; with
//! delta = 0 the unused parabola is inf or NaN and never selected. The parabola multiplies by
//! 1 / (2 delta), which the four calls of one face share: one division per face instead of four
//! (issue 17; round-off differs from dividing, in the parabola's range |z| < delta only).
[[gnu::always_inline]] inline double entropyFixedAbs(double z, double delta) {
  const double a = std::abs(z);
  const double parabola = (z * z + delta * delta) * (0.5 / delta);
  return a >= delta ? a : parabola;
}

//! phi_l of one field of speed a, jump al, limited jumps gL, gR (hartenYeeFlux below).
template <bool Acoustic>
[[gnu::always_inline]] inline double hartenYeePhi(double a, double al, double gL, double gR,
                                                  double delta) {
  const double psiA = Acoustic ? entropyFixedAbs(a, delta) : std::abs(a);
  const double sigma = 0.5 * psiA;
  const bool zero = al == 0.0;  // select, not branch: alpha = 0 is common and unpredictable
  const double gamma = (zero ? 0.0 : sigma * (gR - gL)) / (zero ? 1.0 : al);
  const double z = a + gamma;
  const double psiZ = Acoustic ? entropyFixedAbs(z, delta) : std::abs(z);
  return sigma * (gL + gR) - psiZ * al;
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
[[gnu::always_inline]] inline void hartenYeeFlux(const FaceEigen& f, const double gL[kFields],
                                                const double gR[kFields], const double FL[4],
                                                const double FR[4], double delta, double out[4]) {
  // The fields are written out (no loop over l), so that a loop over faces calling this has no
  // control flow left and vectorises.
  const double phi[kFields] = {
      hartenYeePhi<true>(f.u - f.c, f.alpha[0], gL[0], gR[0], delta),
      hartenYeePhi<false>(f.u, f.alpha[1], gL[1], gR[1], delta),
      hartenYeePhi<false>(f.u, f.alpha[2], gL[2], gR[2], delta),
      hartenYeePhi<true>(f.u + f.c, f.alpha[3], gL[3], gR[3], delta),
      hartenYeePhi<false>(f.u, f.alpha[4], gL[4], gR[4], delta)};
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
