//! @file SPH with the effect `strength` (docs/strength.md, "SPH"): elastic wave speed, the
//! Hugoniot elastic limit, conservation, mirror ghosts, checkpoint and snapshot fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <variant>
#include <vector>

#include "hvi/test/two_wave.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/same_bits.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// Aluminium of the study's Tillotson EOS with a constant (elastic-perfectly plastic) yield and
// the shear modulus of 6061-T6 (Steinberg 1991: 27.6 GPa).
constexpr double kShear = 0.276;  // Mbar
cases::Material strongAluminium(double y0) {
  cases::Material m = test::aluminium();
  strength::Material sm;
  sm.shearModulus = kShear;
  sm.yield = strength::ConstantYield{y0};
  sm.thermal.cv = 0.896e-5;
  m.strength = sm;
  return m;
}

std::set<Effect> effects(bool withStrength) {
  std::set<Effect> e{Effect::ArtificialViscosity, Effect::MassAdjustment};
  if (withStrength) e.insert(Effect::Strength);
  return e;
}

// Uniaxial strain (a 1-D slab): a strip `columns` particles wide between two walls (mirrors)
// at x = 0 and x = width, so the ghosts continue it laterally without end. A flyer of the same
// material (z in [0, flyer]) moving at -v0 hits the target (z in [-depth, 0]) at rest.
// In r-z (`rz`) the strip is a cylinder of radius `width` on the axis inside a rigid tube (a
// wall at r = width): uniaxial strain again, now with the hoop stress balancing the radial one.
cases::Scene slab(double dx, int columns, double depth, double flyer, double v0, double y0,
                  bool withStrength, bool rz = false) {
  const double width = columns * dx;
  auto s = test::baseScene(rz ? Geometry::Axisymmetric : Geometry::Planar, 0.0, width, -depth - 0.5,
                           flyer + 0.5, dx, {});
  s.effects = effects(withStrength);
  s.domain.boundary[0] = rz ? cases::Boundary::Axis : cases::Boundary::Wall;
  s.domain.boundary[1] = cases::Boundary::Wall;
  s.materials = {withStrength ? strongAluminium(y0) : test::aluminium()};
  s.bodies = {test::rectBody("flyer", 0, 0.0, width, 0.0, flyer, {0.0, -v0}),
              test::rectBody("target", 0, 0.0, width, -depth, 0.0)};
  test::resolveDensities(s);
  return s;
}

// Depth of the front: where the row-averaged longitudinal velocity -v_z of the target first
// reaches `level` coming from its undisturbed deep end, linear between rows.
double frontDepth(const ParticleSystem& ps, double dx, double level) {
  std::vector<double> sum, cnt;
  double zmin = 1e300;
  for (std::size_t i = 0; i < ps.size(); ++i) zmin = std::min(zmin, ps.z[i]);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto row = static_cast<std::size_t>(std::lround((ps.z[i] - zmin) / dx));
    if (row >= sum.size()) {
      sum.resize(row + 1, 0.0);
      cnt.resize(row + 1, 0.0);
    }
    sum[row] -= ps.vz[i];
    cnt[row] += 1.0;
  }
  double prev = sum[0] / cnt[0];
  for (std::size_t r = 1; r < sum.size(); ++r) {
    const double v = cnt[r] > 0.0 ? sum[r] / cnt[r] : prev;
    if (v >= level) return zmin + dx * (static_cast<double>(r) - (v - level) / (v - prev));
    prev = v;
  }
  return 0.0;
}

// Speed of the front between times t1 and t2 (front positions from the velocity profile).
double frontSpeed(const cases::Scene& s, double t1, double t2, double level) {
  SphSolver solver(s);
  solver.advance(t1);
  while (solver.time() < t1) solver.advance(t1);
  const double z1 = frontDepth(solver.stepper().particles(), s.sph.spacing, level);
  while (solver.time() < t2) solver.advance(t2);
  const double z2 = frontDepth(solver.stepper().particles(), s.sph.spacing, level);
  return (z1 - z2) / (t2 - t1);
}

// A small velocity step (1 m/s, strain ~1e-4: linear elasticity) in a laterally confined slab
// travels at the longitudinal speed c_L = sqrt((K + 4G/3) / rho) = sqrt(c0^2 + 4G / (3 rho0))
// (Meyers, Dynamic behavior of materials, 1994, ch. 2), not at the bulk speed c0 of the
// hydrodynamic run. The front (half of the particle-velocity jump v0/2 of equal materials) is
// located in the row-averaged velocity profile at 0.5 and 1.4 us, after it has formed; its
// smearing is then nearly steady and cancels in the difference. 1 % is the bound.
// Measured (dx = 0.01 cm, h = dx): c_L -0.16 %; the hydrodynamic run's front gives c0 -0.75 %
// (also at dx = 0.005), the size of what the front's changing shape leaves in this measurement.
// The test discriminates: the bulk speed is 18 % below c_L.
TEST(SphStrength, ElasticWaveTravelsAtLongitudinalSpeed) {
  const double v0 = 1e-4, dx = 0.01;
  const eos::Eos al = test::aluminium().eos;
  const double rho0 = eos::referenceDensity(al);
  const double c0 = std::visit([&](const auto& e) { return e.state(rho0, 0.0).soundSpeed; }, al);
  const double cL = strength::longitudinalSoundSpeed(c0, kShear, rho0);
  const double elastic = frontSpeed(slab(dx, 4, 1.0, 0.3, v0, 1.0, true), 0.5, 1.4, 0.25 * v0);
  const double bulk = frontSpeed(slab(dx, 4, 1.0, 0.3, v0, 1.0, false), 0.5, 1.4, 0.25 * v0);
  std::printf(
      "c0 = %.5f, c_L = %.5f cm/us; measured: strength %.5f (%.2f %%), hydro %.5f "
      "(%.2f %%)\n",
      c0, cL, elastic, 100.0 * (elastic / cL - 1.0), bulk, 100.0 * (bulk / c0 - 1.0));
  EXPECT_NEAR(elastic / cL, 1.0, 0.01);
  EXPECT_NEAR(bulk / c0, 1.0, 0.01);  // and without strength, the bulk speed
  EXPECT_GT(elastic / bulk, 1.15);
}

// Row averages (deep end first) of the longitudinal stress -sigma_zz = P - s_zz and of -v_z.
struct Profile {
  std::vector<double> z, stress, velocity;
};
Profile profile(const SphSolver& solver, double dx) {
  const ParticleSystem ps = solver.stepper().particles();
  const StrengthFields f = solver.stepper().strengthFields();
  double zmin = 1e300;
  for (std::size_t i = 0; i < ps.size(); ++i) zmin = std::min(zmin, ps.z[i]);
  Profile p;
  std::vector<double> cnt;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto row = static_cast<std::size_t>(std::lround((ps.z[i] - zmin) / dx));
    if (row >= cnt.size()) {
      cnt.resize(row + 1, 0.0);
      p.z.resize(row + 1, 0.0);
      p.stress.resize(row + 1, 0.0);
      p.velocity.resize(row + 1, 0.0);
    }
    cnt[row] += 1.0;
    p.z[row] += ps.z[i];
    p.stress[row] += ps.p[i] - (f.szz.empty() ? 0.0 : f.szz[i]);
    p.velocity[row] -= ps.vz[i];
  }
  for (std::size_t r = 0; r < cnt.size(); ++r)
    if (cnt[r] > 0.0) {
      p.z[r] /= cnt[r];
      p.stress[r] /= cnt[r];
      p.velocity[r] /= cnt[r];
    }
  return p;
}

// The same in r-z: the step travels down a cylinder (6 particles across, on the axis, in a rigid
// tube) at c_L. In uniaxial strain s_rr = s_tt, so the radial force (1/r) d(r sigma_rr)/dr -
// sigma_tt / r vanishes only if the hoop stress term balances the r-weighted pair sum, through
// the axis correction: a wrong hoop term drives a radial flow. Measured: c_L -0.48 %, max |v_r|
// 3.5e-6 cm/us at 1 us (the hydrodynamic run's own: 1.3e-5). Bounds: 1 % (the planar test's),
// |v_r| < 5 % of v0.
TEST(SphStrength, ElasticWaveTravelsAtLongitudinalSpeedInRz) {
  const double v0 = 1e-4, dx = 0.01;
  const eos::Eos al = test::aluminium().eos;
  const double rho0 = eos::referenceDensity(al);
  const double c0 = std::visit([&](const auto& e) { return e.state(rho0, 0.0).soundSpeed; }, al);
  const double cL = strength::longitudinalSoundSpeed(c0, kShear, rho0);
  const cases::Scene s = slab(dx, 6, 1.0, 0.3, v0, 1.0, true, true);
  const double elastic = frontSpeed(s, 0.5, 1.4, 0.25 * v0);
  SphSolver solver(s);
  while (solver.time() < 1.0) solver.advance(1.0);
  const double vr = [&] {
    const ParticleSystem ps = solver.stepper().particles();
    double m = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i) m = std::max(m, std::abs(ps.vx[i]));
    return m;
  }();
  std::printf("r-z: c_L = %.5f cm/us; measured %.5f (%.2f %%); max |v_r| = %.2e cm/us (v0 %.0e)\n",
              cL, elastic, 100.0 * (elastic / cL - 1.0), vr, v0);
  EXPECT_NEAR(elastic / cL, 1.0, 0.01);
  // No radial flow beyond a few % of the axial particle velocity v0/2.
  EXPECT_LT(vr, 0.05 * v0);
}

// r-z energy with strength: a disk (a sphere) at 6 km/s on a plate resting on a wall with the
// 6061-T6 Steinberg-Guinan preset; the hoop stress terms cancel particle by particle in the
// energy as the pressure's do (docs/sph-rz.md), so the compatible form stays exact: bound
// 1e-12 as without strength (Conservation.CompatibleEnergyIsExactInRz).
TEST(SphStrength, TotalEnergyIsConservedWithStrengthInRz) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.4, -0.2, 0.3, 0.02,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::Strength});
  s.domain.boundary[2] = cases::Boundary::Wall;
  cases::Material al = test::aluminium();
  al.strength = strength::findPreset("al6061_t6")->material;
  s.materials = {al};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.1}, 0.1, {0.0, -0.6}),
              test::rectBody("plate", 0, 0.0, 0.3, -0.06, 0.0)};
  test::resolveDensities(s);
  SphSolver solver(s);
  const double e0 = solver.totals().energy();
  for (int k = 0; k < 60; ++k) solver.advance(1e9);
  const double d = solver.totals().energy() / e0 - 1.0;
  const StrengthFields f = solver.stepper().strengthFields();
  const double epsMax = *std::max_element(f.plasticStrain.begin(), f.plasticStrain.end());
  std::printf("r-z strength: dE/E = %.2e after 60 steps, max eps_p = %.3f\n", d, epsMax);
  EXPECT_GT(epsMax, 0.05);
  EXPECT_LT(std::abs(d), 1e-12);
}

// The hoop strain rate v_r / r: a cold aluminium cylinder (P ~ 0 at rho0) given v_r = a r. Its
// strain rate is a in r and in the hoop direction, 0 along z, so the deviator grows as
// 2G (a/3, -2a/3, a/3) (rr, zz, tt): s_zz / s_rr = -2, s_tt = s_rr. Without the hoop rate it
// would be 2G (2a/3, -a/3, -a/3) (ratio -0.5). One step (a dt ~ 1e-5: linear). Every particle
// from the axis (its mirror ghosts included) to 6 h inside the free surface at r = 0.3, where
// the truncated kernel reaches (measured there: up to 25 %); measured in the range: 0.5 %
// (s_rr 0.9951, s_zz 0.9988, s_tt 1.0025 of the exact, the same at the axis as in the bulk);
// bound 1 %.
TEST(SphStrength, HoopStrainRateInRz) {
  const double dx = 0.01, a = 1e-3;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.0, 0.0, 10 * dx, dx,
                           {Effect::MassAdjustment, Effect::Strength});
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
  s.materials = {strongAluminium(1.0)};
  s.bodies = {test::rectBody("bar", 0, 0.0, 0.3, 0.0, 10 * dx)};
  test::resolveDensities(s);
  ParticleSystem ps = fillBodies(s);
  for (std::size_t i = 0; i < ps.size(); ++i) ps.vx[i] = a * ps.x[i];
  SphSolver solver(s, ps);
  solver.advance(1e9);
  const double t = solver.time();
  const ParticleSystem p = solver.stepper().particles();
  const StrengthFields f = solver.stepper().strengthFields();
  const double expect = 2.0 * kShear * a * t / 3.0;
  double worst = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.x[i] > 0.3 - 6 * dx) continue;
    ++n;
    worst = std::max({worst, std::abs(f.sxx[i] / expect - 1.0), std::abs(f.stt[i] / expect - 1.0),
                      std::abs(f.szz[i] / (-2.0 * expect) - 1.0)});
  }
  std::printf("hoop rate: %d particles, s_rr expected %.4e, worst relative error %.2e\n", n, expect,
              worst);
  EXPECT_GT(n, 200);
  EXPECT_LT(worst, 0.01);
}

// Planar flyer-plate impact (200 m/s, Al on Al) in an elastic-perfectly plastic metal: a
// two-wave structure whose elastic precursor carries the Hugoniot elastic limit
// sigma_HEL = Y0 (1 - nu) / (1 - 2 nu) = (K + 4G/3) Y0 / 2G (uniaxial strain yields at
// 2 G eps = Y0; Meyers 1994, ch. 7), and a plastic wave behind it at about 2.5 HEL. K is the
// EOS's rho0 c0^2. The precursor's plateau is read where the longitudinal-stress profile is
// flattest between the two fronts. Bound 3 % (the issue's): the linear formula leaves out the
// EOS's finite-strain and Gruneisen terms at eps = 0.55 % (+1 %: the stress at the first
// yielding particle is 1.0115 sigma_HEL) and the plateau carries the plastic wave's foot
// (measured +2.5 % at dx = 0.01 cm, +1.2 % at 0.005 cm).
TEST(SphStrength, ElasticPrecursorCarriesTheHugoniotElasticLimit) {
  const double y0 = 0.003, dx = 0.01;
  const eos::Eos al = test::aluminium().eos;
  const double rho0 = eos::referenceDensity(al);
  const double c0 = std::visit([&](const auto& e) { return e.state(rho0, 0.0).soundSpeed; }, al);
  const double k = rho0 * c0 * c0;
  const double nu = (3.0 * k - 2.0 * kShear) / (2.0 * (3.0 * k + kShear));
  const double hel = y0 * (1.0 - nu) / (1.0 - 2.0 * nu);
  SphSolver solver(slab(dx, 4, 1.8, 0.6, 0.02, y0, true));
  while (solver.time() < 2.5) solver.advance(2.5);
  const Profile p = profile(solver, dx);
  const hvi::test::TwoWave w = hvi::test::twoWave(p.z, p.stress, hel);
  std::printf(
      "nu = %.4f, sigma_HEL = %.6f Mbar; plateau %.6f (%.2f %%) at z = %.3f, peak %.5f; "
      "fronts: elastic z = %.3f, plastic z = %.3f\n",
      nu, hel, w.plateau, 100.0 * (w.plateau / hel - 1.0), w.zPlateau, w.peak, w.zElastic,
      w.zPlastic);
  EXPECT_NEAR(w.plateau / hel, 1.0, 0.03);
  EXPECT_GT(w.peak, 2.0 * hel);  // a plastic wave of well above the HEL follows
  // ... separated from the precursor by the plateau (> 10 spacings at 2.5 us).
  EXPECT_GT(w.zPlastic - w.zElastic, 10.0 * dx);
}

// A 2 km/s block impact (0.19 Mbar, some 30 x the yield: strongly plastic) on a plate resting
// on a wall, with the Steinberg-Guinan 6061-T6 preset (G(P, T), melt). `xmin` = 0 puts a
// mirror (wall) on the symmetry plane x = 0; -0.4 runs the whole, symmetric problem.
cases::Scene blocks(double xmin, cases::EnergyForm energy) {
  auto s = test::baseScene(Geometry::Planar, xmin, 0.4, -0.2, 0.3, 0.02,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::Strength});
  if (xmin == 0.0) s.domain.boundary[0] = cases::Boundary::Wall;
  s.domain.boundary[2] = cases::Boundary::Wall;
  s.sph.energy = energy;
  cases::Material al = test::aluminium();
  al.strength = strength::findPreset("al6061_t6")->material;
  s.materials = {al};
  const double x0 = xmin == 0.0 ? 0.0 : -0.16;
  s.bodies = {test::rectBody("striker", 0, x0, 0.16, 0.0, 0.1, {0.0, -0.2}),
              test::rectBody("plate", 0, x0, 0.16, -0.1, 0.0)};
  test::resolveDensities(s);
  return s;
}

// Total energy with strength (docs/sph.md, "Energy"): the stress pair force enters the
// compatible energy's pair data with the even share of its work (stressPairTerm), so each
// step's internal-energy change is still exactly minus its kinetic-energy change: the same
// round-off bound as the hydrodynamic test (Conservation.CompatibleEnergyIsExactAtAnyTimeStep,
// 1e-12). Momentum: the stress pair forces are antisymmetric (round-off; the wall takes z
// momentum, so x only, which the mirror at x = 0 leaves alone only in the full problem).
// (The study's symmetric form drifts at O(dt^2): measured -1.2e-3 here, at a coarse 0.02 cm.)
TEST(SphStrength, TotalEnergyIsConservedWithStrength) {
  for (auto energy : {cases::EnergyForm::Compatible}) {
    SphSolver solver(blocks(-0.4, energy));
    const Totals t0 = solver.totals();
    for (int k = 0; k < 80; ++k) solver.advance(1e9);
    const Totals t1 = solver.totals();
    const StrengthFields f = solver.stepper().strengthFields();
    const double epsMax = *std::max_element(f.plasticStrain.begin(), f.plasticStrain.end());
    const double dE = t1.energy() / t0.energy() - 1.0;
    std::printf("%s: t = %.3f us, dE/E = %.2e, max eps_p = %.3f, Px = %.1e\n",
                cases::toString(energy).data(), solver.time(), dE, epsMax, t1.momentumX);
    EXPECT_GT(epsMax, 0.05);  // the strength terms are doing work
    EXPECT_LT(std::abs(t1.momentumX), 1e-13 * std::abs(t0.momentumZ));
    EXPECT_LT(std::abs(dE), 1e-12);
  }
}

// A mirror (wall) carries the deviator with s_xz reversed: the half problem with the mirror on
// the symmetry plane gives the whole problem's state (its x >= 0 half) up to round-off
// (measured 1.7e-17 Mbar against |s_xz| up to 1.4e-3). With s_xz copied unchanged instead the
// deviators differ by 2.3e-8 at 0.1 us (tried), which the bound catches.
TEST(SphStrength, MirrorGhostsCarryTheDeviator) {
  SphSolver whole(blocks(-0.4, cases::EnergyForm::Compatible));
  SphSolver half(blocks(0.0, cases::EnergyForm::Compatible));
  while (whole.time() < 0.1) whole.advance(0.1);
  while (half.time() < 0.1) half.advance(0.1);
  const ParticleSystem a = whole.stepper().particles(), b = half.stepper().particles();
  const StrengthFields fa = whole.stepper().strengthFields(), fb = half.stepper().strengthFields();
  double sMax = 0.0, dS = 0.0, dV = 0.0;
  std::size_t matched = 0;
  for (std::size_t j = 0; j < b.size(); ++j) {
    // the whole problem's particle nearest to this one
    std::size_t best = 0;
    double d = 1e300;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const double di = std::hypot(a.x[i] - b.x[j], a.z[i] - b.z[j]);
      if (di < d) {
        d = di;
        best = i;
      }
    }
    if (d > 1e-3 * 0.02) continue;
    ++matched;
    sMax = std::max(sMax, std::abs(fa.sxz[best]));
    dS = std::max({dS, std::abs(fa.sxz[best] - fb.sxz[j]), std::abs(fa.szz[best] - fb.szz[j])});
    dV = std::max(dV, std::hypot(a.vx[best] - b.vx[j], a.vz[best] - b.vz[j]));
  }
  std::printf("matched %zu of %zu, max |s_xz| %.2e, max |ds| %.2e, max |dv| %.2e\n", matched,
              b.size(), sMax, dS, dV);
  EXPECT_EQ(matched, b.size());
  EXPECT_GT(sMax, 1e-4);
  // Round-off grown through the flow (summation orders differ); 1e-6 of the shear scale.
  EXPECT_LT(dS, 1e-6 * sMax);
}

// A restart from a checkpoint continues bit for bit with the deviator, the plastic strain and
// the damage (fracture on, spall strength 1 GPa: the rebound fails part of the plate).
TEST(SphStrength, RestartIsBitForBit) {
  cases::Scene s = blocks(0.0, cases::EnergyForm::Compatible);
  s.effects.insert(Effect::Fracture);
  s.materials[0].strength->spallStrength = 0.01;
  SphSolver original(s);
  for (int k = 0; k < 15; ++k) original.advance(1e9);
  std::stringstream ckpt;
  original.writeCheckpoint(ckpt);
  for (int k = 0; k < 15; ++k) original.advance(1e9);
  SphSolver restarted(s);
  restarted.readCheckpoint(ckpt);
  for (int k = 0; k < 15; ++k) restarted.advance(1e9);
  const ParticleSystem a = original.stepper().particles(), b = restarted.stepper().particles();
  const StrengthFields fa = original.stepper().strengthFields(),
                       fb = restarted.stepper().strengthFields();
  EXPECT_EQ(original.time(), restarted.time());
  using hvi::test::sameBits;
  EXPECT_TRUE(sameBits(a.vx, b.vx));
  EXPECT_TRUE(sameBits(a.vz, b.vz));
  EXPECT_TRUE(sameBits(a.e, b.e));
  EXPECT_TRUE(sameBits(a.p, b.p));
  EXPECT_TRUE(sameBits(fa.sxx, fb.sxx));
  EXPECT_TRUE(sameBits(fa.szz, fb.szz));
  EXPECT_TRUE(sameBits(fa.sxz, fb.sxz));
  EXPECT_TRUE(sameBits(fa.plasticStrain, fb.plasticStrain));
  EXPECT_TRUE(sameBits(fa.damage, fb.damage));
  const auto maxEps = *std::max_element(fa.plasticStrain.begin(), fa.plasticStrain.end());
  const auto maxD = *std::max_element(fa.damage.begin(), fa.damage.end());
  std::printf("restart: max eps_p %.3f, max D %.2f\n", maxEps, maxD);
  EXPECT_GT(maxEps, 0.0);
}

// docs/strength.md, "Cost of strength in SPH": the force passes run inside the strength pass
// (one sweep over the rows, the stress kernel reading the force kernel's W and gradient) give
// the bits of the separate passes (HVI_SPH_FUSED=0): planar with compatible and symmetric
// energy, with the viscosity switch, with fracture, and r-z; over steps of strong plastic flow.
TEST(SphStrength, FusedPassesGiveTheSeparatePassesBits) {
  struct Case {
    const char* name;
    cases::Scene scene;
  };
  std::vector<Case> runs;
  runs.push_back({"compatible", blocks(0.0, cases::EnergyForm::Compatible)});
  runs.push_back({"symmetric", blocks(0.0, cases::EnergyForm::Symmetric)});
  cases::Scene sw = blocks(0.0, cases::EnergyForm::Compatible);
  sw.sph.viscositySwitch = cases::ViscositySwitch::MorrisMonaghan;
  runs.push_back({"switch", sw});
  cases::Scene fr = blocks(0.0, cases::EnergyForm::Compatible);
  fr.effects.insert(Effect::Fracture);
  fr.materials[0].strength->spallStrength = 0.01;
  runs.push_back({"fracture", fr});
  runs.push_back({"rz", slab(0.02, 6, 0.3, 0.1, 0.05, 0.003, true, true)});
  for (const Case& c : runs) {
    SCOPED_TRACE(c.name);
    ParticleSystem p[2];
    StrengthFields f[2];
    for (int fused = 0; fused < 2; ++fused) {
      // Read by the stepper's constructor.
      ASSERT_EQ(setenv("HVI_SPH_FUSED", fused ? "1" : "0", 1), 0);
      SphSolver solver(c.scene);
      for (int k = 0; k < 25; ++k) solver.advance(1e9);
      p[fused] = solver.stepper().particles();
      f[fused] = solver.stepper().strengthFields();
    }
    unsetenv("HVI_SPH_FUSED");
    using hvi::test::sameBits;
    EXPECT_TRUE(sameBits(p[0].x, p[1].x));
    EXPECT_TRUE(sameBits(p[0].z, p[1].z));
    EXPECT_TRUE(sameBits(p[0].vx, p[1].vx));
    EXPECT_TRUE(sameBits(p[0].vz, p[1].vz));
    EXPECT_TRUE(sameBits(p[0].e, p[1].e));
    EXPECT_TRUE(sameBits(p[0].rho, p[1].rho));
    EXPECT_TRUE(sameBits(f[0].sxx, f[1].sxx));
    EXPECT_TRUE(sameBits(f[0].sxz, f[1].sxz));
    EXPECT_TRUE(sameBits(f[0].plasticStrain, f[1].plasticStrain));
    EXPECT_TRUE(sameBits(f[0].damage, f[1].damage));
    EXPECT_TRUE(sameBits(f[0].viscosityAlpha, f[1].viscosityAlpha));
    // Not a run at rest: the stress terms are doing work.
    EXPECT_GT(*std::max_element(f[1].plasticStrain.begin(), f[1].plasticStrain.end()), 0.0);
  }
}

// Snapshots carry the deviator, the plastic strain and the temperature with strength, and
// nothing new without it.
TEST(SphStrength, SnapshotFields) {
  SphSolver solver(blocks(0.0, cases::EnergyForm::Compatible));
  solver.advance(1e9);
  const Snapshot snap = solver.snapshot();
  for (const char* name : {"stress_deviator_xx", "stress_deviator_zz", "stress_deviator_xz",
                           "stress_deviator_tt", "plastic_strain", "temperature"}) {
    const auto it = std::find_if(snap.fields.begin(), snap.fields.end(),
                                 [&](const Field& f) { return f.name == name; });
    ASSERT_NE(it, snap.fields.end()) << name;
    EXPECT_EQ(it->data.size(), solver.stepper().size());
  }
  cases::Scene s = blocks(0.0, cases::EnergyForm::Compatible);
  s.effects.erase(Effect::Strength);
  SphSolver hydro(s);
  for (const Field& f : hydro.snapshot().fields) EXPECT_NE(f.name, "plastic_strain");
}

// Symmetric flyer-plate spall (effect fracture): an elastic Al flyer of thickness d = 0.2 cm at
// 200 m/s on an Al target of 2d. The release from the flyer's rear face and the one from the
// target's rear face meet at depth d in the target (both travel at c_L: ct - 2d = 4d - ct), where
// the tension reaches the impact stress rho c_L v0 / 2 = 1.7 GPa (Meyers 1994, ch. 16). With a
// spall strength of 0.8 GPa the target fails there; with 3 GPa nowhere. The failed layer (D = 1)
// is located by its mean depth; bound 3 spacings (the releases are smeared over ~2 h each and the
// tension first exceeds the spall strength a little before the waves fully overlap).
struct Spall {
  int failed;
  double meanDepth, spread, energyDrift;
};
Spall symmetricSpall(double spallStrength, strength::DamageModel damage = strength::NoDamage{}) {
  const double dx = 0.01, d = 0.2;
  cases::Scene s = slab(dx, 4, 2 * d, d, 0.02, 1.0, true);
  s.effects.insert(Effect::Fracture);
  s.materials[0].strength->spallStrength = spallStrength;
  s.materials[0].strength->damage = damage;
  SphSolver solver(s);
  const double e0 = solver.totals().energy();
  const double tEnd = 5.0 * d / 0.633;  // the releases meet at 3 d / c_L
  while (solver.time() < tEnd) solver.advance(tEnd);
  const ParticleSystem ps = solver.stepper().particles();
  const StrengthFields f = solver.stepper().strengthFields();
  Spall r{0, 0.0, 0.0, solver.totals().energy() / e0 - 1.0};
  double zmin = 1e300, zmax = -1e300;
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (f.damage[i] >= 1.0) {
      ++r.failed;
      r.meanDepth -= ps.z[i];
      zmin = std::min(zmin, ps.z[i]);
      zmax = std::max(zmax, ps.z[i]);
    }
  if (r.failed) {
    r.meanDepth /= r.failed;
    r.spread = zmax - zmin;
  }
  return r;
}

TEST(SphStrength, SymmetricImpactSpallsWhereTheReleasesMeet) {
  const Spall weak = symmetricSpall(0.008), strong = symmetricSpall(0.03);
  std::printf(
      "spall 0.8 GPa: %d failed at mean depth %.4f cm (spread %.3f), dE/E = %.1e; "
      "3 GPa: %d failed\n",
      weak.failed, weak.meanDepth, weak.spread, weak.energyDrift, strong.failed);
  EXPECT_GT(weak.failed, 0);
  // Failed material stays in the flow: the compatible energy stays exact (as without fracture).
  EXPECT_LT(std::abs(weak.energyDrift), 1e-12);
  EXPECT_NEAR(weak.meanDepth, 0.2, 0.03);
  EXPECT_EQ(strong.failed, 0);
}

// Failed material carries no shear wave: at D = 1 the yield is (1 - D) Y = 0, the radial return
// removes every deviator each step, and the fastest signal is the bulk sound speed, so the time
// step reads c, not c_L = sqrt(c^2 + 4G / (3 rho)). A slab at rest stretched to 0.98 rho0
// (P ~ -0.015 Mbar) fails everywhere at the first step's end with a spall strength of
// 0.001 Mbar, and then sits at P = 0 (failed material resists compression only). Against the
// same slab that does not fail (spall strength 1 Mbar) the second step is longer by
// (c_L + 0.6 alpha c) / (c + 0.6 alpha c) (particleTimeStep's signal speed at rest, alpha = 1),
// 1.13 for this aluminium. Bound 1 %: the free ends move in the first step (|v| ~ 2e-3 cm/us,
// 0.3 % of the signal speed) and the two slabs' states differ by that step's motion alone.
TEST(SphStrength, FailedMaterialStepsWithTheBulkSoundSpeed) {
  auto stretched = [](double spallStrength) {
    cases::Scene s = slab(0.01, 4, 0.2, 0.1, 0.0, 0.003, true);
    s.effects.insert(Effect::Fracture);
    s.materials[0].strength->spallStrength = spallStrength;
    for (auto& b : s.bodies) b.density *= 0.98;
    return s;
  };
  auto secondStep = [&](double spallStrength) {
    SphSolver solver(stretched(spallStrength));
    solver.advance(1e9);
    const double t1 = solver.time();
    solver.advance(1e9);
    const StrengthFields f = solver.stepper().strengthFields();
    const auto [lo, hi] = std::minmax_element(f.damage.begin(), f.damage.end());
    return std::array<double, 3>{solver.time() - t1, *lo, *hi};
  };
  const auto failed = secondStep(0.001), intact = secondStep(1.0);
  EXPECT_EQ(failed[1], 1.0);  // every particle failed
  EXPECT_EQ(intact[2], 0.0);  // none did
  // The solver's EOS (no tension cut-off in this scene) at the slab's state.
  const cases::Material al = cases::resolveMaterials(stretched(1.0)).at(0);
  const double rho = 0.98 * eos::referenceDensity(al.eos);
  const double c = eos::state(al.eos, rho, 0.0).soundSpeed;
  const double cL = strength::longitudinalSoundSpeed(c, kShear, rho);
  const double expected = (cL + 0.6 * c) / (c + 0.6 * c);
  std::printf("second step: failed %.6e us, intact %.6e us, ratio %.4f (expected %.4f: c %.4f, "
              "c_L %.4f cm/us)\n",
              failed[0], intact[0], failed[0] / intact[0], expected, c, cL);
  EXPECT_NEAR(failed[0] / intact[0], expected, 0.01 * expected);
}

// The same impact with Grady-Kipp tensile damage (Benz and Asphaug 1995) and no spall-strength
// failure (3 GPa, above the tension): the flaws of the particle volume dp^3 = 1e-6 cm^3 with
// k = 1e24 cm^-3, m = 9 activate at eps_min = (k V)^(-1/m) = 0.01, below the tensile strain at the
// meeting plane (1.7 GPa / E = 0.023, E = 9KG / (3K + G) = 74 GPa) and above anything elsewhere;
// cracks then grow at 0.4 c_L over the particle radius (D = 1 within ~0.02 us). The failed
// layer must sit where the releases meet (bound as above); with k = 1e10 (eps_min ~ 5) no
// particle is damaged.
TEST(SphStrength, GradyKippDamageSpallsWhereTheReleasesMeet) {
  const Spall gk = symmetricSpall(0.03, strength::GradyKipp{1e24, 9.0, 0.4});
  const Spall none = symmetricSpall(0.03, strength::GradyKipp{1e10, 9.0, 0.4});
  std::printf(
      "Grady-Kipp: %d failed at mean depth %.4f cm (spread %.3f), dE/E = %.1e; "
      "k = 1e10: %d failed\n",
      gk.failed, gk.meanDepth, gk.spread, gk.energyDrift, none.failed);
  EXPECT_GT(gk.failed, 0);
  EXPECT_NEAR(gk.meanDepth, 0.2, 0.03);
  EXPECT_LT(std::abs(gk.energyDrift), 1e-12);
  EXPECT_EQ(none.failed, 0);
}

// Colliding elastic rings (Gray, Monaghan and Swift 2001, J. Comput. Phys. 191, the rubber
// rings of their tensile-instability section), scaled down to keep the test short: rings of radii
// 0.75 and 1 cm, spacing 0.05 cm (~1100 particles), rubber-like rho0 = 1, c0 = 0.01 cm/us,
// Poisson's ratio 0.4 (their nu), elastic, each moving at 0.059 c0 (their speed) towards the
// other. Returns the left ring's mean x velocity at tEnd, the largest distance of a particle to
// its nearest neighbour of the same ring (in spacings: a fragment or a detached particle shows
// as > 2) and the energy drift.
struct Rings {
  double vxLeft;
  double maxGap;
  double energyDrift;
};
Rings collideRings(double artificialStress, double tEnd) {
  const double dp = 0.05, rin = 0.75, rout = 1.0, c0 = 0.01, v = 0.059 * c0;
  auto s = test::baseScene(Geometry::Planar, -3.0, 3.0, -2.0, 2.0, dp,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::Strength});
  cases::Material rubber{"rubber", eos::MieGruneisen{1.0, c0, 0.0, 0.0}};
  strength::Material sm;
  const double k = c0 * c0, nu = 0.4;
  sm.shearModulus = 3.0 * k * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
  sm.yield = strength::ConstantYield{1.0};
  rubber.strength = sm;
  s.materials = {rubber};
  s.bodies = {test::diskBody("left", 0, {-1.05, 0.0}, rout, {v, 0.0}),
              test::diskBody("right", 0, {1.05, 0.0}, rout, {-v, 0.0})};
  test::resolveDensities(s);
  ParticleSystem all = fillBodies(s);
  std::vector<unsigned char> keep(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double xc = all.object[i] == 0 ? -1.05 : 1.05;
    keep[i] = std::hypot(all.x[i] - xc, all.z[i]) >= rin ? 1 : 0;
  }
  all.compact(keep);
  (void)adjustMasses(all, massAdjustOptions(s));
  s.sph.artificialStressEpsilon = artificialStress;  // the scene key sph.artificial_stress_epsilon
  Stepper solver(all, sceneMaterials(s), stepperConfig(s));
  const double e0 = solver.totals().energy();
  while (solver.time() < tEnd) solver.step(tEnd);
  const ParticleSystem ps = solver.particles();
  Rings r{0.0, 0.0, solver.totals().energy() / e0 - 1.0};
  double ml = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    double nearest = 1e300;
    for (std::size_t j = 0; j < ps.size(); ++j)
      if (j != i && ps.object[j] == ps.object[i])
        nearest = std::min(nearest, std::hypot(ps.x[i] - ps.x[j], ps.z[i] - ps.z[j]));
    r.maxGap = std::max(r.maxGap, nearest / dp);
    if (ps.object[i] == 0) {
      r.vxLeft += ps.m[i] * ps.vx[i];
      ml += ps.m[i];
    }
  }
  r.vxLeft /= ml;
  return r;
}

// With Monaghan's artificial stress (epsilon 0.3, n 4, the defaults) the rings meet, squash and
// bounce back intact. Measured at 3000 us: the left ring moves back at -0.58 v0 (bound: faster
// than -0.25 v0, i.e. a clear rebound after it came in at +v0), largest neighbour distance
// 1.23 dp (bound 2 dp: no particle or fragment detached), energy exact (bound 1e-12). Without the
// artificial stress (epsilon = 0, the same run; its energy must stay exact too) the rebound is
// much slower, -0.08 v0 at 3000 us, the contact staying stuck longer, but at this resolution and
// time the rings do not break up as in Gray et al. (largest neighbour distance 1.18 dp).
TEST(SphStrength, CollidingRingsBounceWithArtificialStress) {
  const double v0 = 0.059 * 0.01;
  const Rings on = collideRings(0.3, 3000.0), off = collideRings(0.0, 3000.0);
  std::printf(
      "rings at 3000 us: with artificial stress v_left = %.3f v0, max gap %.2f dp, dE/E "
      "%.1e; without: %.3f v0, %.2f dp, %.1e\n",
      on.vxLeft / v0, on.maxGap, on.energyDrift, off.vxLeft / v0, off.maxGap, off.energyDrift);
  EXPECT_LT(on.vxLeft, -0.25 * v0);
  EXPECT_LT(on.maxGap, 2.0);
  EXPECT_LT(std::abs(on.energyDrift), 1e-12);
  EXPECT_LT(std::abs(off.energyDrift), 1e-12);
}

}  // namespace
}  // namespace hvi::sph

namespace hvi::sph {
namespace {

// Johnson-Cook (1985) failure in the solver: a 4340 steel slab (the preset's D1..D5 = 0.05,
// 3.44, -2.12, 0.002, 0.61) pulled apart in uniaxial strain (walls both sides, a mirror at
// z = 0 as the symmetry plane, v_z = a z initially, the far end free). The tension grows with
// the volumetric strain (-P = K eps), the triaxiality sigma* = -P / sigma_eq soon passes 3 and
// the failure strain falls to D1 + D2 exp(D3 sigma*) -> 0.05: the damage
// D = sum d eps_p / eps_f(sigma*, eps_dot*, T*) (Johnson and Cook 1985) must reach 1 at an
// equivalent plastic strain of about D1 = 0.05 plus what the early, low-triaxiality plastic flow
// used up. The test integrates that sum itself, per particle and step, from the solver's own
// state at the step's end (pressure, deviator, temperature, plastic strain) and compares.
// Bound 0.05 in D: the test takes the applied rate 2/3 a = 5.3e4 /s (rate factor
// 1 + D4 ln(eps_dot*) = 1.022), the solver its kernel estimate (the factor moves by only 0.002 per
// factor e in the rate), and the solver evaluates sigma* at the half step, the test at the
// step's end. Measured 0.021.
// The spall strength is set out of reach (1 Mbar) so that only the damage law fails material.
TEST(SphStrength, JohnsonCookFailureAtTheExpectedPlasticStrain) {
  const double dx = 0.01, width = 4 * dx, length = 1.0, a = 0.08;  // a in 1/us
  auto s = test::baseScene(Geometry::Planar, 0.0, width, 0.0, 3.0, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::Strength,
                            Effect::Fracture});
  s.domain.boundary[0] = s.domain.boundary[1] = s.domain.boundary[2] = cases::Boundary::Wall;
  // 4340 steel: Mie-Gruneisen of Steinberg (1996): 7.85 g/cm^3, c0 4.578 km/s, s 1.33,
  // Gamma0 1.67.
  cases::Material steel{"steel", eos::MieGruneisen{7.85, 0.4578, 1.33, 1.67}};
  steel.strength = strength::findPreset("steel_4340")->material;
  steel.strength->spallStrength = 1.0;
  const auto jc = std::get<strength::JohnsonCookFailure>(steel.strength->damage);
  const auto law = std::get<strength::JohnsonCook>(steel.strength->yield);
  s.materials = {steel};
  s.bodies = {test::rectBody("slab", 0, 0.0, width, 0.0, length)};
  test::resolveDensities(s);
  ParticleSystem ps0 = fillBodies(s);
  for (std::size_t i = 0; i < ps0.size(); ++i) ps0.vz[i] = a * ps0.z[i];
  SphSolver solver(s, ps0);
  const std::size_t n = solver.stepper().size();
  std::vector<double> expected(n, 0.0), epsPrev(n, 0.0), epsAtFailure(n, -1.0);
  double worst = 0.0;
  const double rate = 2.0 / 3.0 * a;  // equivalent strain rate of uniaxial strain at a
  while (solver.time() < 1.5) {
    solver.advance(1.5);
    const ParticleSystem ps = solver.stepper().particles();
    const StrengthFields f = solver.stepper().strengthFields();
    ASSERT_EQ(ps.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const strength::Deviator dev{f.sxx[i], f.szz[i], f.sxz[i]};
      const double seq = strength::vonMises(dev);
      const double triax = seq > 0.0 ? -ps.p[i] / seq : 0.0;
      const double deps = f.plasticStrain[i] - epsPrev[i];
      epsPrev[i] = f.plasticStrain[i];
      if (expected[i] < 1.0 && deps > 0.0)
        expected[i] = std::min(
            1.0, expected[i] + deps / jc.failureStrain(triax, rate,
                                                       law.homologous(f.temperature[i])));
      if (f.damage[i] >= 1.0 && epsAtFailure[i] < 0.0) epsAtFailure[i] = f.plasticStrain[i];
      worst = std::max(worst, std::abs(f.damage[i] - expected[i]));
    }
  }
  int failed = 0;
  double epsMean = 0.0, epsMin = 1e300, epsMax = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (epsAtFailure[i] >= 0.0) {
      ++failed;
      epsMean += epsAtFailure[i];
      epsMin = std::min(epsMin, epsAtFailure[i]);
      epsMax = std::max(epsMax, epsAtFailure[i]);
    }
  if (failed) epsMean /= failed;
  std::printf(
      "JC failure: %d of %zu particles failed, eps_p at failure %.4f (%.4f to %.4f; D1 = %.2f); "
      "largest |D - sum d eps_p / eps_f| = %.3e\n",
      failed, n, epsMean, epsMin, epsMax, jc.d1, worst);
  EXPECT_GT(failed, 0);
  EXPECT_LT(worst, 0.05);
  // Most of the failure strain is spent at high triaxiality, where eps_f -> D1.
  EXPECT_GT(epsMin, jc.d1);
  EXPECT_LT(epsMax, 3.0 * jc.d1);
}

}  // namespace
}  // namespace hvi::sph
