//! @file Noh implosion: known post-shock state, jump conditions at the shock, mass budget.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/common/error.hpp"
#include "hvi/verify/noh.hpp"

namespace hvi::verify {
namespace {

TEST(Noh, KnownPostShockStateAndShockSpeed) {
  // gamma = 5/3: shock speed u0 (g-1)/2 = 1/3, compression ((g+1)/(g-1))^(n+1) = 4, 16, 64.
  const double expected[] = {4.0, 16.0, 64.0};
  for (int n = 0; n <= 2; ++n) {
    const NohSolution noh{5.0 / 3.0, 1.0, 1.0, n};
    EXPECT_NEAR(noh.shockRadius(0.6), 0.2, 1e-15);
    const NohSample in = noh.sample(0.1, 0.6);
    EXPECT_NEAR(in.rho, expected[n], 1e-13);
    EXPECT_EQ(in.u, 0.0);
    EXPECT_NEAR(in.p, 2.0 / 3.0 * expected[n] * 0.5, 1e-13);  // (g-1) rho u0^2/2
    const NohSample out = noh.sample(0.4, 0.6);
    EXPECT_NEAR(out.rho, std::pow(1.0 + 0.6 / 0.4, n), 1e-13);
    EXPECT_EQ(out.u, -1.0);
    EXPECT_EQ(out.p, 0.0);
  }
}

TEST(Noh, ShockSatisfiesJumpConditions) {
  // In the shock frame (speed S) mass, momentum and total enthalpy are conserved. The two sides
  // are sampled 1e-12 R apart, so the pre-shock density is off by n 1e-12 relative at most.
  for (double g : {1.4, 5.0 / 3.0, 3.0}) {
    for (int n = 0; n <= 2; ++n) {
      const NohSolution noh{g, 2.0, 0.7, n};
      const double t = 1.3, R = noh.shockRadius(t), S = R / t;
      const NohSample a = noh.sample(R * (1.0 + 1e-12), t), b = noh.sample(R * (1.0 - 1e-12), t);
      const double wa = a.u - S, wb = b.u - S;
      EXPECT_NEAR(a.rho * wa / (b.rho * wb), 1.0, 1e-11);
      EXPECT_NEAR((a.rho * wa * wa + a.p) / (b.rho * wb * wb + b.p), 1.0, 1e-11);
      EXPECT_NEAR((a.e + 0.5 * wa * wa) / (b.e + b.p / b.rho + 0.5 * wb * wb), 1.0, 1e-11);
    }
  }
}

TEST(Noh, MassInsideAFixedRadiusGrowsByTheInflow) {
  // The mass within radius X at time t is the initial mass within X + u0 t (every parcel moves
  // inward at u0 until shocked, then stops): int rho r^n dr = rho0 (X + u0 t)^(n+1)/(n+1).
  // Composite Gauss-Legendre (3 points, 4000 panels) on each side of the shock: exact to
  // ~1e-13 for these polynomial-times-rational integrands.
  const double xg[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, wg[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  for (int n = 0; n <= 2; ++n) {
    const NohSolution noh{5.0 / 3.0, 1.0, 1.0, n};
    const double t = 0.9, X = 1.0, R = noh.shockRadius(t);
    double m = 0.0;
    for (auto [a, b] : {std::pair{0.0, R}, std::pair{R, X}}) {
      const int panels = 4000;
      const double h = (b - a) / panels;
      for (int i = 0; i < panels; ++i) {
        for (int q = 0; q < 3; ++q) {
          const double r = a + h * (i + 0.5 + 0.5 * xg[q]);
          m += 0.5 * h * wg[q] * noh.sample(r, t).rho * std::pow(r, n);
        }
      }
    }
    EXPECT_NEAR(m / (std::pow(X + t, n + 1) / (n + 1)), 1.0, 1e-10) << "n " << n;
  }
}

TEST(Noh, RejectsBadParameters) {
  const NohSolution gammaOne{1.0, 1.0, 1.0, 1}, fourD{1.4, 1.0, 1.0, 3};
  EXPECT_THROW((void)gammaOne.shockRadius(1.0), InputError);
  EXPECT_THROW((void)fourD.sample(0.1, 1.0), InputError);
}

}  // namespace
}  // namespace hvi::verify
