//! @file TVD strength with conservative interfaces (docs/strength.md, "TVD with interfaces"):
//! the elastic stress across a welded contact of two materials against acoustics, energy and
//! every phase's mass with interfaces, restart, and the modes that stay refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/test/same_bits.hpp"
#include "hvi/test/scene_files.hpp"
#include "hvi/test/taylor_data.hpp"
#include "hvi/test/tvd_scenes.hpp"
#include "hvi/test/two_wave.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;
using cases::Effect;

// Elastic solids: a yield far above any stress here (1 Mbar), shear moduli of 6061-T6
// (27.6 GPa, Steinberg 1991) and OFHC copper (46 GPa, the copper_ofhc preset).
constexpr double kShearAl = 0.276, kShearCu = 0.46;  // Mbar
cases::Material elastic(std::string name, eos::Eos e, double shear, double cv) {
  cases::Material m = material(std::move(name), std::move(e));
  strength::Material sm;
  sm.shearModulus = shear;
  sm.yield = strength::ConstantYield{1.0};
  sm.thermal.cv = cv;
  m.strength = sm;
  return m;
}

double soundSpeed(const eos::Eos& e) {
  return std::visit([](const auto& x) { return x.state(x.referenceDensity(), 0.0).soundSpeed; }, e);
}
double density(const eos::Eos& e) { return eos::referenceDensity(e); }

cases::Scene cutScene(double xmin, double xmax, double zmin, double zmax, double h,
                      Geometry g = Geometry::Planar) {
  cases::Scene s = baseScene(xmin, xmax, zmin, zmax, h, g);
  s.effects.insert(Effect::MaterialInterfaces);
  s.effects.insert(Effect::TensionCutoff);
  s.effects.insert(Effect::Strength);
  s.tvd.interfaces = cases::InterfaceMode::Conservative;
  return s;
}

// Uniaxial strain across a welded contact of two materials: an aluminium flyer (z > 0, long,
// continued by an outflow side) moving at -v0 hits a copper target (z < 0) at rest, both
// elastic; walls at x (plane strain, laterally confined) and at the target's far end. Linear
// acoustics (Meyers, Dynamic behavior of materials, 1994, ch. 2; the transmission of a stress
// wave across an interface, sigma_T / sigma_I = 2 Z2 / (Z1 + Z2)) gives on both sides of the
// contact one longitudinal stress and one velocity,
//     sigma = Z_a Z_c v0 / (Z_a + Z_c),   u_c = Z_a v0 / (Z_a + Z_c),
// with the longitudinal impedances Z = rho0 c_L, c_L = sqrt(c0^2 + 4G / (3 rho0)).
cases::Scene weldedBar(bool withStrength, double v0) {
  const double dx = 0.01, width = 4 * dx;
  cases::Scene s = cutScene(0.0, width, -1.0, 1.0, dx);
  if (!withStrength) s.effects.erase(Effect::Strength);
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Outflow};
  const eos::Eos al = eos::aluminiumStudy();
  const eos::Eos cu = eos::MieGruneisen{};
  s.materials = {elastic("aluminium", al, kShearAl, 0.896e-5),
                 elastic("copper", cu, kShearCu, 0.383e-5)};
  if (!withStrength)
    for (auto& m : s.materials) m.strength.reset();
  s.bodies = {body("flyer", 0, cases::Rect{0.0, width, 0.0, 1.0}, {density(al), {0.0, -v0}, 0.0}),
              body("target", 1, cases::Rect{0.0, width, -1.0, 0.0}, {density(cu), {}, 0.0})};
  return s;
}

struct Plateau {
  double stress = 0.0, velocity = 0.0;
};
// Mean longitudinal stress P - s_zz and downward velocity over the rows with z in [z0, z1].
Plateau plateau(const TvdSolver& solver, double z0, double z1) {
  const Snapshot snap = solver.snapshot();
  const GridSpec& g = solver.grid();
  const Field& p = field(snap, "pressure");
  const Field& v = field(snap, "velocity");
  const bool strong = snap.fields.size() > 6;
  Plateau out;
  int n = 0;
  for (int k = 0; k < g.nz; ++k) {
    const double z = g.z0 + (k + 0.5) * g.dz;
    if (z < z0 || z > z1) continue;
    for (int i = 0; i < g.nx; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      out.stress += p.data[c] - (strong ? field(snap, "stress_deviator_zz").data[c] : 0.0);
      out.velocity -= v.data[2 * c + 1];
      ++n;
    }
  }
  out.stress /= n;
  out.velocity /= n;
  return out;
}

// The transmitted and the reflected-side plateau at 0.8 us (the fronts then 0.37 cm into the
// copper and 0.50 cm into the aluminium), read 0.05 cm clear of the contact and of the fronts.
// Bound 1 %: the elastic-wave test's (TvdStrength.ElasticWaveTravelsAtLongitudinalSpeed); the
// linear theory's own error at a strain of 1e-4 is of that order times 1e-2. It discriminates:
// the hydrodynamic impedances (bulk sound speeds) give a stress 18 % lower, and the run without
// strength is checked against them.
TEST(TvdStrengthCut, WeldedContactCarriesTheAcousticStress) {
  const double v0 = 1e-4;
  const eos::Eos al = eos::aluminiumStudy();
  const eos::Eos cu = eos::MieGruneisen{};
  for (const bool strong : {true, false}) {
    const double cLa =
        strength::longitudinalSoundSpeed(soundSpeed(al), strong ? kShearAl : 0.0, density(al));
    const double cLc =
        strength::longitudinalSoundSpeed(soundSpeed(cu), strong ? kShearCu : 0.0, density(cu));
    const double za = density(al) * cLa, zc = density(cu) * cLc;
    const double sigma = za * zc * v0 / (za + zc), uc = za * v0 / (za + zc);
    TvdSolver solver(weldedBar(strong, v0));
    ASSERT_TRUE(solver.cutCells());
    runTo(solver, 0.8);
    const Plateau c = plateau(solver, -0.8 * cLc + 0.05, -0.05);
    const Plateau a = plateau(solver, 0.05, 0.8 * cLa - 0.05);
    std::printf(
        "%s: sigma = %.5e Mbar, u_c = %.5e cm/us; copper %.5e (%+.2f %%), %.5e (%+.2f %%); "
        "aluminium %.5e (%+.2f %%), flyer velocity %.5e (exact %.5e)\n",
        strong ? "strength" : "hydro", sigma, uc, c.stress, 100.0 * (c.stress / sigma - 1.0),
        c.velocity, 100.0 * (c.velocity / uc - 1.0), a.stress, 100.0 * (a.stress / sigma - 1.0),
        a.velocity, uc);
    EXPECT_NEAR(c.stress / sigma, 1.0, 0.01);
    EXPECT_NEAR(a.stress / sigma, 1.0, 0.01);
    EXPECT_NEAR(c.velocity / uc, 1.0, 0.01);
    EXPECT_NEAR(a.velocity / uc, 1.0, 0.01);
  }
}

// Planar impact of two different elastic-perfectly plastic plates (200 m/s, an aluminium flyer
// on a copper target, the welded bar above): each plate carries an elastic precursor at its own
// Hugoniot elastic limit sigma_HEL = Y0 (1 - nu) / (1 - 2 nu), nu from K = rho0 c0^2 and G
// (Meyers 1994, ch. 7), with the plastic wave behind it: the copper precursor runs into the
// target, the aluminium one back into the flyer. Read as in
// TvdStrength.ElasticPrecursorCarriesTheHugoniotElasticLimit (the shared two-wave reading, each
// profile from its plate's far end); bound 3 %, the and that test's (the linear formula
// leaves out the EOS's finite-strain terms).
TEST(TvdStrengthCut, EachPlateCarriesItsOwnHugoniotElasticLimit) {
  const double v0 = 0.02, dx = 0.01, width = 4 * dx;
  const double yAl = 0.003, yCu = 0.002;
  cases::Scene s = cutScene(0.0, width, -1.8, 2.2, dx);
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Outflow};
  const eos::Eos al = eos::aluminiumStudy();
  const eos::Eos cu = eos::MieGruneisen{};
  s.materials = {elastic("aluminium", al, kShearAl, 0.896e-5),
                 elastic("copper", cu, kShearCu, 0.383e-5)};
  s.materials[0].strength->yield = strength::ConstantYield{yAl};
  s.materials[1].strength->yield = strength::ConstantYield{yCu};
  s.bodies = {body("flyer", 0, cases::Rect{0.0, width, 0.0, 2.2}, {density(al), {0.0, -v0}, 0.0}),
              body("target", 1, cases::Rect{0.0, width, -1.8, 0.0}, {density(cu), {}, 0.0})};
  auto hel = [](const eos::Eos& e, double g, double y) {
    const double c = soundSpeed(e), k = density(e) * c * c;
    const double nu = (3.0 * k - 2.0 * g) / (2.0 * (3.0 * k + g));
    return y * (1.0 - nu) / (1.0 - 2.0 * nu);
  };
  const double helAl = hel(al, kShearAl, yAl), helCu = hel(cu, kShearCu, yCu);
  TvdSolver solver(s);
  runTo(solver, 3.0);
  const Snapshot snap = solver.snapshot();
  const GridSpec& g = solver.grid();
  const Field& p = field(snap, "pressure");
  const Field& szz = field(snap, "stress_deviator_zz");
  std::vector<double> zc, sc, za, sa;  // copper from its far end up, aluminium from its top down
  for (int k = 0; k < g.nz; ++k) {
    const double z = g.z0 + (k + 0.5) * g.dz;
    double st = 0.0;
    for (int i = 0; i < g.nx; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      st += (p.data[c] - szz.data[c]) / g.nx;
    }
    if (z < 0.0) {
      zc.push_back(z);
      sc.push_back(st);
    } else {
      za.insert(za.begin(), -z);
      sa.insert(sa.begin(), st);
    }
  }
  const hvi::test::TwoWave wc = hvi::test::twoWave(zc, sc, helCu);
  const hvi::test::TwoWave wa = hvi::test::twoWave(za, sa, helAl);
  std::printf(
      "copper: HEL %.6f Mbar, plateau %.6f (%+.2f %%), peak %.5f, fronts %.3f / %.3f; "
      "aluminium: HEL %.6f, plateau %.6f (%+.2f %%), peak %.5f, fronts %.3f / %.3f\n",
      helCu, wc.plateau, 100.0 * (wc.plateau / helCu - 1.0), wc.peak, wc.zElastic, wc.zPlastic,
      helAl, wa.plateau, 100.0 * (wa.plateau / helAl - 1.0), wa.peak, -wa.zElastic, -wa.zPlastic);
  EXPECT_NEAR(wc.plateau / helCu, 1.0, 0.03);
  EXPECT_NEAR(wa.plateau / helAl, 1.0, 0.03);
  EXPECT_GT(wc.peak, 2.0 * helCu);
  EXPECT_GT(wa.peak, 2.0 * helAl);
  EXPECT_GT(wc.zPlastic - wc.zElastic, 10.0 * dx);
  EXPECT_GT(wa.zPlastic - wa.zElastic, 10.0 * dx);
}

// A 2 km/s copper block (Johnson-Cook OFHC copper) on a 6061-T6 plate (Steinberg-Guinan), walls
// around, strongly plastic: two phases with strength, cut cells at the contact and the free
// surfaces.
cases::Scene blocks(Geometry g) {
  const bool rz = g == Geometry::Axisymmetric;
  cases::Scene s = cutScene(rz ? 0.0 : -0.4, 0.4, -0.2, 0.3, 0.02, g);
  s.domain.boundary = {rz ? cases::Boundary::Axis : cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall, cases::Boundary::Wall};
  cases::Material al = material("aluminium", eos::aluminiumStudy());
  al.strength = strength::findPreset("al6061_t6")->material;
  cases::Material cu = material("copper", eos::MieGruneisen{});
  cu.strength = strength::findPreset("copper_ofhc")->material;
  s.materials = {al, cu};
  const double x0 = rz ? 0.0 : -0.163;
  s.bodies = {body("striker", 1, cases::Rect{x0, 0.163, 0.013, 0.113}, {8.93, {0.0, -0.2}, 0.0}),
              body("plate", 0, cases::Rect{-0.4, 0.4, -0.107, 0.013}, {2.79, {}, 0.0})};
  return s;
}

// Total energy with interfaces: the strength step's face fluxes add to one cell what they take
// from the other, the cell's increments are shared out among its phases so that they sum to
// the cell's, and the walls do no work; the hydrodynamic cut-cell step changes the total only
// by its floors (booked). So the total changes by what the ledger books to round-off: the bound
// 1e-12 of the closed-box and cut-cell tests (TvdCutCells.ImpactConservesEveryMaterial). Every
// phase's mass is exact as without strength; planar x momentum to round-off.
void checkEnergy(Geometry g, bool open = false) {
  cases::Scene scene = blocks(g);
  // Open: the plate runs out through outflow sides at both x ends (r-z: at the rim), as a
  // shield's plates do, so the stress's edge fluxes go to the ledger's outflow.
  if (open) {
    if (g == Geometry::Planar) scene.domain.boundary[0] = cases::Boundary::Outflow;
    scene.domain.boundary[1] = cases::Boundary::Outflow;
  }
  TvdSolver solver(scene);
  const Totals t0 = solver.totals();
  const auto m0 = phaseMasses(solver);
  runTo(solver, 1.0);
  const Totals t1 = solver.totals();
  const auto m1 = phaseMasses(solver);
  const Budget led = solver.ledger().sum();
  double epsMax = 0.0;
  const Snapshot snap = solver.snapshot();
  const Field& eps = field(snap, "plastic_strain");
  const Field& obj = field(snap, "object");
  double epsStriker = 0.0;
  for (std::size_t c = 0; c < eps.data.size(); ++c) {
    epsMax = std::max(epsMax, eps.data[c]);
    if (obj.data[c] == 0.0) epsStriker = std::max(epsStriker, eps.data[c]);
  }
  const double dE = (t1.energy() - t0.energy() - led.energy) / t0.energy();
  std::printf(
      "%s blocks, %ld steps: energy %.2e (ledger %.2e), wall energy %.1e, masses %.1e %.1e, "
      "max eps_p %.3f (striker %.3f)\n",
      toString(g).data(), solver.step(), dE, led.energy / t0.energy(),
      solver.ledger().boundary.energy, m1[0] / m0[0] - 1.0, m1[1] / m0[1] - 1.0, epsMax,
      epsStriker);
  EXPECT_NEAR(dE, 0.0, 1e-12);
  if (open) {
    EXPECT_NE(solver.ledger().outflow.energy, 0.0);  // the edges carried something
  } else {
    EXPECT_EQ(solver.ledger().boundary.energy, 0.0);
  }
  for (std::size_t p = 0; p < m0.size() && !open; ++p) EXPECT_NEAR(m1[p], m0[p], 1e-12 * m0[p]);
  EXPECT_GT(epsMax, 0.05);      // the plastic return is exercised
  EXPECT_GT(epsStriker, 0.05);  // in both phases
  if (g == Geometry::Planar) {
    const double scale = t0.mass * 0.2;
    EXPECT_NEAR(t1.momentumX - t0.momentumX, led.momentumX, 1e-12 * scale);
  }
}
// A copper body in uniform tension at rest (0.99 rho0: P = -1.41 GPa, within what a solid
// carries; no tension cut-off, as in a scene with strength) filling an r-z box with walls stays
// at rest: every radial face's pressure is P, so the hoop source P / r balances the flux
// difference cell by cell. Bound: issue 13's rest property, speed < 1e-10 of the sound speed
// after 200 steps. Before the face pressure could be tension (contactStar's p* >= 0) the hoop
// source was 0 against the flux's -P / r, and the cells next to the axis were pushed outwards
// (the Taylor rod's axis expanded to 0.7 rho0 and its energy grew by 51 %, docs/tvd.md
// "Tension at the axis").
TEST(TvdStrengthCut, UniformTensionAtRestStaysAtRestInRz) {
  const double h = 0.02;
  cases::Scene s = cutScene(0.0, 0.4, 0.0, 0.4, h, Geometry::Axisymmetric);
  s.effects.erase(Effect::TensionCutoff);
  s.domain.boundary = {cases::Boundary::Axis, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall};
  cases::Material cu = material("copper", eos::MieGruneisen{});
  cu.strength = strength::findPreset("copper_ofhc")->material;
  s.materials = {cu};
  const double rho = 0.99 * density(cu.eos);
  s.bodies = {body("block", 0, cases::Rect{0.0, 0.4, 0.0, 0.4}, {rho, {}, 0.0})};
  TvdSolver solver(s);
  const double p0 = std::visit([&](const auto& e) { return e.state(rho, 0.0).pressure; }, cu.eos);
  ASSERT_LT(p0, -0.01);
  for (int n = 0; n < 200; ++n) solver.advance(1e9);
  const Snapshot snap = solver.snapshot();
  const Field& v = field(snap, "velocity");
  double vmax = 0.0;
  for (double x : v.data) vmax = std::max(vmax, std::abs(x));
  std::printf("copper at 0.99 rho0 (P = %.4f Mbar), r-z, 200 steps: max speed %.2e cm/us\n", p0,
              vmax);
  EXPECT_LT(vmax, 1e-10 * soundSpeed(cu.eos));
}

// The rod's shape from its marker line: length = its axial extent, foot = twice its largest
// radius.
std::pair<double, double> rodShape(const TvdSolver& solver) {
  double zmin = 1e300, zmax = -1e300, rmax = 0.0;
  for (const auto& line : solver.markers().lines())
    for (const Vec2& p : line.points) {
      zmin = std::min(zmin, p.z);
      zmax = std::max(zmax, p.z);
      rmax = std::max(rmax, p.x);
    }
  return {zmax - zmin, 2.0 * rmax};
}

// One Taylor run of scene s to its end: the ledger closes to 1e-12, the floors stay below 1e-3
// of the impact's energy, the rod at rest (1e-2 of its kinetic energy), the foot within the
// issue's 5 % of the 190 m/s measurement and the length within lengthBound.
void expectTaylorAnvil(const cases::Scene& s, const char* label, double lengthBound) {
  TvdSolver solver(s);
  const Totals t0 = solver.totals();
  runTo(solver, s.tEnd);
  const Totals t1 = solver.totals();
  const Budget led = solver.ledger().sum();
  const auto [length, foot] = rodShape(solver);
  std::printf(
      "TVD Taylor anvil, %s, %ld steps: L = %.4f cm (%+.1f %%), foot %.4f cm (%+.1f %%), "
      "floors %.1e, kinetic energy left %.1e\n",
      label, static_cast<long>(solver.step()), length,
      100.0 * (length / test::kTaylorFinalLength - 1.0), foot,
      100.0 * (foot / test::kTaylorFootDiameter - 1.0), solver.ledger().floors.energy / t0.energy(),
      t1.kinetic / t0.kinetic);
  EXPECT_NEAR(t1.energy() - t0.energy(), led.energy, 1e-12 * t0.energy());
  EXPECT_LT(std::abs(solver.ledger().floors.energy), 1e-3 * t0.energy());
  EXPECT_LT(t1.kinetic, 1e-2 * t0.kinetic);
  EXPECT_NEAR(foot / test::kTaylorFootDiameter, 1.0, 0.05);
  EXPECT_NEAR(length / test::kTaylorFinalLength, 1.0, lengthBound);
}

// Scene s at the compilation's three shots (test/taylor_data.hpp): each length within
// lengthBound of its shot, the rod at rest, shorter and with a wider foot the faster the shot;
// the feet printed.
void expectTaylorAtThreeSpeeds(cases::Scene s, const char* label, double lengthBound) {
  double lastLength = 1e300, lastFoot = 0.0;
  for (const test::TaylorShot& shot : test::kTaylorShots) {
    s.bodies[0].velocity = {0.0, -shot.speed};
    TvdSolver solver(s);
    const Totals t0 = solver.totals();
    runTo(solver, s.tEnd);
    const Totals t1 = solver.totals();
    const auto [length, foot] = rodShape(solver);
    std::printf("TVD Taylor anvil, %s, %.0f m/s: L = %.4f cm (%+.1f %%), foot %.4f cm (%+.1f %%)\n",
                label, shot.speed * 1e4, length, 100.0 * (length / shot.length - 1.0), foot,
                100.0 * (foot / shot.foot - 1.0));
    EXPECT_NEAR(length / shot.length, 1.0, lengthBound) << shot.speed;
    EXPECT_LT(t1.kinetic, 1e-2 * t0.kinetic) << shot.speed;
    EXPECT_LT(length, lastLength) << shot.speed;
    EXPECT_GT(foot, lastFoot) << shot.speed;
    lastLength = length;
    lastFoot = foot;
  }
}

// The Taylor anvil in TVD (cases/scenes/taylor_copper_tvd.toml, D0/20; the measurement in
// test/taylor_data.hpp): Johnson and Cook's OFHC copper rod at 190 m/s on a rigid frictionless
// anvil, to 80 us. Shape from the marker line: length = its axial extent, foot = twice its
// largest radius. Measured: L 1.7340 cm (+7.0 %), foot 1.3591 cm (+0.2 %); D0/40 +6.0 / +4.4 %
// (session 19, before the opened cells and the r-z interface area: +7.1 / -0.2, +6.0 / +4.3 and
// D0/60 +6.2 / +5.8 %; docs/strength.md, "TVD Taylor anvil"). The foot is held to the issue's
// 5 %. The length is held to kTaylorLengthBound (8.5 %), not 5 %: the excess is the
// Johnson-Cook 1983 model's, not the solver's (docs/strength.md, "Why the Taylor rod is long":
// an independent computation with the same constants gives +7.4 %, mesh independent; no
// numerical option of either solver moves it; only the constants do), plus the 1 % this
// solver's length moves between D0/20 and D0/60. The run with the r-z axis defect met the length
// (+1.3 %); the energy and the foot (+11 %) caught it. Energy: the ledger closes to 1e-12, and
// its floors stay below 1e-3 of the impact's energy (measured 5e-6; the axis defect made 0.51);
// the rod at rest (kinetic energy left 5e-4 of the impact's; bound 1e-2).
TEST(TvdStrengthCut, TaylorAnvilCopper) {
  expectTaylorAnvil(cases::loadScene(cases::test::shippedDir() / "taylor_copper_tvd.toml"), "D0/20",
                    test::kTaylorLengthBound);
}

// The same rod at Johnson and Cook's two slower shots, 130 and 146 m/s (test/taylor_data.hpp),
// with 190 m/s: the length within kTaylorLengthBound of each measurement (measured at D0/20
// +5.0, +5.4, +7.0 %; D0/40 +4.8, +5.1, +6.0 %: the model's excess at every speed, growing with
// it), shorter and with a wider foot the faster the shot. The foot is printed, not held, at
// the slower shots: +8.4 and +6.9 % here, +10.8 and +10.1 % at D0/40, where the measurement's
// own reading differs by 3.5-3.8 % between the compilation's table and its digitised profile
// (docs/strength.md, "Why the Taylor rod is long"). The rod at rest at 80 us (bound 1e-2 of the
// impact's kinetic energy). 4.4 s.
TEST(TvdStrengthCut, TaylorAnvilCopperAtThreeSpeeds) {
  expectTaylorAtThreeSpeeds(cases::loadScene(cases::test::shippedDir() / "taylor_copper_tvd.toml"),
                            "D0/20", test::kTaylorLengthBound);
}

// The shipped TVD Taylor scene with Zerilli and Armstrong's OFHC copper (preset copper_ofhc_za:
// J. Appl. Phys. 61 (1987) 1816, the paper that compared its model with this very shot;
// docs/strength.md, "Zerilli-Armstrong copper") instead of Johnson and Cook's: the yield law is
// the only difference.
cases::Scene zerilliArmstrongTaylor(const std::string& cellSize) {
  return cases::loadScene(
      cases::test::shippedDir() / "taylor_copper_tvd.toml",
      {"tvd.cell_size=" + cellSize, "materials.copper.strength.preset=\"copper_ofhc_za\""});
}

// Issue 15's criterion met: at 190 m/s the Zerilli-Armstrong rod's length and foot are both
// within the 5 % of the measurement. Measured at D0/30: L 1.6685 cm (+3.0 %), foot
// 1.3055 cm (-3.8 %). The length is converged (+3.5, +3.0, +2.9, +3.2 % at D0/20, 30, 40, 60);
// the foot grows with resolution towards the measurement (-5.7, -3.8, -2.6, -1.4 %), so D0/30
// is the coarsest spacing that meets 5 % on both (4 s; D0/20's foot misses by 0.7 %).
// Johnson-Cook 1983 on the same grid: +6 to +7 % long (TaylorAnvilCopper above). Energy and
// rest as there.
TEST(TvdStrengthCut, TaylorAnvilCopperZerilliArmstrong) {
  expectTaylorAnvil(zerilliArmstrongTaylor("0.0254 cm"), "Zerilli-Armstrong, D0/30", 0.05);
}

// The Zerilli-Armstrong rod at the compilation's three shots (test/taylor_data.hpp), D0/20:
// every length within the 5 % (measured +1.7, +1.9, +3.5 % at 130, 146, 190 m/s; at
// D0/60 +1.7, +1.9, +3.2 %), shorter with a wider foot the faster the shot, the rod at rest. The
// feet are printed, not held: +4.8, +2.3, -5.7 % here, but resolved the slower shots' feet are
// too wide (+7.5, +5.7 % at D0/60; Johnson-Cook: +12.0, +11.3 %), the 190 m/s one within 5 %
// (-1.4 %). 4.2 s.
TEST(TvdStrengthCut, TaylorAnvilCopperZerilliArmstrongAtThreeSpeeds) {
  expectTaylorAtThreeSpeeds(zerilliArmstrongTaylor("0.0381 cm"), "Zerilli-Armstrong, D0/20", 0.05);
}

TEST(TvdStrengthCut, TotalEnergyIsConserved) { checkEnergy(Geometry::Planar); }
TEST(TvdStrengthCut, TotalEnergyIsConservedInRz) { checkEnergy(Geometry::Axisymmetric); }
TEST(TvdStrengthCut, TotalEnergyIsConservedWithOutflowSides) {
  checkEnergy(Geometry::Planar, true);
  checkEnergy(Geometry::Axisymmetric, true);
}

// Restart: each phase's strength state is in the checkpoint, and the run continues bit for bit.
TEST(TvdStrengthCut, RestartIsBitForBit) {
  const cases::Scene s = blocks(Geometry::Planar);
  TvdSolver a(s);
  for (int i = 0; i < 31; ++i) a.advance(1e9);
  std::stringstream cp;
  a.writeCheckpoint(cp);
  for (int i = 0; i < 20; ++i) a.advance(1e9);
  TvdSolver b(s);
  b.readCheckpoint(cp);
  for (int i = 0; i < 20; ++i) b.advance(1e9);
  EXPECT_TRUE(hvi::test::sameBits(a.time(), b.time()));
  for (int p = 0; p < 2; ++p) {
    EXPECT_TRUE(hvi::test::sameBits(a.phases().q[p].mz, b.phases().q[p].mz));
    EXPECT_TRUE(hvi::test::sameBits(a.phases().q[p].E, b.phases().q[p].E));
  }
  const Snapshot sa = a.snapshot(), sb = b.snapshot();
  for (const char* f : {"stress_deviator_xx", "stress_deviator_zz", "stress_deviator_xz",
                        "plastic_strain", "temperature"})
    EXPECT_TRUE(hvi::test::sameBits(field(sa, f).data, field(sb, f).data)) << f;
}

// The strength state moves with its phase: an elastic block in uniform motion (0.05, 0.03)
// cm/us through vacuum (outflow sides) carrying a square patch of plastic strain, 4 us: its
// leading and trailing edges cross cells every few steps, so the sweeps' per-phase advection and
// the repair after the marker step both move it. Sum rho_p eps_p V is conserved to round-off
// (every move is conservative: 1e-12, as the cut-cell mass tests), the patch's centroid moves
// with the body (bound 1 % of the displacement, as the single-material advection test,
// TvdStrength.StrengthStateIsAdvectedWithTheMaterial, measured there -0.15 %), and the deviator
// stays zero to round-off: the cut cells keep the block's uniform state in diagonal motion
// (TvdCutMotion; before the settle's routing, docs/tvd.md "Uniform motion", the block's density
// was off by up to 3.8e-3 within 12 steps and the deviator answered with up to 1.7e-4 Mbar).
TEST(TvdStrengthCut, StrengthStateMovesWithItsPhase) {
  const double vx = 0.05, vz = 0.03, t = 4.0, h = 0.05;
  cases::Scene s = cutScene(-0.6, 1.4, -0.6, 1.0, h);
  const eos::Eos al = eos::aluminiumStudy();
  s.materials = {elastic("aluminium", al, kShearAl, 0.896e-5)};
  s.bodies = {
      body("block", 0, cases::Rect{-0.413, 0.437, -0.387, 0.463}, {density(al), {vx, vz}, 0.0})};
  TvdSolver solver(s);
  const GridSpec& g = solver.grid();
  std::vector<double>& eps = solver.phaseStrengthStateForTesting(0, 3);
  const Conserved& q = solver.phases().q[0];
  auto moments = [&](double& sum, double& mx, double& mz) {
    sum = mx = mz = 0.0;
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const auto c = static_cast<std::size_t>(k) * g.nx + i;
        const double v = eps[c] * solver.cellVolume(static_cast<long>(c));
        sum += v;
        mx += v * (g.x0 + (i + 0.5) * g.dx);
        mz += v * (g.z0 + (k + 0.5) * g.dz);
      }
    mx /= sum;
    mz /= sum;
  };
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double x = g.x0 + (i + 0.5) * g.dx, z = g.z0 + (k + 0.5) * g.dz;
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      if (x > -0.2 && x < 0.0 && z > -0.2 && z < 0.0) eps[c] = 0.5 * q.rho[c];
    }
  double s0, x0, z0, s1, x1, z1;
  moments(s0, x0, z0);
  runTo(solver, t);
  moments(s1, x1, z1);
  double smax = 0.0;  // the deviator: the block moves uniformly, so it must stay 0
  for (int k = 0; k < 3; ++k)
    for (std::size_t c = 0; c < q.rho.size(); ++c)
      if (q.rho[c] > 0.0)
        smax = std::max(smax, std::abs(solver.phaseStrengthStateForTesting(0, k)[c] / q.rho[c]));
  std::printf(
      "phase advection: %ld steps, sum %.2e relative, centroid moved (%.5f, %.5f) cm, expected "
      "(%.5f, %.5f); max |s| %.1e Mbar\n",
      solver.step(), s1 / s0 - 1.0, x1 - x0, z1 - z0, vx * t, vz * t, smax);
  EXPECT_NEAR(s1 / s0, 1.0, 1e-12);
  EXPECT_NEAR((x1 - x0) / (vx * t), 1.0, 0.01);
  EXPECT_NEAR((z1 - z0) / (vz * t), 1.0, 0.01);
  // The cut cells carry the block's uniform state to round-off in diagonal motion too (docs/tvd.md,
  // "Uniform motion"; before the settle's routing the deviator answered a density error of 3.8e-3
  // with 1.7e-4 Mbar): no strain rate, no deviator beyond round-off (1e-11 of G; measured 1.8e-16).
  EXPECT_LT(smax, 1e-11 * kShearAl);
}

// Threads: per cell, per face, per line and the edge ledger in a fixed order.
TEST(TvdStrengthCut, ThreadCountDoesNotChangeTheResult) {
  cases::Scene s = blocks(Geometry::Planar);
  s.tvd.cellSize = 0.004;
  Options one, two;
  one.threads = 1;
  two.threads = 2;
  TvdSolver a(s, one), b(s, two);
  ASSERT_GE(a.grid().cells(), kParallelCells);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a.advance(1e9), b.advance(1e9));
  for (int p = 0; p < 2; ++p) {
    EXPECT_EQ(a.phases().q[p].mz, b.phases().q[p].mz);
    EXPECT_EQ(a.phases().q[p].E, b.phases().q[p].E);
  }
  EXPECT_EQ(field(a.snapshot(), "stress_deviator_zz").data,
            field(b.snapshot(), "stress_deviator_zz").data);
}

// The whole-cell interfaces stay refused, with strength and with fracture, naming what to
// change; fracture with the conservative interfaces runs (tests/unit/tvd/test_fracture.cpp), and
// a fracture scene with the whole-cell mode is refused as its strength is.
TEST(TvdStrengthCut, RefusesWhatIsNotBuilt) {
  cases::Scene s = blocks(Geometry::Planar);
  s.tvd.interfaces = cases::InterfaceMode::WholeCell;
  try {
    TvdSolver solver(s);
    ADD_FAILURE() << "strength with whole-cell interfaces was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("conservative"), std::string::npos) << e.what();
  }
  s.effects.erase(Effect::TensionCutoff);
  s.effects.insert(Effect::Fracture);
  for (auto& m : s.materials) m.strength->spallStrength = 0.012;
  EXPECT_THROW(TvdSolver solver(s), InputError);
  s.tvd.interfaces = cases::InterfaceMode::Conservative;
  EXPECT_NO_THROW(TvdSolver solver(s));
  s.effects.erase(Effect::Strength);  // fracture needs strength
  EXPECT_THROW(TvdSolver solver(s), InputError);
  EXPECT_NO_THROW(TvdSolver solver(blocks(Geometry::Planar)));
}

}  // namespace
}  // namespace hvi::tvd
