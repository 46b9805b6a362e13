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

#include "detail/force_lanes.hpp"
#include "hvi/sph/kernel.hpp"
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

template <bool RZ, bool Viscous, bool Cached, bool Compatible>
void checkPolicy(RowKernel kernel, const char* name) {
  SCOPED_TRACE(::testing::Message() << name << " rz " << RZ << " viscous " << Viscous
                                    << " cached " << Cached << " compatible " << Compatible);
  const std::size_t n = 40;  // randomPoints' last 16 are two 8-lane blocks at rest
  const Points p = randomPoints(n, RZ, 17);
  const MonaghanViscosity visc{1.0, 2.0};
  const LaneArrays la = p.lanes();
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
void checkAll(RowKernel (*select)(bool, bool, bool, bool), const char* name) {
  checkPolicy<RZ, Viscous, true, true>(select(RZ, Viscous, true, true), name);
  checkPolicy<RZ, Viscous, true, false>(select(RZ, Viscous, true, false), name);
  checkPolicy<RZ, Viscous, false, true>(select(RZ, Viscous, false, true), name);
  checkPolicy<RZ, Viscous, false, false>(select(RZ, Viscous, false, false), name);
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
  checkAll<false, true>(&detail::rowKernelAvx512, "avx512");
  checkAll<false, false>(&detail::rowKernelAvx512, "avx512");
  checkAll<true, true>(&detail::rowKernelAvx512, "avx512");
  checkAll<true, false>(&detail::rowKernelAvx512, "avx512");
}

// The list build's scan (force_lanes.hpp, ScanKernel) against its one-position-at-a-time
// definition: the same kept slots, W values and count, with a row long enough and with a row
// that overflows (the last slot is overwritten, the count goes on).
void checkScan(detail::ScanKernel scan, const char* name) {
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
    std::vector<double> w(static_cast<std::size_t>(room), -1.0), expW(w);
    const int last = room - 1;
    int cnt = 0, expCnt = 0;
    // Three segments, as the build's rows of cells: [0, 50), [50, 51), [51, n).
    for (auto [s0, s1] : {std::pair{0, 50}, std::pair{50, 51}, std::pair{51, n}}) {
      cnt = scan(sx.data(), sz.data(), sh.data(), order.data(), s0, s1, xi, zi, hi, rf2, self,
                 slot.data(), w.data(), cnt, last);
      for (int s = s0; s < s1; ++s) {
        const auto su = static_cast<std::size_t>(s);
        const double dx = xi - sx[su], dz = zi - sz[su];
        const double r2 = dx * dx + dz * dz;
        const double hij = 0.5 * (hi + sh[su]);
        const auto at = static_cast<std::size_t>(std::min(expCnt, last));
        expSlot[at] = s;
        expW[at] = GaussianKernel::value(r2, hij);
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
    }
  }
}

TEST(ForceLanes, ListScanKeepsThePairsOfTheOneAtATimeLoop) {
  checkScan(detail::scanKernelBaseline(), "baseline");
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("avx2") && detail::scanKernelAvx2())
    checkScan(detail::scanKernelAvx2(), "avx2");
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && detail::scanKernelAvx512())
    checkScan(detail::scanKernelAvx512(), "avx512");
#endif
}

}  // namespace
}  // namespace hvi::sph
