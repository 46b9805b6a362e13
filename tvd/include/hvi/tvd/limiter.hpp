//! @file Scalar limiter functions g(a, b) of Harten-Yee's upwind TVD modified-flux scheme.
#pragma once
#include <algorithm>
#include <cmath>

namespace hvi::tvd {

// Each limiter maps the characteristic jumps a = alpha_{j-1/2}, b = alpha_{j+1/2} on both sides
// of cell j to the limited jump g_j (Yee 1989, NASA TM-101088, eqs. 4.35-4.37). All three are
// symmetric in (a, b) and odd, so the scheme keeps mirror symmetry exactly in floating point.

//! Most dissipative: the smaller jump when both have one sign, else 0.
struct Minmod {
  static constexpr const char* name = "minmod";
  static double g(double a, double b) {
    // Branch-free form of (a b > 0 ? (|a| < |b| ? a : b) : 0).
    const double s = std::copysign(1.0, a);
    return s * std::max(0.0, std::min(std::abs(a), s * b));
  }
};

//! Harmonic mean of the two jumps (smooth, between minmod and superbee).
struct VanLeer {
  static constexpr const char* name = "van_leer";
  static double g(double a, double b) {
    // Selects instead of branching (same values), so that loops over cells vectorise.
    const double ab = a * b;
    const bool same = ab > 0.0;
    const double mean = 2.0 * ab / (same ? a + b : 1.0);
    return same ? mean : 0.0;
  }
};

//! Most compressive: steepens contacts, can square smooth extrema.
struct Superbee {
  static constexpr const char* name = "superbee";
  static double g(double a, double b) {
    // Selects instead of branching (same values), so that loops over cells vectorise.
    const bool same = a * b > 0.0;
    const double fa = std::abs(a), fb = std::abs(b);
    const double m = std::max(std::min(2.0 * fa, fb), std::min(fa, 2.0 * fb));
    const double signedM = a > 0.0 ? m : -m;
    return same ? signedM : 0.0;
  }
};

}  // namespace hvi::tvd
