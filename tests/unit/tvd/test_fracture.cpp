//! @file TVD fracture (docs/strength.md, "TVD fracture"): spall where the release waves meet,
//! mass and energy with failed material in the flow (conservative interfaces), restart bit for
//! bit with the damage, nothing of it without the effect, and Johnson-Cook failure at the
//! failure strain of the state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/same_bits.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;
using cases::Effect;

cases::Scene fractureScene(double xmin, double xmax, double zmin, double zmax, double h,
                           Geometry g = Geometry::Planar) {
  cases::Scene s = baseScene(xmin, xmax, zmin, zmax, h, g);
  s.effects.insert(Effect::MaterialInterfaces);
  s.effects.insert(Effect::Strength);
  s.effects.insert(Effect::Fracture);  // in place of the zero tension cut-off
  s.tvd.interfaces = cases::InterfaceMode::Conservative;
  return s;
}

// The study's Tillotson aluminium, elastic: the shear modulus of 6061-T6 (27.6 GPa) and a yield
// above any stress of these tests; spall strength in Mbar.
cases::Material elasticAluminium(double spallStrength,
                                 strength::DamageModel damage = strength::NoDamage{}) {
  cases::Material al = material("aluminium", eos::aluminiumStudy());
  strength::Material sm;
  sm.shearModulus = 0.276;
  sm.yield = strength::ConstantYield{1.0};
  sm.thermal.cv = 0.896e-5;
  sm.spallStrength = spallStrength;
  sm.damage = damage;
  al.strength = sm;
  return al;
}

// Symmetric flyer-plate spall, the SPH test's set-up (SphStrength.
// SymmetricImpactSpallsWhereTheReleasesMeet): an elastic aluminium flyer of thickness d = 0.2 cm
// at 200 m/s on an aluminium target of 2d, one material without marker lines (the two bodies one
// medium, welded as SPH's particles are), uniaxial strain (four cells between walls), vacuum
// above and below. The releases from the flyer's rear face and from the target's rear face meet
// at depth d in the target (both travel at c_L: ct - 2d = 4d - ct), where the longitudinal
// tension reaches the impact stress rho c_L v0 / 2 = 1.7 GPa (Meyers 1994, Dynamic behavior of
// materials, ch. 16), of which the pressure (what the spall strength limits, as in SPH) is
// K / (K + 4G/3) = 0.67: 1.15 GPa. With a spall strength of 0.8 GPa the target fails there;
// with 3 GPa nowhere. The failed layer (D >= 1/2: the damage is advected, its edge smeared like
// any advected quantity) is located by its mean depth. Bound 3 cells, as the SPH test's 3
// spacings: each release is smeared over a few cells by the scheme, and the tension first
// exceeds the spall strength a little before the two fully overlap. (The same scene with the
// conservative interfaces, flyer and target two phases: InterfacesCarryTheMeetingPlaneTension
// below.)
struct Spall {
  int failed = 0;
  double meanDepth = 0.0, spread = 0.0, energyDrift = 0.0, massDrift = 0.0, dMax = 0.0;
};
Spall symmetricSpall(double spallGpa, strength::DamageModel damage = strength::NoDamage{}) {
  const double dx = 0.01, d = 0.2, v0 = 0.02, width = 4 * dx;
  cases::Scene s = fractureScene(0.0, width, -2 * d - 0.1, d + 0.1, dx);
  s.effects.erase(Effect::MaterialInterfaces);
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Outflow,
                       cases::Boundary::Outflow};
  const cases::Material al = elasticAluminium(spallGpa * 0.01, damage);  // GPa -> Mbar
  s.materials = {al};
  const double rho0 = eos::referenceDensity(al.eos);
  s.bodies = {body("flyer", 0, cases::Rect{0.0, width, 0.0, d}, {rho0, {0.0, -v0}, 0.0}),
              body("target", 0, cases::Rect{0.0, width, -2 * d, 0.0}, {rho0, {}, 0.0})};
  TvdSolver solver(s);
  const Totals t0 = solver.totals();
  runTo(solver, 5.0 * d / 0.633);  // the releases meet at 3 d / c_L
  const GridSpec& g = solver.grid();
  const Conserved& q = solver.conserved();
  const std::vector<double>& rd = solver.strengthStateForTesting(4);
  Spall r;
  const Totals t1 = solver.totals();
  r.energyDrift = (t1.energy() - t0.energy() - solver.ledger().sum().energy) / t0.energy();
  r.massDrift = std::abs(t1.mass / t0.mass - 1.0);
  double zmin = 1e300, zmax = -1e300;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      if (!(q.rho[c] > 0.0)) continue;
      const double dmg = rd[c] / q.rho[c];
      r.dMax = std::max(r.dMax, dmg);
      if (dmg < 0.5) continue;
      const double z = g.z0 + (k + 0.5) * g.dz;
      ++r.failed;
      r.meanDepth -= z;
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
    }
  if (r.failed) {
    r.meanDepth /= r.failed;
    r.spread = zmax - zmin;
  }
  return r;
}

TEST(TvdFracture, SymmetricImpactSpallsWhereTheReleasesMeet) {
  const Spall weak = symmetricSpall(0.8), strong = symmetricSpall(3.0);
  std::printf(
      "spall 0.8 GPa: %d cells failed at mean depth %.4f cm (spread %.3f), dE/E = %.1e, mass "
      "%.1e; 3 GPa: %d failed (max D %.2g)\n",
      weak.failed, weak.meanDepth, weak.spread, weak.energyDrift, weak.massDrift, strong.failed,
      strong.dMax);
  EXPECT_GT(weak.failed, 0);
  EXPECT_NEAR(weak.meanDepth, 0.2, 0.03);
  // One layer: the failure relieves the tension, nothing else fails (the free surfaces' partly
  // filled cells included).
  EXPECT_LE(weak.spread, 0.03);
  // Failed material stays in the flow: energy (with the ledger) and mass exact.
  EXPECT_LT(std::abs(weak.energyDrift), 1e-12);
  EXPECT_LT(weak.massDrift, 1e-12);
  EXPECT_EQ(strong.failed, 0);
  EXPECT_EQ(strong.dMax, 0.0);
}

// The spall scene's tension with the conservative interfaces (flyer and target two phases): the
// most negative pressure between depths 0.1 and 0.3 cm (the meeting plane 0.2 cm, with the
// release fronts' smearing) up to 5 d / c_L, the spall strength out of reach (3 GPa).
double meetingPlaneTension(bool phases, double cfl, bool wallMirror = true) {
  const double dx = 0.01, d = 0.2, v0 = 0.02, width = 4 * dx;
  cases::Scene s = fractureScene(0.0, width, -2 * d - 0.1, d + 0.1, dx);
  if (!phases) s.effects.erase(Effect::MaterialInterfaces);
  s.tvd.cfl = cfl;
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Outflow,
                       cases::Boundary::Outflow};
  const cases::Material al = elasticAluminium(0.03);
  s.materials = {al};
  const double rho0 = eos::referenceDensity(al.eos);
  s.bodies = {body("flyer", 0, cases::Rect{0.0, width, 0.0, d}, {rho0, {0.0, -v0}, 0.0}),
              body("target", 0, cases::Rect{0.0, width, -2 * d, 0.0}, {rho0, {}, 0.0})};
  Options options;
  options.markerWalls = wallMirror;
  TvdSolver solver(s, options);
  const GridSpec& g = solver.grid();
  double pmin = 0.0;
  const double tEnd = 5.0 * d / 0.633;
  while (solver.time() < tEnd) {
    solver.advance(tEnd);
    const Snapshot snap = solver.snapshot();  // the field refers into it
    const Field& p = field(snap, "pressure");
    for (int k = 0; k < g.nz; ++k) {
      const double z = g.z0 + (k + 0.5) * g.dz;
      if (z < -0.3 || z > -0.1) continue;
      for (int i = 0; i < g.nx; ++i)
        pmin = std::min(pmin, p.data[static_cast<std::size_t>(k) * g.nx + i]);
    }
  }
  return -pmin * 100.0;  // GPa
}

// The meeting plane's tension with the conservative interfaces equals one material's (the
// acoustic 1.15 GPa of symmetricSpall's comment), at the default CFL 0.4 and at 0.1: the
// conservative mode's phases carry the same elastic state. Bound 3 %: one material's own
// distance from acoustics is 1 % (fronts smeared over a few cells), and the two modes' schemes
// differ (cut-cell Heun sweeps, marker-measured fractions at the flyer's contact). With the
// markers' earlier velocity field (Options::markerWalls = false: clamped at the outermost
// cell centres, not mirrored at the walls) the phases' side markers move off the walls with the
// wall cells' velocity, uniaxial strain's lateral tension pulls the target off them, and the
// meeting plane's tension is relieved (0.81 GPa at CFL 0.4; docs/strength.md, "TVD fracture").
TEST(TvdFracture, InterfacesCarryTheMeetingPlaneTension) {
  const double one = meetingPlaneTension(false, 0.4);
  const double two = meetingPlaneTension(true, 0.4);
  const double twoFine = meetingPlaneTension(true, 0.1);
  const double clamped = meetingPlaneTension(true, 0.4, false);
  std::printf(
      "meeting-plane tension (GPa): one material %.4f, phases %.4f at CFL 0.4, %.4f at "
      "0.1; markers clamped at the walls %.4f\n",
      one, two, twoFine, clamped);
  EXPECT_NEAR(one, 1.15, 0.03 * 1.15);
  EXPECT_NEAR(two / one, 1.0, 0.03);
  EXPECT_NEAR(twoFine / one, 1.0, 0.03);
  EXPECT_LT(clamped / one, 0.9);  // the mechanism: the option reproduces the earlier loss
}

// A plate of 0.2 cm at 100 m/s on a wall (the mirror image of a symmetric impact), uniaxial strain
// (four cells between the side walls): the release from its free face reflects at the wall as
// tension from 2 d / c_L = 0.63 us. The most negative pressure in the three cells at the wall up
// to 0.9 us, GPa.
double wallTension(bool phases, double cfl, bool mirror) {
  const double dx = 0.01, d = 0.2, v0 = 0.01, width = 4 * dx;
  cases::Scene s = fractureScene(0.0, width, 0.0, d + 0.1, dx);
  if (!phases) s.effects.erase(Effect::MaterialInterfaces);
  s.tvd.cfl = cfl;
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Outflow};
  const cases::Material al = elasticAluminium(0.03);
  s.materials = {al};
  const double rho0 = eos::referenceDensity(al.eos);
  s.bodies = {body("plate", 0, cases::Rect{0.0, width, 0.0, d}, {rho0, {0.0, -v0}, 0.0})};
  Options o;
  o.markerWalls = mirror;  // false: the markers' earlier field, clamped at the walls
  TvdSolver solver(s, o);
  const GridSpec& g = solver.grid();
  double pmin = 0.0;
  while (solver.time() < 0.9) {
    solver.advance(0.9);
    const Snapshot snap = solver.snapshot();  // the field refers into it
    const Field& p = field(snap, "pressure");
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < g.nx; ++i)
        pmin = std::min(pmin, p.data[static_cast<std::size_t>(k) * g.nx + i]);
  }
  return -pmin * 100;
}

// The conservative interfaces' body on a wall keeps the wall's tension as one material does:
// its marker lines on the bottom and side walls stay there. Bound 3 % as above (measured +2 %;
// at CFL 0.1 +4 %, not asserted). With the markers clamped at the walls (the earlier field) the
// wall line moved off the wall with the wall cells' velocity, a gap opened and the tension was
// relieved: 0.69 GPa at CFL 0.4 (0.62 at 0.1) against one material's 1.14.
TEST(TvdFracture, BodyOnAWallKeepsTheWallsTension) {
  const double one = wallTension(false, 0.4, true);
  const double phase = wallTension(true, 0.4, true);
  const double clamped = wallTension(true, 0.4, false);
  std::printf("tension at the wall (GPa): one material %.4f, one phase %.4f, clamped %.4f\n", one,
              phase, clamped);
  EXPECT_NEAR(phase / one, 1.0, 0.03);
  EXPECT_LT(clamped / one, 0.9);
}

// The same impact with Grady-Kipp tensile damage (Benz and Asphaug 1995) and the spall-strength
// failure out of reach (3 GPa), as SphStrength.GradyKippDamageSpallsWhereTheReleasesMeet: the
// flaws of the cell volume h^3 = 1e-6 cm^3 with k = 1e24 cm^-3, m = 9 activate at
// eps_min = (k V)^(-1/m) = 0.01, below the tensile strain at the meeting plane (1.7 GPa / E =
// 0.023) and above anything elsewhere; with k = 1e10 (eps_min ~ 5) no cell is damaged.
TEST(TvdFracture, GradyKippDamageSpallsWhereTheReleasesMeet) {
  const Spall gk = symmetricSpall(3.0, strength::GradyKipp{1e24, 9.0, 0.4});
  const Spall none = symmetricSpall(3.0, strength::GradyKipp{1e10, 9.0, 0.4});
  std::printf("Grady-Kipp: %d cells failed at mean depth %.4f cm (spread %.3f), dE/E = %.1e; "
              "k = 1e10: max D %.2g\n",
              gk.failed, gk.meanDepth, gk.spread, gk.energyDrift, none.dMax);
  EXPECT_GT(gk.failed, 0);
  EXPECT_NEAR(gk.meanDepth, 0.2, 0.03);
  EXPECT_LT(std::abs(gk.energyDrift), 1e-12);
  EXPECT_EQ(none.dMax, 0.0);
}

// A 2 km/s copper block (Johnson-Cook OFHC copper) on a 6061-T6 plate (Steinberg-Guinan), walls
// around (TvdStrengthCut's energy scene), with fracture: spall strength 1.2 GPa (the shield
// scenes' value) in place of the zero cut-off.
cases::Scene blocks(Geometry g) {
  const bool rz = g == Geometry::Axisymmetric;
  cases::Scene s = fractureScene(rz ? 0.0 : -0.4, 0.4, -0.2, 0.3, 0.02, g);
  s.domain.boundary = {rz ? cases::Boundary::Axis : cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall, cases::Boundary::Wall};
  cases::Material al = material("aluminium", eos::aluminiumStudy());
  al.strength = strength::findPreset("al6061_t6")->material;
  cases::Material cu = material("copper", eos::MieGruneisen{});
  cu.strength = strength::findPreset("copper_ofhc")->material;
  for (auto* m : {&al, &cu}) m->strength->spallStrength = 0.012;
  s.materials = {al, cu};
  const double x0 = rz ? 0.0 : -0.163;
  s.bodies = {body("striker", 1, cases::Rect{x0, 0.163, 0.013, 0.113}, {8.93, {0.0, -0.2}, 0.0}),
              body("plate", 0, cases::Rect{-0.4, 0.4, -0.107, 0.013}, {2.79, {}, 0.0})};
  return s;
}

int failedCells(const Snapshot& snap) {
  const Field& dmg = field(snap, "damage");
  return static_cast<int>(std::count_if(dmg.data.begin(), dmg.data.end(),
                                        [](double d) { return d >= 1.0; }));
}

// Mass and total energy with fracture (TvdStrengthCut.TotalEnergyIsConserved's bound 1e-12):
// the pressure limit acts inside the sweeps' fluxes and exchange, which stay conservative
// whatever pressure they carry; the damage changes no conserved quantity. So the total changes
// by what the ledger books, to round-off, and every phase's mass is exact, while material fails.
void checkConservation(Geometry g) {
  TvdSolver solver(blocks(g));
  const Totals t0 = solver.totals();
  const auto m0 = phaseMasses(solver);
  runTo(solver, 1.0);
  const Totals t1 = solver.totals();
  const auto m1 = phaseMasses(solver);
  const Budget led = solver.ledger().sum();
  const int failed = failedCells(solver.snapshot());
  const double dE = (t1.energy() - t0.energy() - led.energy) / t0.energy();
  std::printf("%s blocks with fracture, %ld steps: energy %.2e (ledger %.2e), masses %.1e %.1e, "
              "%d cells failed\n",
              toString(g).data(), solver.step(), dE, led.energy / t0.energy(),
              m1[0] / m0[0] - 1.0, m1[1] / m0[1] - 1.0, failed);
  EXPECT_NEAR(dE, 0.0, 1e-12);
  EXPECT_EQ(solver.ledger().boundary.energy, 0.0);
  for (std::size_t p = 0; p < m0.size(); ++p) EXPECT_NEAR(m1[p], m0[p], 1e-12 * m0[p]);
  EXPECT_GT(failed, 0);  // fracture is exercised
}
TEST(TvdFracture, MassAndEnergyAreConserved) { checkConservation(Geometry::Planar); }
TEST(TvdFracture, MassAndEnergyAreConservedInRz) { checkConservation(Geometry::Axisymmetric); }

// Failed material steps with the bulk sound speed (the SPH test's set-up, SphStrength.
// FailedMaterialStepsWithTheBulkSoundSpeed): at D = 1 the yield is (1 - D) Y = 0 and no
// deviator is carried, so no shear wave, and the step reads c, not c_L. An elastic aluminium
// block at rest at 0.98 rho0 (P ~ -0.015 Mbar) fills a box of walls, so that every cell is away
// from a free surface (where the failure rule holds), as one material without marker lines and
// as a phase of the conservative interfaces (their own time-step scan; one body: a contact
// between two bodies opens under tension, and the block would not stay at rest). With a spall
// strength of 0.001 Mbar every cell fails at the first step's end and then sits at P = 0; with
// 1 Mbar none does. At rest the step is
// cfl dx / max c_L (intact) or cfl dx / max c (failed): the second steps differ by c_L / c
// (1.24). The block stays at rest and uniform (walls, one state), so the ratio is exact to
// round-off: bound 1e-12.
struct SecondStep {
  double dt = 0.0, dMin = 0.0, dMax = 0.0;  // the step (us) and the damage's range after it
};
SecondStep secondStepOfAStretchedBlock(bool phases, double spallStrength) {
  const double dx = 0.02;
  cases::Scene s = fractureScene(0.0, 0.2, 0.0, 0.2, dx);
  if (!phases) s.effects.erase(Effect::MaterialInterfaces);
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall};
  const cases::Material al = elasticAluminium(spallStrength);
  s.materials = {al};
  const double rho = 0.98 * eos::referenceDensity(al.eos);
  s.bodies = {body("block", 0, cases::Rect{0.0, 0.2, 0.0, 0.2}, {rho, {}, 0.0})};
  TvdSolver solver(s);
  solver.advance(1e9);
  const double t1 = solver.time();
  solver.advance(1e9);
  const Snapshot snap = solver.snapshot();
  const Field& d = field(snap, "damage");
  const auto [lo, hi] = std::minmax_element(d.data.begin(), d.data.end());
  return {solver.time() - t1, *lo, *hi};
}

TEST(TvdFracture, FailedMaterialStepsWithTheBulkSoundSpeed) {
  cases::Scene s = fractureScene(0.0, 1.0, 0.0, 1.0, 0.1);
  s.materials = {elasticAluminium(1.0)};
  const cases::Material al = cases::resolveMaterials(s).at(0);  // no tension cut-off
  const double rho = 0.98 * eos::referenceDensity(al.eos);
  const double c = eos::state(al.eos, rho, 0.0).soundSpeed;
  const double expected =
      strength::longitudinalSoundSpeed(c, al.strength->shearModulus, rho) / c;
  for (bool phases : {false, true}) {
    const SecondStep failed = secondStepOfAStretchedBlock(phases, 0.001);
    const SecondStep intact = secondStepOfAStretchedBlock(phases, 1.0);
    std::printf("%s: second step failed %.6e us, intact %.6e us, ratio %.6f (c_L / c %.6f)\n",
                phases ? "conservative interfaces" : "one material", failed.dt, intact.dt,
                failed.dt / intact.dt, expected);
    EXPECT_EQ(failed.dMin, 1.0);  // every cell failed
    EXPECT_EQ(intact.dMax, 0.0);  // none did
    EXPECT_NEAR(failed.dt / intact.dt, expected, 1e-12 * expected);
  }
}

// Restart with the damage in the checkpoint (version 7): the run continues bit for bit; a
// checkpoint across the fracture switch is refused.
TEST(TvdFracture, RestartIsBitForBit) {
  const cases::Scene s = blocks(Geometry::Planar);
  TvdSolver a(s);
  for (int i = 0; i < 31; ++i) a.advance(1e9);
  std::stringstream cp;
  a.writeCheckpoint(cp);
  const std::string saved = cp.str();
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
  for (const char* f : {"pressure", "stress_deviator_zz", "plastic_strain", "damage"})
    EXPECT_TRUE(hvi::test::sameBits(field(sa, f).data, field(sb, f).data)) << f;
  EXPECT_GT(failedCells(sa), 0);
  cases::Scene without = s;
  without.effects.erase(Effect::Fracture);
  without.effects.insert(Effect::TensionCutoff);
  TvdSolver c(without);
  std::stringstream again(saved);
  EXPECT_THROW(c.readCheckpoint(again), InputError);
}

// Without fracture nothing of it is there: no damage field, no damage array.
TEST(TvdFracture, AbsentWithoutTheEffect) {
  cases::Scene s = blocks(Geometry::Planar);
  s.effects.erase(Effect::Fracture);
  s.effects.insert(Effect::TensionCutoff);
  TvdSolver solver(s);
  EXPECT_THROW(field(solver.snapshot(), "damage"), std::runtime_error);
  EXPECT_THROW(solver.phaseStrengthStateForTesting(0, 4), std::logic_error);
}

// Johnson-Cook (1985) failure in the TVD solver, the SPH test's set-up (SphStrength.
// JohnsonCookFailureAtTheExpectedPlasticStrain): a 4340 steel slab (the preset's D1..D5 = 0.05,
// 3.44, -2.12, 0.002, 0.61; Johnson and Cook 1985, Eng. Fract. Mech. 21, 31) pulled apart in
// uniaxial strain, one material without marker lines: walls at x = 0 and x = 4 dx, a wall at
// z = 0 as the symmetry plane, v_z = a z initially, the far end z = L free. Ahead of the release
// from the free end (it leaves z = L at t = 0 at c_L = 0.59 cm/us) the slab stretches uniformly:
// the tension grows with the volumetric strain (-P = K eps), the triaxiality sigma* = -P /
// sigma_eq soon passes 3 and the failure strain falls to D1 + D2 exp(D3 sigma*) -> D1. The
// damage D = sum d eps_p / eps_f(sigma*, eps_dot*, T*) must reach 1 at an equivalent plastic
// strain of about D1 plus what the early, low-triaxiality flow used up. The test integrates that
// sum itself per cell and step from the solver's state at the step's end (pressure, deviator,
// temperature, plastic strain; the rate 2/3 dv_z/dz of uniaxial strain from the cells' velocity)
// over the cells the release has not reached (z < 0.25 L), where the state is uniform along z and
// the advection of D and eps_p changes nothing. Bound 0.05 in D, the SPH test's: the solver
// evaluates sigma*, T and the rate before the step's stress fluxes change the energy and the
// velocity, the test after them.
// The spall strength is out of reach (1 Mbar) so that only the damage law fails material.
TEST(TvdFracture, JohnsonCookFailureAtTheExpectedPlasticStrain) {
  const double dx = 0.01, width = 4 * dx, length = 2.0, a = 0.08;  // a in 1/us
  cases::Scene s = baseScene(0.0, width, 0.0, 2.0 * length, dx);
  s.effects = {Effect::Strength, Effect::Fracture};
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Outflow};
  // 4340 steel: Mie-Gruneisen of Steinberg (1996): 7.85 g/cm^3, c0 4.578 km/s, s 1.33,
  // Gamma0 1.67 (as the SPH test).
  cases::Material steel = material("steel", eos::MieGruneisen{7.85, 0.4578, 1.33, 1.67});
  steel.strength = strength::findPreset("steel_4340")->material;
  steel.strength->spallStrength = 1.0;
  const auto jc = std::get<strength::JohnsonCookFailure>(steel.strength->damage);
  const auto law = std::get<strength::JohnsonCook>(steel.strength->yield);
  s.materials = {steel};
  s.bodies = {body("slab", 0, cases::Rect{0.0, width, 0.0, length}, {7.85, {}, 0.0})};
  TvdSolver solver(s);
  const GridSpec& g = solver.grid();
  {
    Conserved& U = solver.conservedForTesting();
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const auto c = static_cast<std::size_t>(k) * g.nx + i;
        const double vz = a * (g.z0 + (k + 0.5) * g.dz);
        U.mz[c] = U.rho[c] * vz;
        U.E[c] += 0.5 * U.rho[c] * vz * vz;
      }
  }
  const int rows = static_cast<int>(0.25 * length / dx);  // ahead of the release
  const std::size_t n = static_cast<std::size_t>(rows) * g.nx;
  std::vector<double> expected(n, 0.0), epsPrev(n, 0.0), epsAtFailure(n, -1.0);
  double worst = 0.0, tFail = -1.0;
  while (solver.time() < 2.5) {
    solver.advance(2.5);
    const Snapshot snap = solver.snapshot();
    const Field& p = field(snap, "pressure");
    const Field& sxx = field(snap, "stress_deviator_xx");
    const Field& szz = field(snap, "stress_deviator_zz");
    const Field& sxz = field(snap, "stress_deviator_xz");
    const Field& eps = field(snap, "plastic_strain");
    const Field& temp = field(snap, "temperature");
    const Field& dmg = field(snap, "damage");
    const Conserved& U = solver.conserved();
    auto vz = [&](int i, int k) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      return U.mz[c] / U.rho[c];
    };
    for (int k = 0; k < rows; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const auto c = static_cast<std::size_t>(k) * g.nx + i;
        // dv_z/dz central; at the wall z = 0 the mirror (v_z = 0 on the wall face).
        const double dvdz = k == 0 ? (vz(i, 1) + vz(i, 0)) / (2.0 * dx)
                                   : (vz(i, k + 1) - vz(i, k - 1)) / (2.0 * dx);
        const strength::Deviator dev{sxx.data[c], szz.data[c], sxz.data[c]};
        const double seq = strength::vonMises(dev);
        const double triax = seq > 0.0 ? -p.data[c] / seq : 0.0;
        const double deps = eps.data[c] - epsPrev[c];
        epsPrev[c] = eps.data[c];
        if (expected[c] < 1.0 && deps > 0.0)
          expected[c] =
              std::min(1.0, expected[c] + deps / jc.failureStrain(triax, 2.0 / 3.0 * std::abs(dvdz),
                                                                  law.homologous(temp.data[c])));
        if (dmg.data[c] >= 1.0 && epsAtFailure[c] < 0.0) {
          epsAtFailure[c] = eps.data[c];
          if (tFail < 0.0) tFail = solver.time();
        }
        worst = std::max(worst, std::abs(dmg.data[c] - expected[c]));
      }
    if (std::all_of(epsAtFailure.begin(), epsAtFailure.end(), [](double e) { return e >= 0.0; }))
      break;
  }
  int failed = 0;
  double epsMean = 0.0, epsMin = 1e300, epsMax = 0.0;
  for (std::size_t c = 0; c < n; ++c)
    if (epsAtFailure[c] >= 0.0) {
      ++failed;
      epsMean += epsAtFailure[c];
      epsMin = std::min(epsMin, epsAtFailure[c]);
      epsMax = std::max(epsMax, epsAtFailure[c]);
    }
  if (failed) epsMean /= failed;
  const Field& dEnd = field(solver.snapshot(), "damage");
  const double dLeast = *std::min_element(dEnd.data.begin(), dEnd.data.begin() + n);
  std::printf(
      "TVD JC failure: %d of %zu cells (z < %.2f cm) failed, first at t = %.3f us, eps_p at "
      "failure %.4f (%.4f to %.4f; D1 = %.2f); largest |D - sum d eps_p / eps_f| = %.3e, least "
      "D %.3f, %ld steps\n",
      failed, n, rows * dx, tFail, epsMean, epsMin, epsMax, jc.d1, worst, dLeast, solver.step());
  // Once the first cells fail (D = 1: no tension, no deviator) the stretching concentrates in
  // them and a neighbour may unload just short of D = 1 (measured: one row at 0.993, its sum
  // 1.000): most cells fail, and every one comes within the bound of it.
  EXPECT_GE(failed, static_cast<int>(9 * n / 10));
  EXPECT_GT(dLeast, 1.0 - 0.05);
  EXPECT_LT(worst, 0.05);
  // Most of the failure strain is spent at high triaxiality, where eps_f -> D1.
  EXPECT_GT(epsMin, jc.d1);
  EXPECT_LT(epsMax, 3.0 * jc.d1);
}

}  // namespace
}  // namespace hvi::tvd
