//! @file Bisection on the failure flag for the critical diameter.
#include "hvi/shield/bisection.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace hvi::shield {

double CriticalDiameterSearch::round(double d) {
  const double e = std::pow(10.0, std::floor(std::log10(d)) - 4.0);
  return std::round(d / e) * e;
}

CriticalDiameterSearch::CriticalDiameterSearch(double low, double high, double tolerance,
                                               int maxWidenings)
    : low_(round(low)), high_(round(high)), tol_(tolerance), maxWidenings_(maxWidenings) {
  if (!(low > 0 && high > low && tolerance > 0 && tolerance < 1))
    throw std::invalid_argument(
        "critical-diameter search: need 0 < low < high and 0 < tolerance < 1");
}

std::optional<double> CriticalDiameterSearch::survived() const {
  std::optional<double> s;
  for (const auto& [d, f] : results_)
    if (!f && (!s || d > *s)) s = d;
  return s;
}

std::optional<double> CriticalDiameterSearch::failed() const {
  for (const auto& [d, f] : results_)  // ascending
    if (f) return d;
  return std::nullopt;
}

bool CriticalDiameterSearch::bracketed() const {
  const auto s = survived(), f = failed();
  return s && f && *s < *f;
}

std::optional<double> CriticalDiameterSearch::estimate() const {
  if (!bracketed()) return std::nullopt;
  return 0.5 * (*survived() + *failed());
}

bool CriticalDiameterSearch::narrowEnough() const {
  const double s = *survived(), f = *failed();
  // The next midpoint would round onto a bound: no finer answer exists at 5 digits.
  const double mid = round(0.5 * (s + f));
  return f - s <= tol_ * 0.5 * (s + f) || mid <= s || mid >= f;
}

std::vector<double> CriticalDiameterSearch::pending() const {
  if (done()) return {};
  std::vector<double> want;
  const auto s = survived(), f = failed();
  if (!s) {
    // Nothing survived yet: the low bound, halved once per failure below it.
    double d = low_;
    while (results_.count(d) && results_.at(d)) d = round(d / 2);
    want.push_back(d);
  }
  if (!f) {
    double d = high_;
    while (results_.count(d) && !results_.at(d)) d = round(d * 2);
    want.push_back(d);
  }
  if (s && f) {
    if (*s < *f) want.push_back(round(0.5 * (*s + *f)));
    // Non-monotone results (a failure below a survival): nothing more to ask; note() says so.
  }
  for (auto it = want.begin(); it != want.end();)
    it = results_.count(*it) ? want.erase(it) : it + 1;
  return want;
}

void CriticalDiameterSearch::record(double d, bool isFailed) {
  d = round(d);
  results_[d] = isFailed;
  if (isFailed && !survived() && d <= low_) {
    ++lowWidenings_;
    low_ = round(low_ / 2);
  }
  if (!isFailed && !failed() && d >= high_) {
    ++highWidenings_;
    high_ = round(high_ * 2);
  }
}

bool CriticalDiameterSearch::done() const {
  const auto s = survived(), f = failed();
  if (!s && lowWidenings_ > maxWidenings_) return true;
  if (!f && highWidenings_ > maxWidenings_) return true;
  if (s && f && *s > *f) return true;  // non-monotone
  return s && f && narrowEnough();
}

std::string CriticalDiameterSearch::note() const {
  const auto s = survived(), f = failed();
  if (!s && lowWidenings_ > maxWidenings_)
    return fmt::format("every diameter failed, down to {:.5g} cm", results_.begin()->first);
  if (!f && highWidenings_ > maxWidenings_)
    return fmt::format("every diameter survived, up to {:.5g} cm", results_.rbegin()->first);
  if (s && f && *s > *f)
    return fmt::format("not monotone: {:.5g} cm failed, {:.5g} cm survived", *f, *s);
  if (s && f) return fmt::format("bracket [{:.5g}, {:.5g}] cm", *s, *f);
  return "searching";
}

int CriticalDiameterSearch::remainingEstimate() const {
  if (done()) return 0;
  const auto s = survived(), f = failed();
  if (!s || !f) {
    // Unknown bounds, then bisection over the start bracket.
    const double width = (high_ - low_) / (0.5 * (high_ + low_));
    return (!s) + (!f) + static_cast<int>(std::ceil(std::log2(std::max(width / tol_, 1.0))));
  }
  const double width = (*f - *s) / (0.5 * (*f + *s));
  return std::max(1, static_cast<int>(std::ceil(std::log2(width / tol_))));
}

}  // namespace hvi::shield
