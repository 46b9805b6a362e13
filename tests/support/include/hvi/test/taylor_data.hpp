//! @file The Taylor anvil measurement both solvers' tests compare with.
#pragma once

namespace hvi::test {

//! Johnson and Cook (1983), OFHC copper, L0 = 2.54 cm, D0 = 0.762 cm at 190 m/s, as tabulated
//! by Zerilli and Armstrong (J. Appl. Phys. 61 (1987) 1816; also in B. Banerjee's compilation
//! github.com/bbanerjee/HighRateExptData, TaylorData/DAT/CuZerilli.dat, from which they were
//! read: the papers were not at hand; docs/strength.md).
inline constexpr double kTaylorFinalLength = 1.6205;   // cm
inline constexpr double kTaylorFootDiameter = 1.3564;  // cm

}  // namespace hvi::test
