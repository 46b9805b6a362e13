//! @file The critical projectile diameter at one speed, by bisection on the rear wall's
//! failure flag (docs/shield.md, "hvi ballistic-limit").
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hvi::shield {

//! Finds d_c with failed(d) = (d >= d_c), assumed monotone: a bracket [survived, failed] is
//! narrowed until its width is at most `tolerance` times its midpoint. A start bracket that does
//! not bracket is widened (survived bound halved, failed bound doubled) up to `maxWidenings`
//! times each way. Diameters are rounded to 5 significant digits (so that a diameter names one
//! run, and a resumed search asks for the same runs).
class CriticalDiameterSearch {
 public:
  CriticalDiameterSearch(double low, double high, double tolerance, int maxWidenings = 3);

  //! Diameters whose results the search needs now (up to two at the start, then one), not yet
  //! recorded. Empty when done.
  [[nodiscard]] std::vector<double> pending() const;
  void record(double diameter, bool failed);
  [[nodiscard]] bool done() const;

  //! Bracketed: largest survived below smallest failed. Else the reason in `note`.
  [[nodiscard]] bool bracketed() const;
  [[nodiscard]] std::optional<double> survived() const;  //!< largest diameter that survived
  [[nodiscard]] std::optional<double> failed() const;    //!< smallest diameter that failed
  [[nodiscard]] std::optional<double> estimate() const;  //!< bracket midpoint
  [[nodiscard]] std::string note() const;
  //! Runs the search may still ask for (bisection steps left plus unknown bounds); for the ETA.
  [[nodiscard]] int remainingEstimate() const;
  [[nodiscard]] const std::map<double, bool>& results() const { return results_; }

  static double round(double d);

 private:
  [[nodiscard]] bool narrowEnough() const;
  double low_, high_, tol_;
  int maxWidenings_, lowWidenings_ = 0, highWidenings_ = 0;
  std::map<double, bool> results_;
};

}  // namespace hvi::shield
