//! @file Ideal gas and linear Us-up Mie-Gruneisen: derivatives, sound speed, reference curve.
#include <gtest/gtest.h>

#include <cmath>

#include "fd_check.hpp"
#include "hvi/common/error.hpp"
#include "hvi/eos/eos.hpp"

namespace hvi::eos {
namespace {

TEST(IdealGas, DerivativesAndSoundSpeed) {
  for (double g : {1.4, 5.0 / 3.0, 1.1}) {
    const IdealGas gas{g, 1.0};
    for (const auto& [rho, e] : {std::pair{1.0, 2.5}, std::pair{0.125, 2.0},
                                 std::pair{1e-3, 1e-4}, std::pair{50.0, 300.0}}) {
      test::expectDerivativesMatchFd([&](double r, double x) { return gas.state(r, x); }, rho, e,
                                     gas.pressure(rho, e), "ideal gas");
      const EosState s = gas.state(rho, e);
      EXPECT_NEAR(s.soundSpeed * s.soundSpeed, g * s.pressure / rho, 1e-14 * g * s.pressure / rho);
      EXPECT_NEAR(gas.energyFromPressure(rho, s.pressure), e, 1e-15 * e);
      EXPECT_NEAR(energyForPressure(Eos{gas}, rho, s.pressure) / e, 1.0, 1e-13);
    }
  }
  EXPECT_EQ(kindName(Eos{IdealGas{}}), "ideal_gas");
  EXPECT_THROW((void)energyForPressure(Eos{IdealGas{}}, 1.0, -1.0), InputError);
}

const MieGruneisen cu{};  // copper defaults: rho0 8.93, c0 0.394 cm/us, s 1.49, Gamma0 2

TEST(MieGruneisen, DerivativesMatchFiniteDifferences) {
  MieGruneisen noCut = cu;
  noCut.tensionCutoff = false;
  for (double eta : {-0.2, -0.05, 0.02, 0.1, 0.3, 0.5}) {  // expansion and compression
    const double rho = cu.rho0 / (1.0 - eta);
    for (double e : {0.0, 0.01, 0.2}) {
      const double scale = cu.rho0 * cu.c0 * cu.c0 + cu.gamma0 * cu.rho0 * e;
      test::expectDerivativesMatchFd([&](double r, double x) { return noCut.state(r, x); }, rho,
                                     e, scale * 10.0, "Mie-Gruneisen");
    }
  }
}

TEST(MieGruneisen, ReferenceCurveIsTheUsUpHugoniot) {
  // On the reference curve (e = e_H) the state is the shocked state from (rho0, 0, P = 0):
  // up = sqrt(P (1/rho0 - 1/rho)), Us = P / (rho0 up) must equal c0 + s up.
  for (double eta : {0.01, 0.1, 0.2, 0.4}) {
    const double rho = cu.rho0 / (1.0 - eta);
    const double pH = cu.rho0 * cu.c0 * cu.c0 * eta / std::pow(1.0 - cu.s * eta, 2);
    const double eH = 0.5 * pH * (1.0 / cu.rho0 - 1.0 / rho);
    // P = P_H + Gamma0 rho0 (e - e_H) recombines terms of size P_H: a few ulp.
    EXPECT_NEAR(cu.pressure(rho, eH) / pH, 1.0, 1e-13);
    const double up = std::sqrt(pH * (1.0 / cu.rho0 - 1.0 / rho)), us = pH / (cu.rho0 * up);
    EXPECT_NEAR(us, cu.c0 + cu.s * up, 1e-14);
  }
  // Off the curve P moves by Gamma0 rho0 per unit e (Gamma rho = Gamma0 rho0).
  EXPECT_NEAR(cu.state(10.0, 0.1).dPdE, cu.gamma0 * cu.rho0, 1e-14);
  // Reference state: P = 0, c = c0.
  EXPECT_EQ(cu.state(cu.rho0, 0.0).pressure, 0.0);
  EXPECT_NEAR(cu.state(cu.rho0, 0.0).soundSpeed, cu.c0, 1e-15);
  EXPECT_EQ(kindName(Eos{cu}), "mie_gruneisen");
}

TEST(MieGruneisen, CutOffClampAndRoundTrip) {
  MieGruneisen cut = cu;
  cut.tensionCutoff = true;
  const EosState t = cut.state(0.9 * cu.rho0, 0.0);
  EXPECT_EQ(t.pressure, 0.0);
  EXPECT_EQ(t.dPdRho, 0.0);
  EXPECT_EQ(t.soundSpeed, cut.soundSpeedFloorFraction * cut.c0);
  // Beyond the Hugoniot's asymptote eta = 1/s the compression is clamped at 0.95/s: P stays
  // finite and no longer grows with rho.
  const double rhoHigh = cu.rho0 / (1.0 - 0.99 / cu.s);
  EXPECT_TRUE(std::isfinite(cu.pressure(rhoHigh, 0.0)));
  EXPECT_EQ(cu.state(rhoHigh, 0.0).dPdRho, 0.0);
  for (double rho : {8.0, 8.93, 10.0, 12.0}) {
    for (double p : {0.0, 0.1, 1.0}) {
      const double e = energyForPressure(Eos{cu}, rho, p);
      EXPECT_NEAR(cu.pressure(rho, e), p, 1e-13 * (1.0 + p)) << "rho " << rho << " p " << p;
    }
  }
}

}  // namespace
}  // namespace hvi::eos
