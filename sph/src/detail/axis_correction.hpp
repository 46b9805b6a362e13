//! @file Hoop-term correction near the r-z axis for the kernel's bias with mirror ghosts.
#pragma once
#include <cmath>
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

namespace hvi::sph::detail {

//! The symmetric r-z form (docs/sph-rz.md, "Symmetric ring weights"): the density of ring k is
//! rho_k = sum_j m_j W_kj / (2 pi s_k s_j), whose pair weight |r_j| / (s_k s_j) averages to
//! exactly 1 over the kernel (mirror ghosts included) when
//!   s(r) = E[ |r + X| / s(|r + X|) ],   X ~ the kernel's x-marginal,
//! the fixed point tabulated here: s = sqrt(h) sigma(r / h), sigma(u) ~ sqrt(u) far from the
//! axis, sigma'(0) = 0 at it. The same average makes the axial and radial pair sums consistent
//! at the axis, with no correction factor.
class RingScale {
 public:
  explicit RingScale(cases::Kernel kernel);
  //! s(r) and ds/dr for r >= 0 (cm^(1/2), cm^(-1/2)).
  [[nodiscard]] double value(double r, double h) const {
    return std::sqrt(h) * lookup(sigma_, r / h, false);
  }
  [[nodiscard]] double slope(double r, double h) const {
    return lookup(dsigma_, r / h, true) / std::sqrt(h);
  }
  //! kappa, the share of the viscous pair coefficient in the hoop term (docs/sph-rz.md, "The
  //! viscous hoop"; sph.rz_viscous_hoop): 0 in the shared tables, set in a stepper's own copy.
  double viscousHoop = 0.0;

 private:
  [[nodiscard]] double lookup(const std::vector<double>& t, double u, bool derivative) const {
    const double s = u * inv_;
    if (s >= static_cast<double>(t.size() - 1)) {
      // sqrt(u) (1 - V / (16 u^2)): the fixed point's expansion in h / r (V = Var X).
      const double c = var_ / 16.0;
      return derivative ? 0.5 / std::sqrt(u) + 1.5 * c / (u * u * std::sqrt(u))
                        : std::sqrt(u) * (1.0 - c / (u * u));
    }
    const auto k = static_cast<std::size_t>(s);
    const double f = s - static_cast<double>(k);
    return t[k] + f * (t[k + 1] - t[k]);
  }
  double inv_ = 0.0;
  double var_ = 0.0;
  std::vector<double> sigma_, dsigma_;
};

//! The table of each kernel, built once per process (thread-safe static).
const RingScale& ringScale(cases::Kernel kernel);

}  // namespace hvi::sph::detail
