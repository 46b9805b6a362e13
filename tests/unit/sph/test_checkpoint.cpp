//! @file A restart from a checkpoint continues bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "hvi/common/error.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/same_bits.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

cases::Scene scene(Geometry g, cases::EnergyForm energy = cases::EnergyForm::Compatible) {
  auto s =
      test::baseScene(g, g == Geometry::Planar ? -0.4 : 0.0, 0.4, -0.2, 0.3, 0.02,
                      {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::TensionCutoff});
  s.domain.boundary[2] = cases::Boundary::Wall;
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.1}, 0.1, {0.0, -0.6}),
              test::rectBody("plate", 0, g == Geometry::Planar ? -0.3 : 0.0, 0.3, -0.06, 0.0)};
  test::resolveDensities(s);
  s.sph.energy = energy;
  return s;
}

// The two runs' particle states are the same to the bit (positions, velocities, density, energy).
void expectSameState(const ParticleSystem& a, const ParticleSystem& b) {
  EXPECT_TRUE(hvi::test::sameBits(a.x, b.x));
  EXPECT_TRUE(hvi::test::sameBits(a.z, b.z));
  EXPECT_TRUE(hvi::test::sameBits(a.vx, b.vx));
  EXPECT_TRUE(hvi::test::sameBits(a.vz, b.vz));
  EXPECT_TRUE(hvi::test::sameBits(a.rho, b.rho));
  EXPECT_TRUE(hvi::test::sameBits(a.e, b.e));
}

void checkRestart(Geometry g, cases::EnergyForm energy) {
  const cases::Scene s = scene(g, energy);
  SphSolver original(s);
  for (int k = 0; k < 15; ++k) original.advance(1e9);
  std::stringstream ckpt;
  original.writeCheckpoint(ckpt);
  for (int k = 0; k < 15; ++k) original.advance(1e9);

  SphSolver restarted(s);
  restarted.readCheckpoint(ckpt);
  EXPECT_EQ(restarted.step(), 15);
  for (int k = 0; k < 15; ++k) restarted.advance(1e9);
  const ParticleSystem a = original.stepper().particles(), b = restarted.stepper().particles();
  EXPECT_EQ(original.time(), restarted.time());
  expectSameState(a, b);
  EXPECT_TRUE(hvi::test::sameBits(a.p, b.p));
}

// An output frees the step's work space (Stepper::releaseWork, docs/performance.md "SPH
// memory"); the next step allocates it again and must continue bit for bit, as if no output
// had been written.
void checkOutputsChangeNothing(Geometry g) {
  const cases::Scene s = scene(g);
  SphSolver plain(s), written(s);
  for (int k = 0; k < 15; ++k) {
    plain.advance(1e9);
    written.advance(1e9);
    if (k % 4 == 0) (void)written.snapshot();
  }
  const ParticleSystem a = plain.stepper().particles(), b = written.stepper().particles();
  EXPECT_EQ(plain.time(), written.time());
  expectSameState(a, b);
}

TEST(Checkpoint, PlanarOutputsBetweenStepsChangeNoBit) { checkOutputsChangeNothing(Geometry::Planar); }
TEST(Checkpoint, RzOutputsBetweenStepsChangeNoBit) {
  checkOutputsChangeNothing(Geometry::Axisymmetric);
}

// The compatible energy (the default) keeps no state between steps beyond the checkpointed one;
// the study's symmetric form is checked as well.
// The shared bit-for-bit comparison (tests/support hvi/test/same_bits.hpp) is stricter than ==
// where a restart could differ unseen: the sign of a zero, and a NaN equals itself only bitwise.
TEST(Checkpoint, SameBitsIsBitwise) {
  using hvi::test::sameBits;
  EXPECT_FALSE(sameBits(0.0, -0.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(sameBits(nan, nan));
  EXPECT_TRUE(sameBits(std::vector<double>{1.0, nan}, std::vector<double>{1.0, nan}));
  const auto diff = sameBits(std::vector<double>{1.0, 0.0}, std::vector<double>{1.0, -0.0});
  EXPECT_FALSE(diff);
  EXPECT_NE(std::string(diff.message()).find("element 1 of 2"), std::string::npos)
      << diff.message();
  EXPECT_FALSE(sameBits(std::vector<double>{1.0}, std::vector<double>{1.0, 2.0}));
}

TEST(Checkpoint, PlanarRestartIsBitForBit) {
  checkRestart(Geometry::Planar, cases::EnergyForm::Compatible);
  checkRestart(Geometry::Planar, cases::EnergyForm::Symmetric);
}
TEST(Checkpoint, RzRestartIsBitForBit) {
  checkRestart(Geometry::Axisymmetric, cases::EnergyForm::Compatible);
  checkRestart(Geometry::Axisymmetric, cases::EnergyForm::Symmetric);
}

// A time step a million times below the first stops the run, and the message names the particle
// that set it. The state is made singular by patching one particle's energy in a checkpoint
// (the only way in between steps): e = 1e16 cm^2/us^2 gives c ~ a sqrt(e) = 5e7 cm/us against
// the cold 0.52 cm/us, so dt falls by ~1e8 (> 1e6) whichever limit (signal or acceleration) sets
// it.
TEST(Checkpoint, TimeStepCollapseNamesTheParticle) {
  const cases::Scene s = scene(Geometry::Planar);
  SphSolver solver(s);
  for (int k = 0; k < 3; ++k) solver.advance(1e9);
  std::stringstream ckpt;
  solver.writeCheckpoint(ckpt);
  std::string bytes = ckpt.str();
  const ParticleSystem ps = solver.stepper().particles();
  const std::size_t n = ps.size(), k = n / 2;
  // Layout (sph/src/checkpoint.cpp): magic 8, n 8, geometry 4, materials 4, t 8, steps 8, dt0 8,
  // outflow 5 x 8; then x, z, vx, vz, h (doubles), object (int), e (doubles).
  const std::size_t eAt = 88 + 5 * n * sizeof(double) + n * sizeof(int) + k * sizeof(double);
  double eOld = 0.0;
  std::memcpy(&eOld, bytes.data() + eAt, sizeof eOld);
  ASSERT_EQ(eOld, ps.e[k]);  // the layout is what this test assumes
  const double hot = 1e16;
  std::memcpy(bytes.data() + eAt, &hot, sizeof hot);
  SphSolver restarted(s);
  std::stringstream patched(bytes);
  restarted.readCheckpoint(patched);
  try {
    restarted.advance(1e9);
    FAIL() << "a collapsed time step must stop the run";
  } catch (const SimulationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("time step collapsed at step 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fmt::format("particle {} of object", ps.id[k])), std::string::npos) << msg;
    EXPECT_NE(msg.find("e = 1e+16"), std::string::npos) << msg;
  }
}

TEST(Checkpoint, ForeignDataIsAnInputError) {
  SphSolver solver(scene(Geometry::Planar));
  std::stringstream junk("not a checkpoint at all");
  EXPECT_THROW(solver.readCheckpoint(junk), InputError);
}

}  // namespace
}  // namespace hvi::sph
