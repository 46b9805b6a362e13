//! @file Sedov-Taylor blast from Sedov's closed form (standard case, uniform ambient density).
#include "hvi/verify/sedov.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "hvi/common/error.hpp"
#include "root_find.hpp"

namespace hvi::verify {
namespace {

// Gauss-Legendre nodes and weights on [-1, 1] by Newton iteration on P_m.
void gaussLegendre(int m, std::vector<double>& x, std::vector<double>& w) {
  x.assign(m, 0.0);
  w.assign(m, 0.0);
  for (int i = 0; i < m; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (m + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= m; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      dp = m * (z * p0 - p1) / (z * z - 1.0);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

// Smallest lambda tabulated; below it sample() extends the bracket, the quadrature adds the
// centre's share analytically (uniform pressure, negligible kinetic energy).
constexpr double kLambdaMin = 1e-8;

}  // namespace

SedovSolution::SedovSolution(double gamma, double rho0, double energy, int n)
    : gamma_(gamma), rho0_(rho0), energy_(energy), n_(n) {
  const double j = n + 1.0, g = gamma, xg2 = j + 2.0;
  const double v2 = 4.0 / (xg2 * (g + 1.0)), vStar = 2.0 / ((g - 1.0) * j + 2.0);
  if (!(g > 1.0) || !(rho0 > 0.0) || !(energy > 0.0) || n < 0 || n > 2 || !(v2 < vStar) ||
      std::abs(j * (2.0 - g)) < 1e-6) {
    throw InputError(fmt::format(
        "SedovSolution: gamma {}, rho0 {}, energy {}, n {}: needs rho0 > 0, energy > 0, n in "
        "0..2 and 1 < gamma in the standard (non-vacuum) case, gamma != 2",
        gamma, rho0, energy, n));
  }
  const double denom2 = 2.0 * (g - 1.0) + j, denom3 = j * (2.0 - g);
  a0_ = 2.0 / xg2;
  a2_ = -(g - 1.0) / denom2;
  a1_ = xg2 * g / (2.0 + j * (g - 1.0)) * (2.0 * j * (2.0 - g) / (g * xg2 * xg2) - a2_);
  a3_ = j / denom2;
  a4_ = xg2 * j * a1_ / denom3;
  a5_ = -2.0 * j / denom3;
  av_ = 0.25 * xg2 * (g + 1.0);
  bv_ = (g + 1.0) / (g - 1.0);
  cv_ = 0.5 * xg2 * g;
  dv_ = xg2 * (g + 1.0) / (xg2 * (g + 1.0) - 2.0 * (2.0 + j * (g - 1.0)));
  ev_ = 0.5 * (2.0 + j * (g - 1.0));

  // Table from the shock (s = 0) inwards until lambda < kLambdaMin.
  const double ds = 0.05;
  for (double s = 0.0;; s -= ds) {
    const Profile p = profile(s);
    s_.push_back(s);
    lambda_.push_back(p.lambda);
    rhoRatio_.push_back(p.rho);
    uRatio_.push_back(p.u);
    pRatio_.push_back(p.p);
    if (p.lambda < kLambdaMin) break;
  }
  std::reverse(s_.begin(), s_.end());
  std::reverse(lambda_.begin(), lambda_.end());
  std::reverse(rhoRatio_.begin(), rhoRatio_.end());
  std::reverse(uRatio_.begin(), uRatio_.end());
  std::reverse(pRatio_.begin(), pRatio_.end());

  // Energy integral int (rho u^2/2 + p/(g-1)) lambda^(j-1) dlambda in the scaled variables,
  // over s with dlambda/ds = lambda dln(lambda)/ds; 10-point Gauss-Legendre on each table step
  // (the integrand is analytic in s and varies on scales >= 1, so each panel is exact to
  // round-off).
  std::vector<double> gx, gw;
  gaussLegendre(10, gx, gw);
  auto integrand = [&](double s) {
    const double x2 = std::exp(s), v = (1.0 + x2 / bv_) / cv_, dvds = x2 / (bv_ * cv_);
    const double dlnLam = -a0_ * dvds / v - a2_ + a1_ * ev_ * dvds / (1.0 - ev_ * v);
    const Profile p = profile(s);
    return (0.5 * p.rho * p.u * p.u + p.p / (g - 1.0)) * std::pow(p.lambda, j) * dlnLam;
  };
  double integral = 0.0;
  for (std::size_t i = 0; i + 1 < s_.size(); ++i) {
    const double mid = 0.5 * (s_[i] + s_[i + 1]), half = 0.5 * (s_[i + 1] - s_[i]);
    for (std::size_t q = 0; q < gx.size(); ++q) {
      integral += half * gw[q] * integrand(mid + half * gx[q]);
    }
  }
  integral += pRatio_.front() / (g - 1.0) * std::pow(lambda_.front(), j) / j;
  const double sigma = n == 0 ? 1.0 : (n == 1 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi);
  alpha_ = sigma * a0_ * a0_ * integral;
}

SedovSolution::Profile SedovSolution::profile(double s) const {
  const double j = n_ + 1.0, g = gamma_;
  const double x2 = std::exp(s), v = (1.0 + x2 / bv_) / cv_;
  const double lx1 = std::log(av_ * v), lx3 = std::log(dv_ * (1.0 - ev_ * v));
  const double lx4 = std::log(bv_ * (1.0 - 0.5 * (j + 2.0) * v));
  Profile p;
  p.lambda = std::exp(-a0_ * lx1 - a2_ * s - a1_ * lx3);
  // Kamm & Timmes' f, g, h are scaled by the post-shock values: u2 = 2 R'/(g+1),
  // rho2 = rho0 (g+1)/(g-1), p2 = 2 rho0 R'^2/(g+1).
  p.u = 2.0 / (g + 1.0) * std::exp(lx1) * p.lambda;
  p.rho = bv_ * std::exp(a3_ * s + a4_ * lx3 + a5_ * lx4);
  p.p = 2.0 / (g + 1.0) * std::exp(a0_ * j * lx1 + (a4_ - 2.0 * a1_) * lx3 + (1.0 + a5_) * lx4);
  return p;
}

double SedovSolution::shockRadius(double t) const {
  if (!(t > 0.0)) return 0.0;
  return std::pow(energy_ * t * t / (alpha_ * rho0_), 1.0 / (n_ + 3.0));
}

SedovSample SedovSolution::sample(double r, double t) const {
  r = std::abs(r);
  const double R = shockRadius(t);
  if (!(r <= R) || R == 0.0) return SedovSample{rho0_, 0.0, 0.0};
  const double Rdot = 2.0 / (n_ + 3.0) * R / t;
  const double lam = r / R;
  Profile p;
  if (lam == 0.0) {
    p = profile(-1e4);  // the centre: x2 underflows to 0, lambda, rho, u vanish, p is finite
  } else if (lam >= lambda_.back()) {
    p = profile(0.0);  // the shock itself (lambda(0) = 1 up to round-off)
  } else {
    // Bracket lambda between table nodes (extending below the table towards the centre),
    // then solve ln lambda(s) = ln lam; lambda is increasing in s.
    double lo, hi;
    auto it = std::lower_bound(lambda_.begin(), lambda_.end(), lam);
    if (it == lambda_.begin()) {
      hi = s_.front();
      lo = hi - 10.0;
      while (profile(lo).lambda > lam) lo -= 2.0 * (hi - lo);
    } else {
      hi = s_[it - lambda_.begin()];
      lo = s_[it - lambda_.begin() - 1];
    }
    auto f = [&](double s) { return std::log(profile(s).lambda / lam); };
    p = profile(detail::brent(f, lo, hi, 1e-15, "Sedov similarity coordinate"));
  }
  return SedovSample{rho0_ * p.rho, Rdot * p.u, rho0_ * Rdot * Rdot * p.p};
}

}  // namespace hvi::verify
