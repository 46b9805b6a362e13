//! @file The Whipple BLE against values computed by hand from Christiansen (1993)'s equations.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/shield/ble.hpp"

namespace hvi::shield {
namespace {

// The example shield (shield/examples/whipple_tp2003.toml): Al 2017-T4 projectile rho_p = 2.8,
// Al 6061-T6 bumper t_b = 0.127 cm rho_b = 2.7, standoff S = 10.16 cm, Al 2024-T3 rear wall
// t_w = 0.406 cm, sigma = 50 ksi.
WhippleBle example() {
  return {.projectileDensity = 2.8,
          .bumperDensity = 2.7,
          .bumperThickness = 0.127,
          .rearWallThickness = 0.406,
          .rearWallYieldKsi = 50.0,
          .standoff = 10.16};
}

// Products rounded to 6 digits at every step: 1e-5 relative covers the rounding.
constexpr double kRel = 1e-5;

TEST(WhippleBle, HypervelocityRegimeByHand) {
  // V = 10 km/s: t_w^(2/3) = 0.548299, rho_p^(-1/3) = 0.709492, rho_b^(-1/9) = 0.895511,
  // V^(-2/3) = 0.215443, S^(1/3) = 2.165864, (50/70)^(1/3) = 0.893904;
  // d_c = 3.918 * 0.548299 * 0.709492 * 0.895511 * 0.215443 * 2.165864 * 0.893904 = 0.569318 cm.
  EXPECT_NEAR(criticalDiameter(example(), 10.0), 0.569318, 0.569318 * kRel);
  EXPECT_EQ(bleRegime(example(), 10.0), BleRegime::Hypervelocity);
  // d_c ~ V^(-2/3): at 7 km/s 0.569318 * (10/7)^(2/3) = 0.722143.
  EXPECT_NEAR(criticalDiameter(example(), 7.0), 0.722143, 0.722143 * kRel);
}

TEST(WhippleBle, BallisticRegimeByHand) {
  // V = 2 km/s: t_w (sigma/40)^0.5 + t_b = 0.406 * 1.118034 + 0.127 = 0.580922;
  // 0.6 rho_p^0.5 V^(2/3) = 0.6 * 1.673320 * 1.587401 = 1.593738;
  // d_c = (0.580922 / 1.593738)^(18/19) = 0.364503^(0.947368) = 0.384387 cm.
  EXPECT_NEAR(criticalDiameter(example(), 2.0), 0.384387, 0.384387 * kRel);
  EXPECT_EQ(bleRegime(example(), 2.0), BleRegime::Ballistic);
  // Independent of the standoff below 3 km/s.
  WhippleBle far = example();
  far.standoff = 30.0;
  EXPECT_DOUBLE_EQ(criticalDiameter(far, 2.0), criticalDiameter(example(), 2.0));
}

TEST(WhippleBle, ShatterRegimeIsTheLinearInterpolation) {
  // d_c(3) = (0.580922 / (0.6 * 1.673320 * 3^(2/3) [2.080084] = 2.088388))^(18/19) = 0.297546;
  // d_c(7) = 0.722143 (above); at 5 km/s halfway: (0.297546 + 0.722143) / 2 = 0.509845.
  EXPECT_NEAR(criticalDiameter(example(), 3.0), 0.297546, 0.297546 * kRel);
  EXPECT_NEAR(criticalDiameter(example(), 5.0), 0.509845, 0.509845 * kRel);
  EXPECT_EQ(bleRegime(example(), 5.0), BleRegime::Shatter);
  // Continuous at both regime boundaries.
  for (double v : {3.0, 7.0})
    EXPECT_NEAR(criticalDiameter(example(), v * (1 + 1e-12)), criticalDiameter(example(), v), 1e-9);
}

TEST(WhippleBle, ObliqueImpactUsesTheNormalComponent) {
  // 45 degrees, 10 km/s: V cos = 7.071068, still hypervelocity:
  // d_c = 0.569318 * (1 / cos 45)^(2/3) = 0.569318 * 1.259921 = 0.717296.
  WhippleBle s = example();
  s.angleDegrees = 45.0;
  EXPECT_NEAR(criticalDiameter(s, 10.0), 0.717296, 0.717296 * kRel);
}

TEST(WhippleBle, RefusesNonPhysicalInput) {
  WhippleBle s = example();
  s.rearWallThickness = 0.0;
  EXPECT_THROW((void)criticalDiameter(s, 7.0), std::invalid_argument);
  EXPECT_THROW((void)criticalDiameter(example(), -1.0), std::invalid_argument);
}

TEST(WhippleBle, BumperAdequacy) {
  // t_b / d = 0.127 / 0.5 = 0.254 >= 0.25 (S/d = 20.3 < 30); 0.127 / 0.6 = 0.212 < 0.25.
  EXPECT_TRUE(bumperAdequate(example(), 0.5));
  EXPECT_FALSE(bumperAdequate(example(), 0.6));
}

}  // namespace
}  // namespace hvi::shield
