//! @file Release isentrope of a general EOS, tabulated by adaptive Dormand-Prince (internal).
#pragma once
#include <vector>

#include "hvi/eos/eos.hpp"

namespace hvi::verify::detail {

//! The isentrope through (rhoK, eK), followed in expansion. The independent variable is
//! sigma = ln(rhoK / rho) >= 0; along it de/dsigma = -P/rho (de = P/rho^2 drho) and the
//! velocity gained by a rarefaction, w = integral c/rho |drho| = integral c dsigma.
//!
//! The table ends where the material can no longer be expanded by a rarefaction:
//! - at the spall point, where the formula pressure reaches 0 for an EOS with tension cut-off
//!   (the free surface there has finite density and the physical sound speed of that state);
//! - in a polytropic tail when c has fallen below 1e-8 c_K (gas expanding to zero density):
//!   beyond the last node c ~ rho^k with k = dln c/dln rho of the last step, which is exact for
//!   an ideal gas and adds the remaining escape velocity c_m / k;
//! - at rho = rhoK / 2 for a material that carries tension (tension far beyond spall there).
class Isentrope {
 public:
  struct Point {
    double sigma = 0.0, rho = 0.0, e = 0.0;
    double w = 0.0;  //!< velocity gained from the start, cm/us
    double p = 0.0, c = 0.0;
  };

  Isentrope(const eos::Eos& eos, double rho, double e);

  [[nodiscard]] const Point& start() const { return nodes_.front(); }
  //! Last state reachable by expansion: spall point (P = 0, finite rho) or vacuum (rho = 0).
  [[nodiscard]] const Point& end() const { return end_; }
  //! The state where P = p, for end().p <= p <= start().p.
  [[nodiscard]] Point atPressure(double p) const;
  //! The state where w - c = q (the similarity coordinate of a fan, measured from the initial
  //! velocity), for -c_K <= q <= w_end - c_end. Monotone for a genuinely nonlinear EOS.
  [[nodiscard]] Point atWaveCoordinate(double q) const;
  [[nodiscard]] std::size_t size() const { return nodes_.size(); }

 private:
  struct Y {
    double e, w;
  };
  [[nodiscard]] Y rhs(double sigma, double e) const;
  //! One Dormand-Prince 5(4) step of length h from node `from`; err gets the embedded estimate.
  [[nodiscard]] Y step(const Point& from, double h, Y* err) const;
  [[nodiscard]] Point complete(double sigma, Y y) const;
  [[nodiscard]] Point at(double sigma) const;
  [[nodiscard]] Point tailAt(double sigma) const;
  template <class G>
  [[nodiscard]] Point solveMonotone(G&& g, double target) const;

  eos::Eos eos_;
  double rhoK_;
  std::vector<Point> nodes_;
  Point end_;
  bool tail_ = false;  //!< polytropic tail beyond the last node
  bool truncated_ = false;  //!< ends where c^2 <= 0 (a material that carries tension)
  double k_ = 0.0;     //!< its exponent dln c / dln rho
};

}  // namespace hvi::verify::detail
