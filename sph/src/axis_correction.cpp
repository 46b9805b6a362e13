//! @file Tabulation of the axis correction C(r / h) from the kernel's x-marginal.
#include "detail/axis_correction.hpp"

#include <cmath>

#include "hvi/sph/kernel.hpp"

namespace hvi::sph::detail {
namespace {

template <class K>
std::vector<double> tabulate(double step) {
  const double support = K::support;
  // x-marginal M(u) = int W(sqrt(u^2 + y^2), 1) dy on a fine grid (midpoint rule, 1e-3).
  const int nu = 2000;
  const double du = 2.0 * support / nu;
  std::vector<double> u(nu), m(nu);
  double norm = 0.0;
  for (int a = 0; a < nu; ++a) {
    u[a] = -support + (a + 0.5) * du;
    const int ny = 2000;
    const double ymax = std::sqrt(std::max(support * support - u[a] * u[a], 0.0));
    const double dy = 2.0 * ymax / ny;
    double s = 0.0;
    for (int b = 0; b < ny; ++b) {
      const double y = -ymax + (b + 0.5) * dy;
      s += K::value(u[a] * u[a] + y * y, 1.0) * dy;
    }
    m[a] = s;
    norm += s * du;
  }
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

}  // namespace

AxisCorrection::AxisCorrection(cases::Kernel kernel) {
  const double step = 0.01;
  inv_ = 1.0 / step;
  table_ = kernel == cases::Kernel::Gaussian ? tabulate<GaussianKernel>(step)
                                             : tabulate<CubicSplineKernel>(step);
}

}  // namespace hvi::sph::detail
