//! @file r-z: a closed box of gas at uniform pressure stays at rest, the axis included.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// Gas at rho = 1, P = 1 (c = 1.29 cm/us) filling r < 0.3, |z| < 0.1 with walls all round and
// the axis: uniform pressure exerts no force, so nothing may move. The particles next to the
// axis test the hoop terms: there the pair sums see the mirror ghosts' |r| smoothed by the
// kernel and, uncorrected, push them outwards at ~1.8 P / (rho h) (docs/sph-rz.md).
double maxSpeedInPressurisedBox(int steps) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.3, -0.1, 0.1, 0.01,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  for (int k = 1; k < 4; ++k) s.domain.boundary[k] = cases::Boundary::Wall;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.3, -0.1, 0.1, {}, 1.0, 1.5)};
  SphSolver solver(s);
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  const double v = test::maxSpeed(solver.stepper().particles());
  std::printf("r-z box at P = 1 Mbar: max speed after %d steps (t = %.3f us): %.3e cm/us\n",
              steps, solver.time(), v);
  return v;
}

TEST(RzAxis, UniformPressureBoxStaysAtRest) {
  // The corrected hoop term balances the radial pressure sum only up to the lattice's
  // deviation from the continuum (the correction is derived for a continuous distribution of
  // neighbours): measured 6e-3 c after 40 steps. Uncorrected (C = 1) the axis particles reach
  // 6e-2 c; 2e-2 c separates the two with margin on both sides.
  EXPECT_LT(maxSpeedInPressurisedBox(40), 2e-2 * 1.29);
}

}  // namespace
}  // namespace hvi::sph
