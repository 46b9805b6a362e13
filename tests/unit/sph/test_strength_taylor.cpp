//! @file The Taylor anvil test (r-z SPH with Johnson-Cook strength) against the measured final
//! shape of an OFHC copper cylinder (docs/strength.md, "Taylor anvil").
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/test/taylor.hpp"

namespace hvi::sph {
namespace {

// Johnson and Cook (1983): an OFHC copper cylinder, 2.54 cm long and 0.762 cm in diameter, hits
// a rigid anvil at 190 m/s; measured final length 1.6205 cm, foot diameter 1.3564 cm
// (test/taylor.hpp for the source). The scene cases/scenes/taylor_copper_sph.toml: Johnson-Cook
// 1983 constants (preset copper_ofhc), a mirror wall as the anvil (rigid and frictionless),
// 670 particles (dx = D0 / 20), 80 us (the rod at rest). Bounds: foot diameter within 5 % of
// the measurement (the bound); the rod at rest (kinetic energy < 1e-3 of the impact's);
// total energy exact (1e-12, the compatible form with strength).
// The final length is NOT within 5 %: measured +22 % at this spacing, +16 % at dx = D0 / 40
// (docs/strength.md, "Taylor anvil", open); the convergence study with the length bound is
// `ctest -L study` (tests/study, -DHVI_STUDY=ON). It is printed here, not asserted.
TEST(SphStrength, TaylorAnvilCopperFootDiameter) {
  const double dx = 0.0381;
  const test::TaylorShape t = test::taylorAnvil(dx);
  test::printTaylor(dx, t);
  EXPECT_NEAR(t.footDiameter / test::kTaylorFootDiameter, 1.0, 0.05);
  EXPECT_LT(t.kineticLeft, 1e-3);
  EXPECT_LT(std::abs(t.energyDrift), 1e-12);
}

}  // namespace
}  // namespace hvi::sph
