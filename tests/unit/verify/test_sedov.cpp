//! @file Sedov-Taylor blast: alpha, similarity ODEs, energy and mass integrals, shock state.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "hvi/common/error.hpp"
#include "hvi/verify/sedov.hpp"

namespace hvi::verify {
namespace {

double sphereMeasure(int n) {
  return n == 0 ? 1.0 : (n == 1 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi);
}

// Composite 5-point Gauss-Legendre of f over [a, b].
template <class F>
double integrate(F&& f, double a, double b, int panels) {
  const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                       0.9061798459386640};
  const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                       0.2369268850561891, 0.2369268850561891};
  const double h = (b - a) / panels;
  double s = 0.0;
  for (int i = 0; i < panels; ++i)
    for (int q = 0; q < 5; ++q) s += 0.5 * h * w[q] * f(a + h * (i + 0.5 + 0.5 * x[q]));
  return s;
}

TEST(Sedov, AlphaAgainstLiterature) {
  // ExactPack's standard spherical problem (R = 1 at t = 1) uses E = 0.851072, 6 digits.
  EXPECT_NEAR(SedovSolution(1.4, 1.0, 1.0, 2).alpha(), 0.851072, 1e-6);
  // Kamm & Timmes (2007) Table 4: 0.538548, 0.984041, 0.851060. Their quadrature of the weakly
  // singular energy integrand near V0 is known to be off in the 4th digit (ExactPack marks the
  // 1e-6 comparison as an expected failure), so 5e-4 relative.
  EXPECT_NEAR(SedovSolution(1.4, 1.0, 1.0, 0).alpha() / 0.538548, 1.0, 5e-4);
  EXPECT_NEAR(SedovSolution(1.4, 1.0, 1.0, 1).alpha() / 0.984041, 1.0, 5e-4);
  EXPECT_NEAR(SedovSolution(1.4, 1.0, 1.0, 2).alpha() / 0.851060, 1.0, 5e-4);
  for (int n = 0; n <= 2; ++n) {
    std::printf("Sedov gamma 1.4 n %d: alpha = %.9f\n", n, SedovSolution(1.4, 1.0, 1.0, n).alpha());
  }
}

// The similarity ODEs written independently of the closed form: u = R' f, rho = rho0 G,
// p = rho0 R'^2 H with R ~ t^(2/(j+2)); mass, momentum and entropy equations solved for
// (f, ln G, ln H) as functions of x = ln(lambda), integrated from the strong shock inwards by
// classical RK4. Inward integration is unstable near the centre (perturbations grow like
// lambda^-j), so it stops at lambda = 0.1, where the amplification is at most 1e3.
std::array<double, 3> similarityOde(double gamma, int n, double lambdaEnd) {
  const double j = n + 1.0, g = gamma, k = 1.0 - (j + 2.0) / 2.0;  // k = (delta - 1)/delta
  auto rhs = [&](double x, const std::array<double, 3>& y) {
    const double lam = std::exp(x), f = y[0], G = std::exp(y[1]), H = std::exp(y[2]);
    const double d = f - lam, q = H / G;
    const double fp = (q * (g * (j - 1.0) * f / lam + 2.0 * k) - k * f * d) / (d * d - g * q);
    const double gl = -(fp + (j - 1.0) * f / lam) / d;
    return std::array<double, 3>{lam * fp, lam * gl, lam * (g * gl - 2.0 * k / d)};
  };
  std::array<double, 3> y{2.0 / (g + 1.0), std::log((g + 1.0) / (g - 1.0)),
                          std::log(2.0 / (g + 1.0))};
  const int steps = 20000;
  const double h = std::log(lambdaEnd) / steps;
  for (int i = 0; i < steps; ++i) {
    const double x = i * h;
    auto add = [&](const std::array<double, 3>& a, double s) {
      return std::array<double, 3>{y[0] + s * a[0], y[1] + s * a[1], y[2] + s * a[2]};
    };
    const auto k1 = rhs(x, y), k2 = rhs(x + 0.5 * h, add(k1, 0.5 * h));
    const auto k3 = rhs(x + 0.5 * h, add(k2, 0.5 * h)), k4 = rhs(x + h, add(k3, h));
    for (int c = 0; c < 3; ++c) y[c] += h / 6.0 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
  }
  return {std::exp(y[1]), y[0], std::exp(y[2])};  // rho/rho0, u/R', p/(rho0 R'^2)
}

TEST(Sedov, ClosedFormSolvesTheSimilarityOdes) {
  // RK4 with 20000 steps over ln(10): truncation ~1e-15, times the inward amplification
  // (<= 1e3) gives ~1e-12; 1e-9 relative leaves margin.
  for (double g : {1.2, 1.4, 5.0 / 3.0}) {
    for (int n = 0; n <= 2; ++n) {
      const SedovSolution s(g, 1.3, 2.0, n);
      const double t = 0.7, R = s.shockRadius(t), Rdot = 2.0 / (n + 3.0) * R / t;
      for (double lam : {0.9, 0.6, 0.3, 0.1}) {
        const auto ref = similarityOde(g, n, lam);
        const SedovSample x = s.sample(lam * R, t);
        EXPECT_NEAR(x.rho / (1.3 * ref[0]), 1.0, 1e-9) << "g " << g << " n " << n << " " << lam;
        EXPECT_NEAR(x.u / (Rdot * ref[1]), 1.0, 1e-9);
        EXPECT_NEAR(x.p / (1.3 * Rdot * Rdot * ref[2]), 1.0, 1e-9);
      }
    }
  }
}

TEST(Sedov, SampledProfileHoldsTheEnergyAndTheSweptMass) {
  // Quadrature of the sampled profile (not of the similarity functions): total energy equals E
  // and the mass inside the shock equals the ambient mass it swept, both to 1e-8 (5-point
  // Gauss-Legendre on 400 panels of a profile smooth up to the shock).
  for (double g : {1.4, 5.0 / 3.0}) {
    for (int n = 0; n <= 2; ++n) {
      const double rho0 = 1.3, E = 2.0, t = 0.7;
      const SedovSolution s(g, rho0, E, n);
      const double R = s.shockRadius(t), sig = sphereMeasure(n);
      const double energy = integrate(
          [&](double r) {
            const SedovSample x = s.sample(r, t);
            return sig * std::pow(r, n) * (0.5 * x.rho * x.u * x.u + x.p / (g - 1.0));
          },
          0.0, R, 400);
      const double mass = integrate(
          [&](double r) { return sig * std::pow(r, n) * s.sample(r, t).rho; }, 0.0, R, 400);
      EXPECT_NEAR(energy / E, 1.0, 1e-8) << "g " << g << " n " << n;
      EXPECT_NEAR(mass / (rho0 * sig * std::pow(R, n + 1) / (n + 1)), 1.0, 1e-8);
    }
  }
}

TEST(Sedov, StrongShockStateAndCentre) {
  const double g = 1.4, rho0 = 1.0, t = 2.0;
  for (int n = 0; n <= 2; ++n) {
    const SedovSolution s(g, rho0, 1.0, n);
    const double R = s.shockRadius(t), Rdot = 2.0 / (n + 3.0) * R / t;
    EXPECT_NEAR(R, std::pow(t * t / s.alpha(), 1.0 / (n + 3.0)), 1e-15);
    const SedovSample b = s.sample(R * (1.0 - 1e-14), t);
    EXPECT_NEAR(b.rho, rho0 * (g + 1.0) / (g - 1.0), 1e-10);
    EXPECT_NEAR(b.u, 2.0 * Rdot / (g + 1.0), 1e-10);
    EXPECT_NEAR(b.p, 2.0 * rho0 * Rdot * Rdot / (g + 1.0), 1e-10);
    const SedovSample a = s.sample(R * (1.0 + 1e-14), t);
    EXPECT_EQ(a.rho, rho0);
    EXPECT_EQ(a.p, 0.0);
    // Centre: empty, at rest, at the finite central pressure the profile tends to.
    const SedovSample c = s.sample(0.0, t), c1 = s.sample(1e-6 * R, t);
    EXPECT_EQ(c.rho, 0.0);
    EXPECT_EQ(c.u, 0.0);
    EXPECT_GT(c.p, 0.0);
    EXPECT_NEAR(c1.p / c.p, 1.0, 1e-9);
    EXPECT_NEAR(c1.u / (1e-6 * R / (g * t) * 2.0 / (n + 3.0)), 1.0, 1e-6);  // u -> delta r/(g t)
  }
}

TEST(Sedov, RejectsUnsupportedParameters) {
  EXPECT_THROW(SedovSolution(1.0, 1.0, 1.0, 2), InputError);
  EXPECT_THROW(SedovSolution(1.4, 1.0, 1.0, 3), InputError);
  EXPECT_THROW(SedovSolution(8.0, 1.0, 1.0, 2), InputError);  // vacuum-centre case
}

}  // namespace
}  // namespace hvi::verify
