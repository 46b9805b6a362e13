//! @file Published strength sets (docs/strength.md, Presets), converted to cm-g-us:
//! 1 GPa = 0.01 Mbar, 1 MPa = 1e-5 Mbar, 1 J/(kg K) = 1e-8 cm^2/us^2/K, 1/s = 1e-6 /us.
#include <array>

#include "hvi/strength/strength.hpp"

namespace hvi::strength {
namespace {

constexpr double kGPa = 1e-2, kMPa = 1e-5, kCv = 1e-8;

Material steinbergAl6061() {
  // Steinberg (1991) UCRL-MA-106439, 6061-T6: G0 27.6 GPa, Y0 0.29 GPa, Ymax 0.68 GPa, beta 125,
  // n 0.10, G'_P 1.8, G'_T -0.0170 GPa/K, Tm0 1220 K, gamma0 1.97, a 1.5; c_v 896 J/(kg K).
  SteinbergGuinan sg{.g0 = 27.6 * kGPa,
                     .y0 = 0.29 * kGPa,
                     .yMax = 0.68 * kGPa,
                     .beta = 125.0,
                     .n = 0.10,
                     .dGdP = 1.8,
                     .dGdT = -0.0170 * kGPa,
                     .meltTemperature0 = 1220.0,
                     .gamma0 = 1.97,
                     .a = 1.5};
  return {.shearModulus = sg.g0, .yield = sg, .thermal = {.cv = 896.0 * kCv}};
}

Material lesuerAl2024(double aMPa) {
  // Lesuer (2000) UCRL-ID-138213, 2024-T3: A 369 MPa, B 684 MPa, n 0.73, C 0.0083, m 1.7,
  // T_melt 775 K, T_room 294 K, eps_dot0 1/s. G 28.6 GPa (Steinberg 1991, 2024); c_v 875.
  JohnsonCook jc{.a = aMPa * kMPa,
                 .b = 684.0 * kMPa,
                 .n = 0.73,
                 .c = 0.0083,
                 .m = 1.7,
                 .referenceRate = 1e-6,
                 .roomTemperature = 294.0,
                 .meltTemperature = 775.0};
  return {.shearModulus = 28.6 * kGPa, .yield = jc, .thermal = {.cv = 875.0 * kCv}};
}

Material jcCopper() {
  // Johnson and Cook (1983) OFHC copper: A 90 MPa, B 292 MPa, n 0.31, C 0.025, m 1.09,
  // T_melt 1356 K; G 46 GPa; failure (Johnson and Cook 1985): D1..D5 = 0.54, 4.89, -3.03,
  // 0.014, 1.12; c_v 383 J/(kg K).
  JohnsonCook jc{.a = 90.0 * kMPa,
                 .b = 292.0 * kMPa,
                 .n = 0.31,
                 .c = 0.025,
                 .m = 1.09,
                 .referenceRate = 1e-6,
                 .roomTemperature = 294.0,
                 .meltTemperature = 1356.0};
  return {.shearModulus = 46.0 * kGPa,
          .yield = jc,
          .thermal = {.cv = 383.0 * kCv},
          .damage = JohnsonCookFailure{0.54, 4.89, -3.03, 0.014, 1.12, 1e-6}};
}

Material jcSteel4340() {
  // Johnson and Cook (1983) 4340 steel (Rc 30): A 792 MPa, B 510 MPa, n 0.26, C 0.014, m 1.03,
  // T_melt 1793 K; G 77.5 GPa; failure (Johnson and Cook 1985): 0.05, 3.44, -2.12, 0.002, 0.61;
  // c_v 477 J/(kg K).
  JohnsonCook jc{.a = 792.0 * kMPa,
                 .b = 510.0 * kMPa,
                 .n = 0.26,
                 .c = 0.014,
                 .m = 1.03,
                 .referenceRate = 1e-6,
                 .roomTemperature = 294.0,
                 .meltTemperature = 1793.0};
  return {.shearModulus = 77.5 * kGPa,
          .yield = jc,
          .thermal = {.cv = 477.0 * kCv},
          .damage = JohnsonCookFailure{0.05, 3.44, -2.12, 0.002, 0.61, 1e-6}};
}

Material jcTungsten() {
  // Johnson and Cook (1983) tungsten alloy (.07 Ni, .03 Fe): A 1506 MPa, B 177 MPa, n 0.12,
  // C 0.016, m 1.00, T_melt 1723 K; G 160 GPa; c_v 134 J/(kg K).
  JohnsonCook jc{.a = 1506.0 * kMPa,
                 .b = 177.0 * kMPa,
                 .n = 0.12,
                 .c = 0.016,
                 .m = 1.00,
                 .referenceRate = 1e-6,
                 .roomTemperature = 294.0,
                 .meltTemperature = 1723.0};
  return {.shearModulus = 160.0 * kGPa, .yield = jc, .thermal = {.cv = 134.0 * kCv}};
}

Material zaCopper() {
  // Zerilli and Armstrong (1987) OFHC copper, fcc form: C0 65 MPa, C2 890 MPa, C3 0.0028 /K,
  // C4 0.000115 /K (eps_dot in 1/s); C0 is their Delta sigma'_G + k l^(-1/2) = 46.5 + 5 * 3.7
  // MPa (73 um grains), the split Uintah's copper inputs give (docs/strength.md). G, c_v and
  // T_melt are copper_ofhc's, so the two presets differ in the yield law alone. No damage: the
  // paper gives none.
  Material m = jcCopper();
  m.yield = ZerilliArmstrong{.c0 = 65.0 * kMPa,
                             .c2 = 890.0 * kMPa,
                             .c3 = 0.0028,
                             .c4 = 0.000115,
                             .meltTemperature = std::get<JohnsonCook>(m.yield).meltTemperature};
  m.damage = NoDamage{};
  return m;
}

const std::array<Preset, 7> kPresets{{
    {"al6061_t6", "Steinberg-Guinan, Steinberg (1991) UCRL-MA-106439", steinbergAl6061()},
    // No published JC or SG set for 2017-T4 is known to us: the 2024-T3 set of the same Al-Cu-Mg
    // family with A = 276 MPa, 2017-T4's 0.2 % yield (ASM Handbook vol. 2) instead of 369.
    {"al2017_t4", "Johnson-Cook, Lesuer (2000) 2024-T3 set with A = 276 MPa (approximation)",
     lesuerAl2024(276.0)},
    {"al2024_t3", "Johnson-Cook, Lesuer (2000) UCRL-ID-138213", lesuerAl2024(369.0)},
    {"copper_ofhc", "Johnson-Cook (1983), failure Johnson-Cook (1985)", jcCopper()},
    {"copper_ofhc_za", "Zerilli-Armstrong (1987), fcc form", zaCopper()},
    {"steel_4340", "Johnson-Cook (1983), failure Johnson-Cook (1985)", jcSteel4340()},
    {"tungsten", "Johnson-Cook (1983), tungsten alloy", jcTungsten()},
}};

constexpr std::array<std::string_view, 4> kYieldNames{"constant", "johnson_cook",
                                                      "steinberg_guinan", "zerilli_armstrong"};
constexpr std::array<std::string_view, 3> kDamageNames{"none", "grady_kipp", "johnson_cook"};

}  // namespace

std::span<const std::string_view> yieldModelNames() { return kYieldNames; }
std::span<const std::string_view> damageModelNames() { return kDamageNames; }
std::span<const Preset> presets() { return kPresets; }
const Preset* findPreset(std::string_view name) {
  for (const Preset& p : kPresets)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace hvi::strength
