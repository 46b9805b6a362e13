//! @file Strength and fracture for shield scenes: the single place that turns them on
//! (docs/shield.md, "Strength").
#include "strength_hook.hpp"

#include <fmt/format.h>

#include "hvi/cases/effects.hpp"
#include "hvi/strength/strength.hpp"

namespace hvi::shield::detail {
namespace {

// Spall strength of the wrought aluminium alloys: plate-impact pull-back measurements at strain
// rates of 1e4-1e6 /s give about 1 to 1.7 GPa for them (Kanel, Razorenov and Fortov, "Shock-wave
// phenomena and the properties of condensed matter", Springer 2004, ch. 6); one value in that
// range for every alloy, since the catalogue has no alloy-by-alloy measurement. A user who has
// one writes the scene by hand (`hvi shield-scene`, then [materials.<alloy>.strength]).
constexpr double kAlloySpallGpa = 1.2;

// The two alloys without a published Johnson-Cook or Steinberg-Guinan set in strength/ run
// elastic-perfectly plastic at their 0.2 % yield stress (the catalogue's, NASA's test records),
// with handbook shear moduli and specific heats (ASM Handbook vol. 2: 7075-T6 26.9 GPa,
// 960 J/(kg K); 1100-O 26.0 GPa, 904 J/(kg K)).
struct ConstantAlloy {
  const char* name;
  double shearGpa, cv;
};
constexpr ConstantAlloy kConstant[] = {{"al7075_t6", 26.9, 960.0}, {"al1100_o", 26.0, 904.0}};

}  // namespace

std::vector<std::string> strengthEffects(cases::SolverKind solver) {
  // Looked up by name so that this file builds whichever effects the solver has: every shield
  // scene asks for each one its solver supports.
  std::vector<std::string> on;
  // TVD carries strength and fracture per phase with marker lines in its conservative interface
  // mode (the shield scenes' default; docs/strength.md, "TVD with interfaces"): its shield scenes
  // get both, as SPH's do.
  for (const char* name : {"strength", "fracture"}) {
    const auto e = cases::effectFromString(name);
    if (e && cases::supports(solver, *e)) on.emplace_back(name);
  }
  return on;
}

std::string strengthMaterialKeys(const ShieldMaterial& m, bool strengthOn) {
  if (!strengthOn) return {};
  const std::string head = fmt::format("[materials.{}.strength]\n", m.name);
  if (strength::findPreset(m.name) != nullptr)
    return head + fmt::format("preset = \"{}\"\nspall_strength = \"{:g} GPa\"\n", m.name,
                              kAlloySpallGpa);
  for (const auto& c : kConstant)
    if (m.name == c.name)
      return head + fmt::format(
                        "model = \"constant\"\nyield_stress = \"{:.17g} MPa\"\nshear_modulus = "
                        "\"{:g} GPa\"\nspecific_heat = \"{:g} J/kg/K\"\nspall_strength = \"{:g} "
                        "GPa\"\n",
                        m.yieldMpa, c.shearGpa, c.cv, kAlloySpallGpa);
  // The study's aluminium has no yield: no shear strength and the zero tension cut-off, which is
  // what it gets without these effects (fracture with spall_strength 0).
  return head + fmt::format(
                    "model = \"constant\"\nyield_stress = \"0 MPa\"\nshear_modulus = \"27 GPa\"\n"
                    "specific_heat = \"896 J/kg/K\"\nspall_strength = \"0 GPa\"\n");
}

}  // namespace hvi::shield::detail
