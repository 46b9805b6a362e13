//! @file The pair term: viscosity only on approach; momentum and energy balance of one pair.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/sph/kernel.hpp"
#include "hvi/sph/pair_force.hpp"

namespace hvi::sph {
namespace {

TEST(Viscosity, ActsOnlyOnApproachingPairs) {
  const MonaghanViscosity v{1.0, 2.0};
  double phi = 1.0;
  EXPECT_EQ(v(+0.3, 1.0, 0.5, 1.0, 2.0, phi), 0.0);
  EXPECT_EQ(phi, 0.0);
  EXPECT_EQ(v(0.0, 1.0, 0.5, 1.0, 2.0, phi), 0.0);
  const double pi = v(-0.3, 1.0, 0.5, 1.0, 2.0, phi);
  const double expectPhi = 0.5 * -0.3 / (1.0 + 0.01 * 0.25);
  EXPECT_DOUBLE_EQ(phi, expectPhi);
  EXPECT_DOUBLE_EQ(pi, (-1.0 * 1.0 * expectPhi + 2.0 * expectPhi * expectPhi) / 2.0);
  EXPECT_GT(pi, 0.0);  // a positive pressure-like term: it decelerates the approach
}

PairState state(double x, double z, double vx, double vz, double rho, double p, double m,
                double r) {
  // r < 0 means planar (rw = 1, mu = m); otherwise r-z with ring radius r = x.
  const bool rz = r > 0.0;
  const double rw = rz ? r : 1.0;
  const double mu = rz ? m / (2.0 * M_PI * r) : m;
  return {x, z, vx, vz, rho, 0.5, 0.02, mu, rw, rw * p / (rho * rho), rz ? -vx / r : 0.0};
}

template <bool RZ>
void checkBalance(const PairState& a, const PairState& b) {
  const MonaghanViscosity visc{1.0, 2.0};
  const double dx = a.x - b.x, dz = a.z - b.z;
  const double w = GaussianKernel::value(dx * dx + dz * dz, 0.5 * (a.h + b.h));
  const PairResult ab = pairTerms<GaussianKernel, RZ, true>(a, b, w, visc);
  const PairResult ba = pairTerms<GaussianKernel, RZ, true>(b, a, w, visc);
  // Mass of each side = 2 pi mu rw (r-z) or mu (planar); the r-z sums are divided by r.
  const double ma = RZ ? 2 * M_PI * a.mu * a.rw : a.mu, mb = RZ ? 2 * M_PI * b.mu * b.rw : b.mu;
  const double sa = RZ ? 1.0 / a.rw : 1.0, sb = RZ ? 1.0 / b.rw : 1.0;
  const double scale = std::abs(ma * ab.ax * sa) + std::abs(ma * ab.az * sa);
  ASSERT_GT(scale, 0.0);
  // Axial momentum (and x momentum in planar): equal and opposite to round-off.
  EXPECT_NEAR(ma * ab.az * sa + mb * ba.az * sb, 0.0, 1e-14 * scale);
  if (!RZ) {
    EXPECT_NEAR(ma * ab.ax + mb * ba.ax, 0.0, 1e-14 * scale);
  }
  // Energy: the work of the pair forces is returned exactly as internal energy
  // (m_a v_a.a_a + m_b v_b.a_b + m_a de_a + m_b de_b = 0), viscous heating included.
  const double work =
      ma * sa * (a.vx * ab.ax + a.vz * ab.az) + mb * sb * (b.vx * ba.ax + b.vz * ba.az);
  const double heat = ma * sa * ab.de + mb * sb * ba.de;
  EXPECT_NEAR(work + heat, 0.0, 1e-14 * (std::abs(work) + std::abs(heat)));
  EXPECT_LT(ab.phi, 0.0);  // the pairs below approach
}

TEST(PairTerms, PlanarPairConservesMomentumAndEnergy) {
  checkBalance<false>(state(0.010, 0.002, 0.3, -0.1, 2.9, 0.2, 1e-3, -1),
                      state(0.025, 0.011, -0.2, 0.05, 2.7, 0.05, 1.3e-3, -1));
}

TEST(PairTerms, RzPairConservesAxialMomentumAndEnergy) {
  checkBalance<true>(state(0.010, 0.002, 0.3, -0.1, 2.9, 0.2, 1e-3, 0.010),
                     state(0.025, 0.011, -0.2, 0.05, 2.7, 0.05, 1.3e-3, 0.025));
}

// Compatible energy (docs/sph.md, "Energy"): the two sides' energy summands add up to the
// symmetric form's pair heat (same semi-discrete total), each side is charged its own
// pressure's work, and the shares of the step remainder are complementary.
template <bool RZ>
void checkCompatible(const PairState& a, const PairState& b) {
  const MonaghanViscosity visc{1.0, 2.0};
  const double dx = a.x - b.x, dz = a.z - b.z;
  const double w = GaussianKernel::value(dx * dx + dz * dz, 0.5 * (a.h + b.h));
  const PairResult sab = pairTerms<GaussianKernel, RZ, true>(a, b, w, visc);
  const PairResult sba = pairTerms<GaussianKernel, RZ, true>(b, a, w, visc);
  const PairResult cab = pairTerms<GaussianKernel, RZ, true, true>(a, b, w, visc);
  const PairResult cba = pairTerms<GaussianKernel, RZ, true, true>(b, a, w, visc);
  const double ma = RZ ? 2 * M_PI * a.mu * a.rw : a.mu, mb = RZ ? 2 * M_PI * b.mu * b.rw : b.mu;
  const double sa = RZ ? 1.0 / a.rw : 1.0, sb = RZ ? 1.0 / b.rw : 1.0;
  EXPECT_EQ(cab.ax, sab.ax);  // the momentum summands are the same bits
  EXPECT_EQ(cab.az, sab.az);
  const double heatSym = ma * sa * sab.de + mb * sb * sba.de;
  const double heatCom = ma * sa * cab.de + mb * sb * cba.de;
  EXPECT_NEAR(heatCom, heatSym, 1e-14 * std::abs(heatSym));
  EXPECT_NEAR(cab.share + cba.share, 1.0, 1e-15);
  EXPECT_GE(cab.share, 0.0);
  EXPECT_LE(cab.share, 1.0);
}

TEST(PairTerms, CompatibleEnergySplitsThePairWork) {
  checkCompatible<false>(state(0.010, 0.002, 0.3, -0.1, 2.9, 0.2, 1e-3, -1),
                         state(0.025, 0.011, -0.2, 0.05, 2.7, 0.05, 1.3e-3, -1));
  checkCompatible<true>(state(0.010, 0.002, 0.3, -0.1, 2.9, 0.2, 1e-3, 0.010),
                        state(0.025, 0.011, -0.2, 0.05, 2.7, 0.05, 1.3e-3, 0.025));
}

TEST(PairTerms, CompatibleEnergyDoesNotCoolAPressurelessParticle) {
  // a at P = 0 (cut off) separates from b at 1 Mbar: the pair's work all comes from b's
  // pressure. The symmetric form charges a half of it (a cools); the compatible form none,
  // and a takes no part of the step remainder either.
  const PairState a = state(0.010, 0.0, -0.2, 0.0, 2.6, 0.0, 1e-3, -1);
  const PairState b = state(0.018, 0.0, 0.2, 0.0, 3.6, 1.0, 1e-3, -1);
  const double w = GaussianKernel::value(0.008 * 0.008, 0.02);
  const MonaghanViscosity visc{1.0, 2.0};
  const PairResult sym = pairTerms<GaussianKernel, false, true>(a, b, w, visc);
  const PairResult com = pairTerms<GaussianKernel, false, true, true>(a, b, w, visc);
  EXPECT_EQ(sym.phi, 0.0);  // separating: no viscosity
  EXPECT_LT(sym.de, 0.0);
  EXPECT_EQ(com.de, 0.0);
  EXPECT_EQ(com.share, 0.0);
}

TEST(PairTerms, NoViscosityPolicyDropsPi) {
  const PairState a = state(0.01, 0.0, 0.5, 0.0, 2.79, 0.0, 1e-3, -1);
  const PairState b = state(0.02, 0.0, -0.5, 0.0, 2.79, 0.0, 1e-3, -1);
  const double w = GaussianKernel::value(1e-4, 0.02);
  // Zero pressure: only the viscosity could push; without the policy nothing does.
  const auto off = pairTerms<GaussianKernel, false, false>(a, b, w, MonaghanViscosity{});
  const auto on = pairTerms<GaussianKernel, false, true>(a, b, w, MonaghanViscosity{});
  EXPECT_EQ(off.ax, 0.0);
  EXPECT_LT(on.ax, 0.0);  // a moves towards +x into b and is pushed back
}

}  // namespace
}  // namespace hvi::sph
