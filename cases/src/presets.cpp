//! @file Named material presets (cm-g-us).
#include "hvi/cases/presets.hpp"

#include <array>

namespace hvi::cases {
namespace {
constexpr std::array<std::string_view, 4> kPresets{"aluminium_tillotson", "aluminium_mie_gruneisen",
                                                   "copper_mie_gruneisen", "air_ideal_gas"};
}  // namespace

std::span<const std::string_view> presetNames() { return kPresets; }

std::optional<eos::Eos> materialPreset(std::string_view name) {
  // The study's aluminium: spec section 2, docs/method.md (the defaults of eos::Tillotson).
  if (name == "aluminium_tillotson") return eos::Eos{eos::aluminiumStudy()};
  // Al 2024 linear Us-up fit (LASL shock Hugoniot data, Steinberg 1996): 5.328 km/s, s = 1.338.
  if (name == "aluminium_mie_gruneisen")
    return eos::Eos{eos::MieGruneisen{.rho0 = 2.785, .c0 = 0.5328, .s = 1.338, .gamma0 = 2.0}};
  // Copper (Steinberg 1996): 8.93 g/cm^3, 3.94 km/s, s = 1.49, Gamma0 = 2.0.
  if (name == "copper_mie_gruneisen")
    return eos::Eos{eos::MieGruneisen{.rho0 = 8.93, .c0 = 0.394, .s = 1.49, .gamma0 = 2.0}};
  // Sea-level air, 1.225 kg/m^3.
  if (name == "air_ideal_gas") return eos::Eos{eos::IdealGas{.gamma = 1.4, .rho0 = 1.225e-3}};
  return std::nullopt;
}

}  // namespace hvi::cases
