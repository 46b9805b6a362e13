//! @file The Taylor anvil measurements both solvers' tests compare with.
#pragma once

#include <array>

namespace hvi::test {

//! Johnson and Cook (1983), OFHC copper, L0 = 2.54 cm, D0 = 0.762 cm at 190 m/s, as tabulated
//! by Zerilli and Armstrong (J. Appl. Phys. 61 (1987) 1816; also in B. Banerjee's compilation
//! github.com/bbanerjee/HighRateExptData, TaylorData/DAT/CuZerilli.dat, from which they were
//! read: the papers were not at hand; docs/strength.md).
inline constexpr double kTaylorFinalLength = 1.6205;   // cm
inline constexpr double kTaylorFootDiameter = 1.3564;  // cm

//! One shot of the same rod: impact speed (cm/us), final length and foot diameter (cm).
struct TaylorShot {
  double speed, length, foot;
};
//! The three shots of that compilation (CuZerilli.dat; TaylorData/MATLAB/plotOFHCCu.m gives them
//! as Lf / L0 = 0.770, 0.736, 0.638 and Df / D0 = 1.30, 1.40, 1.78, "actually from Johnson and
//! Cook (1983)").
inline constexpr std::array<TaylorShot, 3> kTaylorShots{
    {{0.0130, 1.9558, 0.9906},
     {0.0146, 1.8694, 1.0668},
     {0.0190, kTaylorFinalLength, kTaylorFootDiameter}}};

//! The length bound of the tests (docs/strength.md, "Why the Taylor rod is long"): the
//! Johnson-Cook 1983 model's own length error at 190 m/s in an independent computation with the
//! same constants (+7.4 %) plus this project's discretisation spread (TVD D0/20 to D0/60: 1 %).
inline constexpr double kTaylorLengthBound = 0.085;

}  // namespace hvi::test
