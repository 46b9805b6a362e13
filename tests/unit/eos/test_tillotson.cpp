//! @file Tillotson EOS: derivatives in every region, continuity, cut-off, floor, known values.
#include <gtest/gtest.h>

#include <cmath>

#include "fd_check.hpp"
#include "hvi/common/error.hpp"
#include "hvi/eos/eos.hpp"

namespace hvi::eos {
namespace {

const Tillotson al = aluminiumStudy();

// Magnitude of the largest terms summed in P (for the round-off part of FD tolerances).
double termScale(double rho, double e) {
  const double mu = rho / al.rho0 - 1.0;
  return (al.a + al.b) * rho * std::abs(e) + al.A * std::abs(mu) + al.B * mu * mu;
}

struct Point {
  double rho, e;
  Tillotson::Region region;
};

// Several states per region, each farther than the FD step from every region border. In the
// expanded branches rho >= 1.6 keeps exp(-alpha z^2) >= 0.06, so every term of P_H is exercised;
// the low densities check the vapour limit P -> a rho e.
const Point kPoints[] = {
    {3.0, 0.0, Tillotson::Region::Compressed},       {3.5, 0.05, Tillotson::Region::Compressed},
    {4.5, 0.3, Tillotson::Region::Compressed},       {6.0, 2.0, Tillotson::Region::Compressed},
    {2.8, 0.2, Tillotson::Region::Compressed},       {2.5, 0.01, Tillotson::Region::ColdExpanded},
    {2.0, 0.025, Tillotson::Region::ColdExpanded},   {1.2, 0.0, Tillotson::Region::ColdExpanded},
    {2.5, 0.05, Tillotson::Region::Blend},           {2.0, 0.1, Tillotson::Region::Blend},
    {1.0, 0.08, Tillotson::Region::Blend},           {0.4, 0.14, Tillotson::Region::Blend},
    {2.5, 0.2, Tillotson::Region::HotExpanded},      {2.0, 0.3, Tillotson::Region::HotExpanded},
    {1.6, 0.2, Tillotson::Region::HotExpanded},      {1.0, 0.5, Tillotson::Region::HotExpanded},
    {0.3, 1.0, Tillotson::Region::HotExpanded},      {0.05, 2.0, Tillotson::Region::HotExpanded},
};

TEST(Tillotson, AnalyticDerivativesMatchFiniteDifferencesInEveryRegion) {
  for (const Point& p : kPoints) {
    ASSERT_EQ(al.region(p.rho, p.e), p.region) << "rho " << p.rho << " e " << p.e;
    // The formula, whatever its sign (cold expanded states are in tension).
    test::expectDerivativesMatchFd([](double r, double e) { return al.formulaState(r, e); },
                                   p.rho, p.e, termScale(p.rho, p.e), "formula");
    // Where the formula is positive, state() is the formula: same check through it.
    if (al.formulaState(p.rho, p.e).pressure > 1e-3) {
      test::expectDerivativesMatchFd([](double r, double e) { return al.state(r, e); }, p.rho,
                                     p.e, termScale(p.rho, p.e), "state");
    }
  }
}

TEST(Tillotson, SoundSpeedFollowsTheDerivatives) {
  for (const Point& p : kPoints) {
    const EosState s = al.state(p.rho, p.e);
    const double c2 = s.dPdRho + s.pressure / (p.rho * p.rho) * s.dPdE;
    if (c2 > al.soundSpeedFloor() * al.soundSpeedFloor()) {
      EXPECT_NEAR(s.soundSpeed, std::sqrt(c2), 1e-14 * std::sqrt(c2));
    } else {
      EXPECT_EQ(s.soundSpeed, al.soundSpeedFloor());
    }
  }
}

TEST(Tillotson, PressureIsContinuousAcrossRegionBorders) {
  // Across rho = rho0 both branches give (a + b/w) rho0 e at mu = 0: continuous for every e.
  // Across e = e1 and e = e2 (rho < rho0) the blend is linear in e between the branch values:
  // continuous (its slope jumps). A step of 1e-10 moves P by |dP/dx| 1e-10, so the tolerance is
  // 1e-8 times the local scale: a missing or wrong branch would leave an O(P) gap.
  const double d = 1e-10;
  for (double e : {0.0, 0.01, 0.03, 0.05, 0.1, 0.15, 0.3, 1.0}) {
    const double lo = al.pressure(al.rho0 * (1 - d), e), hi = al.pressure(al.rho0 * (1 + d), e);
    EXPECT_NEAR(lo, hi, 1e-8 * (termScale(al.rho0, e) + al.A)) << "e " << e;
  }
  for (double rho : {2.6, 2.0, 1.4, 0.8, 0.2}) {
    for (double eb : {al.e1, al.e2}) {
      const EosState a = al.formulaState(rho, eb * (1 - d)), b = al.formulaState(rho, eb * (1 + d));
      EXPECT_NEAR(a.pressure, b.pressure, 1e-8 * (termScale(rho, eb) + al.A))
          << "rho " << rho << " e " << eb;
    }
  }
}

TEST(Tillotson, TensionCutOff) {
  // Expanded cold aluminium is in tension by the formula; with the cut-off it has spalled:
  // P = 0, no response (derivatives 0), sound speed at the floor.
  for (const auto& [rho, e] : {std::pair{2.5, 0.0}, std::pair{2.0, 0.01}, std::pair{1.0, 0.02}}) {
    ASSERT_LT(al.formulaState(rho, e).pressure, 0.0);
    const EosState s = al.state(rho, e);
    EXPECT_EQ(s.pressure, 0.0);
    EXPECT_EQ(s.dPdRho, 0.0);
    EXPECT_EQ(s.dPdE, 0.0);
    EXPECT_EQ(s.soundSpeed, al.soundSpeedFloor());
  }
  Tillotson noCut = al;
  noCut.tensionCutoff = false;
  EXPECT_LT(noCut.state(2.5, 0.0).pressure, 0.0);
  EXPECT_EQ(noCut.state(2.5, 0.0).pressure, al.formulaState(2.5, 0.0).pressure);
}

TEST(Tillotson, SoundSpeedFloorIsPositiveEverywhere) {
  const double floor = al.soundSpeedFloor();
  EXPECT_NEAR(floor, 0.05 * std::sqrt(al.A / al.rho0), 1e-16);
  ASSERT_GT(floor, 0.0);
  for (int i = 0; i <= 60; ++i) {
    const double rho = 0.01 * std::pow(1000.0, i / 60.0);  // 0.01 .. 10 g/cm^3
    for (int j = 0; j <= 60; ++j) {
      const double e = j == 0 ? 0.0 : 1e-4 * std::pow(1e5, j / 60.0);  // 0, 1e-4 .. 10
      const EosState s = al.state(rho, e);
      EXPECT_TRUE(std::isfinite(s.pressure) && std::isfinite(s.soundSpeed));
      EXPECT_GE(s.soundSpeed, floor) << "rho " << rho << " e " << e;
      EXPECT_GE(s.pressure, 0.0);
    }
  }
}

TEST(Tillotson, KnownValues) {
  // Reference state: no pressure, bulk sound speed sqrt(A/rho0) = 0.518476 cm/us (5.18 km/s).
  const EosState ref = al.state(al.rho0, 0.0);
  EXPECT_EQ(ref.pressure, 0.0);
  EXPECT_NEAR(ref.soundSpeed, 0.5184758473652126, 1e-15);
  // By hand at delta = 1.2, e = 0.05: w = 1 + 0.05/(0.05 1.44) = 61/36,
  // P = (0.5 + 1.63 36/61) 3.348 0.05 + 0.75 0.2 + 0.65 0.04 = 0.4207333114754098 Mbar.
  EXPECT_NEAR(al.pressure(1.2 * al.rho0, 0.05), 0.4207333114754098, 1e-15);
  // Study parameters in cm-g-us (spec section 2, docs/method.md).
  EXPECT_EQ(al.rho0, 2.79);
  EXPECT_EQ(al.A, 0.75);
  EXPECT_EQ(al.B, 0.65);
  EXPECT_EQ(al.e0, 0.05);
  EXPECT_EQ(al.e1, 0.03);
  EXPECT_EQ(al.e2, 0.15);
  EXPECT_EQ(al.phase(0.01), Phase::Solid);
  EXPECT_EQ(al.phase(0.1), Phase::PartlyVaporised);
  EXPECT_EQ(al.phase(0.2), Phase::Vapour);
  EXPECT_EQ(kindName(Eos{al}), "tillotson");
}

TEST(Tillotson, BelowTheColdReferenceIsTheTangentPlaneWithoutPole) {
  // e < 0 is an undershoot below the cold reference state. The formula's thermal term has a pole
  // at w = 1 + e/(e0 delta^2) = 0, only e0 delta^2 below zero in expanded states: the state SPH
  // reached in the coarse variant 1 (rho 0.77, e -0.0038: w = 0.003) gave P = 278 Mbar and a
  // time-step collapse. Below e = 0 the thermal coefficient is frozen at a + b:
  // P = (a + b) rho e + A mu + B mu^2, finite for every e, with P, dP/de and dP/drho continuous at
  // e = 0 (round-off values of e around 0 see no kink).
  Tillotson noCut = al;
  noCut.tensionCutoff = false;
  const double g0 = al.a + al.b;
  for (double rho : {0.77, 1.5, 2.79, 3.5, 6.0}) {
    const double mu = rho / al.rho0 - 1.0;
    const double cold = al.A * mu + al.B * mu * mu;
    for (double e : {-1e-12, -0.0038, -0.05 * std::pow(rho / al.rho0, 2), -1.0}) {
      const EosState s = noCut.state(rho, e);
      EXPECT_NEAR(s.pressure, cold + g0 * rho * e, 1e-15 * (std::abs(cold) + g0 * rho))
          << "rho " << rho << " e " << e;
      EXPECT_DOUBLE_EQ(s.dPdE, g0 * rho);
      EXPECT_TRUE(std::isfinite(s.soundSpeed));
    }
    // C1 at e = 0: the formula's value and derivatives there equal the plane's.
    const EosState at0 = noCut.state(rho, 0.0), below = noCut.state(rho, -1e-300);
    EXPECT_NEAR(at0.pressure, below.pressure, 1e-15 * (std::abs(cold) + al.A));
    EXPECT_DOUBLE_EQ(at0.dPdE, below.dPdE);
    EXPECT_DOUBLE_EQ(at0.dPdRho, below.dPdRho);
  }
  // The variant-1 particle: tension in the formula, so spalled under the cut-off.
  EXPECT_LT(noCut.pressure(0.77, -0.0038), 0.0);
  EXPECT_EQ(al.pressure(0.77, -0.0038), 0.0);
}

TEST(Tillotson, EnergyForPressureRoundTrip) {
  // Newton/bisection to ~1e-15: P(rho, e(p)) = p to 1e-12 relative, in every region, including
  // compressed states below the cold curve (e < 0) and with no cut-off in tension.
  const Eos eos{al};
  for (const Point& p : kPoints) {
    const double target = al.pressure(p.rho, p.e);
    if (target <= 0.0) continue;  // spalled: P = 0 for a whole range of e
    const double e = energyForPressure(eos, p.rho, target);
    EXPECT_NEAR(al.pressure(p.rho, e) / target, 1.0, 1e-12) << "rho " << p.rho << " e " << p.e;
    EXPECT_NEAR(e, p.e, 1e-10 * std::max(1.0, std::abs(p.e)));
  }
  const double below = energyForPressure(eos, 3.5, 0.1);  // P(3.5, 0) = 0.233 > 0.1
  EXPECT_LT(below, 0.0);
  EXPECT_NEAR(al.pressure(3.5, below) / 0.1, 1.0, 1e-12);
  Tillotson noCut = al;
  noCut.tensionCutoff = false;
  const double tens = energyForPressure(Eos{noCut}, 2.5, -0.05);
  EXPECT_NEAR(noCut.pressure(2.5, tens) / -0.05, 1.0, 1e-12);
  EXPECT_THROW((void)energyForPressure(eos, 2.5, -0.05), InputError);  // cut-off: no tension
}

}  // namespace
}  // namespace hvi::eos
