//! @file The effect table and the resolution of a scene's materials.
#include "hvi/cases/effects.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::cases {
namespace {
constexpr std::array<EffectInfo, 9> kEffects{{
    {Effect::ArtificialViscosity, "artificial_viscosity", "Monaghan viscosity"},
    {Effect::TensionCutoff, "tension_cutoff", "P = 0 in tension (Tillotson, Mie-Gruneisen)"},
    {Effect::MassAdjustment, "mass_adjustment",
     "modified SPH mass iteration (absent: traditional SPH)"},
    {Effect::PhaseBookkeeping, "phase_bookkeeping", "solid / partly vaporised / vapour fractions"},
    {Effect::EnergyBudget, "energy_budget", "kinetic / internal / total energy per step"},
    {Effect::MaterialInterfaces, "material_interfaces", "marker lines between objects"},
    {Effect::Features, "features", "debris-cloud features at each snapshot"},
    {Effect::Strength, "strength",
     "elastic-plastic solids: deviatoric stress, yield, plastic work (docs/strength.md)"},
    {Effect::Fracture, "fracture",
     "spall strength instead of the zero cut-off, tensile / ductile damage (docs/strength.md)"},
}};

// What each solver implements, in the order its messages list them.
constexpr std::array kSph{Effect::ArtificialViscosity, Effect::TensionCutoff,
                          Effect::MassAdjustment,      Effect::PhaseBookkeeping,
                          Effect::EnergyBudget,        Effect::Features,
                          Effect::Strength,            Effect::Fracture};
constexpr std::array kTvd{Effect::TensionCutoff,    Effect::MaterialInterfaces,
                          Effect::PhaseBookkeeping, Effect::EnergyBudget,
                          Effect::Features,         Effect::Strength,
                          Effect::Fracture};
constexpr std::array kRiemann{Effect::EnergyBudget};  // the exact solution has no physics to add
}  // namespace

std::span<const EffectInfo> effectTable() { return kEffects; }

std::string_view toString(Effect e) {
  for (const auto& row : kEffects)
    if (row.effect == e) return row.name;
  return "?";
}
std::optional<Effect> effectFromString(std::string_view s) {
  for (const auto& row : kEffects)
    if (row.name == s) return row.effect;
  return std::nullopt;
}
std::vector<std::string_view> allEffectNames() {
  std::vector<std::string_view> v;
  for (const auto& row : kEffects) v.push_back(row.name);
  return v;
}

std::span<const Effect> supportedEffects(SolverKind s) {
  switch (s) {
    case SolverKind::Sph:
      return kSph;
    case SolverKind::Tvd:
      return kTvd;
    case SolverKind::Riemann:
      return kRiemann;
  }
  return {};
}
bool supports(SolverKind s, Effect e) {
  const auto v = supportedEffects(s);
  return std::find(v.begin(), v.end(), e) != v.end();
}

double bulkSoundSpeed(const eos::Eos& e) {
  if (const auto* t = std::get_if<eos::Tillotson>(&e)) return std::sqrt(t->A / t->rho0);
  if (const auto* g = std::get_if<eos::MieGruneisen>(&e)) return g->c0;
  return 0.0;  // a gas: no cold curve
}

std::vector<Material> resolveMaterials(const Scene& scene) {
  const bool cutoff = scene.has(Effect::TensionCutoff);
  std::vector<Material> out = scene.materials;
  for (Material& m : out) {
    if (auto* t = std::get_if<eos::Tillotson>(&m.eos)) t->tensionCutoff = cutoff;
    if (auto* g = std::get_if<eos::MieGruneisen>(&m.eos)) g->tensionCutoff = cutoff;
    // The temperature model's cold curve takes the EOS's bulk sound speed unless the scene
    // gives one (docs/strength.md, Temperature).
    if (m.strength && !(m.strength->thermal.bulkSoundSpeed > 0.0))
      m.strength->thermal.bulkSoundSpeed = bulkSoundSpeed(m.eos);
  }
  return out;
}

}  // namespace hvi::cases
