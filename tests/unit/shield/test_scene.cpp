//! @file Shield declarations: parsing, errors naming file / key / allowed values, the generated
//! scene's layout.
#include <gtest/gtest.h>

#include <algorithm>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/shield/ble.hpp"
#include "hvi/shield/shield.hpp"

namespace hvi::shield {
namespace {

const std::string kExample = std::string(HVI_SOURCE_DIR) + "/shield/examples/whipple_tp2003.toml";

const char* kTwoWalls = R"(
title = "t"
[projectile]
material = "al2017_t4"
diameter = "0.3 cm"
speed = "7 km/s"
[[walls]]
material = "al6061_t6"
thickness = "0.06 cm"
[[walls]]
material = "al2024_t3"
thickness = "0.16 cm"
gap = "3 cm"
)";

std::string errorOf(const std::string& text) {
  try {
    (void)parseShield(text, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ShieldScene, ExampleParsesAndGeneratesAValidScene) {
  const ShieldSpec s = loadShield(kExample);
  ASSERT_EQ(s.walls.size(), 2u);
  EXPECT_DOUBLE_EQ(s.standoff(), 10.16);
  EXPECT_DOUBLE_EQ(s.projectile.speed, 7.44);
  // min(0.634 / 8 = 0.07925, 0.127 / 3 = 0.042333)
  EXPECT_NEAR(s.spacing(), 0.127 / 3.0, 1e-12);
  const cases::Scene scene = buildScene(s);
  EXPECT_EQ(scene.solver, cases::SolverKind::Tvd);
  EXPECT_EQ(scene.geometry, Geometry::Axisymmetric);
  ASSERT_EQ(scene.bodies.size(), 3u);
  EXPECT_EQ(scene.bodies[0].name, kProjectile);
  EXPECT_EQ(scene.bodies[2].name, kRearWall);
  const auto& bumper = std::get<cases::Rect>(scene.bodies[1].shape);
  const auto& rear = std::get<cases::Rect>(scene.bodies[2].shape);
  const auto& ball = std::get<cases::Disk>(scene.bodies[0].shape);
  // The gap is the clear space; the projectile touches the bumper; thicknesses as declared.
  EXPECT_NEAR(bumper.zmin - rear.zmax, 10.16, 1e-5);
  EXPECT_NEAR(bumper.zmax - bumper.zmin, 0.127, 1e-5);
  EXPECT_NEAR(rear.zmax - rear.zmin, 0.406, 1e-5);
  EXPECT_NEAR(ball.centre.z - ball.radius, bumper.zmax, 1e-5);
  EXPECT_NEAR(scene.bodies[0].velocity.z, -0.744, 1e-9);  // cm/us
  // Densities of the alloys (rho0 of each material), the domain starting at the axis.
  EXPECT_NEAR(scene.materials[static_cast<std::size_t>(scene.bodies[2].material)].rho0(), 2.77,
              1e-12);
  EXPECT_EQ(scene.domain.boundary[0], cases::Boundary::Axis);
  EXPECT_NEAR(scene.tvd.cellSize, 0.127 / 3.0, 1e-6);
  // The domain holds whole cells and the rear wall with room behind it.
  EXPECT_GT(rear.zmin, 0.0);
  EXPECT_NEAR(scene.domain.xmax / scene.tvd.cellSize,
              std::round(scene.domain.xmax / scene.tvd.cellSize), 1e-6);
}

TEST(ShieldScene, CoarseExampleHasOneSpacingForEveryDiameter) {
  // The coarse example: the same shield as the example, SPH, one fixed spacing (bumper / 3) that
  // the generated scene carries whatever the diameter, where the example refines as d / 8.
  ShieldSpec coarse = loadShield(std::string(HVI_SOURCE_DIR) +
                                 "/shield/examples/whipple_tp2003_coarse.toml");
  ShieldSpec fine = loadShield(kExample);
  EXPECT_EQ(coarse.solver, cases::SolverKind::Sph);
  EXPECT_DOUBLE_EQ(coarse.standoff(), fine.standoff());
  for (double d : {0.2, 0.634, 1.2}) {
    coarse.projectile.diameter = fine.projectile.diameter = d;
    EXPECT_NEAR(coarse.spacing(), 0.0423333, 1e-12) << d;
    EXPECT_NEAR(buildScene(coarse).sph.spacing, 0.0423333, 1e-12) << d;
    EXPECT_NEAR(fine.spacing(), std::min(d / 8.0, 0.127 / 3.0), 1e-12) << d;
  }
  EXPECT_NE(sceneToml(coarse).find("fixed resolution.spacing"), std::string::npos);
}

TEST(ShieldScene, SphSceneAndStandoffScaling) {
  ShieldSpec s = parseShield("solver = \"sph\"\n" + std::string(kTwoWalls), "s.toml");
  EXPECT_EQ(s.walls.front().name, "bumper");
  EXPECT_EQ(s.walls.back().name, kRearWall);
  setStandoff(s, 6.0);
  EXPECT_DOUBLE_EQ(s.walls.back().gap, 6.0);
  const cases::Scene scene = buildScene(s);
  EXPECT_EQ(scene.solver, cases::SolverKind::Sph);
  EXPECT_NEAR(scene.sph.spacing, 0.02, 1e-9);  // min(0.3 / 8, 0.06 / 3)
  // The BLE of the declaration: t_w 0.16, S 6, sigma 50 ksi, rho_b 2.7, rho_p 2.8.
  const WhippleBle b = whippleBle(s);
  EXPECT_DOUBLE_EQ(b.standoff, 6.0);
  EXPECT_NEAR(b.rearWallYieldKsi, 50.0, 1e-12);
}

TEST(ShieldScene, SphPlatesCarryStrengthAndSpall) {
  // SPH has the effects strength and fracture (docs/strength.md), so its shield scenes name both,
  // drop the zero cut-off that fracture replaces, and give every material a strength table: the
  // alloys with a preset take it, 7075-T6 runs elastic-perfectly plastic at its 73 ksi yield.
  std::string text = "solver = \"sph\"\n" + std::string(kTwoWalls);
  text.replace(text.find("al2017_t4"), 9, "al7075_t6");
  const cases::Scene scene = buildScene(parseShield(text, "s.toml"));
  EXPECT_TRUE(scene.has(cases::Effect::Strength));
  EXPECT_TRUE(scene.has(cases::Effect::Fracture));
  EXPECT_FALSE(scene.has(cases::Effect::TensionCutoff));
  for (const auto& m : scene.materials) {
    ASSERT_TRUE(m.strength.has_value()) << m.name;
    EXPECT_NEAR(m.strength->spallStrength, 0.012, 1e-15) << m.name;  // 1.2 GPa in Mbar
  }
  auto of = [&](const std::string& name) {
    return std::find_if(scene.materials.begin(), scene.materials.end(),
                        [&](const auto& m) { return m.name == name; });
  };
  EXPECT_TRUE(std::holds_alternative<strength::SteinbergGuinan>(of("al6061_t6")->strength->yield));
  EXPECT_TRUE(std::holds_alternative<strength::JohnsonCook>(of("al2024_t3")->strength->yield));
  const auto* y = std::get_if<strength::ConstantYield>(&of("al7075_t6")->strength->yield);
  ASSERT_NE(y, nullptr);
  EXPECT_NEAR(y->y0, 73.0 * kMpaPerKsi * 1e-5, 1e-12);  // MPa -> Mbar
  // TVD carries strength and fracture per phase (conservative interfaces, the default): its
  // shield scenes name both, drop the zero cut-off, and give every material its strength table
  // with the spall strength.
  const cases::Scene tvd = buildScene(parseShield(std::string(kTwoWalls), "s.toml"));
  EXPECT_TRUE(tvd.has(cases::Effect::Strength));
  EXPECT_TRUE(tvd.has(cases::Effect::Fracture));
  EXPECT_FALSE(tvd.has(cases::Effect::TensionCutoff));
  EXPECT_EQ(tvd.tvd.interfaces, cases::InterfaceMode::Conservative);
  // What leaves through an outflow side does not come back (docs/shield.md, "The generated scene").
  EXPECT_EQ(tvd.tvd.outflow, cases::OutflowMode::NoReentry);
  for (const auto& m : tvd.materials) EXPECT_TRUE(m.strength.has_value()) << m.name;
}

TEST(ShieldScene, IntermediateWallCountsInTheStandoff) {
  const std::string three =
      std::string(kTwoWalls).insert(std::string(kTwoWalls).rfind("[[walls]]"),
                                    "[[walls]]\nname = \"mid\"\nmaterial = "
                                    "\"al6061_t6\"\nthickness = \"0.1 cm\"\ngap = \"2 cm\"\n");
  ShieldSpec s = parseShield(three, "s.toml");
  ASSERT_EQ(s.walls.size(), 3u);
  EXPECT_DOUBLE_EQ(s.standoff(), 2.0 + 0.1 + 3.0);
  EXPECT_THROW((void)whippleBle(s), InputError);  // the Whipple BLE is for two walls
  setStandoff(s, 10.2);                           // gaps 5 -> 10.1: scaled by 2.02
  EXPECT_NEAR(s.walls[1].gap, 4.04, 1e-12);
  EXPECT_NEAR(s.standoff(), 10.2, 1e-12);
  EXPECT_EQ(buildScene(s).bodies.size(), 4u);
}

TEST(ShieldScene, BadInputNamesFileKeyAndAllowedValues) {
  std::string bad = kTwoWalls;
  bad.replace(bad.find("al2024_t3"), 9, "unobtanium");
  std::string e = errorOf(bad);
  EXPECT_NE(e.find("s.toml:"), std::string::npos) << e;
  EXPECT_NE(e.find("walls[1].material"), std::string::npos) << e;
  EXPECT_NE(e.find("al2024_t3"), std::string::npos) << e;  // the allowed list

  bad = kTwoWalls;
  bad.replace(bad.find("\"3 cm\""), 6, "\"3 kg\"");
  e = errorOf(bad);
  EXPECT_NE(e.find("walls[1].gap"), std::string::npos) << e;
  EXPECT_NE(e.find("cm"), std::string::npos) << e;

  bad = kTwoWalls;
  bad.replace(bad.find("gap = \"3 cm\""), 12, "");
  EXPECT_NE(errorOf(bad).find("walls[1].gap: missing"), std::string::npos) << errorOf(bad);

  e = errorOf("solver = \"riemann\"\n" + std::string(kTwoWalls));
  EXPECT_NE(e.find("solver"), std::string::npos);
  EXPECT_NE(e.find("sph, tvd"), std::string::npos) << e;

  e = errorOf("colour = 1\n" + std::string(kTwoWalls));
  EXPECT_NE(e.find("colour: unknown key"), std::string::npos) << e;

  // A fixed spacing replaces the knobs: both at once is refused, naming the knob.
  e = errorOf(std::string(kTwoWalls) +
              "[resolution]\nspacing = \"0.02 cm\"\ncells_across_projectile = 8\n");
  EXPECT_NE(e.find("resolution.cells_across_projectile: given with resolution.spacing"),
            std::string::npos)
      << e;
  e = errorOf(std::string(kTwoWalls) + "[resolution]\nspacing = \"0.02 kg\"\n");
  EXPECT_NE(e.find("resolution.spacing"), std::string::npos) << e;

  EXPECT_THROW((void)loadShield("/nonexistent/shield.toml"), InputError);
}

}  // namespace
}  // namespace hvi::shield
