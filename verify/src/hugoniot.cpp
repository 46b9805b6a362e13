//! @file Shock state on the Hugoniot of a general EOS by a bracketed 1-D root find in density.
#include "hugoniot.hpp"

#include <cmath>
#include <fmt/format.h>

#include "root_find.hpp"

namespace hvi::verify::detail {

ShockState shockState(const eos::Eos& eos, double rhoK, double eK, double pK, double cK,
                      double p) {
  const double vK = 1.0 / rhoK;
  auto energy = [&](double rho) { return eK + 0.5 * (p + pK) * (vK - 1.0 / rho); };
  auto h = [&](double rho) { return eos::pressure(eos, rho, energy(rho)) - p; };
  // Acoustic estimate of the compression, doubled until the Hugoniot pressure exceeds p.
  double x = std::min(0.5, 2.0 * (p - pK) / (rhoK * std::max(cK * cK, 1e-300)));
  if (!(x > 0.0)) x = 1e-12;
  double hHi = h(rhoK * (1.0 + x));
  while (!(hHi > 0.0)) {
    x *= 2.0;
    if (x > 1e4) {
      throw SimulationError(fmt::format(
          "verify: no Hugoniot state reaches P = {} from rho {}, e {}, P {}", p, rhoK, eK, pK));
    }
    hHi = h(rhoK * (1.0 + x));
  }
  ShockState s;
  s.rho = brent(h, rhoK, rhoK * (1.0 + x), h(rhoK), hHi, 0.0, "Hugoniot density");
  s.e = energy(s.rho);
  const double dv = vK - 1.0 / s.rho;
  if (dv > 0.0 && p > pK) {
    s.massFlux = std::sqrt((p - pK) / dv);
    s.du = std::sqrt((p - pK) * dv);
  } else {  // vanishing shock: the acoustic limit
    s.massFlux = rhoK * cK;
    s.du = 0.0;
  }
  return s;
}

}  // namespace hvi::verify::detail
