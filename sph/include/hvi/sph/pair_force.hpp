//! @file The pair term of the momentum, energy and continuity sums, planar and r-z (pure).
#pragma once
#include <cmath>

#include "hvi/sph/viscosity.hpp"

namespace hvi::sph {

//! What one side of a pair contributes. In planar geometry mu = m, rw = 1, q = P / rho^2 and
//! lam = 0. In r-z (docs/sph-rz.md) mu = m / (2 pi r) is the planar kernel weight of the ring
//! mass m, rw = r its radius, q = r P / rho^2 and lam = -v_r / r the rate d(ln mu)/dt.
struct PairState {
  double x, z, vx, vz;  //!< cm, cm/us
  double rho, c, h;     //!< g/cm^3, cm/us, cm
  double mu, rw, q, lam;
  //! r-z axis correction (sph.rz_axis_correction, docs/sph-rz.md), else 0, 1, false: the
  //! z row (L_zx, L_zz) of the particle's corrected-gradient matrix L = M^{-1}.
  double lzx = 0.0, lzz = 1.0;
  bool corr = false;
};

//! Summands of particle a's sums for neighbour b. The driver adds them up over b and, in r-z,
//! divides the momentum and energy sums by r_a and adds the hoop terms (docs/sph-rz.md):
//!   dv_a/dt   = (1/r_a) sum ax,az + e_r H_a / r_a^2
//!   de_a/dt   = (1/r_a) sum de    + lam_a H_a / r_a
//!   drho_a/dt = sum drho + d/dt (sum_b mu_b W_ab),   H_a = sum hoop (+ self term);
//! the second part of the continuity rate, the change of the ring weights mu_b (self term
//! included), is taken exactly by the step driver, not summed here (docs/sph-rz.md).
//! With r = 1 these are the spec's planar equations exactly (section 3, docs/method.md).
struct PairResult {
  double ax = 0.0, az = 0.0;  //!< -mu_b (q_a + q_b + rbar Pi) grad_a W_ab
  //! Symmetric (METHOD.md): mu_b (q_a + q_b + rbar Pi) v_ab . grad_a W_ab / 2.
  //! Compatible: a's own share, mu_b k_a v_ab . grad_a W_ab with k_a = q_a + rbar Pi / 2.
  double de = 0.0;
  //! Compatible only: w_ab = |k_a| / (|k_a| + |k_b|) (1/2 if both vanish), a's part of the
  //! pair's time-discretisation remainder (docs/sph.md, "Energy"); w_ba = 1 - w_ab.
  double share = 0.5;
  double drho = 0.0;  //!< mu_b v_ab . grad_a W_ab
  double hoop = 0.0;  //!< mu_b q_b W_ab
  double hoopPi = 0.0;  //!< r-z, viscous: mu_b Pi_ab W_ab (the symmetric form's viscous hoop)
  double phi = 0.0;   //!< viscosity phi_ab (<= 0), for the time-step limit
};

//! `w` is W(|x_a - x_b|, h_ab) (cached or freshly computed); K supplies grad W from it.
//! `Viscous` = false removes the Pi term at compile time (effect artificial_viscosity absent);
//! `RZ` = false drops the radius weights (planar: rw = 1, lam = 0, hoop unused).
//! `ih2` = 1 / h_ab^2 (precomputed by the caller). `Compatible` selects the energy summand
//! (the momentum summands are the same bits either way).
template <class K, bool RZ, bool Viscous, bool Compatible = false>
inline PairResult pairTerms(const PairState& a, const PairState& b, double w, double ih2,
                            const MonaghanViscosity& visc) {
  const double dx = a.x - b.x, dz = a.z - b.z;
  const double r2 = dx * dx + dz * dz;
  const double h = 0.5 * (a.h + b.h);
  const double f = K::gradFactor(w, r2, h, ih2);
  const double gx = f * dx, gz0 = f * dz;
  const double dvx = a.vx - b.vx, dvz = a.vz - b.vz;
  const double vdg0 = dvx * gx + dvz * gz0;  // the continuity rate's: uncorrected
  // Axis correction: the axial component of (L_a + L_b) grad W / 2, antisymmetric in a, b
  // (Bonet and Lok 1999), so momentum and the compatible energy stay exact.
  const double gz = a.corr || b.corr ? 0.5 * ((a.lzx + b.lzx) * gx + (a.lzz + b.lzz) * gz0) : gz0;
  const double vdg = a.corr || b.corr ? dvx * gx + dvz * gz : vdg0;
  double coef = a.q + b.q;
  double halfPi = 0.0;  // rbar Pi / 2: each side's part of the viscous work
  PairResult res;
  if constexpr (Viscous) {
    const double pi =
        visc(dvx * dx + dvz * dz, r2, h, 0.5 * (a.c + b.c), 0.5 * (a.rho + b.rho), res.phi);
    const double rpi = RZ ? 0.5 * (a.rw + b.rw) * pi : pi;
    if constexpr (RZ) res.hoopPi = b.mu * pi * w;
    coef += rpi;
    halfPi = 0.5 * rpi;
  }
  const double mc = b.mu * coef;
  res.ax = -mc * gx;
  res.az = -mc * gz;
  if constexpr (Compatible) {
    const double ka = a.q + halfPi, kb = b.q + halfPi;
    res.de = b.mu * ka * vdg;
    const double s = std::abs(ka) + std::abs(kb);
    res.share = s > 0.0 ? std::abs(ka) / s : 0.5;
  } else {
    (void)halfPi;
    res.de = 0.5 * mc * vdg;
  }
  res.drho = b.mu * vdg0;
  if constexpr (RZ) res.hoop = b.mu * b.q * w;
  return res;
}

template <class K, bool RZ, bool Viscous, bool Compatible = false>
inline PairResult pairTerms(const PairState& a, const PairState& b, double w,
                            const MonaghanViscosity& visc) {
  const double h = 0.5 * (a.h + b.h);
  return pairTerms<K, RZ, Viscous, Compatible>(a, b, w, 1.0 / (h * h), visc);
}

}  // namespace hvi::sph
