//! @file EOS presets and helpers common to every EOS.
#include <cmath>
#include <limits>
#include <fmt/format.h>

#include "hvi/common/error.hpp"
#include "hvi/eos/eos.hpp"

namespace hvi::eos {

std::string kindName(const Eos& eos) {
  struct V {
    std::string operator()(const Tillotson&) const { return "tillotson"; }
    std::string operator()(const IdealGas&) const { return "ideal_gas"; }
    std::string operator()(const MieGruneisen&) const { return "mie_gruneisen"; }
  };
  return std::visit(V{}, eos);
}

double lowestSpecificEnergy(const Eos& eos) {
  if (std::holds_alternative<IdealGas>(eos)) return 0.0;
  return -std::numeric_limits<double>::infinity();
}

namespace {

bool carriesTension(const Eos& eos) {
  if (const auto* t = std::get_if<Tillotson>(&eos)) return !t->tensionCutoff;
  if (const auto* m = std::get_if<MieGruneisen>(&eos)) return !m->tensionCutoff;
  return false;
}

}  // namespace

double energyForPressure(const Eos& eos, double rho, double p) {
  if (!(rho > 0.0) || !std::isfinite(p) || (p < 0.0 && !carriesTension(eos))) {
    throw InputError(fmt::format(
        "energyForPressure: no {} state at rho {} with P = {} (needs rho > 0, and P >= 0 for a "
        "material that carries no tension)",
        kindName(eos), rho, p));
  }
  // P is increasing in e above lowestSpecificEnergy for every EOS here (dP/de > 0 there; 0 only
  // where the cut-off holds P at 0), so bracket there, then bisect with Newton steps that stay
  // inside the bracket.
  auto f = [&](double e) { return pressure(eos, rho, e) - p; };
  auto noState = [&] {
    return InputError(fmt::format("energyForPressure: no {} state at rho {} reaches P = {}",
                                  kindName(eos), rho, p));
  };
  double lo = 0.0, hi = 1.0;
  if (f(lo) > 0.0) {
    // Below e = 0: the ideal gas has no states; Tillotson (linear below its cold reference) and
    // Mie-Gruneisen have no lower bound, so walk outwards, doubling.
    if (lowestSpecificEnergy(eos) == 0.0) throw noState();
    for (int k = 0; f(lo) > 0.0; ++k) {
      if (k > 1100) throw noState();
      hi = lo;
      lo = -std::ldexp(1.0, k);
    }
  } else {
    while (f(hi) < 0.0) {
      if (hi > 1e12) throw noState();
      lo = hi;
      hi *= 2.0;
    }
  }
  double e = 0.5 * (lo + hi);
  for (int it = 0; it < 400; ++it) {
    const double fe = f(e);
    if (fe == 0.0) return e;
    if (fe > 0.0) hi = e; else lo = e;
    const EosState s = state(eos, rho, e);
    double next = (s.dPdE > 0.0) ? e - fe / s.dPdE : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double tol = 1e-15 * std::max(1.0, std::abs(e));
    if (std::abs(next - e) <= tol || hi - lo <= tol) return next;
    e = next;
  }
  return e;
}

Tillotson aluminiumStudy() { return Tillotson{}; }

}  // namespace hvi::eos
