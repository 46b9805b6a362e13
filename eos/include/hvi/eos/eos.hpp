//! @file One EOS interface for both solvers: a closed variant, dispatched once per material.
#pragma once
#include <algorithm>
#include <string>
#include <variant>

#include "hvi/eos/ideal_gas.hpp"
#include "hvi/eos/mie_gruneisen.hpp"
#include "hvi/eos/state.hpp"
#include "hvi/eos/tillotson.hpp"

namespace hvi::eos {

static_assert(EquationOfState<IdealGas>);
static_assert(EquationOfState<Tillotson>);
static_assert(EquationOfState<MieGruneisen>);

//! Solvers call std::visit once per material outside their hot loops, so the loop body sees the
//! concrete type and inlines it; no virtual call per particle or cell.
using Eos = std::variant<Tillotson, IdealGas, MieGruneisen>;

inline double pressure(const Eos& eos, double rho, double e) {
  return std::visit([&](const auto& m) { return m.pressure(rho, e); }, eos);
}
inline EosState state(const Eos& eos, double rho, double e) {
  return std::visit([&](const auto& m) { return m.state(rho, e); }, eos);
}
inline double referenceDensity(const Eos& eos) {
  return std::visit([](const auto& m) { return m.referenceDensity(); }, eos);
}

//! Phase bookkeeping (effect phase_bookkeeping) at specific energy e: the Tillotson phase from e
//! against the incipient (e1) and full (e2) vaporisation energies and the vapour fraction
//! (e - e1) / (e2 - e1) clamped to [0, 1]. The other EOS model no vaporisation: solid, 0.
//! The one definition both solvers' snapshots use.
struct PhaseState {
  double vapourFraction = 0.0;
  Phase phase = Phase::Solid;
};
inline PhaseState phaseState(const Eos& eos, double e) {
  const auto* t = std::get_if<Tillotson>(&eos);
  if (t == nullptr) return {};
  return {std::clamp((e - t->e1) / (t->e2 - t->e1), 0.0, 1.0), t->phase(e)};
}

//! "tillotson", "ideal_gas" or "mie_gruneisen".
std::string kindName(const Eos& eos);

//! Lowest specific energy a state can have: 0 for the ideal gas; unbounded for Mie-Gruneisen
//! (energies below its reference curve) and Tillotson (linear in e below its cold reference
//! state, docs/eos.md).
double lowestSpecificEnergy(const Eos& eos);

//! Specific energy e such that P(rho, e) = p, by bracketed Newton iteration (monotone in e for
//! every EOS here where dP/de > 0). Used to set up initial states given a pressure.
//! Compressed Tillotson states below the cold curve get e < 0. With a cut-off, p = 0 returns the
//! lowest e with P > 0 beyond it.
//! Throws hvi::InputError for p < 0 in a material that carries no tension, and where no state
//! reaches p.
double energyForPressure(const Eos& eos, double rho, double p);

//! The study's aluminium (the table of spec section 2, docs/method.md), Tillotson with cut-off,
//! cm-g-us units.
Tillotson aluminiumStudy();

}  // namespace hvi::eos
