//! @file Unit conversion of scene-file quantities to internal cm-g-us.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/cases/load.hpp"
#include "hvi/cases/quantity.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"

namespace hvi::cases {
namespace {

double q(std::string_view text, Dimension d) {
  auto v = parseQuantity(text, d);
  EXPECT_TRUE(v.has_value()) << text;
  return v.value_or(NAN);
}

// Each conversion is one multiplication by a decimal factor, so the result is within one rounding
// of the exact product: EXPECT_DOUBLE_EQ (4 ulp) is the right tolerance, not a tuned one.
TEST(SceneQuantity, ConvertsEveryUnitToInternal) {
  EXPECT_DOUBLE_EQ(q("6.7 km/s", Dimension::Velocity), 0.67);
  EXPECT_DOUBLE_EQ(q("6.18 km/s", Dimension::Velocity), 0.618);
  EXPECT_DOUBLE_EQ(q("670 m/s", Dimension::Velocity), 0.067);
  EXPECT_DOUBLE_EQ(q("0.67 cm/us", Dimension::Velocity), 0.67);
  EXPECT_DOUBLE_EQ(q("6.7 mm/us", Dimension::Velocity), 0.67);
  EXPECT_DOUBLE_EQ(q("75 GPa", Dimension::Pressure), 0.75);
  EXPECT_DOUBLE_EQ(q("1 Mbar", Dimension::Pressure), 1.0);
  EXPECT_DOUBLE_EQ(q("10 kbar", Dimension::Pressure), 0.01);
  EXPECT_DOUBLE_EQ(q("1e6 bar", Dimension::Pressure), 1.0);
  EXPECT_DOUBLE_EQ(q("1e5 MPa", Dimension::Pressure), 1.0);
  EXPECT_DOUBLE_EQ(q("1e11 Pa", Dimension::Pressure), 1.0);
  EXPECT_DOUBLE_EQ(q("5 MJ/kg", Dimension::SpecificEnergy), 0.05);
  EXPECT_DOUBLE_EQ(q("5000 kJ/kg", Dimension::SpecificEnergy), 0.05);
  EXPECT_DOUBLE_EQ(q("5e6 J/kg", Dimension::SpecificEnergy), 0.05);
  EXPECT_DOUBLE_EQ(q("0.05 cm^2/us^2", Dimension::SpecificEnergy), 0.05);
  EXPECT_DOUBLE_EQ(q("2790 kg/m^3", Dimension::Density), 2.79);
  EXPECT_DOUBLE_EQ(q("2.79 g/cm^3", Dimension::Density), 2.79);
  EXPECT_DOUBLE_EQ(q("9.5 mm", Dimension::Length), 0.95);
  EXPECT_DOUBLE_EQ(q("0.0155 m", Dimension::Length), 1.55);
  EXPECT_DOUBLE_EQ(q("150 um", Dimension::Length), 0.015);
  EXPECT_DOUBLE_EQ(q("300 ns", Dimension::Time), 0.3);
  EXPECT_DOUBLE_EQ(q("7.2e-6 s", Dimension::Time), 7.2);
  EXPECT_DOUBLE_EQ(q("0.001 ms", Dimension::Time), 1.0);
  EXPECT_DOUBLE_EQ(q("2 min", Dimension::WallTime), 120.0);
  EXPECT_DOUBLE_EQ(q("1 h", Dimension::WallTime), 3600.0);
}

TEST(SceneQuantity, AcceptsSignsExponentsAndNoSpace) {
  EXPECT_DOUBLE_EQ(q("-6.7 km/s", Dimension::Velocity), -0.67);
  EXPECT_DOUBLE_EQ(q("+2 us", Dimension::Time), 2.0);
  EXPECT_DOUBLE_EQ(q("1.5e-2cm", Dimension::Length), 0.015);
  EXPECT_DOUBLE_EQ(q("  8.155 cm  ", Dimension::Length), 8.155);
}

TEST(SceneQuantity, RejectsWithAReason) {
  struct Bad {
    const char* text;
    Dimension d;
    const char* reason;
  };
  for (const Bad& b : {Bad{"6.7", Dimension::Velocity, "has no unit"},
                       Bad{"6.7 km/h", Dimension::Velocity, "unknown velocity unit \"km/h\""},
                       Bad{"km/s", Dimension::Velocity, "does not start with a number"},
                       Bad{"", Dimension::Length, "does not start with a number"},
                       Bad{"nan cm", Dimension::Length, "not finite"},
                       Bad{"inf us", Dimension::Time, "not finite"},
                       Bad{"1e400 cm", Dimension::Length, "out of range"},
                       Bad{"1e308 m", Dimension::Length, "overflows"},
                       Bad{"1 mbar", Dimension::Pressure, "unknown pressure unit \"mbar\""},
                       Bad{"1 cm", Dimension::Time, "unknown time unit \"cm\""}}) {
    std::string why;
    EXPECT_FALSE(parseQuantity(b.text, b.d, &why).has_value()) << b.text;
    EXPECT_NE(why.find(b.reason), std::string::npos) << b.text << " -> " << why;
  }
}

TEST(SceneQuantity, UnitListsStartWithTheInternalUnit) {
  EXPECT_EQ(internalUnit(Dimension::Length), "cm");
  EXPECT_EQ(internalUnit(Dimension::Velocity), "cm/us");
  EXPECT_EQ(internalUnit(Dimension::Pressure), "Mbar");
  EXPECT_EQ(internalUnit(Dimension::SpecificEnergy), "cm^2/us^2");
  for (auto d : {Dimension::Length, Dimension::Time, Dimension::Velocity, Dimension::Density,
                 Dimension::Pressure, Dimension::SpecificEnergy, Dimension::WallTime,
                 Dimension::SpecificHeat, Dimension::StrainRate, Dimension::PressurePerKelvin})
    EXPECT_EQ(unitsOf(d).front().toInternal, 1.0);
  // The strength units (docs/strength.md): 1 J/(kg K) = 1e-8 cm^2/us^2/K, 1/s = 1e-6 /us.
  EXPECT_DOUBLE_EQ(*parseQuantity("896 J/kg/K", Dimension::SpecificHeat), 8.96e-6);
  EXPECT_DOUBLE_EQ(*parseQuantity("1000 1/s", Dimension::StrainRate), 1e-3);
  EXPECT_DOUBLE_EQ(*parseQuantity("-0.017 GPa/K", Dimension::PressurePerKelvin), -1.7e-4);
  EXPECT_EQ(allowedUnits(Dimension::Length), "cm, mm, m, um");
}

// The same conversions through a whole scene: the body and material values land in cm-g-us.
TEST(SceneQuantity, SceneValuesArriveInInternalUnits) {
  const std::string text = test::plateScene(R"(
[[bodies]]
name = "striker"
material = "al"
shape = "disk"
centre = ["0 mm", "5 mm"]
radius = "5 mm"
velocity = ["0 m/s", "-6180 m/s"]
density = "2790 kg/m^3"
specific_energy = "1 MJ/kg"
)");
  const Scene s = parseScene(text, "units.toml");
  ASSERT_EQ(s.bodies.size(), 2u);
  const Body& b = s.bodies[0];
  EXPECT_DOUBLE_EQ(std::get<Disk>(b.shape).centre.z, 0.5);
  EXPECT_DOUBLE_EQ(std::get<Disk>(b.shape).radius, 0.5);
  EXPECT_DOUBLE_EQ(b.velocity.z, -0.618);
  EXPECT_DOUBLE_EQ(b.density, 2.79);
  EXPECT_DOUBLE_EQ(b.specificEnergy, 0.01);
  const auto& t = std::get<eos::Tillotson>(s.materials[0].eos);
  EXPECT_DOUBLE_EQ(t.A, 0.75);   // "75 GPa"
  EXPECT_DOUBLE_EQ(t.B, 0.65);   // "65 GPa"
  EXPECT_DOUBLE_EQ(t.e0, 0.05);  // "5 MJ/kg"
  EXPECT_DOUBLE_EQ(t.rho0, 2.79);
  EXPECT_DOUBLE_EQ(s.tEnd, 5.0);
}

// Bare numbers are internal units only where the file says so.
TEST(SceneQuantity, BareNumbersNeedTheUnitsDeclaration) {
  const std::string body = R"(
[[bodies]]
name = "striker"
material = "al"
shape = "disk"
centre = ["0 cm", "0.5 cm"]
radius = 0.5
)";
  try {
    (void)parseScene(test::plateScene(body), "bare.toml");
    FAIL() << "a bare radius without units = \"cm-g-us\" must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0].radius"), std::string::npos) << e.what();
  }
  const Scene s =
      parseScene(test::plateScene(body, "units = \"cm-g-us\"\ngeometry = \"planar\""), "bare.toml");
  EXPECT_DOUBLE_EQ(std::get<Disk>(s.bodies[0].shape).radius, 0.5);
}

}  // namespace
}  // namespace hvi::cases
