//! @file Kernels: unit integral, gradient = derivative of the value, continuity at the cut.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/sph/kernel.hpp"

namespace hvi::sph {
namespace {

// Midpoint-rule integral over a fine square lattice of spacing h/40: the error of the rule is
// O((h/40)^2 W'') relative ~ 1e-4 for the cubic spline's kinks, ~1e-9 for the smooth Gaussian.
template <class K>
double latticeIntegral(double h, double step) {
  const int n = static_cast<int>(std::ceil(K::support * h / step)) + 1;
  double sum = 0.0;
  for (int i = -n; i < n; ++i)
    for (int k = -n; k < n; ++k) {
      const double x = (i + 0.5) * step, z = (k + 0.5) * step;
      sum += K::value(x * x + z * z, h) * step * step;
    }
  return sum;
}

TEST(Kernel, GaussianHasUnitIntegralAndVanishesContinuouslyAtTheCut) {
  const double h = 0.7;
  EXPECT_NEAR(latticeIntegral<GaussianKernel>(h, h / 40.0), 1.0, 1e-6);
  // W and dW/dr vanish continuously at r = 3h (the reason for the correction): at
  // 3h (1 - 1e-6), W ~ exp(-9) (2 q dq)^2 / 2 W(0) ~ 2e-14 W(0) and r F ~ 6 q dq exp(-9) / h;
  // beyond the cut both are exactly 0.
  const double r = 3.0 * h * (1.0 - 1e-6);
  const double w0 = GaussianKernel::value(0.0, h);
  EXPECT_LT(GaussianKernel::value(r * r, h), 1e-12 * w0);
  EXPECT_LT(std::abs(r * GaussianKernel::gradFactor(GaussianKernel::value(r * r, h), r * r, h)),
            1e-7 * w0 / h);
  EXPECT_EQ(GaussianKernel::value(9.0 * h * h, h), 0.0);
  // Shape within 1.2e-3 of the study's exp(-q^2), after taking out the normalisation.
  for (double q = 0.0; q < 3.0; q += 0.25) {
    const double shape = GaussianKernel::value(q * q * h * h, h) * h * h / GaussianKernel::norm;
    EXPECT_NEAR(shape, std::exp(-q * q), 1.24e-3);
  }
}

TEST(Kernel, CubicSplineHasUnitIntegral) {
  EXPECT_NEAR(latticeIntegral<CubicSplineKernel>(0.5, 0.5 / 40.0), 1.0, 1e-4);
}

template <class K>
void checkGradient(double h) {
  for (double q : {0.05, 0.3, 0.9, 1.1, 1.7, 2.4, 2.9}) {
    if (q >= K::support) continue;
    const double r = q * h, d = 1e-6 * h;
    const double dwdr = (K::value((r + d) * (r + d), h) - K::value((r - d) * (r - d), h)) / (2 * d);
    const double f = K::gradFactor(K::value(r * r, h), r * r, h);
    // Central difference error O(d^2 W''') ~ 1e-12 relative; the rest is round-off of
    // W / d ~ 1e-16 / 1e-6.
    EXPECT_NEAR(f * r, dwdr, 1e-8 * std::abs(K::value(0.0, h)) / h) << "q = " << q;
  }
}

TEST(Kernel, GradientFactorIsTheDerivative) {
  checkGradient<GaussianKernel>(0.3);
  checkGradient<CubicSplineKernel>(0.3);
}

}  // namespace
}  // namespace hvi::sph

namespace hvi::sph {
namespace {

TEST(Kernel, InlineExponentialMatchesLibm) {
  // Over the kernel's range q^2 in [0, 9]: within 2 ulp (4.4e-16 relative) of std::exp
  // (Estrin's evaluation order rounds slightly differently from Horner's).
  double worst = 0.0;
  for (int k = 0; k <= 900000; ++k) {
    const double x = 9.0 * k / 900000.0;
    worst = std::max(worst, std::abs(expNegative(x) / std::exp(-x) - 1.0));
  }
  std::printf("inline exp: worst relative deviation from std::exp %.2e\n", worst);
  EXPECT_LT(worst, 4.5e-16);
}

}  // namespace
}  // namespace hvi::sph
