//! @file Release isentrope of a general EOS by adaptive Dormand-Prince 5(4) in ln(rhoK/rho).
#include "isentrope.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "eos_traits.hpp"
#include "root_find.hpp"
#include "hvi/common/stop_flag.hpp"

namespace hvi::verify::detail {
namespace {

// Dormand & Prince (1980) RK5(4)7M tableau.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                 b6 = 11.0 / 84;
// Difference between the 5th- and the embedded 4th-order weights.
constexpr double d1 = 71.0 / 57600, d3 = -71.0 / 16695, d4 = 71.0 / 1920, d5 = -17253.0 / 339200,
                 d6 = 22.0 / 525, d7 = -1.0 / 40;

// Local error per step relative to the state; the 5th-order solution is propagated, so the
// accepted error is that of the 4th-order estimate and the true local error is smaller still.
constexpr double kRelTol = 1e-13;
constexpr double kMaxStep = 0.05;      // keeps nodes dense enough to bracket every query
constexpr double kTailFraction = 1e-8; // c / c_K below which the gas tail is polytropic
constexpr std::size_t kMaxNodes = 2000000;

}  // namespace

Isentrope::Y Isentrope::rhs(double sigma, double e) const {
  const double rho = rhoK_ * std::exp(-sigma);
  const eos::EosState s = uncutState(eos_, rho, e);
  return {-s.pressure / rho, s.soundSpeed};
}

Isentrope::Y Isentrope::step(const Point& from, double h, Y* err) const {
  const double s = from.sigma, e = from.e;
  const Y k1 = rhs(s, e);
  const Y k2 = rhs(s + c2 * h, e + h * a21 * k1.e);
  const Y k3 = rhs(s + c3 * h, e + h * (a31 * k1.e + a32 * k2.e));
  const Y k4 = rhs(s + c4 * h, e + h * (a41 * k1.e + a42 * k2.e + a43 * k3.e));
  const Y k5 = rhs(s + c5 * h, e + h * (a51 * k1.e + a52 * k2.e + a53 * k3.e + a54 * k4.e));
  const Y k6 =
      rhs(s + h, e + h * (a61 * k1.e + a62 * k2.e + a63 * k3.e + a64 * k4.e + a65 * k5.e));
  Y y;
  y.e = e + h * (b1 * k1.e + b3 * k3.e + b4 * k4.e + b5 * k5.e + b6 * k6.e);
  y.w = from.w + h * (b1 * k1.w + b3 * k3.w + b4 * k4.w + b5 * k5.w + b6 * k6.w);
  if (err) {
    const Y k7 = rhs(s + h, y.e);
    err->e = h * (d1 * k1.e + d3 * k3.e + d4 * k4.e + d5 * k5.e + d6 * k6.e + d7 * k7.e);
    err->w = h * (d1 * k1.w + d3 * k3.w + d4 * k4.w + d5 * k5.w + d6 * k6.w + d7 * k7.w);
  }
  return y;
}

Isentrope::Point Isentrope::complete(double sigma, Y y) const {
  Point p;
  p.sigma = sigma;
  p.rho = rhoK_ * std::exp(-sigma);
  p.e = y.e;
  p.w = y.w;
  const eos::EosState s = uncutState(eos_, p.rho, p.e);
  p.p = s.pressure;
  p.c = s.soundSpeed;
  return p;
}

Isentrope::Isentrope(const eos::Eos& eos, double rho, double e) : eos_(eos), rhoK_(rho) {
  nodes_.push_back(complete(0.0, {e, 0.0}));
  const Point k = nodes_.front();
  const bool tension = carriesTension(eos_);
  if (!tension && k.p <= 0.0) {
    // Already at (or beyond) the spall point: no rarefaction can lower the pressure further.
    end_ = k;
    end_.p = 0.0;
    return;
  }
  if (!(k.c > 0.0)) {
    throw SimulationError(fmt::format(
        "verify: isentrope starts at a state with no sound speed (rho {}, e {}, P {})", rho, e,
        k.p));
  }
  // A material that carries tension is followed down to half its starting density, already
  // far beyond any real spall strength (Mie-Gruneisen copper reaches -1.4 Mbar there).
  const double sigmaMax = tension ? std::log(2.0) : 700.0;
  const double eScale = std::max({std::abs(e), std::abs(k.p) / rho, k.c * k.c});
  const double atolE = 1e-14 * eScale, atolW = 1e-14 * k.c;
  double h = 1e-3;
  for (long pass = 0;; ++pass) {
    // Bounded (sigma <= 700 in steps up to kMaxStep, ~1e4 nodes) but rejected steps can shrink h
    // to 1e-15 first: `hvi run` is told about a stop request every 1024 passes.
    if ((pass & 1023) == 1023) throwIfStopRequested("the exact Riemann solution (isentrope)");
    const Point last = nodes_.back();
    if (last.sigma >= sigmaMax) {
      end_ = last;
      return;
    }
    h = std::min({h, kMaxStep, sigmaMax - last.sigma});
    Y err{};
    const Y y = step(last, h, &err);
    const double scE = atolE + kRelTol * std::max(std::abs(last.e), std::abs(y.e));
    const double scW = atolW + kRelTol * std::max(std::abs(last.w), std::abs(y.w));
    const double ratio = std::max(std::abs(err.e) / scE, std::abs(err.w) / scW);
    if (!(ratio <= 1.0)) {  // also rejects NaN from a stage outside the EOS's domain
      h *= std::isfinite(ratio) ? std::max(0.1, 0.9 * std::pow(ratio, -0.2)) : 0.1;
      if (h < 1e-15) {
        throw SimulationError(fmt::format(
            "verify: isentrope from rho {}, e {} stalls at rho {}, e {}", rho, e, last.rho,
            last.e));
      }
      continue;
    }
    Point next = complete(last.sigma + h, y);
    if (!tension && next.p <= 0.0) {
      // Spall: locate where the formula pressure crosses zero inside this step.
      auto pAt = [&](double s) { return complete(s, step(last, s - last.sigma, nullptr)).p; };
      const double s0 = brent(pAt, last.sigma, next.sigma, last.p, next.p, 1e-15,
                              "isentrope spall density");
      end_ = complete(s0, step(last, s0 - last.sigma, nullptr));
      end_.p = 0.0;
      nodes_.push_back(end_);
      return;
    }
    if (!(next.c > 0.0) && tension && nodes_.size() > 1) {
      // A material that carries tension (Tillotson without the cut-off) leaves the EOS's
      // hyperbolic domain on the way down (aluminium near rho / rho0 = 0.57): the isentrope
      // ends at the last state with c > 0. Solutions that need lower pressures are refused by
      // the Riemann solver (atPressure beyond the end).
      end_ = last;
      truncated_ = true;
      return;
    }
    if (!(next.c > 0.0)) {
      throw SimulationError(fmt::format(
          "verify: release isentrope from rho {}, e {} loses hyperbolicity (c^2 <= 0) at rho {}, "
          "e {}, P {}",
          rho, e, next.rho, next.e, next.p));
    }
    nodes_.push_back(next);
    if (!tension && next.c < kTailFraction * k.c) {
      const Point& prev = nodes_[nodes_.size() - 2];
      k_ = std::log(prev.c / next.c) / (next.sigma - prev.sigma);
      if (!(k_ > 0.0)) {
        throw SimulationError("verify: gas tail of the isentrope is not polytropic");
      }
      tail_ = true;
      end_ = next;
      end_.sigma = std::numeric_limits<double>::infinity();
      end_.rho = 0.0;
      end_.e = 0.0;
      end_.w = next.w + next.c / k_;
      end_.p = 0.0;
      end_.c = 0.0;
      return;
    }
    if (nodes_.size() > kMaxNodes) {
      throw SimulationError("verify: isentrope needs too many steps");
    }
    h *= std::min(5.0, 0.9 * std::pow(std::max(ratio, 1e-10), -0.2));
  }
}

Isentrope::Point Isentrope::tailAt(double sigma) const {
  const Point& m = nodes_.back();
  const double d = sigma - m.sigma;
  Point p;
  p.sigma = sigma;
  p.rho = rhoK_ * std::exp(-sigma);
  p.c = m.c * std::exp(-k_ * d);
  p.w = m.w + (m.c - p.c) / k_;
  p.e = m.e * std::exp(-2.0 * k_ * d);
  p.p = uncutState(eos_, p.rho, p.e).pressure;
  return p;
}

Isentrope::Point Isentrope::at(double sigma) const {
  if (sigma <= 0.0) return nodes_.front();
  if (sigma >= nodes_.back().sigma) return tail_ ? tailAt(sigma) : nodes_.back();
  auto it = std::upper_bound(nodes_.begin(), nodes_.end(), sigma,
                             [](double s, const Point& p) { return s < p.sigma; });
  const Point& from = *(it - 1);
  if (sigma == from.sigma) return from;
  return complete(sigma, step(from, sigma - from.sigma, nullptr));
}

template <class G>
Isentrope::Point Isentrope::solveMonotone(G&& g, double target) const {
  // g(point) increases along the isentrope; find the first node past the target, then refine
  // inside that step (a partial step from the node below is as accurate as the full one).
  if (target <= g(nodes_.front())) return nodes_.front();
  auto it = std::lower_bound(nodes_.begin(), nodes_.end(), target,
                             [&](const Point& p, double t) { return g(p) < t; });
  double lo, hi;
  if (it == nodes_.end()) {
    if (!tail_ || target >= g(end_)) return end_;
    lo = nodes_.back().sigma;
    hi = lo + 1.0;
    while (g(tailAt(hi)) < target && hi < 740.0) hi = lo + 2.0 * (hi - lo);
    if (hi >= 740.0) return end_;
  } else {
    if (g(*it) == target) return *it;
    hi = it->sigma;
    lo = (it - 1)->sigma;
  }
  auto f = [&](double s) { return g(at(s)) - target; };
  const double s = brent(f, lo, hi, 1e-15, "isentrope state");
  return at(s);
}

Isentrope::Point Isentrope::atPressure(double p) const {
  if (truncated_ && p < end_.p) {
    throw SimulationError(fmt::format(
        "verify: the release isentrope from rho {} ends where the EOS loses hyperbolicity (rho "
        "{}, P {}); the solution needs P = {} (add the tension cut-off)",
        rhoK_, end_.rho, end_.p, p));
  }
  return solveMonotone([](const Point& q) { return -q.p; }, -p);
}

Isentrope::Point Isentrope::atWaveCoordinate(double q) const {
  return solveMonotone([](const Point& x) { return x.w - x.c; }, q);
}

}  // namespace hvi::verify::detail
