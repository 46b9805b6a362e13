//! @file Hoop-term correction near the r-z axis for the kernel's bias with mirror ghosts.
#pragma once
#include <vector>

#include "hvi/cases/scene.hpp"

namespace hvi::sph::detail {

//! With mirror ghosts, SPH sums near the axis see the radius weight as |r| smoothed by the
//! kernel: sum_k mu_k r_k W_ik ~ rho f(r_i) and sum_k mu_k r_k grad W_ik ~ rho f'(r_i), where
//! f(r) = E|r + X| for X distributed as the kernel's x-marginal. The hoop term H_i / r_i^2 of
//! docs/sph-rz.md then no longer cancels the radial pressure-gradient sum in a uniform state
//! (it exceeds it by rho (f - r f') / r^2, which grows like h / r^2): particles within ~h of
//! the axis are pushed out. Multiplying H_i by C(r_i / h_i) = r f'(r) / f(r) restores the
//! balance; C -> 1 beyond ~2 h and C ~ 2 (r/h)^2 at the axis, so the hoop term stays finite.
//! Energy is still conserved exactly: the momentum and energy hoop terms use the same H_i and
//! cancel particle by particle.
class AxisCorrection {
 public:
  explicit AxisCorrection(cases::Kernel kernel);
  //! C(r / h) for r >= 0 (linear interpolation in a table built once).
  [[nodiscard]] double operator()(double r, double h) const {
    const double s = r / h * inv_;
    if (s >= static_cast<double>(table_.size() - 1)) return 1.0;
    const auto k = static_cast<std::size_t>(s);
    const double f = s - static_cast<double>(k);
    return table_[k] + f * (table_[k + 1] - table_[k]);
  }

 private:
  double inv_ = 0.0;  // 1 / table step
  std::vector<double> table_;
};

}  // namespace hvi::sph::detail
