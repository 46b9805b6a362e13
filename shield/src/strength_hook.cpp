//! @file Strength and fracture for shield scenes: the single place to change when issue 15
//! lands (docs/shield.md, "Strength").
#include "strength_hook.hpp"

#include "hvi/cases/effects.hpp"

namespace hvi::shield::detail {

std::vector<std::string> strengthEffects(cases::SolverKind solver) {
  // Looked up by name so that this file builds before and after the effects exist: once the
  // effect table names them and the solver supports them, every shield scene asks for them.
  // SPH supports strength, but the material keys it needs are not written yet
  // (strengthMaterialKeys below, docs/strength.md Open item 4): until then SPH shield scenes
  // stay hydrodynamic rather than name an effect no material table feeds.
  if (solver == cases::SolverKind::Sph) return {};
  std::vector<std::string> on;
  for (const char* name : {"strength", "fracture"}) {
    const auto e = cases::effectFromString(name);
    if (e && cases::supports(solver, *e)) on.emplace_back(name);
  }
  return on;
}

std::string strengthMaterialKeys(const ShieldMaterial& m, bool strengthOn) {
  // When issue 15 lands: write here the keys its [materials.*] tables take for m (a strength
  // preset named after m.name, or the yield stress m.yieldMpa, shear modulus, spall strength),
  // e.g. return fmt::format("strength_preset = \"{}\"\n", m.name). Until then nothing: the
  // scene carries only the hydrodynamic EOS.
  (void)m;
  (void)strengthOn;
  return {};
}

}  // namespace hvi::shield::detail
