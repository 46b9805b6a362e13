//! @file Names of the effects a scene may request.
#include <array>
#include <utility>

#include "hvi/cases/scene.hpp"

namespace hvi::cases {
namespace {
constexpr std::array<std::pair<Effect, std::string_view>, 7> kNames{{
    {Effect::ArtificialViscosity, "artificial_viscosity"},
    {Effect::TensionCutoff, "tension_cutoff"},
    {Effect::MassAdjustment, "mass_adjustment"},
    {Effect::PhaseBookkeeping, "phase_bookkeeping"},
    {Effect::EnergyBudget, "energy_budget"},
    {Effect::MaterialInterfaces, "material_interfaces"},
    {Effect::Features, "features"},
}};
}  // namespace

std::string_view toString(Effect e) {
  for (auto& [k, n] : kNames)
    if (k == e) return n;
  return "?";
}
std::optional<Effect> effectFromString(std::string_view s) {
  for (auto& [k, n] : kNames)
    if (n == s) return k;
  return std::nullopt;
}
std::vector<std::string_view> allEffectNames() {
  std::vector<std::string_view> v;
  for (auto& [k, n] : kNames) v.push_back(n);
  return v;
}

}  // namespace hvi::cases
