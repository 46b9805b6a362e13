//! @file Body of the stress lane kernels (stress_lanes.hpp), included once per instruction set
//! with HVI_LANES (the lane count) and HVI_LANES_NS (a namespace of its own) defined. Like
//! force_lanes_impl.hpp it calls no inline function of another header (an AVX-512 copy of a
//! shared inline function could be the one the linker keeps for baseline code), hence the lane
//! helpers and the lane exponential come from lane_ops_impl.hpp, included inside this file's
//! own namespace.
#include <cstddef>
#include <cstdint>
#if (HVI_LANES == 8 && defined(__AVX512F__)) || (HVI_LANES == 4 && defined(__AVX2__))
#include <immintrin.h>
#endif

#include "detail/stress_lanes.hpp"
#include "hvi/sph/kernel.hpp"  // GaussianKernel's constants only

namespace hvi::sph::detail::HVI_LANES_NS {
namespace {

#include "detail/lane_ops_impl.hpp"

// The 8 columns of the neighbours' point records (StressLaneArrays::rec, 8 doubles a point):
// L whole-record loads transposed in registers instead of 8 element-by-element gathers (the
// same values).
inline void records(const double* rec, const int* idx, D (&c)[8]) {
#if HVI_LANES == 8
  {
    using M = I;
    D r[8];
    for (int l = 0; l < 8; ++l) r[l] = load(rec + 8 * static_cast<std::ptrdiff_t>(idx[l]));
    const M e1{0, 8, 2, 10, 4, 12, 6, 14}, o1{1, 9, 3, 11, 5, 13, 7, 15};
    const M e2{0, 1, 8, 9, 4, 5, 12, 13}, o2{2, 3, 10, 11, 6, 7, 14, 15};
    const M e3{0, 1, 2, 3, 8, 9, 10, 11}, o3{4, 5, 6, 7, 12, 13, 14, 15};
    D t[8], u[8];
    for (int p = 0; p < 8; p += 2) {
      t[p] = __builtin_shuffle(r[p], r[p + 1], e1);
      t[p + 1] = __builtin_shuffle(r[p], r[p + 1], o1);
    }
    // u[k] holds columns k and k + 4 of records 0-3 (low half) or 4-7 (u[k + 4]).
    for (int q = 0; q < 8; q += 4) {
      u[q + 0] = __builtin_shuffle(t[q + 0], t[q + 2], e2);
      u[q + 2] = __builtin_shuffle(t[q + 0], t[q + 2], o2);
      u[q + 1] = __builtin_shuffle(t[q + 1], t[q + 3], e2);
      u[q + 3] = __builtin_shuffle(t[q + 1], t[q + 3], o2);
    }
    for (int k = 0; k < 4; ++k) {
      c[k] = __builtin_shuffle(u[k], u[k + 4], e3);
      c[k + 4] = __builtin_shuffle(u[k], u[k + 4], o3);
    }
  }
#elif HVI_LANES == 4
  {
    using M = I;
    const M e1{0, 4, 2, 6}, o1{1, 5, 3, 7}, e2{0, 1, 4, 5}, o2{2, 3, 6, 7};
    for (int half = 0; half < 8; half += 4) {
      D r[4];
      for (int l = 0; l < 4; ++l)
        r[l] = load(rec + 8 * static_cast<std::ptrdiff_t>(idx[l]) + half);
      const D t0 = __builtin_shuffle(r[0], r[1], e1), t1 = __builtin_shuffle(r[0], r[1], o1);
      const D t2 = __builtin_shuffle(r[2], r[3], e1), t3 = __builtin_shuffle(r[2], r[3], o1);
      c[half + 0] = __builtin_shuffle(t0, t2, e2);
      c[half + 2] = __builtin_shuffle(t0, t2, o2);
      c[half + 1] = __builtin_shuffle(t1, t3, e2);
      c[half + 3] = __builtin_shuffle(t1, t3, o2);
    }
  }
#else
  for (int k = 0; k < 8; ++k)
    for (int l = 0; l < L; ++l) c[k][l] = rec[8 * static_cast<std::ptrdiff_t>(idx[l]) + k];
#endif
}

// GaussianKernel::value(r2, h, ih2), lane by lane.
inline D gaussianW(D r2, D ih2) {
  using GK = GaussianKernel;
  const D q2 = r2 * ih2;
  const D wv =
      (expNegative(select(q2 < 9.0, q2, splat(9.0))) - GK::tail * (10.0 - q2)) * GK::norm * ih2;
  return select(q2 < GK::support * GK::support, wv, splat(0.0));
}

// strength_pass.cpp's stressPairs loop body for the Gaussian kernel, L pairs at a time.
// Fused: dx, dz, dv, h_j, W and the gradient factor f read from the force kernel's stores
// (`geom`), which computed them with these operations on the same operands.
template <bool RZ, bool Switch, bool Fused>
void row(const StressLaneArrays& a, std::size_t i, const int* nb, const double* wc, int cnt,
         const StressRowParams& prm, const StressRowTerms& out, const PairGeometry* geom) {
  using GK = GaussianKernel;
  const double hiS = a.h[i];
  const double ih2iS = 1.0 / (hiS * hiS);
  // W(dp) at h_i, as the scalar loop's K::value(q2dp h_i h_i, h_i, 1 / h_i^2), kept for the next
  // row of the same h_i (a latency-bound exponential per row otherwise).
  D wdpi;
  double* memo = out.wdpMemo;
  if (memo && memo[0] == hiS && memo[1] == prm.q2dp) {
    wdpi = splat(memo[2]);
  } else {
    wdpi = gaussianW(splat(prm.q2dp * hiS * hiS), splat(ih2iS));
    if (memo) {
      memo[0] = hiS;
      memo[1] = prm.q2dp;
      memo[2] = wdpi[0];
    }
  }
  const D xi = splat(a.x[i]), zi = splat(a.z[i]), vxi = splat(a.vx[i]), vzi = splat(a.vz[i]);
  const D hi = splat(hiS), ih2i = splat(ih2iS);
  const D tixx = splat(a.txx[i]), tizz = splat(a.tzz[i]), tixz = splat(a.txz[i]);
  const D rixx = splat(a.rxx[i]), rizz = splat(a.rzz[i]), rixz = splat(a.rxz[i]);
  const D zero = splat(0.0);
  I lane;
  for (int l = 0; l < L; ++l) lane[l] = l;
  for (int k = 0; k < cnt; k += L) {
    // The last block's lanes past the row repeat its last neighbour and are masked out.
    const int* idx = nb + k;
    int pad[L];
    if (k + L > cnt) {
      for (int l = 0; l < L; ++l) pad[l] = nb[k + l < cnt ? k + l : cnt - 1];
      idx = pad;
    }
    const I inRow = lane < (I{} + (cnt - k));
    const D hj = Fused ? load(geom->hj + k) : gather(a.h, idx);
    const I other = hj != hi;
    D hij = hi, ih2 = ih2i, wdp = wdpi;
    if (anyLane(other)) {
      const D hm = 0.5 * (hi + hj);
      const D ihm = 1.0 / (hm * hm);
      hij = select(other, hm, hi);
      ih2 = select(other, ihm, ih2i);
      wdp = select(other, gaussianW(prm.q2dp * hm * hm, ihm), wdpi);
    }
    D dx, dz, w, f, dvx, dvz;
    if constexpr (Fused) {
      dx = load(geom->dx + k);
      dz = load(geom->dz + k);
      w = load(geom->w + k);
      f = load(geom->f + k);
      dvx = load(geom->dvx + k);
      dvz = load(geom->dvz + k);
      (void)wc;
    } else {
      dx = xi - gather(a.x, idx);
      dz = zi - gather(a.z, idx);
      const D r2 = dx * dx + dz * dz;
      if (wc) {
        if (k + L <= cnt)
          __builtin_memcpy(&w, wc + k, sizeof w);
        else
          for (int l = 0; l < L; ++l) w[l] = wc[k + l < cnt ? k + l : cnt - 1];
      } else {
        w = gaussianW(r2, ih2);
      }
      f = -2.0 * ih2 * (w + GK::tail * (9.0 - r2 * ih2) * GK::norm * ih2);
      dvx = vxi - gather(a.vx, idx);
      dvz = vzi - gather(a.vz, idx);
    }
    const I live = inRow & (w != 0.0);
    const D gx = f * dx, gz = f * dz;
    D col[8];
    records(a.rec, idx, col);
    const D muj = col[7];
    // velocityGradientTerm(mu_j / rho_j, -dvx, -dvz, gx, gz)
    const D vol = col[6];
    const D mdvx = -dvx, mdvz = -dvz;
    store(out.gxx + k, select(live, vol * mdvx * gx, zero));
    store(out.gxz + k, select(live, vol * mdvx * gz, zero));
    store(out.gzx + k, select(live, vol * mdvz * gx, zero));
    store(out.gzz + k, select(live, vol * mdvz * gz, zero));
    D txx = tixx + col[0], tzz = tizz + col[1];
    D txz = tixz + col[2];
    if (prm.power > 0) {
      const D rxx = rixx + col[3], rzz = rizz + col[4];
      const D rxz = rixz + col[5];
      // A block without tension at either end (R_i + R_j = 0 in every lane: compression or
      // a body at rest) skips the division: the scalar loop adds f^n 0 = +0 there, which
      // leaves T as it is (T = -0 is not reached: an unstressed point's s / rho^2 is +0).
      if (anyLane((rxx != 0.0) | (rzz != 0.0) | (rxz != 0.0))) {
        const D fab = w / wdp;
        D fn = fab;
        for (int e = 1; e < prm.power; ++e) fn *= fab;
        txx += fn * rxx;
        txz += fn * rxz;
        tzz += fn * rzz;
      }
    }
    if constexpr (Switch) {
      const D vdotx = dvx * dx + dvz * dz;
      const I approach = vdotx < 0.0;
      D phi = zero;
      if (anyLane(approach)) {
        const D aij = 0.5 * (splat(a.alpha[i]) + gather(a.alpha, idx));
        const D bij = prm.betaPerAlpha * aij;
        const D cbar = 0.5 * (splat(a.c[i]) + gather(a.c, idx));
        const D rhobar = 0.5 * (splat(a.rho[i]) + gather(a.rho, idx));
        const D r2 = dx * dx + dz * dz;
        const D ph = hij * vdotx / (r2 + 0.01 * hij * hij);
        const D pi = (-aij * cbar * ph + bij * ph * ph) / rhobar;
        phi = select(approach, ph, zero);
        D rpi = select(approach, pi, zero);
        if constexpr (RZ) rpi = 0.5 * (splat(a.rw[i]) + gather(a.rw, idx)) * rpi;
        txx -= rpi;
        tzz -= rpi;
      }
      store(out.phi + k, select(live, phi, zero));
    }
    // stressPairTerm(t, mu_j, dvx, dvz, gx, gz)
    const D fx = txx * gx + txz * gz, fz = txz * gx + tzz * gz;
    const D sax = select(live, muj * fx, zero), saz = select(live, muj * fz, zero);
    store(out.ax + k, sax);
    store(out.az + k, saz);
    store(out.de + k, select(live, -0.5 * muj * (dvx * fx + dvz * fz), zero));
    if (out.pwx) {
      // The compatible energy's pair data: the stress power's even share, 1/2 (the pass's
      // pwx[k] += 0.5 ax[k], lane by lane; the row has cnt slots, none past it written).
      if (k + L <= cnt) {
        store(out.pwx + k, load(out.pwx + k) + 0.5 * sax);
        store(out.pwz + k, load(out.pwz + k) + 0.5 * saz);
      } else {
        for (int l = 0; k + l < cnt; ++l) {
          out.pwx[k + l] += 0.5 * sax[l];
          out.pwz[k + l] += 0.5 * saz[l];
        }
      }
    }
    if constexpr (RZ) store(out.hoop + k, select(live, muj * gather(a.htt, idx) * w, zero));
  }
}

}  // namespace

template <bool Fused>
StressRowKernel pickStress2(bool rz, bool sw) {
  if (rz) return sw ? &row<true, true, Fused> : &row<true, false, Fused>;
  return sw ? &row<false, true, Fused> : &row<false, false, Fused>;
}

StressRowKernel pickStress(bool rz, bool sw, bool fused) {
  return fused ? pickStress2<true>(rz, sw) : pickStress2<false>(rz, sw);
}

}  // namespace hvi::sph::detail::HVI_LANES_NS
