//! @file The deviatoric-stress pair terms of SPH with strength (docs/strength.md), planar,
//! pure and header-only like pair_force.hpp, to be added to its terms by a strength pass:
//! the kernel velocity gradient, the symmetric stress force of Libersky and Petschek (1991) /
//! Gray, Monaghan and Swift (2001, eqs. 2.3-2.5) with the matching stress power, and
//! Monaghan's (2000) artificial stress against the tensile instability. Summed by the strength
//! pass (sph/src/strength_pass.cpp, planar); the r-z hoop terms are still to be written.
#pragma once
#include <cmath>

namespace hvi::sph {

//! A symmetric in-plane 2x2 tensor (xx, zz, xz): a stress, or a stress over rho^2.
struct Sym2 {
  double xx = 0.0, zz = 0.0, xz = 0.0;
};

//! Summand of particle a's velocity gradient for neighbour b, the first-order estimate
//! (dv^i/dx^j)_a = sum_b (m_b / rho_b) (v_b - v_a)^i (grad_a W_ab)^j (Gray et al. 2001, eq. 2.7).
//! `gx, gz` = grad_a W_ab; the result adds to (dvx/dx, dvx/dz, dvz/dx, dvz/dz).
struct VelocityGradientTerm {
  double xx = 0.0, xz = 0.0, zx = 0.0, zz = 0.0;
};
inline VelocityGradientTerm velocityGradientTerm(double volumeB, double dvx, double dvz, double gx,
                                                 double gz) {
  // dv = v_b - v_a
  return {volumeB * dvx * gx, volumeB * dvx * gz, volumeB * dvz * gx, volumeB * dvz * gz};
}

//! Stress pair terms for neighbour b of a, with T_ab = s_a / rho_a^2 + s_b / rho_b^2 (+ the
//! artificial stress):
//!   dv_a/dt += m_b T_ab . grad_a W_ab
//!   de_a/dt += -(1/2) m_b (v_a - v_b) . (T_ab . grad_a W_ab)
//! The pressure enters through pair_force.hpp as T = -(P_a / rho_a^2 + P_b / rho_b^2) I; the
//! same signs. Both are antisymmetric in the pair, so the sums conserve momentum and total
//! energy exactly; the energy term sums to the stress power s : eps' / rho of the particle.
struct StressPairTerm {
  double ax = 0.0, az = 0.0, de = 0.0;
};
inline StressPairTerm stressPairTerm(const Sym2& t, double mB, double dvx, double dvz, double gx,
                                     double gz) {
  // dv = v_a - v_b
  const double fx = t.xx * gx + t.xz * gz, fz = t.xz * gx + t.zz * gz;
  return {mB * fx, mB * fz, -0.5 * mB * (dvx * fx + dvz * fz)};
}

//! Monaghan's (2000) artificial stress of one particle from its in-plane total stress sigma
//! (= -P I + s): in the principal frame R_i = -epsilon sigma_i / rho^2 where sigma_i > 0
//! (tension), 0 in compression, rotated back. The pair adds f_ab^n (R_a + R_b) to T_ab with
//! f_ab = W(r_ab) / W(dp), dp the initial spacing (Gray et al. 2001: epsilon = 0.3, n = 4).
inline Sym2 artificialStress(const Sym2& sigma, double rho, double epsilon) {
  const double mean = 0.5 * (sigma.xx + sigma.zz);
  const double half = 0.5 * (sigma.xx - sigma.zz);
  const double rad = std::sqrt(half * half + sigma.xz * sigma.xz);
  const double s1 = mean + rad, s2 = mean - rad;  // principal stresses, s1 >= s2
  const double k = -epsilon / (rho * rho);
  const double r1 = s1 > 0.0 ? k * s1 : 0.0, r2 = s2 > 0.0 ? k * s2 : 0.0;
  // Principal direction of s1 at angle theta: cos 2theta = half / rad, sin 2theta = xz / rad.
  const double c2 = rad > 0.0 ? half / rad : 1.0, s2t = rad > 0.0 ? sigma.xz / rad : 0.0;
  const double rm = 0.5 * (r1 + r2), rh = 0.5 * (r1 - r2);
  return {rm + rh * c2, rm - rh * c2, rh * s2t};
}

}  // namespace hvi::sph
