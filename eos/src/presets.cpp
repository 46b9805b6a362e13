//! @file EOS presets and helpers common to every EOS.
#include <cmath>
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

namespace {

// Lowest specific energy where the EOS is increasing in e, and whether it can carry tension.
// Tillotson carries no thermal pressure below e = 0 (P(rho, e < 0) = P(rho, 0), tillotson.cpp),
// so a pressure below its cold curve P(rho, 0) has no state.
struct EnergyDomain {
  double eMin;
  bool tension;
};
EnergyDomain energyDomain(const Eos& eos, double rho) {
  struct V {
    double rho;
    EnergyDomain operator()(const Tillotson& t) const {
      return {0.0, !t.tensionCutoff};
    }
    EnergyDomain operator()(const IdealGas&) const { return {0.0, false}; }
    EnergyDomain operator()(const MieGruneisen& m) const { return {-1e300, !m.tensionCutoff}; }
  };
  return std::visit(V{rho}, eos);
}

}  // namespace

double energyForPressure(const Eos& eos, double rho, double p) {
  const EnergyDomain dom = energyDomain(eos, rho);
  if (!(rho > 0.0) || !std::isfinite(p) || (p < 0.0 && !dom.tension)) {
    throw InputError(fmt::format(
        "energyForPressure: no {} state at rho {} with P = {} (needs rho > 0, and P >= 0 for a "
        "material that carries no tension)",
        kindName(eos), rho, p));
  }
  // P is increasing in e on (eMin, inf) for every EOS here (dP/de > 0 there; 0 only where the
  // cut-off holds P at 0), so bracket inside that interval, then bisect with Newton steps that
  // stay inside the bracket.
  auto f = [&](double e) { return pressure(eos, rho, e) - p; };
  auto noState = [&] {
    return InputError(fmt::format("energyForPressure: no {} state at rho {} reaches P = {}",
                                  kindName(eos), rho, p));
  };
  double lo = 0.0, hi = 1.0;
  if (f(lo) > 0.0) {
    if (dom.eMin == 0.0) throw noState();  // below the cold curve
    // Walk down: halving the gap to eMin (where the Tillotson formula falls to -inf), or
    // doubling outwards when the formula has no lower bound in e.
    const bool bounded = dom.eMin > -1e300;
    for (int k = 0; f(lo) > 0.0; ++k) {
      if (k > 1100) throw noState();
      hi = lo;
      lo = bounded ? dom.eMin * (1.0 - std::ldexp(1.0, -k - 1)) : -std::ldexp(1.0, k);
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
