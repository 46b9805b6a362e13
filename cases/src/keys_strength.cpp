//! @file The key table of [materials.<name>.strength] (docs/strength.md): the keys every solid
//! has, then those of one yield model (variant: its index in strength::YieldModel), then those of
//! one damage model (variant: its index in strength::DamageModel).
#include <array>
#include <vector>

#include "detail/keys.hpp"

namespace hvi::cases::detail {
namespace {

using K = ValueKind;
using strength::Material;

// A member of the yield law or damage model alternative T: reads 0 where the material holds
// another alternative (the row is then not read or written: its variant differs).
#define HVI_YIELD_FIELD(T, member)                                   \
  .get =                                                             \
      [](const Material& m) {                                        \
        const auto* y = std::get_if<strength::T>(&m.yield);          \
        return y != nullptr ? y->member : 0.0;                       \
      },                                                             \
  .set = [](Material& m, double v) {                                 \
    if (auto* y = std::get_if<strength::T>(&m.yield)) y->member = v; \
  }
#define HVI_DAMAGE_FIELD(T, member)                                   \
  .get =                                                              \
      [](const Material& m) {                                         \
        const auto* d = std::get_if<strength::T>(&m.damage);          \
        return d != nullptr ? d->member : 0.0;                        \
      },                                                              \
  .set = [](Material& m, double v) {                                  \
    if (auto* d = std::get_if<strength::T>(&m.damage)) d->member = v; \
  }
#define HVI_POSITIVE .ok = [](double v) { return v > 0.0; }, .problem = "must be > 0"
#define HVI_NONNEGATIVE .ok = [](double v) { return v >= 0.0; }, .problem = "must be >= 0"

constexpr int kConstant = 0, kJc = 1, kSg = 2;  // strength::YieldModel's order
constexpr int kGradyKipp = 1, kJcFailure = 2;   // strength::DamageModel's order

constexpr std::array<KeyRow<Material>, 26> kStrength{{
    {.key = "preset",
     .kind = K::Custom,
     .docValue = "a strength preset (docs/strength.md): `\"al6061_t6\"`, `\"al2017_t4\"`, "
                 "`\"al2024_t3\"`, `\"copper_ofhc\"`, `\"steel_4340\"`, `\"tungsten\"`; its "
                 "values may then be overridden one by one",
     .docDefault = "none"},
    {.key = "model",
     .kind = K::Custom,
     .docValue = "`\"constant\"`, `\"johnson_cook\"` or `\"steinberg_guinan\"`, with **all** its "
                 "keys; with a preset of another model, that model's keys",
     .docDefault = "the preset's"},
    {.key = "damage",
     .kind = K::Custom,
     .docValue = "`\"none\"`, `\"grady_kipp\"` or `\"johnson_cook\"` (failure strain), with its "
                 "keys; used with effect `fracture`",
     .docDefault = "the preset's, else `\"none\"`"},
    {.key = "shear_modulus",
     .kind = K::Quantity,
     HVI_KEY_FIELD(Material, shearModulus),
     .dimension = Dimension::Pressure,
     HVI_POSITIVE,
     .allowed = "a pressure > 0",
     .docValue = "**required**, pressure > 0 (G0; steinberg_guinan: G at P = 0, 300 K)",
     .required = true},
    {.key = "specific_heat",
     .kind = K::Quantity,
     .get = [](const Material& m) { return m.thermal.cv; },
     .set = [](Material& m, double v) { m.thermal.cv = v; },
     .dimension = Dimension::SpecificHeat,
     HVI_POSITIVE,
     .allowed = "a specific heat > 0 (J/kg/K)",
     .docValue = "**required**, specific heat > 0 (c_v of the temperature model)",
     .required = true},
    {.key = "reference_temperature",
     .kind = K::Number,
     .get = [](const Material& m) { return m.thermal.t0; },
     .set = [](Material& m, double v) { m.thermal.t0 = v; },
     HVI_POSITIVE,
     .allowed = "a temperature > 0 in K",
     .docValue = "> 0, K at e = 0 and rho = rho0",
     .docDefault = "300"},
    {.key = "bulk_sound_speed",
     .kind = K::Quantity,
     .get = [](const Material& m) { return m.thermal.bulkSoundSpeed; },
     .set = [](Material& m, double v) { m.thermal.bulkSoundSpeed = v; },
     .dimension = Dimension::Velocity,
     HVI_NONNEGATIVE,
     .allowed = "a velocity >= 0",
     .docValue = "velocity >= 0, c0 of the cold curve (0: from the EOS)",
     .docDefault = "0"},
    {.key = "spall_strength",
     .kind = K::Quantity,
     HVI_KEY_FIELD(Material, spallStrength),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "pressure >= 0, the largest tension (effect `fracture`; 0: the zero cut-off)",
     .docDefault = "0"},
    {.key = "yield_stress",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(ConstantYield, y0),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "constant: **required**, pressure >= 0 (Y0)",
     .required = true,
     .variant = kConstant},
    {.key = "jc_a",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(JohnsonCook, a),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "johnson_cook: **required**, pressure >= 0 (A)",
     .required = true,
     .variant = kJc},
    {.key = "jc_b",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(JohnsonCook, b),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "johnson_cook: **required**, pressure >= 0 (B)",
     .required = true,
     .variant = kJc},
    {.key = "jc_n",
     .kind = K::Number,
     HVI_YIELD_FIELD(JohnsonCook, n),
     HVI_POSITIVE,
     .allowed = "jc_n > 0",
     .docValue = "johnson_cook: **required**, > 0 (n)",
     .required = true,
     .variant = kJc},
    {.key = "jc_c",
     .kind = K::Number,
     HVI_YIELD_FIELD(JohnsonCook, c),
     HVI_NONNEGATIVE,
     .allowed = "jc_c >= 0",
     .docValue = "johnson_cook: **required**, >= 0 (C)",
     .required = true,
     .variant = kJc},
    {.key = "jc_m",
     .kind = K::Number,
     HVI_YIELD_FIELD(JohnsonCook, m),
     HVI_POSITIVE,
     .allowed = "jc_m > 0",
     .docValue = "johnson_cook: **required**, > 0 (m)",
     .required = true,
     .variant = kJc},
    {.key = "jc_reference_rate",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(JohnsonCook, referenceRate),
     .dimension = Dimension::StrainRate,
     HVI_POSITIVE,
     .allowed = "a strain rate > 0",
     .docValue = "johnson_cook: strain rate > 0",
     .docDefault = "`\"1 1/s\"`",
     .variant = kJc},
    {.key = "jc_room_temperature",
     .kind = K::Number,
     HVI_YIELD_FIELD(JohnsonCook, roomTemperature),
     HVI_POSITIVE,
     .allowed = "a temperature > 0 in K",
     .docValue = "johnson_cook: > 0, K",
     .docDefault = "294",
     .variant = kJc},
    // > jc_room_temperature is checked once both are read (parse_strength.cpp).
    {.key = "jc_melt_temperature",
     .kind = K::Number,
     HVI_YIELD_FIELD(JohnsonCook, meltTemperature),
     .docValue = "johnson_cook: **required**, K > jc_room_temperature",
     .required = true,
     .variant = kJc},
    {.key = "sg_y0",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(SteinbergGuinan, y0),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "steinberg_guinan: **required**, pressure >= 0 (Y0)",
     .required = true,
     .variant = kSg},
    {.key = "sg_y_max",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(SteinbergGuinan, yMax),
     .dimension = Dimension::Pressure,
     HVI_NONNEGATIVE,
     .allowed = "a pressure >= 0",
     .docValue = "steinberg_guinan: **required**, pressure >= 0 (Ymax)",
     .required = true,
     .variant = kSg},
    {.key = "sg_beta",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, beta),
     HVI_NONNEGATIVE,
     .allowed = "sg_beta >= 0",
     .docValue = "steinberg_guinan: **required**, >= 0 (beta)",
     .required = true,
     .variant = kSg},
    {.key = "sg_n",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, n),
     HVI_NONNEGATIVE,
     .allowed = "sg_n >= 0",
     .docValue = "steinberg_guinan: **required**, >= 0 (n)",
     .required = true,
     .variant = kSg},
    {.key = "sg_dg_dp",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, dGdP),
     .docValue = "steinberg_guinan: **required**, G'_P (dimensionless)",
     .required = true,
     .variant = kSg},
    {.key = "sg_dg_dt",
     .kind = K::Quantity,
     HVI_YIELD_FIELD(SteinbergGuinan, dGdT),
     .dimension = Dimension::PressurePerKelvin,
     .docValue = "steinberg_guinan: **required**, G'_T (pressure per K, negative)",
     .required = true,
     .variant = kSg},
    {.key = "sg_melt_temperature",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, meltTemperature0),
     HVI_POSITIVE,
     .allowed = "a temperature > 0 in K",
     .docValue = "steinberg_guinan: **required**, K > 0 (T_m0)",
     .required = true,
     .variant = kSg},
    {.key = "sg_gamma0",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, gamma0),
     HVI_NONNEGATIVE,
     .allowed = "sg_gamma0 >= 0",
     .docValue = "steinberg_guinan: **required**, >= 0 (the melt curve's gamma0)",
     .required = true,
     .variant = kSg},
    {.key = "sg_a",
     .kind = K::Number,
     HVI_YIELD_FIELD(SteinbergGuinan, a),
     HVI_NONNEGATIVE,
     .allowed = "sg_a >= 0",
     .docValue = "steinberg_guinan: **required**, >= 0 (the melt curve's a)",
     .required = true,
     .variant = kSg},
}};

constexpr std::array<KeyRow<Material>, 9> kDamage{{
    {.key = "weibull_k",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(GradyKipp, k),
     HVI_POSITIVE,
     .allowed = "weibull_k > 0 (flaws per cm^3)",
     .docValue = "damage grady_kipp: **required**, > 0, Weibull k in cm^-3",
     .required = true,
     .variant = kGradyKipp},
    {.key = "weibull_m",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(GradyKipp, m),
     HVI_POSITIVE,
     .allowed = "weibull_m > 0",
     .docValue = "damage grady_kipp: **required**, > 0, Weibull m",
     .required = true,
     .variant = kGradyKipp},
    {.key = "crack_speed",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(GradyKipp, crackSpeed),
     .ok = [](double v) { return v > 0.0 && v <= 1.0; },
     .problem = "must be in (0, 1]",
     .allowed = "0 < crack_speed <= 1 (a fraction of c_L)",
     .docValue = "damage grady_kipp: (0, 1], crack growth speed / c_L",
     .docDefault = "0.4",
     .variant = kGradyKipp},
    {.key = "d1",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, d1),
     .docValue = "damage johnson_cook: **required**, D1",
     .required = true,
     .variant = kJcFailure},
    {.key = "d2",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, d2),
     .docValue = "damage johnson_cook: **required**, D2",
     .required = true,
     .variant = kJcFailure},
    {.key = "d3",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, d3),
     .docValue = "damage johnson_cook: **required**, D3",
     .required = true,
     .variant = kJcFailure},
    {.key = "d4",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, d4),
     .docValue = "damage johnson_cook: **required**, D4",
     .required = true,
     .variant = kJcFailure},
    {.key = "d5",
     .kind = K::Number,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, d5),
     .docValue = "damage johnson_cook: **required**, D5",
     .required = true,
     .variant = kJcFailure},
    {.key = "failure_reference_rate",
     .kind = K::Quantity,
     HVI_DAMAGE_FIELD(JohnsonCookFailure, referenceRate),
     .dimension = Dimension::StrainRate,
     HVI_POSITIVE,
     .allowed = "a strain rate > 0",
     .docValue = "damage johnson_cook: strain rate > 0",
     .docDefault = "`\"1 1/s\"`",
     .variant = kJcFailure},
}};
#undef HVI_YIELD_FIELD
#undef HVI_DAMAGE_FIELD
#undef HVI_POSITIVE
#undef HVI_NONNEGATIVE

}  // namespace

std::span<const KeyRow<Material>> strengthKeys() { return kStrength; }
std::span<const KeyRow<Material>> damageKeys() { return kDamage; }

std::span<const std::string_view> strengthKeyNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n;
    for (const auto& r : kStrength) n.push_back(r.key);
    for (const auto& r : kDamage) n.push_back(r.key);
    return n;
  }();
  return names;
}

}  // namespace hvi::cases::detail
