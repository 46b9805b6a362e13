//! @file The strength pass's vector-lane pair terms (sph/src/detail/stress_lanes.hpp) give the
//! one-pair-at-a-time loop's bits (strength_pass.cpp, whose physics the SphStrength tests check):
//! the pass adds the per-pair terms in list order, so its sums are that loop's only if every
//! term is. Exact equality for each policy (planar / r-z, viscosity switch off / on) on rows
//! with every lane condition: pairs beyond the support (W = 0), another object's h (h_ij != h_i,
//! W(dp) at h_ij), approaching and receding pairs, tension (artificial stress) and whole blocks
//! without it (the division skipped), and row lengths that are not a multiple of the lanes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "detail/force_lanes.hpp"
#include "detail/stress_lanes.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/pair_stress.hpp"
#include "hvi/sph/viscosity.hpp"

namespace hvi::sph {
namespace {

using detail::StressRowKernel;
using detail::StressRowParams;
using detail::StressRowTerms;

struct Points {
  std::vector<double> x, z, vx, vz, h, mu, rho, c, rw, txx, tzz, txz, rxx, rzz, rxz, htt, alpha,
      vol, rec, q;
  std::vector<int> obj;
  detail::LaneArrays forceLanes() const {
    return {x.data(), z.data(),  vx.data(), vz.data(), rho.data(), c.data(),
            h.data(), mu.data(), rw.data(), q.data(),  obj.data()};
  }
  detail::StressLaneArrays lanes() const {
    return {x.data(),   z.data(),   vx.data(),  vz.data(),    h.data(),   mu.data(),  rho.data(),
            c.data(),   rw.data(),  txx.data(), tzz.data(),   txz.data(), rxx.data(), rzz.data(),
            rxz.data(), htt.data(), alpha.data(), vol.data(), rec.data()};
  }
};

Points randomPoints(std::size_t n, std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  for (std::size_t i = 0; i < n; ++i) {
    // As test_force_lanes.cpp: a 0.1 cm square, h = 0.02 cm (some pairs beyond 3 h), every 7th
    // point with a larger h; the last 16 at rest and unstressed (no tension, no approach).
    const bool still = i >= n - 16;
    const bool other = i % 7 == 3 && !still;
    const bool tension = i % 3 == 0 && !still;
    p.x.push_back(0.05 + 0.1 * u(gen));
    p.z.push_back(0.1 * u(gen));
    p.vx.push_back(still ? 0.1 : 0.3 * (u(gen) - 0.5));
    p.vz.push_back(still ? 0.0 : 0.3 * (u(gen) - 0.5));
    p.h.push_back(other ? 0.025 : 0.02);
    p.mu.push_back(1e-4 * (1.0 + u(gen)));
    p.rho.push_back(2.0 + u(gen));
    p.c.push_back(0.5 + 0.1 * u(gen));
    p.rw.push_back(p.x.back());
    const double s = still ? 0.0 : 1e-3;
    p.txx.push_back(s * (u(gen) - 0.5));
    p.tzz.push_back(s * (u(gen) - 0.5));
    p.txz.push_back(s * (u(gen) - 0.5));
    const double r = tension ? -1e-4 : 0.0;
    p.rxx.push_back(r * u(gen));
    p.rzz.push_back(r * u(gen));
    p.rxz.push_back(r * (u(gen) - 0.5));
    p.htt.push_back(s * (u(gen) - 0.5));
    p.alpha.push_back(0.1 + 0.9 * u(gen));
    p.vol.push_back(p.mu.back() / p.rho.back());
    p.q.push_back(1e-2 * u(gen));
    p.obj.push_back(other ? 1 : 0);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (const auto* v : {&p.txx, &p.tzz, &p.txz, &p.rxx, &p.rzz, &p.rxz, &p.vol, &p.mu})
      p.rec.push_back((*v)[i]);
  return p;
}

// strength_pass.cpp's one-pair-at-a-time terms (its loop body, the same operations).
struct Ref {
  double gxx, gxz, gzx, gzz, ax, az, de, hoop, phi;
};
Ref reference(const Points& p, std::size_t i, std::size_t j, const StressRowParams& prm, bool rz,
              bool sw) {
  using K = GaussianKernel;
  const double hi = p.h[i], ih2i = 1.0 / (hi * hi);
  const double wdpi = K::value(prm.q2dp * hi * hi, hi, ih2i);
  const double hj = p.h[j];
  double ih2 = ih2i, hij = hi, wdp = wdpi;
  if (hj != hi) {
    hij = 0.5 * (hi + hj);
    ih2 = 1.0 / (hij * hij);
    wdp = K::value(prm.q2dp * hij * hij, hij, ih2);
  }
  const double dx = p.x[i] - p.x[j], dz = p.z[i] - p.z[j];
  const double r2 = dx * dx + dz * dz;
  const double w = K::value(r2, hij, ih2);
  Ref r{};
  if (w == 0.0) return r;
  const double f = K::gradFactor(w, r2, hij, ih2);
  const double gx = f * dx, gz = f * dz;
  const double dvx = p.vx[i] - p.vx[j], dvz = p.vz[i] - p.vz[j];
  const VelocityGradientTerm t = velocityGradientTerm(p.vol[j], -dvx, -dvz, gx, gz);
  Sym2 tab{p.txx[i] + p.txx[j], p.tzz[i] + p.tzz[j], p.txz[i] + p.txz[j]};
  if (prm.power > 0) {
    const double fab = w / wdp;
    double fn = fab;
    for (int e = 1; e < prm.power; ++e) fn *= fab;
    tab.xx += fn * (p.rxx[i] + p.rxx[j]);
    tab.zz += fn * (p.rzz[i] + p.rzz[j]);
    tab.xz += fn * (p.rxz[i] + p.rxz[j]);
  }
  if (sw) {
    const double aij = 0.5 * (p.alpha[i] + p.alpha[j]);
    const MonaghanViscosity visc{aij, prm.betaPerAlpha * aij};
    const double pi = visc(dvx * dx + dvz * dz, r2, hij, 0.5 * (p.c[i] + p.c[j]),
                           0.5 * (p.rho[i] + p.rho[j]), r.phi);
    const double rpi = rz ? 0.5 * (p.rw[i] + p.rw[j]) * pi : pi;
    tab.xx -= rpi;
    tab.zz -= rpi;
  }
  const StressPairTerm st = stressPairTerm(tab, p.mu[j], dvx, dvz, gx, gz);
  r = {t.xx, t.xz, t.zx, t.zz, st.ax, st.az, st.de, rz ? p.mu[j] * p.htt[j] * w : 0.0, r.phi};
  return r;
}

// Equal bits, or both zero: a masked lane stores +0 where the loop skips (sums unchanged).
bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || (a == 0.0 && b == 0.0);
}

// `force` (fused kernels): the force lane kernel of the same width, whose stored pair geometry
// the stress kernel reads (StrengthModel::passWithForces), for each of its policies (cached
// and half-state, viscous unless switched, compatible or not).
void checkKernel(StressRowKernel (*make)(bool, bool, bool), bool fused = false,
                 detail::RowKernel (*force)(bool, bool, bool, bool, bool) = nullptr) {
  const Points p = randomPoints(200, 7);
  const std::size_t n = p.x.size();
  std::vector<int> nb;
  for (std::size_t j = 0; j < n; ++j) nb.push_back(static_cast<int>(j));
  std::vector<double> buf(9 * 208 + 3);
  double* b = buf.data();
  StressRowTerms out{b, b + 208, b + 416, b + 624, b + 832, b + 1040, b + 1248, b + 1456, b + 1664};
  // W(dp) kept from row to row (the rows below alternate h_i: every 7th point has another h).
  out.wdpMemo = b + 9 * 208;
  out.wdpMemo[0] = std::nan("");
  std::vector<double> fbuf(15 * 208);
  double* f = fbuf.data();
  const detail::PairGeometry geom{f + 8 * 208,  f + 9 * 208,  f + 10 * 208, f + 11 * 208,
                                  f + 12 * 208, f + 13 * 208, f + 14 * 208};
  detail::RowTerms ft{f,           f + 208,     f + 2 * 208, f + 3 * 208,
                      f + 4 * 208, f + 5 * 208, f + 6 * 208, f + 7 * 208};
  ft.geom = &geom;
  std::vector<double> pw0(n + 1), pwx(n + 1), pwz(n + 1);
  long pairs = 0, live = 0;
  for (bool rz : {false, true})
    for (bool sw : {false, true}) {
      const StressRowKernel k = make(rz, sw, fused);
      ASSERT_NE(k, nullptr);
      for (int power : {0, 4}) {
        const StressRowParams prm{1.0 / (1.2 * 1.2), power, 2.0};
        for (std::size_t i : {std::size_t{0}, std::size_t{3}, std::size_t{10}, n - 1, n - 5})
          for (int cnt : {static_cast<int>(n) - 1, 13, 16, 5}) {
            // the row: every point but i (count cnt, from the end: the still block included)
            std::vector<int> row;
            for (std::size_t j = n; j-- > 0 && static_cast<int>(row.size()) < cnt;)
              if (j != i) row.push_back(static_cast<int>(j));
            if (fused) {
              // The force kernel's policy varies with the row: its geometry must not.
              const bool cached = cnt % 2 == 1, compatible = i % 2 == 0;
              const detail::RowKernel fk = force(rz, !sw && i % 3 != 1, cached, compatible, false);
              ASSERT_NE(fk, nullptr);
              std::fill(fbuf.begin(), fbuf.end(), std::nan(""));
              fk(p.forceLanes(), i, row.data(), nullptr, cnt, 1.0, 2.0, ft);
              // The pair data the kernel adds to (slot cnt, past the row, left alone).
              for (int t = 0; t <= cnt; ++t) pw0[t] = 1e-3 * (t + 1);
              pwx = pw0;
              pwz = pw0;
              out.pwx = pwx.data();
              out.pwz = pwz.data();
              k(p.lanes(), i, row.data(), nullptr, cnt, prm, out, &geom);
              out.pwx = out.pwz = nullptr;
              EXPECT_EQ(pwx[cnt], pw0[cnt]);
              EXPECT_EQ(pwz[cnt], pw0[cnt]);
            } else {
              k(p.lanes(), i, row.data(), nullptr, cnt, prm, out, nullptr);
            }
            for (int s = 0; s < cnt; ++s) {
              const Ref r = reference(p, i, static_cast<std::size_t>(row[s]), prm, rz, sw);
              ++pairs;
              live += r.ax != 0.0;
              SCOPED_TRACE(::testing::Message() << "rz " << rz << " switch " << sw << " power "
                                                << power << " row " << i << " slot " << s);
              ASSERT_TRUE(same(out.gxx[s], r.gxx) && same(out.gxz[s], r.gxz) &&
                          same(out.gzx[s], r.gzx) && same(out.gzz[s], r.gzz));
              ASSERT_TRUE(same(out.ax[s], r.ax) && same(out.az[s], r.az) && same(out.de[s], r.de));
              if (rz) {
                ASSERT_TRUE(same(out.hoop[s], r.hoop));
              }
              if (sw) {
                ASSERT_TRUE(same(out.phi[s], r.phi));
              }
              if (fused) {
                ASSERT_TRUE(same(pwx[s], pw0[s] + 0.5 * r.ax) && same(pwz[s], pw0[s] + 0.5 * r.az));
              }
            }
          }
      }
    }
  EXPECT_GT(live, pairs / 4);  // most pairs within the support
  EXPECT_LT(live, pairs);      // and some beyond it
}

TEST(StressLanes, Avx2LanesGiveTheScalarTermsBitForBit) {
  if (detail::laneWidth() < 4 || !detail::stressRowKernelAvx2(false, false))
    GTEST_SKIP() << "no AVX2 on this CPU or compiler: the scalar loop runs";
  checkKernel(&detail::stressRowKernelAvx2);
}

TEST(StressLanes, Avx512LanesGiveTheScalarTermsBitForBit) {
  if (detail::laneWidth() < 8 || !detail::stressRowKernelAvx512(false, false))
    GTEST_SKIP() << "no AVX-512 on this CPU or compiler";
  checkKernel(&detail::stressRowKernelAvx512);
}

// docs/strength.md, "Cost of strength in SPH": the fused kernels read dx, dv, h_j, W and the
// gradient factor from the force kernel's stores instead of computing them: the same terms.
TEST(StressLanes, FusedAvx2LanesGiveTheScalarTermsBitForBit) {
  if (detail::laneWidth() < 4 || !detail::stressRowKernelAvx2(false, false, true))
    GTEST_SKIP() << "no AVX2 on this CPU or compiler: the scalar loop runs";
  checkKernel(&detail::stressRowKernelAvx2, true, &detail::rowKernelAvx2);
}

TEST(StressLanes, FusedAvx512LanesGiveTheScalarTermsBitForBit) {
  if (detail::laneWidth() < 8 || !detail::stressRowKernelAvx512(false, false, true))
    GTEST_SKIP() << "no AVX-512 on this CPU or compiler";
  checkKernel(&detail::stressRowKernelAvx512, true, &detail::rowKernelAvx512);
}

}  // namespace
}  // namespace hvi::sph
