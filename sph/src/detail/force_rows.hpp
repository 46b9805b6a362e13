//! @file A force pass's rates of one row from its lane kernel's per-pair terms (force_lanes.hpp),
//! shared by the force passes (passes.cpp) and the strength pass that runs the force kernel
//! with its own (strength_pass.cpp): the same code, so the same bits.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "detail/arrays.hpp"
#include "detail/axis_correction.hpp"
#include "detail/force_lanes.hpp"
#include "detail/passes.hpp"
#include "hvi/sph/kernel.hpp"

namespace hvi::sph::detail {

// The symmetric r-z form's rates of particle i from its pair sums (docs/sph-rz.md, "Symmetric
// ring weights"): the pair sums divided by s_i; the hoop force, the radial derivative of the
// weights s_i (in nu_i and in rho_i = sum nu_j W_ij / s_i), s'_i / s_i^2 (H_i + A_i s_i rho_i)
// with H_i = sum_k nu_k A_k W_ik (k = i included); its work -v_r a_hoop is charged to i itself,
// so the hoop terms conserve energy particle by particle, as in the ring form.
inline double symmetricRz(const PairArrays& a, std::size_t i, const RingScale* ring, double wii,
                          double sax, double saz, double sde, double shoop, double shoopPi,
                          const Rates& out) {
  const double si = a.rs[i], inv = 1.0 / si;
  const double slope = ring->slope(std::abs(a.x[i]), a.h[i]);
  const double hoop =
      slope * inv * inv *
      (shoop + a.mu[i] * a.q[i] * wii + a.q[i] * si * a.rho[i] + ring->viscousHoop * shoopPi);
  const double hoopAx = a.x[i] >= 0.0 ? hoop : -hoop;  // a particle briefly past the axis
  out.ax[i] = sax * inv + hoopAx;
  out.az[i] = saz * inv;
  out.de[i] = sde * inv - a.vx[i] * hoopAx;
  return hoopAx;
}

// A row's force sums, added term by term in list order as forcePass adds them.
struct ForceRowSums {
  double ax = 0.0, az = 0.0, de = 0.0, drho = 0.0, hoop = 0.0, hoopPi = 0.0, phi = 0.0;
};
template <bool RZ, bool Viscous, bool Cached>
inline void addForceTerms(ForceRowSums& s, const RowTerms& t, int k) {
  s.ax += t.ax[k];
  s.az += t.az[k];
  s.de += t.de[k];
  if constexpr (Cached) s.drho += t.drho[k];
  if constexpr (RZ) s.hoop += t.hoop[k];
  if constexpr (Viscous && Cached) s.phi = std::min(s.phi, t.phi[k]);
}

// Row i's rates from its sums: the scalar forcePass's (kernel K) and the lane passes'.
template <bool RZ, bool Viscous, bool Cached, bool Compatible, class K = GaussianKernel>
inline void forceRowRates(const PairArrays& a, std::size_t i, const ForceRowSums& s,
                          const AxisCorrection* axis, const RingScale* ring, const Rates& out) {
  constexpr bool kPairs = Compatible && !Cached;
  const double sax = s.ax, saz = s.az, sde = s.de, sdrho = s.drho, shoop = s.hoop;
  const double shoopPi = s.hoopPi, phi = s.phi;
  if constexpr (RZ) {
    if (ring) {
      const double hoopAx =
          symmetricRz(a, i, ring, K::value(0.0, a.h[i]), sax, saz, sde, shoop, shoopPi, out);
      if constexpr (kPairs) out.hoopAx[i] = hoopAx;
      if constexpr (Cached) out.drho[i] = sdrho;
      if constexpr (Cached) out.phi[i] = phi;
      return;
    }
    // docs/sph-rz.md: the sums carry r_j weights; divide by r_i and add the hoop terms, whose
    // self parts (j = i) come from d mu_i / d r_i, corrected for the axis bias. The weight
    // part of the continuity rate is the predictor's (weightChange).
    const double hi = a.h[i], rwi = a.rw[i];
    const double wii = K::value(0.0, hi);
    const double hoop = (shoop + a.mu[i] * a.q[i] * wii) * (*axis)(rwi, hi);
    const double inv = 1.0 / rwi;
    const double sgn = a.x[i] >= 0.0 ? 1.0 : -1.0;
    const double hoopAx = sgn * hoop * inv * inv;
    out.ax[i] = sax * inv + hoopAx;
    if constexpr (kPairs) out.hoopAx[i] = hoopAx;
    out.az[i] = saz * inv;
    out.de[i] = sde * inv + a.lam[i] * hoop * inv;
    if constexpr (Cached) out.drho[i] = sdrho;
  } else {
    (void)axis;
    out.ax[i] = sax;
    out.az[i] = saz;
    out.de[i] = sde;
    if constexpr (Cached) out.drho[i] = sdrho;
  }
  if constexpr (Cached) out.phi[i] = phi;
}

// Row i's rates from its terms t (cnt slots), added up in list order as forcePass adds them.
template <bool RZ, bool Viscous, bool Cached, bool Compatible>
inline void laneRowRates(const PairArrays& a, std::size_t i, int cnt, const RowTerms& t,
                         bool viscHoop, const AxisCorrection* axis, const RingScale* ring,
                         const Rates& out) {
  ForceRowSums s;
  if (viscHoop)
    for (int k = 0; k < cnt; ++k) s.hoopPi += t.hoopPi[k];
  for (int k = 0; k < cnt; ++k) addForceTerms<RZ, Viscous, Cached>(s, t, k);
  forceRowRates<RZ, Viscous, Cached, Compatible>(a, i, s, axis, ring, out);
}

}  // namespace hvi::sph::detail
