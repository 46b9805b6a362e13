//! @file Brent's bracketed root finder, shared by the exact solutions (internal).
#pragma once
#include <cmath>
#include <limits>
#include <string>

#include "hvi/common/error.hpp"

namespace hvi::verify::detail {

//! Root of f in [a, b] where f(a) and f(b) differ in sign (or one is zero). Brent's method:
//! inverse quadratic / secant steps, safeguarded by bisection, so it converges for any continuous
//! f and superlinearly near a simple root. Stops when the bracket is below
//! 4 eps |x| + absTol. `what` names the quantity in the error message.
template <class F>
double brent(F&& f, double a, double b, double fa, double fb, double absTol, const char* what,
             int maxIter = 300) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  if ((fa > 0.0) == (fb > 0.0)) {
    throw SimulationError(std::string("verify: root of ") + what + " is not bracketed");
  }
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < maxIter; ++it) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * eps * std::abs(b) + 0.5 * absTol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qq = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q; else p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += (std::abs(d) > tol) ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  throw SimulationError(std::string("verify: root of ") + what + " did not converge");
}

template <class F>
double brent(F&& f, double a, double b, double absTol, const char* what) {
  return brent(f, a, b, f(a), f(b), absTol, what);
}

}  // namespace hvi::verify::detail
