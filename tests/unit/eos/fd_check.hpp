//! @file Central finite-difference check of an EOS's analytic derivatives (test helper).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hvi/eos/state.hpp"

namespace hvi::eos::test {

// Central differences with relative step h = 1e-6: truncation error h^2/6 |f'''| x^2 ~ 1e-13
// relative for these smooth formulas; round-off eps |T| / (h x) ~ 1e-10 of T/x, where T bounds
// the magnitude of the terms summed in P (cancellation between them is what round-off sees).
// The tolerance 1e-7 (|dP/dx| + T/x) therefore has three orders of margin on both errors while
// any wrong term in an analytic derivative (an O(1) relative error) still fails it.
constexpr double kFdStep = 1e-6;
constexpr double kFdTol = 1e-7;

template <class F>
void expectDerivativesMatchFd(F&& stateAt, double rho, double e, double termScale,
                              const char* where) {
  const EosState s = stateAt(rho, e);
  const double hr = kFdStep * rho;
  const double he = kFdStep * std::max(std::abs(e), 1e-3);
  const double fdRho = (stateAt(rho + hr, e).pressure - stateAt(rho - hr, e).pressure) / (2 * hr);
  const double fdE = (stateAt(rho, e + he).pressure - stateAt(rho, e - he).pressure) / (2 * he);
  EXPECT_NEAR(s.dPdRho, fdRho, kFdTol * (std::abs(fdRho) + termScale / rho))
      << where << " rho " << rho << " e " << e;
  EXPECT_NEAR(s.dPdE, fdE, kFdTol * (std::abs(fdE) + termScale / std::max(std::abs(e), 1e-3)))
      << where << " rho " << rho << " e " << e;
}

}  // namespace hvi::eos::test
