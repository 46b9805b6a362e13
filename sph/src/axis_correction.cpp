//! @file Tabulation of the axis correction C(r / h) from the kernel's x-marginal.
#include "detail/axis_correction.hpp"

#include <algorithm>
#include <cmath>

#include "hvi/sph/kernel.hpp"

namespace hvi::sph::detail {
namespace {

// The kernel's x-marginal int W(sqrt(u^2 + y^2), 1) dy at nu midpoints u of [-support,
// support], by the midpoint rule with ny points in y; not normalised.
template <class K>
void marginalSums(int nu, int ny, std::vector<double>& u, std::vector<double>& m) {
  const double support = K::support;
  const double du = 2.0 * support / nu;
  u.resize(nu);
  m.resize(nu);
  for (int a = 0; a < nu; ++a) {
    u[a] = -support + (a + 0.5) * du;
    const double ymax = std::sqrt(std::max(support * support - u[a] * u[a], 0.0));
    const double dy = 2.0 * ymax / ny;
    double s = 0.0;
    for (int b = 0; b < ny; ++b) {
      const double y = -ymax + (b + 0.5) * dy;
      s += K::value(u[a] * u[a] + y * y, 1.0) * dy;
    }
    m[a] = s;
  }
}

template <class K>
std::vector<double> tabulate(double step) {
  const double support = K::support;
  // x-marginal M(u) = int W(sqrt(u^2 + y^2), 1) dy on a fine grid (midpoint rule, 1e-3).
  const int nu = 2000;
  const double du = 2.0 * support / nu;
  std::vector<double> u, m;
  marginalSums<K>(nu, 2000, u, m);
  double norm = 0.0;
  for (int a = 0; a < nu; ++a) norm += m[a] * du;
  std::vector<double> table;
  for (double r = 0.0; r <= support + step; r += step) {
    double f = 0.0, g = 0.0;  // E|r + X| and E sign(r + X)
    for (int a = 0; a < nu; ++a) {
      const double x = r + u[a];
      f += std::abs(x) * m[a] * du;
      g += (x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0)) * m[a] * du;
    }
    f /= norm;
    g /= norm;
    table.push_back(r > 0.0 ? r * g / f : 0.0);
  }
  table.back() = 1.0;  // beyond the support the mirror ghosts are out of reach
  return table;
}

// The kernel's x-marginal on nu midpoints of [-support, support], normalised: u, weight.
template <class K>
void marginal(int nu, std::vector<double>& u, std::vector<double>& m) {
  marginalSums<K>(nu, 1000, u, m);
  double norm = 0.0;
  for (const double s : m) norm += s;
  for (double& v : m) v /= norm;
}

}  // namespace

RingScale::RingScale(cases::Kernel kernel) {
  std::vector<double> u, m;
  if (kernel == cases::Kernel::Gaussian)
    marginal<GaussianKernel>(600, u, m);
  else
    marginal<CubicSplineKernel>(600, u, m);
  var_ = 0.0;
  for (std::size_t a = 0; a < u.size(); ++a) var_ += u[a] * u[a] * m[a];
  const double step = 0.01, umax = 12.0;
  inv_ = 1.0 / step;
  const auto nt = static_cast<std::size_t>(umax / step) + 1;
  sigma_.assign(nt, 0.0);
  for (std::size_t k = 0; k < nt; ++k) sigma_[k] = std::sqrt(std::max(k * step, 0.5));
  // Fixed-point iteration sigma <- sqrt(sigma E[|u+X| / sigma(|u+X|)]): the geometric mean
  // damps the plain map's alternation (a relative error e maps to -e), so it converges fast.
  std::vector<double> next(nt);
  for (int it = 0; it < 200; ++it) {
    double change = 0.0;
    for (std::size_t k = 0; k < nt; ++k) {
      const double uk = k * step;
      double e = 0.0;
      for (std::size_t a = 0; a < u.size(); ++a) {
        const double y = std::abs(uk + u[a]);
        e += y / lookup(sigma_, y, false) * m[a];
      }
      next[k] = std::sqrt(sigma_[k] * e);
      change = std::max(change, std::abs(next[k] / sigma_[k] - 1.0));
    }
    sigma_.swap(next);
    if (change < 1e-13) break;
  }
  dsigma_.assign(nt, 0.0);
  for (std::size_t k = 1; k + 1 < nt; ++k) dsigma_[k] = (sigma_[k + 1] - sigma_[k - 1]) / (2 * step);
  dsigma_[nt - 1] = lookup(dsigma_, umax + 1e-9, true);  // matches the expansion at the end
}

const RingScale& ringScale(cases::Kernel kernel) {
  static const RingScale gaussian(cases::Kernel::Gaussian);
  static const RingScale spline(cases::Kernel::CubicSpline);
  return kernel == cases::Kernel::Gaussian ? gaussian : spline;
}

AxisCorrection::AxisCorrection(cases::Kernel kernel) {
  const double step = 0.01;
  inv_ = 1.0 / step;
  table_ = kernel == cases::Kernel::Gaussian ? tabulate<GaussianKernel>(step)
                                             : tabulate<CubicSplineKernel>(step);
}

}  // namespace hvi::sph::detail
