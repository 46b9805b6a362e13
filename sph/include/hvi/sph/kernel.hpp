//! @file Smoothing kernels in 2-D: truncated Gaussian (the study's) and the M4 cubic spline.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace hvi::sph {

//! exp(-x) for 0 <= x <= 9 (the Gaussian kernel's range), inlinable into the pair loops where
//! the libm call was a fifth of the run time. Range reduction x = n ln2 - r with a two-part
//! ln2, degree-13 Taylor polynomial on |r| <= ln2/2 (truncation < 2e-17), exact scaling by
//! 2^-n: within 2 ulp of std::exp (tested).
inline double expNegative(double x) {
  constexpr double ln2hi = 6.93147180369123816490e-01;  // high bits of ln 2, exact n*ln2hi
  constexpr double ln2lo = 1.90821492927058770002e-10;
  constexpr double invLn2 = 1.44269504088896338700e+00;
  // x >= 0, so truncation rounds to nearest here (and compiles to one instruction, unlike
  // nearbyint on baseline x86-64).
  const int ni = static_cast<int>(x * invLn2 + 0.5);
  const double n = ni;
  const double r = (n * ln2hi - x) + n * ln2lo;  // -x = -n ln2 + r, |r| <= ln2 / 2
  // Estrin's scheme: a depth-4 tree instead of a 13-step Horner chain, whose latency (not
  // its arithmetic) dominated the pair loop.
  const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const double a0 = 1.0 + r, a1 = 0.5 + r * (1.0 / 6.0);
  const double a2 = 1.0 / 24.0 + r * (1.0 / 120.0), a3 = 1.0 / 720.0 + r * (1.0 / 5040.0);
  const double a4 = 1.0 / 40320.0 + r * (1.0 / 362880.0);
  const double a5 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0);
  const double a6 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
  const double b0 = a0 + a1 * r2, b1 = a2 + a3 * r2, b2 = a4 + a5 * r2;
  const double d0 = b0 + b1 * r4, d1 = b2 + a6 * r4;
  const double p = d0 + d1 * r8;
  const auto scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - ni) << 52);
  return p * scale;
}

//! Gaussian of spec section 3 (docs/method.md), W ~ exp(-(r/h)^2) / (pi h^2) cut at r = 3h,
//! with a small quadratic subtracted so that W and dW/dr both vanish at the cut:
//!   W = (exp(-q^2) - exp(-9) (10 - q^2)) / (pi h^2 (1 - 50.5 exp(-9))),  q = r/h < 3;  0 beyond.
//! The plain cut jumps by exp(-9) W(0) at 3h (and its gradient by 6 exp(-9) W(0) / h). On a
//! square lattice with h = dx the (3, 0) neighbours sit exactly there, so round-off in their
//! distance flips a finite term in and out of the sums: a free plate then drifts at 1e-5 cm/us
//! instead of staying at rest, and a mirror-symmetric impact loses its symmetry at 1e-6. The
//! correction changes the shape by at most 1.2e-3 W(0); the factor restores unit integral.
//! docs/sph.md.
struct GaussianKernel {
  static constexpr double support = 3.0;  //!< cut-off radius in units of h
  static constexpr const char* name = "gaussian";
  static constexpr double tail = 1.2340980408667956e-4;  //!< exp(-9)
  static constexpr double norm = 1.0 / (std::numbers::pi * (1.0 - 50.5 * tail));

  //! W from the squared distance r2 (cm^2) and pair smoothing length h (cm); 1/cm^2.
  static double value(double r2, double h) { return value(r2, h, 1.0 / (h * h)); }
  //! Same with ih2 = 1 / h^2 given (the pair loops reuse it and save a division per pair).
  static double value(double r2, double /*h*/, double ih2) {
    const double q2 = r2 * ih2;
    if (q2 >= support * support) return 0.0;
    return (expNegative(q2) - tail * (10.0 - q2)) * norm * ih2;
  }
  //! F = (1/r) dW/dr, so that grad_i W_ij = F (x_i - x_j):
  //! F = -2 (exp(-q^2) - exp(-9)) norm / h^4 = -2 (W + exp(-9) (9 - q^2) norm / h^2) / h^2,
  //! so the stepper reuses a cached W without a second exponential.
  static double gradFactor(double w, double r2, double h) {
    return gradFactor(w, r2, h, 1.0 / (h * h));
  }
  static double gradFactor(double w, double r2, double /*h*/, double ih2) {
    return -2.0 * ih2 * (w + tail * (9.0 - r2 * ih2) * norm * ih2);
  }
};

//! Monaghan-Lattanzio M4 cubic spline in 2-D, support 2h, sigma = 10 / (7 pi h^2).
struct CubicSplineKernel {
  static constexpr double support = 2.0;
  static constexpr const char* name = "cubic_spline";

  static double value(double r2, double h, double /*ih2*/) { return value(r2, h); }
  static double gradFactor(double w, double r2, double h, double /*ih2*/) {
    return gradFactor(w, r2, h);
  }
  static double value(double r2, double h) {
    const double q = std::sqrt(r2) / h;
    const double sigma = 10.0 / (7.0 * std::numbers::pi * h * h);
    if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) {
      const double t = 2.0 - q;
      return sigma * 0.25 * t * t * t;
    }
    return 0.0;
  }
  static double gradFactor(double /*w*/, double r2, double h) {
    const double r = std::sqrt(r2);
    const double q = r / h;
    const double sigma = 10.0 / (7.0 * std::numbers::pi * h * h);
    // dW/dr / r; the q < 1 branch is written without dividing by r so that r -> 0 is finite.
    if (q < 1.0) return sigma * (-3.0 + 2.25 * q) / (h * h);
    if (q < 2.0) {
      const double t = 2.0 - q;
      return -sigma * 0.75 * t * t / (h * r);
    }
    return 0.0;
  }
};

}  // namespace hvi::sph
