//! @file `--set key=value` overrides: values read as TOML or strings, unknown paths rejected.
#include <gtest/gtest.h>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"

namespace hvi::cases {
namespace {

const std::filesystem::path kVariant1 = test::shippedDir() / "variant1_tvd.toml";

std::string errorOf(const std::filesystem::path& f, const std::vector<std::string>& sets) {
  try {
    (void)loadScene(f, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for the overrides";
  return {};
}

TEST(SceneOverrides, SetNumbersStringsQuantitiesAndArrays) {
  const Scene s =
      loadScene(kVariant1, {"sph.alpha=1.5", "time.end=2 us", "tvd.limiter=superbee",
                            "output.times=[\"0.5 us\", \"2 us\"]", "bodies[0].velocity[1]=-7 km/s",
                            "title=changed", "output.vtk=false", "tvd.cfl = 0.25"});
  EXPECT_EQ(s.sph.alpha, 1.5);
  EXPECT_EQ(s.tEnd, 2.0);
  EXPECT_EQ(s.tvd.limiter, Limiter::Superbee);
  EXPECT_EQ(s.output.times, (std::vector<double>{0.5, 2.0}));
  EXPECT_DOUBLE_EQ(s.bodies[0].velocity.z, -0.7);
  EXPECT_EQ(s.title, "changed");
  EXPECT_FALSE(s.output.vtk);
  EXPECT_EQ(s.tvd.cfl, 0.25);
}

TEST(SceneOverrides, LaterOverridesWinAndMissingSectionsAreCreated) {
  const auto sod = test::shippedDir() / "sod_x.toml";
  const Scene s =
      loadScene(sod, {"riemann.cells=100", "riemann.cells=200", "output.checkpoint_every=10 min",
                      "sph.h_factor=1.3", "effects=[\"energy_budget\"]"});
  EXPECT_EQ(s.riemann.cells, 200);
  EXPECT_EQ(s.output.checkpointEvery, 600.0);
  EXPECT_EQ(s.sph.hFactor, 1.3);
  EXPECT_TRUE(s.has(Effect::EnergyBudget));
  // Switching the solver also switches which effects are allowed.
  const Scene v = loadScene(kVariant1, {"solver=sph", "effects=[\"artificial_viscosity\"]"});
  EXPECT_EQ(v.solver, SolverKind::Sph);
}

TEST(SceneOverrides, NewMaterialFromTheCommandLine) {
  const Scene s =
      loadScene(kVariant1, {"materials.cu.preset=copper_mie_gruneisen", "bodies[0].material=cu"});
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[1].name, "cu");  // created by --set: after the file's materials
  EXPECT_EQ(s.bodies[0].material, 1);
  EXPECT_EQ(s.bodies[0].density, 8.93);
}

TEST(SceneOverrides, UnknownPathsAreRejectedWithASuggestion) {
  auto has = [](const std::string& msg, const std::string& part) {
    EXPECT_NE(msg.find(part), std::string::npos) << "missing \"" << part << "\" in: " << msg;
  };
  std::string m = errorOf(kVariant1, {"sph.alpa=1.5"});
  has(m, "variant1_tvd.toml (--set sph.alpa=1.5): sph.alpa: unknown key");
  has(m, "did you mean \"alpha\"");
  m = errorOf(kVariant1, {"sovler=tvd"});
  has(m, "did you mean \"solver\"");
  m = errorOf(kVariant1, {"bodies[7].radius=1 cm"});
  has(m, "no element 7");
  m = errorOf(kVariant1, {"bodies[0].radiuss=1 cm"});
  has(m, "did you mean \"radius\"");
  m = errorOf(kVariant1, {"time.end.x=1"});
  has(m, "no keys below it");
  m = errorOf(kVariant1, {"sph.alpha"});
  has(m, "expected key=value");
  m = errorOf(kVariant1, {"bodies[x].radius=1 cm"});
  has(m, "bad array index");
}

// The body keys --set accepts are the parser's (one table, keys_structure.cpp): radial_velocity
// and radial_centre used to be missing there, so the override was refused as an unknown key.
TEST(SceneOverrides, RadialVelocityAndCentreOfABody) {
  const auto rz = test::shippedDir() / "study" / "noh_cylindrical_rz.toml";
  const Scene s = loadScene(rz, {"bodies[0].radial_velocity=-5 km/s"});
  ASSERT_TRUE(s.bodies[0].radial);
  EXPECT_DOUBLE_EQ(s.bodies[0].radialSpeed, -0.5);  // 5 km/s = 0.5 cm/us
  // The path is accepted; the parser then refuses a centre in rz, naming the override.
  const std::string m = errorOf(rz, {"bodies[0].radial_centre=[\"0 cm\", \"0 cm\"]"});
  EXPECT_NE(m.find("bodies[0].radial_centre: in rz geometry the radial field is about the axis"),
            std::string::npos)
      << m;
  const Scene p =
      loadScene(test::shippedDir() / "sod_x.toml",
                {"solver=tvd", "bodies[1].radial_velocity=-1 km/s",
                 "bodies[1].radial_centre=[\"0.75 cm\", \"0.01 cm\"]"});
  ASSERT_TRUE(p.bodies[1].radial);
  EXPECT_DOUBLE_EQ(p.bodies[1].radialSpeed, -0.1);
  EXPECT_EQ(p.bodies[1].radialCentre, (Vec2{0.75, 0.01}));
  // An unknown body key lists them among the allowed ones.
  const std::string u = errorOf(rz, {"bodies[0].radial_speed=1 km/s"});
  EXPECT_NE(u.find("radial_velocity, radial_centre"), std::string::npos) << u;
}

// A material's keys come from its EOS table (keys_structure.cpp): the message lists them in the
// table's order, the order toToml writes them in.
TEST(SceneOverrides, KeyOfAnotherEosListsTheTableOfThisOne) {
  const std::string m = errorOf(kVariant1, {"materials.aluminium.c0=1"});
  EXPECT_NE(m.find("materials.aluminium.c0: not a parameter of eos = \"tillotson\"; allowed: "
                   "preset, eos, rho0, a, b, A, B, e0, alpha, beta, e1, e2, sound_speed_floor"),
            std::string::npos)
      << m;
}

TEST(SceneOverrides, BadValuesPointAtTheOverride) {
  auto has = [](const std::string& msg, const std::string& part) {
    EXPECT_NE(msg.find(part), std::string::npos) << "missing \"" << part << "\" in: " << msg;
  };
  std::string m = errorOf(kVariant1, {"sph.alpha=-1"});
  has(m, "(--set sph.alpha=-1): sph.alpha: must be >= 0");
  m = errorOf(kVariant1, {"time.end=2"});  // a bare number in a file with units
  has(m, "(--set time.end=2): time.end: a bare number has no unit");
  m = errorOf(kVariant1, {"tvd.limiter=vanleer"});
  has(m, "did you mean \"van_leer\"");
  m = errorOf(kVariant1, {"bodies[0].radius=0.6 cm"});  // the sphere now sinks into the plate
  has(m, "overlaps bodies[0]");
  m = errorOf(kVariant1, {"effects=[\"mass_adjustment\"]"});
  has(m, "not supported by solver \"tvd\"");
}

}  // namespace
}  // namespace hvi::cases
