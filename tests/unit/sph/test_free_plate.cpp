//! @file A free aluminium plate at rest in vacuum: modified SPH keeps it at rest.
#include <gtest/gtest.h>

#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// No tension cut-off: a density deficit then means real tension, which is what makes the
// deficient free surface of traditional SPH move (with the cut-off it would merely give P = 0).
double maxSpeedAfter(bool modified, int steps) {
  auto s = test::baseScene(Geometry::Planar, -1.0, 1.0, -1.0, 1.0, 0.01,
                           {Effect::ArtificialViscosity});
  if (modified) s.effects.insert(Effect::MassAdjustment);
  s.materials = {test::aluminium()};
  s.bodies = {test::rectBody("plate", 0, -0.2, 0.2, -0.05, 0.05)};
  test::resolveDensities(s);
  SphSolver solver(s);
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  std::printf("%s SPH: %d steps to t = %.3f us, max speed %.3e cm/us\n",
              modified ? "modified" : "traditional", steps, solver.time(),
              test::maxSpeed(solver.stepper().particles()));
  return test::maxSpeed(solver.stepper().particles());
}

TEST(FreePlate, ModifiedStaysAtRestTraditionalDoesNot) {
  const double vMod = maxSpeedAfter(true, 200);
  const double vTrad = maxSpeedAfter(false, 200);
  // Bound for modified SPH: the mass iteration leaves |rho/rho0 - 1| < 1e-9, so |P| < A 1e-9
  // = 7.5e-10 Mbar; the pressure acceleration is at most ~2 |P| sum_j m_j |grad W| / rho^2
  // ~ 2.3 |P| / (rho0 h) = 6e-8 cm/us^2, which over the ~0.7 us of 200 steps gives
  // < 4.5e-8 cm/us even if it never reversed. (Measured: see the printed value.)
  EXPECT_LT(vMod, 1e-7);
  // Traditional SPH: the free-surface particles miss ~25% of their kernel, sit in tension of
  // ~0.2 Mbar and are pulled inwards at a sizeable fraction of the sound speed.
  EXPECT_GT(vTrad, 1e4 * 1e-7);
}

}  // namespace
}  // namespace hvi::sph
