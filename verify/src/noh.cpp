//! @file Exact Noh implosion: stagnant shocked core inside a converging cold stream.
#include "hvi/verify/noh.hpp"

#include <cmath>
#include <fmt/format.h>

#include "hvi/common/error.hpp"

namespace hvi::verify {
namespace {

void check(const NohSolution& s) {
  if (!(s.gamma > 1.0) || !(s.rho0 > 0.0) || !(s.u0 > 0.0) || s.n < 0 || s.n > 2) {
    throw InputError(fmt::format(
        "NohSolution: gamma {} (> 1), rho0 {} (> 0), u0 {} (> 0), n {} (0, 1 or 2) out of range",
        s.gamma, s.rho0, s.u0, s.n));
  }
}

}  // namespace

double NohSolution::shockRadius(double t) const {
  check(*this);
  return 0.5 * (gamma - 1.0) * u0 * t;
}

NohSample NohSolution::sample(double r, double t) const {
  check(*this);
  NohSample s;
  if (t <= 0.0) {  // before the implosion starts: the uniform cold stream
    return NohSample{rho0, -u0, 0.0, 0.0};
  }
  if (r < shockRadius(t)) {
    // Shocked gas at rest: the stream's kinetic energy u0^2/2 per unit mass is all internal.
    s.rho = rho0 * std::pow((gamma + 1.0) / (gamma - 1.0), n + 1);
    s.u = 0.0;
    s.e = 0.5 * u0 * u0;
    s.p = (gamma - 1.0) * s.rho * s.e;
  } else {
    // Cold stream: geometric convergence piles it up as (1 + u0 t / r)^n.
    s.rho = rho0 * std::pow(1.0 + u0 * t / r, n);
    s.u = -u0;
    s.e = 0.0;
    s.p = 0.0;
  }
  return s;
}

}  // namespace hvi::verify
