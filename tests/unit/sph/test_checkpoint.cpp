//! @file A restart from a checkpoint continues bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "hvi/common/error.hpp"
#include "hvi/sph/sph.hpp"
#include "sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

cases::Scene scene(Geometry g) {
  auto s = test::baseScene(g, g == Geometry::Planar ? -0.4 : 0.0, 0.4, -0.2, 0.3, 0.02,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment,
                            Effect::TensionCutoff});
  s.domain.boundary[2] = cases::Boundary::Wall;
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.1}, 0.1, {0.0, -0.6}),
              test::rectBody("plate", 0, g == Geometry::Planar ? -0.3 : 0.0, 0.3, -0.06, 0.0)};
  test::resolveDensities(s);
  return s;
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void checkRestart(Geometry g) {
  const cases::Scene s = scene(g);
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
  EXPECT_TRUE(sameBits(a.x, b.x));
  EXPECT_TRUE(sameBits(a.z, b.z));
  EXPECT_TRUE(sameBits(a.vx, b.vx));
  EXPECT_TRUE(sameBits(a.vz, b.vz));
  EXPECT_TRUE(sameBits(a.rho, b.rho));
  EXPECT_TRUE(sameBits(a.e, b.e));
  EXPECT_TRUE(sameBits(a.p, b.p));
}

TEST(Checkpoint, PlanarRestartIsBitForBit) { checkRestart(Geometry::Planar); }
TEST(Checkpoint, RzRestartIsBitForBit) { checkRestart(Geometry::Axisymmetric); }

TEST(Checkpoint, ForeignDataIsAnInputError) {
  SphSolver solver(scene(Geometry::Planar));
  std::stringstream junk("not a checkpoint at all");
  EXPECT_THROW(solver.readCheckpoint(junk), InputError);
}

}  // namespace
}  // namespace hvi::sph
