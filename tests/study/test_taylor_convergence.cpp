//! @file The Taylor anvil (docs/strength.md, "Taylor anvil") at three spacings against the
//! measurement: final length and foot diameter within 5 % at the finest (the bound).
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "hvi/test/taylor.hpp"

namespace hvi::sph {
namespace {

// Runs the rod at `spacings` (coarse to fine) with the scene overrides `options`: the total
// energy exact and the length falling with dx (towards the measurement); at the spacings below
// `checkedBelow` the length and the foot within the 5 % of the measurement and, where
// `restBound` is given, the kinetic energy left below it (of the impact's).
void expectTaylorConverges(const std::vector<std::string>& options,
                           std::initializer_list<double> spacings, double checkedBelow,
                           std::optional<double> restBound = std::nullopt) {
  double previous = 1e300;
  for (double dx : spacings) {
    const test::TaylorShape t = test::taylorAnvil(dx, options);
    test::printTaylor(dx, t);
    EXPECT_LT(std::abs(t.energyDrift), 1e-12);
    EXPECT_LT(t.length, previous);
    previous = t.length;
    if (dx < checkedBelow) {
      EXPECT_NEAR(t.length / test::kTaylorFinalLength, 1.0, 0.05);
      EXPECT_NEAR(t.footDiameter / test::kTaylorFootDiameter, 1.0, 0.05);
      if (restBound) {
        EXPECT_LT(t.kineticLeft, *restBound);
      }
    }
  }
}

// Johnson and Cook (1983) OFHC copper at 190 m/s (test/taylor.hpp): dx = D0 / 20, D0 / 30,
// D0 / 40 (670, 1500, 2660 particles; ~10, 30, 90 s of one core). Measured on branch taylor
// (session 14): L = 1.9764, 1.9223, 1.8828 cm (+22, +19, +16 %), D = 1.3383, 1.3763, 1.3924 cm
// (-1.3, +1.5, +2.7 %): the length fails the 5 % bound (open, docs/strength.md).
TEST(SphStrengthStudy, TaylorAnvilCopperConverges) {
  expectTaylorConverges({}, {0.0381, 0.0254, 0.01905}, 0.02);
}

// With the Morris-Monaghan viscosity switch (docs/strength.md, "SPH viscosity switch"):
// measured L = 1.8198, 1.8095, 1.7880 cm (+12.3, +11.7, +10.3 %), D = 1.2765, 1.3415, 1.3390 cm
// (-5.9, -1.1, -1.3 %) at D0/20, D0/30, D0/40, against +22.0, +18.6, +16.2 % with the constant
// viscosity (0.56 to 0.64 of its excess). Asserted: energy exact, the foot within 5 % from
// D0/30, and the length within 5 % at D0/40, which fails today (open).
TEST(SphStrengthStudy, TaylorAnvilCopperWithViscositySwitch) {
  const std::string sw = "sph.viscosity_switch=\"morris_monaghan\"";
  for (double dx : {0.0381, 0.0254, 0.01905}) {
    const test::TaylorShape t = test::taylorAnvil(dx, {sw});
    test::printTaylor(dx, t);
    EXPECT_LT(std::abs(t.energyDrift), 1e-12);
    if (dx < 0.03) {
      EXPECT_NEAR(t.footDiameter / test::kTaylorFootDiameter, 1.0, 0.05);
    }
    if (dx < 0.02) {
      EXPECT_NEAR(t.length / test::kTaylorFinalLength, 1.0, 0.05);
    }
  }
}

// With the switch and the yield law's plastic strain rate (docs/strength.md, "The plastic strain
// rate in the yield law"): measured L = 1.7297, 1.7160, 1.6935 cm (+6.7, +5.9, +4.5 %), D =
// 1.3211, 1.3871, 1.4025 cm (-2.6, +2.3, +3.4 %) at D0/30, D0/40, D0/60 (1500, 2660, 6000
// particles; the last ~260 s of one core). Asserted: energy exact, the length falling with dx,
// and at D0/60 the length and the foot within the 5 % of the measurement.
TEST(SphStrengthStudy, TaylorAnvilCopperWithSwitchAndPlasticRate) {
  expectTaylorConverges(
      {"sph.viscosity_switch=\"morris_monaghan\"", "sph.yield_strain_rate=\"plastic\""},
      {0.0254, 0.01905, 0.0127}, 0.015);
}

// Zerilli and Armstrong's copper (preset copper_ofhc_za; docs/strength.md, "Zerilli-Armstrong
// copper") with the switch and the plastic strain rate: measured L = 1.6846, 1.6600 cm (+4.0,
// +2.4 %), D = 1.3104, 1.3672 cm (-3.4, +0.8 %) at D0/30, D0/40 (28 and 70 s of one core), the
// kinetic energy left 3.6e-2 and 2.3e-3 of the impact's (with the switch the rod still rings at
// 80 us; these runs move by up to 3 % of the foot when a step is cut short for an output, the
// plastic rate being eps_p's increment over that step). Asserted: energy exact, the length
// falling with dx, and at D0/40 the length and the foot within the 5 % and the rod at
// rest (1e-2).
TEST(SphStrengthStudy, TaylorAnvilCopperZerilliArmstrongWithSwitchAndPlasticRate) {
  expectTaylorConverges({"materials.copper.strength.preset=\"copper_ofhc_za\"",
                         "sph.viscosity_switch=\"morris_monaghan\"",
                         "sph.yield_strain_rate=\"plastic\""},
                        {0.0254, 0.01905}, 0.02, 1e-2);
}

}  // namespace
}  // namespace hvi::sph
