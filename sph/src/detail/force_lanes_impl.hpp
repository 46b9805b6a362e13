//! @file Body of the lane kernels (force_lanes.hpp), included once per instruction set with
//! HVI_LANES (the lane count) and HVI_LANES_NS (a namespace of its own) defined. It calls no
//! inline function of another header: an AVX-512 copy of a shared inline function could
//! otherwise be the one the linker keeps for the baseline code.
#include <cstdint>
#if (HVI_LANES == 8 && defined(__AVX512F__)) || (HVI_LANES == 4 && defined(__AVX2__))
#include <immintrin.h>
#endif

#include "detail/force_lanes.hpp"
#include "hvi/sph/kernel.hpp"  // GaussianKernel's constants only

namespace hvi::sph::detail::HVI_LANES_NS {
namespace {

#include "detail/lane_ops_impl.hpp"

#if HVI_LANES == 8 && defined(__AVX512F__)
// Whether the packed rows hold every point of idx[0..8) (LaneArrays::packBegin, packEnd).
inline bool packedHolds(const int* idx, int begin, int end) {
  const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idx));
  return (_mm256_cmplt_epi32_mask(v, _mm256_set1_epi32(end)) &
          _mm256_cmpge_epi32_mask(v, _mm256_set1_epi32(begin))) == 0xFF;
}

// Rows idx[0..8) of the packed point data (LaneArrays::packed), transposed: f[k] lane l is
// field k of point idx[l]. The same values as the 8 gathers.
inline void loadPacked(const double* pk, int mask, const int* idx, D f[8]) {
  D r[8];
  for (int l = 0; l < 8; ++l)
    __builtin_memcpy(&r[l], pk + 8 * static_cast<std::size_t>(idx[l] & mask), sizeof(D));
  // Pairs of rows interleaved, then quarters, then halves (an 8 x 8 transpose in 24 shuffles).
  const I lo2{0, 8, 2, 10, 4, 12, 6, 14}, hi2{1, 9, 3, 11, 5, 13, 7, 15};
  const I lo4{0, 1, 8, 9, 4, 5, 12, 13}, hi4{2, 3, 10, 11, 6, 7, 14, 15};
  const I lo8{0, 1, 2, 3, 8, 9, 10, 11}, hi8{4, 5, 6, 7, 12, 13, 14, 15};
  D t[8], u[8];
  for (int p = 0; p < 4; ++p) {
    t[2 * p] = __builtin_shuffle(r[2 * p], r[2 * p + 1], lo2);      // fields 0 2 4 6
    t[2 * p + 1] = __builtin_shuffle(r[2 * p], r[2 * p + 1], hi2);  // fields 1 3 5 7
  }
  for (int q = 0; q < 2; ++q)
    for (int o = 0; o < 2; ++o) {
      u[4 * q + o] = __builtin_shuffle(t[4 * q + o], t[4 * q + 2 + o], lo4);      // fields o, 4+o
      u[4 * q + 2 + o] = __builtin_shuffle(t[4 * q + o], t[4 * q + 2 + o], hi4);  // 2+o, 6+o
    }
  for (int k = 0; k < 4; ++k) {
    f[k] = __builtin_shuffle(u[k], u[4 + k], lo8);
    f[k + 4] = __builtin_shuffle(u[k], u[4 + k], hi8);
  }
}
#endif

// Half: also the j side's terms of each pair (half lists, planar: no hoop term), each
// pairTerms(j, i)'s operations on the same operands, so its bits: dx, dv and g change sign
// exactly, r2, h_ij, Pi and vdg are symmetric, -(mu_i coef)(-g) = (mu_i coef) g.
template <bool RZ, bool Viscous, bool Cached, bool Compatible, bool Half>
void row(const LaneArrays& a, std::size_t i, const int* nb, const double* wc, int cnt,
         double alpha, double beta, const RowTerms& out) {
  static_assert(!(RZ && Half), "half lists are planar");
  using GK = GaussianKernel;
  constexpr bool kPairs = Compatible && !Cached;
  const D xi = splat(a.x[i]), zi = splat(a.z[i]), vxi = splat(a.vx[i]), vzi = splat(a.vz[i]);
  const D rhoi = splat(a.rho[i]), ci = splat(a.c[i]), hi = splat(a.h[i]), qi = splat(a.q[i]);
  const D rwi = splat(a.rw[i]), mui = splat(a.mu[i]);
  const D ih2i = splat(1.0 / (a.h[i] * a.h[i]));
  const std::int64_t oi = a.obj[i];
  // The half rows' remainder wants the pair data only (null ax): the rates are not stored.
  const bool rates = !(kPairs && Half) || out.ax;
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
    // The j side: x, z, vx, vz, h, q, mu, c (c gathered only where the viscosity needs it).
    D fj[8];
    bool haveC = false;
#if HVI_LANES == 8 && defined(__AVX512F__)
    if (a.packed && packedHolds(idx, a.packBegin, a.packEnd)) {
      loadPacked(a.packed, a.packMask, idx, fj);
      haveC = true;
    } else
#endif
    {
      fj[0] = gather(a.x, idx);
      fj[1] = gather(a.z, idx);
      fj[2] = gather(a.vx, idx);
      fj[3] = gather(a.vz, idx);
      fj[4] = gather(a.h, idx);
      fj[5] = gather(a.q, idx);
      fj[6] = gather(a.mu, idx);
    }
    const D dx = xi - fj[0], dz = zi - fj[1];
    const D r2 = dx * dx + dz * dz;
    // h_ij = h_i bit for bit when h_j = h_i: the division gives pairTerms' 1 / h_i^2.
    const D hj = fj[4];
    const D hij = 0.5 * (hi + hj);
    // Within an object h is constant, h_ij = h_i bit for bit and 1 / h_ij^2 is i's own: the
    // division (the costliest lane operation) only for blocks that reach another object's h.
    const D ih2 = anyLane(hj != hi) ? 1.0 / (hij * hij) : ih2i;
    const D q2 = r2 * ih2;
    D w;
    if (Cached && wc) {
      if (k + L <= cnt)
        __builtin_memcpy(&w, wc + k, sizeof w);
      else
        for (int l = 0; l < L; ++l) w[l] = wc[k + l < cnt ? k + l : cnt - 1];
    } else {
      const D wv = (expNegative(select(q2 < 9.0, q2, splat(9.0))) - GK::tail * (10.0 - q2)) *
                   GK::norm * ih2;
      w = select(q2 < GK::support * GK::support, wv, splat(0.0));
    }
    const I live = inRow & (w != 0.0);
    const D f = -2.0 * ih2 * (w + GK::tail * (9.0 - r2 * ih2) * GK::norm * ih2);
    const D gx = f * dx, gz = f * dz;
    const D dvx = vxi - fj[2], dvz = vzi - fj[3];
    if (!Half && out.geom) {
      const PairGeometry& g = *out.geom;
      store(g.dx + k, dx);
      store(g.dz + k, dz);
      store(g.dvx + k, dvx);
      store(g.dvz + k, dvz);
      store(g.hj + k, hj);
      store(g.w + k, w);
      store(g.f + k, f);
    }
    const D vdg = dvx * gx + dvz * gz;
    const D qj = fj[5], muj = fj[6];
    D coef = qi + qj;
    D halfPi = splat(0.0);
    D phij = splat(0.0);
    D piRaw = splat(0.0);  // Pi_ij without the ring form's rbar weight (r-z viscous hoop)
    if constexpr (Viscous) {
      const D vdotx = dvx * dx + dvz * dz;
      const I approach = vdotx < 0.0;
      // Pi only acts on approaching pairs: a block without one (a body at rest, expansion)
      // skips its two divisions; the others compute it in every lane and mask.
      if (anyLane(approach)) {
        const D ph = hij * vdotx / (r2 + 0.01 * hij * hij);
        const D cj = haveC ? fj[7] : gather(a.c, idx);
        const D pi = (-alpha * (0.5 * (ci + cj)) * ph + beta * ph * ph) /
                     (0.5 * (rhoi + gather(a.rho, idx)));
        phij = select(approach, ph, splat(0.0));
        D rpi = select(approach, pi, splat(0.0));
        piRaw = rpi;
        if constexpr (RZ) rpi = 0.5 * (rwi + gather(a.rw, idx)) * rpi;
        coef += rpi;
        halfPi = 0.5 * rpi;
      }
    }
    const D mc = muj * coef;
    const D ax = -mc * gx, az = -mc * gz;
    const D zero = splat(0.0);
    D de;
    if constexpr (Compatible) {
      const D ka = qi + halfPi, kb = qj + halfPi;
      de = muj * ka * vdg;
      if (Half && rates) store(out.dej + k, select(live, mui * kb * vdg, zero));
      // Null pwx: the remainder recomputes them (passes.hpp, RemainderPass); no share then.
      if (kPairs && out.pwx) {
        const D s = vabs(ka) + vabs(kb);
        const I pos = s > 0.0;
        const D sd = select(pos, s, splat(1.0));
        const D share = select(pos, vabs(ka) / sd, splat(0.5));
        const D px = select(live, share * ax, splat(0.0));
        const D pz = select(live, share * az, splat(0.0));
        for (int l = 0; l < L && k + l < cnt; ++l) {
          out.pwx[k + l] = px[l];
          out.pwz[k + l] = pz[l];
        }
        if constexpr (Half) {
          // The j side's weight |k_j| / (|k_j| + |k_i|): the same sum (commutative), so the
          // same bits as pairTerms(j, i)'s; its pair acceleration is (mu_i coef) g.
          const D sharej = select(pos, vabs(kb) / sd, splat(0.5));
          const D mci = mui * coef;
          store(out.pwxj + k, select(live, sharej * (mci * gx), zero));
          store(out.pwzj + k, select(live, sharej * (mci * gz), zero));
        }
      }
    } else {
      de = 0.5 * mc * vdg;
      if constexpr (Half) store(out.dej + k, select(live, 0.5 * (mui * coef) * vdg, zero));
    }
    if (Half && rates) {
      const D mci = mui * coef;
      store(out.axj + k, select(live, mci * gx, zero));
      store(out.azj + k, select(live, mci * gz, zero));
    }
    if (rates) {
      store(out.ax + k, select(live, ax, zero));
      store(out.az + k, select(live, az, zero));
      store(out.de + k, select(live, de, zero));
    }
    if constexpr (Cached) {
      I objj;
      for (int l = 0; l < L; ++l) objj[l] = a.obj[idx[l]];
      const I same = live & (objj == oi);
      store(out.drho + k, select(same, muj * vdg, zero));
      if constexpr (Half) store(out.drhoj + k, select(same, mui * vdg, zero));
    }
    if constexpr (RZ) store(out.hoop + k, select(live, muj * qj * w, zero));
    if constexpr (RZ && Viscous)
      if (out.hoopPi) store(out.hoopPi + k, select(live, muj * piRaw * w, zero));
    if constexpr (Viscous && Cached) store(out.phi + k, select(live, phij, zero));
  }
  (void)rwi;
  (void)mui;
}

// The Gaussian W of lanes at squared distance r2 and pair length h_ij (kernel.hpp's
// GaussianKernel::value: the same bits). ih2i = 1 / h_i^2 stands for 1 / h_ij^2 in a block
// whose pairs all have h_ij = h_i ((h_i + h_i) / 2 = h_i exactly): no division there.
inline D gaussianW(D r2, D hij, D hi, D ih2i) {
  using GK = GaussianKernel;
  const D ih2 = anyLane(hij != hi) ? 1.0 / (hij * hij) : ih2i;
  const D q2 = r2 * ih2;
  const D wv =
      (expNegative(select(q2 < 9.0, q2, splat(9.0))) - GK::tail * (10.0 - q2)) * GK::norm * ih2;
  return select(q2 < GK::support * GK::support, wv, splat(0.0));
}

int scan(const double* sx, const double* sz, const double* sh, const int* order, int s0, int s1,
         double xi, double zi, double hi, double rf2, int self, int* slot, double* r2o,
         double* ho, int cnt, int last) {
  int s = s0;
  for (; s < s1; s += L) {
    // The block's lanes past s1 repeat its last position and are never kept.
    D px, pz, ph;
    I valid = I{} - 1;
    if (s + L <= s1) {
      __builtin_memcpy(&px, sx + s, sizeof px);
      __builtin_memcpy(&pz, sz + s, sizeof pz);
      __builtin_memcpy(&ph, sh + s, sizeof ph);
    } else {
      for (int l = 0; l < L; ++l) {
        const int t = s + l < s1 ? s + l : s1 - 1;
        px[l] = sx[t];
        pz[l] = sz[t];
        ph[l] = sh[t];
        valid[l] = s + l < s1 ? -1 : 0;
      }
    }
    const D dx = xi - px, dz = zi - pz;
    const D r2 = dx * dx + dz * dz;
    const D hij = 0.5 * (hi + ph);
    const I near = (r2 < rf2 * hij * hij) & valid;
#if HVI_LANES == 8 && defined(__AVX512F__)
    if (cnt + L <= last + 1 && s + L <= s1) {
      // The kept positions (and their r2, h_ij) packed to the front of a register, stored at the
      // row's end: the lanes past them land in the row's spare slots, as the one-at-a-time
      // loop's rejected positions do.
      const __m256i ord = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(order + s));
      const __mmask8 keep = _mm512_cmpneq_epi64_mask((__m512i)near, _mm512_setzero_si512()) &
                            _mm256_cmpneq_epi32_mask(ord, _mm256_set1_epi32(self));
      const __m256i pos = _mm256_add_epi32(_mm256_set1_epi32(s),
                                           _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(slot + cnt),
                          _mm256_maskz_compress_epi32(keep, pos));
      if (r2o) {
        _mm512_storeu_pd(r2o + cnt, _mm512_maskz_compress_pd(keep, (__m512d)r2));
        _mm512_storeu_pd(ho + cnt, _mm512_maskz_compress_pd(keep, (__m512d)hij));
      }
      cnt += __builtin_popcount(keep);
      continue;
    }
#endif
    for (int l = 0; l < L && s + l < s1; ++l) {
      const int at = cnt < last ? cnt : last;
      slot[at] = s + l;
      if (r2o) {
        r2o[at] = r2[l];
        ho[at] = hij[l];
      }
      cnt += static_cast<int>(near[l] != 0) & static_cast<int>(order[s + l] != self);
    }
  }
  return cnt;
}

// W of the scan's kept pairs, in place: w[k] = gaussianW(w[k], hs[k]) for k < cnt, so the W of
// the pairs a row keeps and not of every candidate its cells hold. The last block's lanes past
// cnt are computed from the row's first pair and not stored (the slots there may be another
// row's).
void distanceW(double* w, const double* hs, int cnt, double hi) {
  const D hiv = splat(hi), ih2i = splat(1.0 / (hi * hi));
  for (int k = 0; k < cnt; k += L) {
    D r2, hij;
    const bool whole = k + L <= cnt;
    if (whole) {
      r2 = load(w + k);
      hij = load(hs + k);
    } else {
      for (int l = 0; l < L; ++l) {
        const int t = k + l < cnt ? k + l : 0;
        r2[l] = w[t];
        hij[l] = hs[t];
      }
    }
    const D out = gaussianW(r2, hij, hiv, ih2i);
    if (whole)
      store(w + k, out);
    else
      for (int l = 0; k + l < cnt; ++l) w[k + l] = out[l];
  }
}

template <bool RZ, bool Viscous, bool Cached, bool Half>
RowKernel pick3(bool compatible) {
  return compatible ? &row<RZ, Viscous, Cached, true, Half> : &row<RZ, Viscous, Cached, false, Half>;
}
template <bool RZ, bool Viscous, bool Half>
RowKernel pick2(bool cached, bool compatible) {
  return cached ? pick3<RZ, Viscous, true, Half>(compatible)
                : pick3<RZ, Viscous, false, Half>(compatible);
}
template <bool RZ, bool Half>
RowKernel pick1(bool viscous, bool cached, bool compatible) {
  return viscous ? pick2<RZ, true, Half>(cached, compatible)
                 : pick2<RZ, false, Half>(cached, compatible);
}

// The Gaussian W_ij of row i's neighbours nb[0, cnt) into w (room for the lanes past cnt):
// scan's distances and gaussianW, the same bits as the list build found them.
void rowW(const double* x, const double* z, const double* h, std::size_t i, const int* nb,
          int cnt, double* w) {
  const double xi = x[i], zi = z[i], hi = h[i];
  const D hiv = splat(hi), ih2i = splat(1.0 / (hi * hi));
  for (int k = 0; k < cnt; k += L) {
    int idx[L];
    for (int l = 0; l < L; ++l) idx[l] = nb[k + l < cnt ? k + l : cnt - 1];
    const D dx = xi - gather(x, idx), dz = zi - gather(z, idx);
    const D r2 = dx * dx + dz * dz;
    const D hij = 0.5 * (hi + gather(h, idx));
    store(w + k, gaussianW(r2, hij, hiv, ih2i));
  }
}

}  // namespace

RowKernel pick(bool rz, bool viscous, bool cached, bool compatible, bool half) {
  if (half)  // planar only
    return rz ? nullptr : pick1<false, true>(viscous, cached, compatible);
  return rz ? pick1<true, false>(viscous, cached, compatible)
            : pick1<false, false>(viscous, cached, compatible);
}

RowWKernel rowWKernel() { return &rowW; }

}  // namespace hvi::sph::detail::HVI_LANES_NS
