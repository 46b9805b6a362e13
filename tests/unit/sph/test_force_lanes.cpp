//! @file The vector-lane pair kernels (sph/src/detail/force_lanes.hpp) give pairTerms' bits.
//!
//! The lane kernels are an implementation of pair_force.hpp's pairTerms (whose physics is tested
//! in test_pair_force.cpp) several pairs at a time; the force passes add their per-pair terms in
//! list order, so a step is bit for bit the one-pair-at-a-time step only if every term is. So the
//! test asks for exact equality, for every policy, on rows with every lane condition: pairs
//! beyond the support (W = 0, masked), approaching and receding pairs (viscosity on and off),
//! another object's h (h_ij != h_i), another object (continuity rate masked), a both-zero
//! compatible weight (share 1/2), and row lengths that are not a multiple of the lanes.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "detail/force_lanes.hpp"
#include "detail/passes.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/pair_force.hpp"

namespace hvi::sph {
namespace {

using detail::LaneArrays;
using detail::RowKernel;
using detail::RowTerms;

struct Points {
  std::vector<double> x, z, vx, vz, rho, c, h, mu, rw, q;
  std::vector<int> obj;
  LaneArrays lanes() const {
    return {x.data(),  z.data(),  vx.data(), vz.data(), rho.data(), c.data(),
            h.data(),  mu.data(), rw.data(), q.data(),  obj.data()};
  }
  PairState state(std::size_t i, bool rz) const {
    return {x[i], z[i], vx[i], vz[i], rho[i], c[i], h[i], mu[i], rw[i], q[i],
            rz ? -vx[i] / x[i] : 0.0};
  }
};

Points randomPoints(std::size_t n, bool rz, std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  for (std::size_t i = 0; i < n; ++i) {
    // A 0.1 cm square with h = 0.02 cm: most pairs within 3 h, some beyond (W = 0).
    // Another object, with a larger h; the last 16 points form a block of one h at rest (whole
    // lane blocks where h_ij = h_i and no pair approaches: the kernels' shortcuts).
    const bool still = i >= n - 16;
    const bool other = i % 7 == 3 && !still;
    p.x.push_back(0.05 + 0.1 * u(gen));
    p.z.push_back(0.1 * u(gen));
    p.vx.push_back(still ? 0.1 : 0.3 * (u(gen) - 0.5));
    p.vz.push_back(still ? 0.0 : 0.3 * (u(gen) - 0.5));
    p.rho.push_back(2.0 + u(gen));
    p.c.push_back(0.5 + 0.1 * u(gen));
    p.h.push_back(other ? 0.025 : 0.02);
    const double m = 1e-4 * (1.0 + u(gen));
    p.rw.push_back(rz ? p.x.back() : 1.0);
    p.mu.push_back(rz ? m / (2.0 * M_PI * p.x.back()) : m);
    // Every 11th point has P = 0 (q = 0): with a receding neighbour of P = 0 the compatible
    // weights' denominator |k_i| + |k_j| vanishes.
    const double pr = i % 11 == 5 ? 0.0 : 0.2 * (u(gen) - 0.3);
    p.q.push_back(p.rw.back() * pr / (p.rho.back() * p.rho.back()));
    p.obj.push_back(other ? 1 : 0);
  }
  p.vx[16] = p.vx[5];  // a receding-or-resting pair of two P = 0 points
  p.vz[16] = p.vz[5];
  p.q[16] = 0.0;
  return p;
}

// p's lanes, with `packed` also the packed rows the 8-lane kernels read instead of gathers
// (LaneArrays::packed): in a ring of 64 rows (in `rows`), holding the points 2 to 34, so that
// blocks with a neighbour below 2 or at 35 or beyond are gathered; both ways must give
// pairTerms' bits.
LaneArrays lanesOf(const Points& p, bool packed, std::vector<double>& rows) {
  LaneArrays la = p.lanes();
  if (!packed) return la;
  rows.assign(8 * 64 + 8, 0.0);
  const auto at = reinterpret_cast<std::uintptr_t>(rows.data());
  double* base = rows.data() + (8 - at / sizeof(double) % 8) % 8;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const double f[8] = {p.x[i], p.z[i], p.vx[i], p.vz[i], p.h[i], p.q[i], p.mu[i], p.c[i]};
    std::copy(f, f + 8, base + 8 * i);
  }
  la.packed = base;
  la.packMask = 63;
  la.packBegin = 2;
  la.packEnd = 35;
  return la;
}

template <bool RZ, bool Viscous, bool Cached, bool Compatible>
void checkPolicy(RowKernel kernel, const char* name, bool packed) {
  SCOPED_TRACE(::testing::Message() << name << " rz " << RZ << " viscous " << Viscous
                                    << " cached " << Cached << " compatible " << Compatible
                                    << " packed " << packed);
  const std::size_t n = 40;  // randomPoints' last 16 are two 8-lane blocks at rest
  const Points p = randomPoints(n, RZ, 17);
  const MonaghanViscosity visc{1.0, 2.0};
  std::vector<double> rows;
  const LaneArrays la = lanesOf(p, packed, rows);
  int rowsWithZeroW = 0, approaching = 0, receding = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Rows of every length 1 .. n-1 (lane counts 2 and 8: every remainder).
    std::vector<int> nb;
    for (std::size_t j = 0; j < n && nb.size() < 1 + i % (n - 1); ++j)
      if (j != i) nb.push_back(static_cast<int>(j));
    const int cnt = static_cast<int>(nb.size());
    std::vector<double> wc(nb.size());
    for (int k = 0; k < cnt; ++k) {
      const std::size_t j = static_cast<std::size_t>(nb[static_cast<std::size_t>(k)]);
      const double dx = p.x[i] - p.x[j], dz = p.z[i] - p.z[j];
      wc[static_cast<std::size_t>(k)] = GaussianKernel::value(dx * dx + dz * dz, 0.5 * (p.h[i] + p.h[j]));
    }
    const std::size_t cap = (nb.size() + 7) / 8 * 8;
    std::vector<double> buf(9 * cap, -7.0);
    const RowTerms t{buf.data(),           buf.data() + cap,     buf.data() + 2 * cap,
                     buf.data() + 3 * cap, buf.data() + 4 * cap, buf.data() + 5 * cap,
                     buf.data() + 6 * cap, buf.data() + 7 * cap, buf.data() + 8 * cap};
    kernel(la, i, nb.data(), Cached ? wc.data() : nullptr, cnt, visc.alpha, visc.beta, t);
    const PairState a = p.state(i, RZ);
    for (int k = 0; k < cnt; ++k) {
      const std::size_t ks = static_cast<std::size_t>(k);
      const std::size_t j = static_cast<std::size_t>(nb[ks]);
      const PairState b = p.state(j, RZ);
      const double hij = 0.5 * (a.h + b.h);
      const double ih2 = 1.0 / (hij * hij);
      const double w = wc[ks];  // the list's W, and the fresh pass's from the same positions
      const PairResult r = pairTerms<GaussianKernel, RZ, Viscous, Compatible>(a, b, w, ih2, visc);
      const bool live = w != 0.0;
      rowsWithZeroW += !live;
      const double vdotx = (a.vx - b.vx) * (a.x - b.x) + (a.vz - b.vz) * (a.z - b.z);
      approaching += live && vdotx < 0.0;
      receding += live && vdotx >= 0.0;
      // Exact: the same IEEE operations in the same order (see the file comment).
      EXPECT_EQ(t.ax[ks], live ? r.ax : 0.0) << "pair " << i << "," << j;
      EXPECT_EQ(t.az[ks], live ? r.az : 0.0) << "pair " << i << "," << j;
      EXPECT_EQ(t.de[ks], live ? r.de : 0.0) << "pair " << i << "," << j;
      if (Cached) {
        EXPECT_EQ(t.drho[ks], live && p.obj[i] == p.obj[j] ? r.drho : 0.0);
      }
      if (RZ) {
        EXPECT_EQ(t.hoop[ks], live ? r.hoop : 0.0);
      }
      if (RZ && Viscous) {  // the symmetric form's viscous hoop (docs/sph-rz.md)
        EXPECT_EQ(t.hoopPi[ks], live ? r.hoopPi : 0.0);
      }
      if (Viscous && Cached) {
        EXPECT_EQ(t.phi[ks], live ? r.phi : 0.0);
      }
      if (Compatible && !Cached) {
        EXPECT_EQ(t.pwx[ks], live ? r.share * r.ax : 0.0);
        EXPECT_EQ(t.pwz[ks], live ? r.share * r.az : 0.0);
      }
    }
    // The pair data beyond the row is not touched (it is the next row's).
    if (Compatible && !Cached) {
      for (std::size_t k = nb.size(); k < cap; ++k) EXPECT_EQ(t.pwx[k], -7.0);
    }
  }
  // The rows above did meet every lane condition.
  EXPECT_GT(rowsWithZeroW, 0);
  EXPECT_GT(approaching, 0);
  EXPECT_GT(receding, 0);
}

template <bool RZ, bool Viscous>
void checkAll(RowKernel (*select)(bool, bool, bool, bool, bool), const char* name,
              bool packed = false) {
  checkPolicy<RZ, Viscous, true, true>(select(RZ, Viscous, true, true, false), name, packed);
  checkPolicy<RZ, Viscous, true, false>(select(RZ, Viscous, true, false, false), name, packed);
  checkPolicy<RZ, Viscous, false, true>(select(RZ, Viscous, false, true, false), name, packed);
  checkPolicy<RZ, Viscous, false, false>(select(RZ, Viscous, false, false, false), name, packed);
}

TEST(ForceLanes, BaselineLanesGivePairTermsBitForBit) {
  checkAll<false, true>(&detail::rowKernelBaseline, "baseline");
  checkAll<false, false>(&detail::rowKernelBaseline, "baseline");
  checkAll<true, true>(&detail::rowKernelBaseline, "baseline");
  checkAll<true, false>(&detail::rowKernelBaseline, "baseline");
}

TEST(ForceLanes, Avx2LanesGivePairTermsBitForBit) {
#if defined(__x86_64__) || defined(__i386__)
  const bool cpu = __builtin_cpu_supports("avx2");
#else
  const bool cpu = false;
#endif
  if (!cpu || !detail::rowKernelAvx2(false, true, true, true))
    GTEST_SKIP() << "no AVX2 on this CPU or compiler";
  checkAll<false, true>(&detail::rowKernelAvx2, "avx2");
  checkAll<false, false>(&detail::rowKernelAvx2, "avx2");
  checkAll<true, true>(&detail::rowKernelAvx2, "avx2");
  checkAll<true, false>(&detail::rowKernelAvx2, "avx2");
}

TEST(ForceLanes, Avx512LanesGivePairTermsBitForBit) {
#if defined(__x86_64__) || defined(__i386__)
  const bool cpu = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512vl");
#else
  const bool cpu = false;
#endif
  if (!cpu || !detail::rowKernelAvx512(false, true, true, true))
    GTEST_SKIP() << "no AVX-512 on this CPU or compiler: the baseline lanes run";
  for (const bool packed : {false, true}) {
    checkAll<false, true>(&detail::rowKernelAvx512, "avx512", packed);
    checkAll<false, false>(&detail::rowKernelAvx512, "avx512", packed);
    checkAll<true, true>(&detail::rowKernelAvx512, "avx512", packed);
    checkAll<true, false>(&detail::rowKernelAvx512, "avx512", packed);
  }
}

// Half rows (planar): the kernel also gives each pair's other end, which must be pairTerms(j, i)
// bit for bit (the pass adds it to j in place of j's own evaluation of the pair), and its own
// end as before. Same rows and lane conditions as checkPolicy.
template <bool Viscous, bool Cached, bool Compatible>
void checkHalfPolicy(RowKernel (*select)(bool, bool, bool, bool, bool), const char* name,
                     bool packed = false) {
  SCOPED_TRACE(::testing::Message() << name << " half, viscous " << Viscous << " cached "
                                    << Cached << " compatible " << Compatible << " packed "
                                    << packed);
  const RowKernel kernel = select(false, Viscous, Cached, Compatible, true);
  ASSERT_NE(kernel, nullptr);
  EXPECT_EQ(select(true, Viscous, Cached, Compatible, true), nullptr);  // planar only
  const std::size_t n = 40;
  const Points p = randomPoints(n, false, 23);
  const MonaghanViscosity visc{1.0, 2.0};
  std::vector<double> rows;
  const LaneArrays la = lanesOf(p, packed, rows);
  int live = 0, otherObject = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<int> nb;
    for (std::size_t j = 0; j < n && nb.size() < 1 + i % (n - 1); ++j)
      if (j != i) nb.push_back(static_cast<int>(j));
    const int cnt = static_cast<int>(nb.size());
    const std::size_t cap = (nb.size() + 7) / 8 * 8;
    std::vector<double> buf(14 * cap, -7.0);
    auto col = [&](int c) { return buf.data() + static_cast<std::size_t>(c) * cap; };
    RowTerms t{col(0), col(1), col(2), col(3), col(4), col(5), col(6), col(7)};
    t.axj = col(8);
    t.azj = col(9);
    t.dej = col(10);
    t.drhoj = col(11);
    t.pwxj = col(12);
    t.pwzj = col(13);
    kernel(la, i, nb.data(), nullptr, cnt, visc.alpha, visc.beta, t);
    const PairState a = p.state(i, false);
    for (int k = 0; k < cnt; ++k) {
      const std::size_t ks = static_cast<std::size_t>(k);
      const std::size_t j = static_cast<std::size_t>(nb[ks]);
      const PairState b = p.state(j, false);
      const double dx = a.x - b.x, dz = a.z - b.z;
      const double hij = 0.5 * (a.h + b.h);
      const double ih2 = 1.0 / (hij * hij);
      const double w = GaussianKernel::value(dx * dx + dz * dz, hij);
      const PairResult r = pairTerms<GaussianKernel, false, Viscous, Compatible>(a, b, w, ih2, visc);
      const PairResult rj = pairTerms<GaussianKernel, false, Viscous, Compatible>(b, a, w, ih2, visc);
      const bool on = w != 0.0;
      const bool same = on && p.obj[i] == p.obj[j];
      live += on;
      otherObject += on && !same;
      EXPECT_EQ(t.ax[ks], on ? r.ax : 0.0) << "pair " << i << "," << j;
      EXPECT_EQ(t.axj[ks], on ? rj.ax : 0.0) << "pair " << i << "," << j;
      EXPECT_EQ(t.azj[ks], on ? rj.az : 0.0) << "pair " << i << "," << j;
      EXPECT_EQ(t.dej[ks], on ? rj.de : 0.0) << "pair " << i << "," << j;
      if (Cached) {
        EXPECT_EQ(t.drho[ks], same ? r.drho : 0.0);
        EXPECT_EQ(t.drhoj[ks], same ? rj.drho : 0.0);
      }
      if (Viscous && Cached) {
        EXPECT_EQ(t.phi[ks], on ? r.phi : 0.0);
        EXPECT_EQ(r.phi, rj.phi);  // the one phi serves both ends
      }
      if (Compatible && !Cached) {
        EXPECT_EQ(t.pwx[ks], on ? r.share * r.ax : 0.0);
        EXPECT_EQ(t.pwxj[ks], on ? rj.share * rj.ax : 0.0);
        EXPECT_EQ(t.pwzj[ks], on ? rj.share * rj.az : 0.0);
      }
    }
  }
  EXPECT_GT(live, 100);
  EXPECT_GT(otherObject, 0);
}

void checkHalf(RowKernel (*select)(bool, bool, bool, bool, bool), const char* name,
               bool packed = false) {
  checkHalfPolicy<true, true, true>(select, name, packed);
  checkHalfPolicy<true, true, false>(select, name, packed);
  checkHalfPolicy<true, false, true>(select, name, packed);
  checkHalfPolicy<true, false, false>(select, name, packed);
  checkHalfPolicy<false, true, true>(select, name, packed);
  checkHalfPolicy<false, true, false>(select, name, packed);
  checkHalfPolicy<false, false, true>(select, name, packed);
  checkHalfPolicy<false, false, false>(select, name, packed);
}

TEST(ForceLanes, HalfRowKernelsGiveBothEndsBitForBit) {
  checkHalf(&detail::rowKernelBaseline, "baseline");
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("avx2") && detail::rowKernelAvx2(false, true, true, true))
    checkHalf(&detail::rowKernelAvx2, "avx2");
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && detail::rowKernelAvx512(false, true, true, true)) {
    checkHalf(&detail::rowKernelAvx512, "avx512");
    checkHalf(&detail::rowKernelAvx512, "avx512", true);  // the j side from packed rows
  }
#endif
}

// The list build's scan (force_lanes.hpp, ScanKernel) against its one-position-at-a-time
// definition: the same kept slots, W values and count, with a row long enough and with a row
// that overflows (the last slot is overwritten, the count goes on).
void checkScan(detail::ScanKernel scan, detail::DistanceWKernel distanceW, const char* name) {
  SCOPED_TRACE(name);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 203;  // not a multiple of any lane count
  std::vector<double> sx(n), sz(n), sh(n);
  std::vector<int> order(n);
  for (int s = 0; s < n; ++s) {
    sx[static_cast<std::size_t>(s)] = 0.2 * u(gen);
    sz[static_cast<std::size_t>(s)] = 0.2 * u(gen);
    sh[static_cast<std::size_t>(s)] = s % 5 == 0 ? 0.03 : 0.02;
    order[static_cast<std::size_t>(s)] = (s * 37) % n;  // a permutation
  }
  const double xi = 0.1, zi = 0.1, hi = 0.02, rf2 = 3.3 * 3.3;
  const int self = order[100];
  for (int room : {n + 8, 17}) {
    std::vector<int> slot(static_cast<std::size_t>(room), -1), expSlot(slot);
    std::vector<double> w(static_cast<std::size_t>(room), -1.0), expW(w), hs(w), expH(w);
    const int last = room - 1;
    int cnt = 0, expCnt = 0;
    // Three segments, as the build's rows of cells: [0, 50), [50, 51), [51, n).
    for (auto [s0, s1] : {std::pair{0, 50}, std::pair{50, 51}, std::pair{51, n}}) {
      cnt = scan(sx.data(), sz.data(), sh.data(), order.data(), s0, s1, xi, zi, hi, rf2, self,
                 slot.data(), w.data(), hs.data(), cnt, last);
      for (int s = s0; s < s1; ++s) {
        const auto su = static_cast<std::size_t>(s);
        const double dx = xi - sx[su], dz = zi - sz[su];
        const double r2 = dx * dx + dz * dz;
        const double hij = 0.5 * (hi + sh[su]);
        const auto at = static_cast<std::size_t>(std::min(expCnt, last));
        expSlot[at] = s;
        expW[at] = r2;
        expH[at] = hij;
        expCnt += r2 < rf2 * hij * hij && order[su] != self;
      }
    }
    ASSERT_EQ(cnt, expCnt) << "room " << room;
    ASSERT_GT(cnt, 20);  // the rows above hold many kept and many rejected points
    ASSERT_LT(cnt, n - 20);
    for (int k = 0; k < std::min(cnt, last); ++k) {
      const auto ku = static_cast<std::size_t>(k);
      EXPECT_EQ(slot[ku], expSlot[ku]) << "room " << room << " slot " << k;
      EXPECT_EQ(w[ku], expW[ku]) << "room " << room << " slot " << k;
      EXPECT_EQ(hs[ku], expH[ku]) << "room " << room << " slot " << k;
    }
    if (cnt > last) continue;
    // The kept pairs' W from their r2 and h_ij, in place: GaussianKernel::value's bits, and
    // nothing written past the row (a sentinel there).
    std::vector<double> wk(w.begin(), w.begin() + cnt);
    wk.push_back(-7.0);
    distanceW(wk.data(), hs.data(), cnt, hi);
    for (int k = 0; k < cnt; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const double exact = GaussianKernel::value(expW[ku], expH[ku]);
      EXPECT_EQ(std::memcmp(&wk[ku], &exact, sizeof exact), 0) << "room " << room << " W " << k;
    }
    EXPECT_EQ(wk[static_cast<std::size_t>(cnt)], -7.0);
  }
}

// The mass iteration recomputes W_ij per sweep for the rows it does not cache
// (docs/performance.md, "SPH memory"): every lane width must give the list build's cached W
// bit for bit, also with mixed smoothing lengths and ghost-like points past the reals.
TEST(ForceLanes, RowWeightsAreTheListBuildsBitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 900, nReal = 800;
  std::vector<double> x(n), z(n), h(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = u(rng);
    z[i] = 0.8 * u(rng);
    h[i] = i % 5 ? 0.025 : 0.04;
  }
  CellGrid grid;
  NeighbourList list;  // caches W
  buildNeighbourList(x.data(), z.data(), h.data(), n, nReal, 3.0, grid, list);
#if defined(__x86_64__) || defined(__i386__)
  const bool avx2 = __builtin_cpu_supports("avx2");
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                      __builtin_cpu_supports("avx512vl");
#else
  const bool avx2 = false, avx512 = false;
#endif
  int checked = 0;
  for (detail::RowWKernel k :
       {detail::rowWKernelBaseline(), avx2 ? detail::rowWKernelAvx2() : nullptr,
        avx512 ? detail::rowWKernelAvx512() : nullptr, detail::rowWKernel()}) {
    if (!k) continue;
    std::vector<double> w(list.stride + 8);
    for (std::size_t i = 0; i < nReal; ++i) {
      k(x.data(), z.data(), h.data(), i, list.index.data() + list.start[i], list.count[i],
        w.data());
      for (int m = 0; m < list.count[i]; ++m)
        ASSERT_EQ(std::memcmp(&w[static_cast<std::size_t>(m)],
                              &list.w[list.start[i] + static_cast<std::size_t>(m)], sizeof(double)),
                  0)
            << "row " << i << " slot " << m;
    }
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

TEST(ForceLanes, ListScanKeepsThePairsOfTheOneAtATimeLoop) {
  checkScan(detail::scanKernelBaseline(), detail::distanceWKernelBaseline(), "baseline");
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("avx2") && detail::scanKernelAvx2())
    checkScan(detail::scanKernelAvx2(), detail::distanceWKernelAvx2(), "avx2");
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && detail::scanKernelAvx512())
    checkScan(detail::scanKernelAvx512(), detail::distanceWKernelAvx512(), "avx512");
#endif
}

// The passes on half rows against the full rows' (ForceLanes above: the same per-pair terms)
// on a jittered lattice large enough for several of the half passes' blocks (2048 rows) and a
// thread team, two objects of different h, every fifth point moving towards the middle, the
// last 4 lattice rows ghosts, rows 0 and 1 moved to the end of the order (pairs more than a
// block past their row's block: the passes' far records). The half rows add the same terms in another order, so each rate may
// differ by round-off only: for a sum of n terms any two orders differ by at most
// 2 (n - 1) u sum |t_k| (u = 2^-53, Higham, "Accuracy and Stability of Numerical Algorithms",
// 2nd ed., eq. 4.4, first order), with n the pairs of the particle (both ends' terms are the
// same numbers, ForceLanes.HalfRowKernelsGiveBothEndsBitForBit). The bound is checked with
// sum |t_k| from pairTerms over the full row; a pair lost or counted twice breaks it by far.
// And the half rows' rates are the same bits with 1 and 2 threads (fixed block order).
struct Lattice {
  detail::PairArrays a;
  std::size_t nReal = 0;
};

Lattice lattice(std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Lattice l;
  detail::PairArrays& a = l.a;
  const int side = 72;
  const double dp = 0.01;
  // Rows 2 .. side-5, then rows 0 and 1 (so that row 2's neighbours below lie more than a
  // block past its block: the passes' far records), then the last 4 rows as ghosts.
  std::vector<int> rows;
  for (int iz = 2; iz < side - 4; ++iz) rows.push_back(iz);
  for (int iz : {0, 1}) rows.push_back(iz);
  for (int iz = side - 4; iz < side; ++iz) rows.push_back(iz);
  for (const int iz : rows)
    for (int ix = 0; ix < side; ++ix) {
      const bool upper = iz >= side / 2;
      const double x = ix * dp + 0.1 * dp * u(gen), z = iz * dp + 0.1 * dp * u(gen);
      a.x.push_back(x);
      a.z.push_back(z);
      const bool moving = (ix + iz) % 5 == 0;
      a.vx.push_back(moving ? 0.2 * (0.36 - x) : 0.01 * u(gen));
      a.vz.push_back(moving ? 0.2 * (0.36 - z) : 0.01 * u(gen));
      a.rho.push_back(2.7 * (1.0 + 0.05 * u(gen)));
      a.p.push_back(0.01 * u(gen));
      a.c.push_back(0.5);
      a.h.push_back(upper ? 1.3 * dp : 1.2 * dp);
      a.obj.push_back(upper ? 1 : 0);
      a.mu.push_back(2.7 * dp * dp * (1.0 + 0.1 * u(gen)));
      a.rw.push_back(1.0);
      a.rs.push_back(1.0);
      a.q.push_back(a.p.back() / (a.rho.back() * a.rho.back()));
      a.lam.push_back(0.0);
    }
  l.nReal = a.x.size() - 4 * side;
  return l;
}

struct PassRates {
  std::vector<double> ax, az, de, drho, phi;
  explicit PassRates(std::size_t n) : ax(n), az(n), de(n), drho(n), phi(n) {}
  detail::Rates rates() { return {ax.data(), az.data(), de.data(), drho.data(), phi.data()}; }
};

void setThreads(int t) {
#ifdef _OPENMP
  omp_set_num_threads(t);
#else
  (void)t;
#endif
}

template <bool Viscous, bool Cached, bool Compatible>
void checkHalfPass() {
  SCOPED_TRACE(::testing::Message() << "viscous " << Viscous << " cached " << Cached
                                    << " compatible " << Compatible);
  const Lattice l = lattice(31);
  const detail::PairArrays& a = l.a;
  const std::size_t n = l.nReal;
  const MonaghanViscosity visc{1.0, 2.0};
  const auto kernel = cases::Kernel::Gaussian;
  const double rf = detail::kernelSupport(kernel) + 0.3;
  CellGrid grid;
  NeighbourList full, half;
  full.cacheW = half.cacheW = false;
  half.half = true;
  half.scanStride = 8;  // a scratch row too short for the rows: the build widens it and redoes
  std::vector<double> rhoFull(n), rhoHalf(n);
  detail::selectListPass(kernel)(a, n, rf, grid, full, rhoFull.data());
  detail::selectListPass(kernel)(a, n, rf, grid, half, rhoHalf.data());
  EXPECT_EQ(rhoFull, rhoHalf);  // the density still sums the full row, in its order
  EXPECT_GT(half.scanStride, 8u);
  std::size_t pairsFull = 0, pairsHalf = 0;
  for (std::size_t i = 0; i < n; ++i) {
    pairsFull += static_cast<std::size_t>(full.count[i]);
    pairsHalf += static_cast<std::size_t>(half.count[i]);
  }
  std::size_t ghostPairs = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < full.count[i]; ++k)
      ghostPairs += full.index[full.start[i] + static_cast<std::size_t>(k)] >= static_cast<int>(n);
  EXPECT_EQ(2 * pairsHalf, pairsFull + ghostPairs);  // each real pair once, each ghost pair once

  PassRates rf1(n), rh1(n), rh2(n);
  setThreads(1);
  detail::selectForcePass(kernel, false, Viscous, Compatible, Cached, false)(
      a, n, full, visc, nullptr, nullptr, rf1.rates());
  const auto halfPass = detail::selectForcePass(kernel, false, Viscous, Compatible, Cached, true);
  ASSERT_NE(halfPass, nullptr);
  halfPass(a, n, half, visc, nullptr, nullptr, rh1.rates());
  std::size_t farRecords = 0;
  for (const auto& js : half.farJ) farRecords += js.size();
  EXPECT_GT(farRecords, 0u);  // the lattice's order above exercises them
  EXPECT_GT(half.spillSpan[0], 0u);  // and the dense spill
  setThreads(2);
  halfPass(a, n, half, visc, nullptr, nullptr, rh2.rates());
  setThreads(1);
  EXPECT_EQ(rh1.ax, rh2.ax);
  EXPECT_EQ(rh1.az, rh2.az);
  EXPECT_EQ(rh1.de, rh2.de);
  if (Cached) {
    EXPECT_EQ(rh1.drho, rh2.drho);
  }

  constexpr double u = 0x1p-53;
  int differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double sax = 0.0, saz = 0.0, sde = 0.0, sdrho = 0.0;
    const PairState A{a.x[i], a.z[i], a.vx[i], a.vz[i], a.rho[i], a.c[i], a.h[i], a.mu[i], 1.0, a.q[i], 0.0};
    for (int k = 0; k < full.count[i]; ++k) {
      const auto j = static_cast<std::size_t>(full.index[full.start[i] + static_cast<std::size_t>(k)]);
      const PairState B{a.x[j], a.z[j], a.vx[j], a.vz[j], a.rho[j], a.c[j], a.h[j], a.mu[j], 1.0, a.q[j], 0.0};
      const double dx = A.x - B.x, dz = A.z - B.z, hij = 0.5 * (A.h + B.h);
      const double w = GaussianKernel::value(dx * dx + dz * dz, hij);
      if (w == 0.0) continue;
      const PairResult r = pairTerms<GaussianKernel, false, Viscous, Compatible>(A, B, w, visc);
      sax += std::abs(r.ax);
      saz += std::abs(r.az);
      sde += std::abs(r.de);
      if (a.obj[i] == a.obj[j]) sdrho += std::abs(r.drho);
    }
    const double m = 2.0 * (full.count[i] + 1) * u;
    EXPECT_LE(std::abs(rh1.ax[i] - rf1.ax[i]), m * sax) << i;
    EXPECT_LE(std::abs(rh1.az[i] - rf1.az[i]), m * saz) << i;
    EXPECT_LE(std::abs(rh1.de[i] - rf1.de[i]), m * sde) << i;
    if (Cached) {
      EXPECT_LE(std::abs(rh1.drho[i] - rf1.drho[i]), m * sdrho) << i;
      EXPECT_EQ(rh1.phi[i], rf1.phi[i]) << i;  // a minimum: exact in any order
    }
    differ += rh1.ax[i] != rf1.ax[i];
  }
  // The orders do differ (else this test would not test the tolerance).
  EXPECT_GT(differ, 0);
}

TEST(ForceLanes, HalfRowPassesAgreeWithFullRowsToRoundOff) {
  if (!detail::halfListsAvailable(cases::Kernel::Gaussian, false))
    GTEST_SKIP() << "no AVX2: the full rows run";
  checkHalfPass<true, true, true>();
  checkHalfPass<true, false, true>();
  checkHalfPass<true, true, false>();
  checkHalfPass<false, false, false>();
}

// The compatible remainder on half rows against the full rows' (the same bound, with the
// terms w_ij a_ij . (da_i - da_j)), and the same bits with 1 and 2 threads.
TEST(ForceLanes, HalfRowRemainderAgreesWithFullRowsToRoundOff) {
  if (!detail::halfListsAvailable(cases::Kernel::Gaussian, false))
    GTEST_SKIP() << "no AVX2: the full rows run";
  const Lattice l = lattice(37);
  const detail::PairArrays& a = l.a;
  const std::size_t n = l.nReal;
  const MonaghanViscosity visc{1.0, 2.0};
  const auto kernel = cases::Kernel::Gaussian;
  const double rf = detail::kernelSupport(kernel) + 0.3;
  CellGrid grid;
  NeighbourList full, half;
  full.cacheW = half.cacheW = false;
  half.half = true;
  detail::selectListPass(kernel)(a, n, rf, grid, full, nullptr);
  detail::selectListPass(kernel)(a, n, rf, grid, half, nullptr);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u01(-1.0, 1.0);
  std::vector<double> dax(a.size()), daz(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    dax[i] = u01(gen);
    daz[i] = u01(gen);
  }
  const double halfDt = 0.01;
  std::vector<double> deFull(n, 1.0), deHalf1(n, 1.0), deHalf2(n, 1.0);
  setThreads(1);
  detail::selectRemainderPass(kernel, false, true, false)(a, n, full, visc, dax.data(), daz.data(),
                                                          nullptr, halfDt, deFull.data());
  const auto halfRem = detail::selectRemainderPass(kernel, false, true, true);
  ASSERT_NE(halfRem, nullptr);
  halfRem(a, n, half, visc, dax.data(), daz.data(), nullptr, halfDt, deHalf1.data());
  setThreads(2);
  halfRem(a, n, half, visc, dax.data(), daz.data(), nullptr, halfDt, deHalf2.data());
  setThreads(1);
  EXPECT_EQ(deHalf1, deHalf2);
  constexpr double u = 0x1p-53;
  int differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const PairState A{a.x[i], a.z[i], a.vx[i], a.vz[i], a.rho[i], a.c[i], a.h[i], a.mu[i], 1.0, a.q[i], 0.0};
    double st = 0.0;
    for (int k = 0; k < full.count[i]; ++k) {
      const auto j = static_cast<std::size_t>(full.index[full.start[i] + static_cast<std::size_t>(k)]);
      const PairState B{a.x[j], a.z[j], a.vx[j], a.vz[j], a.rho[j], a.c[j], a.h[j], a.mu[j], 1.0, a.q[j], 0.0};
      const double dx = A.x - B.x, dz = A.z - B.z, hij = 0.5 * (A.h + B.h);
      const double w = GaussianKernel::value(dx * dx + dz * dz, hij);
      if (w == 0.0) continue;
      const PairResult r = pairTerms<GaussianKernel, false, true, true>(A, B, w, visc);
      st += std::abs(r.share * r.ax * (dax[i] - dax[j])) + std::abs(r.share * r.az * (daz[i] - daz[j]));
    }
    // The sums' bound, scaled by halfDt, plus the rounding of de - halfDt s (1 ulp of de).
    const double bound = halfDt * 2.0 * (2 * full.count[i] + 2) * u * st + 2.0 * u * std::abs(deFull[i]);
    EXPECT_LE(std::abs(deHalf1[i] - deFull[i]), bound) << i;
    differ += deHalf1[i] != deFull[i];
  }
  EXPECT_GT(differ, 0);
}

}  // namespace
}  // namespace hvi::sph
