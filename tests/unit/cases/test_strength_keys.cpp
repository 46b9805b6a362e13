//! @file [materials.<name>.strength]: presets, models and their keys, damage, toToml round trip,
//! --set paths and the errors (file, key, allowed values). docs/strength.md.
#include <gtest/gtest.h>

#include "hvi/cases/effects.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"

namespace hvi::cases {
namespace {

using test::plateScene;

std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    (void)parseScene(text, "s.toml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(StrengthKeys, PresetGivesThePublishedSetAndKeysOverrideIt) {
  const Scene s = parseScene(
      plateScene(
          "\n[materials.al.strength]\npreset = \"al6061_t6\"\nspall_strength = \"1.2 GPa\"\n"),
      "s.toml");
  ASSERT_TRUE(s.materials[0].strength.has_value());
  const auto& st = *s.materials[0].strength;
  const auto& sg = std::get<strength::SteinbergGuinan>(st.yield);
  EXPECT_DOUBLE_EQ(sg.y0, 0.29e-2);
  EXPECT_DOUBLE_EQ(st.shearModulus, 0.276);
  EXPECT_DOUBLE_EQ(st.spallStrength, 1.2e-2);
  // The cold curve's sound speed from the Tillotson EOS: sqrt(A / rho0) = sqrt(0.75 / 2.79).
  EXPECT_DOUBLE_EQ(st.thermal.bulkSoundSpeed, std::sqrt(0.75 / 2.79));
  // Without the table nothing changes: no strength.
  EXPECT_FALSE(parseScene(plateScene(""), "s.toml").materials[0].strength.has_value());
}

TEST(StrengthKeys, ModelWithItsKeysAndUnits) {
  const Scene s = parseScene(plateScene(R"(
[materials.al.strength]
model = "johnson_cook"
shear_modulus = "26 GPa"
specific_heat = "896 J/kg/K"
jc_a = "324 MPa"
jc_b = "114 MPa"
jc_n = 0.42
jc_c = 0.002
jc_m = 1.34
jc_melt_temperature = 925
damage = "grady_kipp"
weibull_k = 1e20
weibull_m = 9
)"),
                             "s.toml");
  const auto& st = *s.materials[0].strength;
  const auto& jc = std::get<strength::JohnsonCook>(st.yield);
  EXPECT_DOUBLE_EQ(jc.a, 324e-5);
  EXPECT_DOUBLE_EQ(jc.referenceRate, 1e-6);  // default 1/s
  EXPECT_DOUBLE_EQ(st.thermal.cv, 896e-8);
  const auto& gk = std::get<strength::GradyKipp>(st.damage);
  EXPECT_DOUBLE_EQ(gk.k, 1e20);
  EXPECT_DOUBLE_EQ(gk.crackSpeed, 0.4);
}

TEST(StrengthKeys, ToTomlReadsBackToTheSameValues) {
  for (const char* preset : {"al6061_t6", "al2017_t4", "al2024_t3", "copper_ofhc", "copper_ofhc_za",
                             "steel_4340", "tungsten"}) {
    const Scene a = parseScene(
        plateScene(std::string("\n[materials.al.strength]\npreset = \"") + preset + "\"\n"),
        "s.toml");
    Scene b = parseScene(toToml(a), "resolved.toml");
    b.path = a.path;
    EXPECT_EQ(toToml(a), toToml(b)) << preset;
    const auto& x = *a.materials[0].strength;
    const auto& y = *b.materials[0].strength;
    EXPECT_EQ(x.yield.index(), y.yield.index()) << preset;
    EXPECT_EQ(x.damage.index(), y.damage.index()) << preset;
    EXPECT_EQ(strength::yieldStress(x.yield, {.plasticStrain = 0.1, .temperature = 400.0}),
              strength::yieldStress(y.yield, {.plasticStrain = 0.1, .temperature = 400.0}))
        << preset;
  }
}

TEST(StrengthKeys, ZerilliArmstrongModelAndPreset) {
  // The model with all its keys, in the units given.
  const Scene s = parseScene(plateScene(R"(
[materials.al.strength]
model = "zerilli_armstrong"
shear_modulus = "46 GPa"
specific_heat = "383 J/kg/K"
za_c0 = "65 MPa"
za_c2 = "0.89 GPa"
za_c3 = 0.0028
za_c4 = 0.000115
za_melt_temperature = 1356
)"),
                             "s.toml");
  const auto& za = std::get<strength::ZerilliArmstrong>(s.materials[0].strength->yield);
  EXPECT_DOUBLE_EQ(za.c0, 65e-5);
  EXPECT_DOUBLE_EQ(za.c2, 890e-5);
  EXPECT_DOUBLE_EQ(za.c3, 0.0028);
  EXPECT_DOUBLE_EQ(za.c4, 0.000115);
  EXPECT_DOUBLE_EQ(za.meltTemperature, 1356.0);
  // The preset, one key overridden (also by --set); its G and c_v are copper_ofhc's.
  const std::string text = plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\n");
  const Scene p = parseScene(text, "s.toml", {"materials.al.strength.za_c0=\"46.5 MPa\""});
  const auto& st = *p.materials[0].strength;
  EXPECT_DOUBLE_EQ(std::get<strength::ZerilliArmstrong>(st.yield).c0, 46.5e-5);
  EXPECT_DOUBLE_EQ(std::get<strength::ZerilliArmstrong>(st.yield).c2, 890e-5);
  EXPECT_DOUBLE_EQ(st.shearModulus, 0.46);
  EXPECT_DOUBLE_EQ(st.thermal.cv, 383e-8);
  EXPECT_EQ(st.damage.index(), 0u);  // none: the paper gives no failure model
}

TEST(StrengthKeys, ZerilliArmstrongErrors) {
  // A key of the model missing: named, with the model.
  std::string e = errorOf(plateScene(R"(
[materials.al.strength]
model = "zerilli_armstrong"
shear_modulus = "46 GPa"
specific_heat = "383 J/kg/K"
za_c0 = "65 MPa"
za_c2 = "890 MPa"
za_c3 = 0.0028
za_melt_temperature = 1356
)"));
  EXPECT_TRUE(contains(e, "za_c4")) << e;
  // Out of range, with what is allowed.
  e = errorOf(plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\nza_c3 = -0.1\n"));
  EXPECT_TRUE(contains(e, "za_c3")) << e;
  EXPECT_TRUE(contains(e, "must be >= 0")) << e;
  e = errorOf(
      plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\nza_c0 = \"-1 MPa\"\n"));
  EXPECT_TRUE(contains(e, "za_c0")) << e;
  EXPECT_TRUE(contains(e, "must be >= 0")) << e;
  e = errorOf(plateScene(
      "\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\nza_melt_temperature = 0\n"));
  EXPECT_TRUE(contains(e, "za_melt_temperature")) << e;
  EXPECT_TRUE(contains(e, "must be > 0")) << e;
  // A pressure where one is due.
  e = errorOf(
      plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\nza_c2 = \"890 K\"\n"));
  EXPECT_TRUE(contains(e, "za_c2")) << e;
  // Keys of another model, either way round.
  e = errorOf(
      plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc_za\"\njc_a = \"1 GPa\"\n"));
  EXPECT_TRUE(contains(e, "jc_a")) << e;
  EXPECT_TRUE(contains(e, "not a parameter of model = \"zerilli_armstrong\"")) << e;
  e = errorOf(
      plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc\"\nza_c0 = \"1 MPa\"\n"));
  EXPECT_TRUE(contains(e, "za_c0")) << e;
  EXPECT_TRUE(contains(e, "not a parameter of model = \"johnson_cook\"")) << e;
  // The model's name among the allowed ones.
  e = errorOf(plateScene("\n[materials.al.strength]\nmodel = \"zerilli\"\n"));
  EXPECT_TRUE(contains(e, "zerilli_armstrong")) << e;
  e = errorOf(plateScene("\n[materials.al.strength]\npreset = \"copper_za\"\n"));
  EXPECT_TRUE(contains(e, "copper_ofhc_za")) << e;
}

TEST(StrengthKeys, SetReachesTheStrengthTable) {
  const std::string text = plateScene("\n[materials.al.strength]\npreset = \"copper_ofhc\"\n");
  const Scene s = parseScene(text, "s.toml", {"materials.al.strength.jc_a=\"100 MPa\""});
  EXPECT_DOUBLE_EQ(std::get<strength::JohnsonCook>(s.materials[0].strength->yield).a, 100e-5);
  const std::string e = errorOf(text, {"materials.al.strength.jc_q=1"});
  EXPECT_TRUE(contains(e, "unknown key")) << e;
  EXPECT_TRUE(contains(e, "jc_a")) << e;
}

TEST(StrengthKeys, ErrorsNameTheKeyAndWhatIsAllowed) {
  // No preset and no model.
  std::string e = errorOf(plateScene("\n[materials.al.strength]\nshear_modulus = \"1 GPa\"\n"));
  EXPECT_TRUE(contains(e, "materials.al.strength")) << e;
  EXPECT_TRUE(contains(e, "steinberg_guinan")) << e;
  // A key of another model.
  e = errorOf(plateScene("\n[materials.al.strength]\npreset = \"al6061_t6\"\njc_a = \"1 GPa\"\n"));
  EXPECT_TRUE(contains(e, "jc_a")) << e;
  EXPECT_TRUE(contains(e, "not a parameter of model = \"steinberg_guinan\"")) << e;
  // A model without a required key.
  e = errorOf(
      plateScene("\n[materials.al.strength]\nmodel = \"constant\"\nshear_modulus = \"1 GPa\"\n"
                 "specific_heat = \"900 J/kg/K\"\n"));
  EXPECT_TRUE(contains(e, "yield_stress")) << e;
  // Out of range, with the allowed values.
  e = errorOf(plateScene(
      "\n[materials.al.strength]\npreset = \"al6061_t6\"\nshear_modulus = \"-1 GPa\"\n"));
  EXPECT_TRUE(contains(e, "shear_modulus")) << e;
  EXPECT_TRUE(contains(e, "must be > 0")) << e;
  e = errorOf(plateScene("\n[materials.al.strength]\npreset = \"al6061\"\n"));
  EXPECT_TRUE(contains(e, "al6061_t6")) << e;
  // JC melt temperature below room temperature.
  e = errorOf(plateScene(
      "\n[materials.al.strength]\npreset = \"copper_ofhc\"\njc_melt_temperature = 200\n"));
  EXPECT_TRUE(contains(e, "jc_melt_temperature")) << e;
}

TEST(StrengthKeys, AGasHasNoStrength) {
  const std::string gas = R"(units = "cm-g-us"
geometry = "planar"
solver = "sph"
[time]
end = "1 us"
[domain]
x = ["0 cm", "1 cm"]
z = ["0 cm", "1 cm"]
[materials.gas]
eos = "ideal_gas"
rho0 = 1.0
gamma = 1.4
[materials.gas.strength]
model = "constant"
shear_modulus = "1 GPa"
specific_heat = "900 J/kg/K"
yield_stress = "1 MPa"
[[bodies]]
name = "g"
material = "gas"
shape = "rect"
x = ["0 cm", "1 cm"]
z = ["0 cm", "1 cm"]
specific_energy = 1.0
)";
  const std::string e = errorOf(gas);
  EXPECT_TRUE(contains(e, "ideal gas")) << e;
  EXPECT_TRUE(contains(e, "materials.gas.strength")) << e;
}

TEST(StrengthKeys, EffectsAreInTheTable) {
  EXPECT_EQ(effectFromString("strength"), Effect::Strength);
  EXPECT_EQ(effectFromString("fracture"), Effect::Fracture);
}

}  // namespace
}  // namespace hvi::cases
