//! @file EOS presets and helpers common to every EOS.
#include <cmath>
#include <stdexcept>

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

double energyForPressure(const Eos& eos, double rho, double p) {
  // P is increasing in e for every EOS here (dP/de > 0 away from the cut-off), so bracket and
  // bisect with Newton steps where they stay inside the bracket.
  double lo = 0.0, hi = 1.0;
  auto f = [&](double e) { return pressure(eos, rho, e) - p; };
  if (f(lo) > 0.0) {
    lo = -1.0;
    while (f(lo) > 0.0 && lo > -1e6) lo *= 2.0;
  }
  while (f(hi) < 0.0 && hi < 1e12) hi *= 2.0;
  double e = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const double fe = f(e);
    if (fe > 0.0) hi = e; else lo = e;
    const EosState s = state(eos, rho, e);
    double next = (s.dPdE > 0.0) ? e - fe / s.dPdE : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - e) <= 1e-15 * std::max(1.0, std::abs(e))) return next;
    e = next;
  }
  return e;
}

Tillotson aluminiumStudy() { return Tillotson{}; }

}  // namespace hvi::eos
