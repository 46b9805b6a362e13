//! @file TVD with the effect `strength` (docs/strength.md, "TVD"): elastic wave speed, the
//! Hugoniot elastic limit, conservation, checkpoint, snapshot fields and what is refused. The
//! SPH tests of the same physics (tests/unit/sph/test_strength_solver.cpp) are the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "hvi/test/two_wave.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/same_bits.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;
using cases::Effect;

// Aluminium of the study's Tillotson EOS with a constant (elastic-perfectly plastic) yield and
// the shear modulus of 6061-T6 (Steinberg 1991: 27.6 GPa), as in the SPH tests.
constexpr double kShear = 0.276;  // Mbar
cases::Material strongAluminium(double y0) {
  cases::Material m = material("aluminium", eos::aluminiumStudy());
  strength::Material sm;
  sm.shearModulus = kShear;
  sm.yield = strength::ConstantYield{y0};
  sm.thermal.cv = 0.896e-5;
  m.strength = sm;
  return m;
}

double rho0() { return eos::referenceDensity(eos::aluminiumStudy()); }
double bulkSpeed() {
  const eos::Eos al = eos::aluminiumStudy();
  return std::visit([&](const auto& e) { return e.state(rho0(), 0.0).soundSpeed; }, al);
}

// Uniaxial strain (a 1-D slab): a strip `columns` cells wide between two walls (x = 0 and
// x = width; in r-z the axis and a rigid tube). A flyer of the same material (z in [0, flyer])
// moving at -v0 hits the target (z in [-depth, 0]) at rest. The domain ends at the flyer's back
// with an outflow side (zero-gradient: the flyer continues without end, no release) and at the
// target's far end with a wall.
cases::Scene slab(double dx, int columns, double depth, double flyer, double v0, double y0,
                  bool withStrength, bool rz = false) {
  const double width = columns * dx;
  cases::Scene s =
      baseScene(0.0, width, -depth, flyer, dx, rz ? Geometry::Axisymmetric : Geometry::Planar);
  s.domain.boundary = {rz ? cases::Boundary::Axis : cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall, cases::Boundary::Outflow};
  if (withStrength) s.effects.insert(Effect::Strength);
  s.materials = {withStrength ? strongAluminium(y0) : material("aluminium", eos::aluminiumStudy())};
  s.bodies = {body("flyer", 0, cases::Rect{0.0, width, 0.0, flyer}, {rho0(), {0.0, -v0}, 0.0}),
              body("target", 0, cases::Rect{0.0, width, -depth, 0.0}, {rho0(), {}, 0.0})};
  return s;
}

// Row averages (deep end first) of -v_z and of the longitudinal stress -sigma_zz = P - s_zz.
struct Profile {
  std::vector<double> z, velocity, stress;
};
Profile profile(const TvdSolver& solver) {
  const Snapshot snap = solver.snapshot();
  const GridSpec& g = solver.grid();
  const Field& v = field(snap, "velocity");
  const Field& p = field(snap, "pressure");
  const bool strong = solver.snapshot().fields.size() > 6;
  Profile out;
  for (int k = 0; k < g.nz; ++k) {
    double sv = 0.0, ss = 0.0;
    for (int i = 0; i < g.nx; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      sv -= v.data[2 * c + 1];
      ss += p.data[c] - (strong ? field(snap, "stress_deviator_zz").data[c] : 0.0);
    }
    out.z.push_back(g.z0 + (k + 0.5) * g.dz);
    out.velocity.push_back(sv / g.nx);
    out.stress.push_back(ss / g.nx);
  }
  return out;
}

// Depth of the front: where -v_z first reaches `level` coming from the deep end, linear
// between rows.
double frontDepth(const TvdSolver& solver, double level) {
  const Profile p = profile(solver);
  for (std::size_t r = 1; r < p.z.size(); ++r)
    if (p.velocity[r] >= level)
      return p.z[r] -
             (p.z[r] - p.z[r - 1]) * (p.velocity[r] - level) / (p.velocity[r] - p.velocity[r - 1]);
  return p.z.back();
}

double frontSpeed(const cases::Scene& s, double t1, double t2, double level) {
  TvdSolver solver(s);
  runTo(solver, t1);
  const double z1 = frontDepth(solver, level);
  runTo(solver, t2);
  const double z2 = frontDepth(solver, level);
  return (z1 - z2) / (t2 - t1);
}

// A small velocity step (1 m/s, strain ~1e-4: linear elasticity) in a laterally confined slab
// travels at the longitudinal speed c_L = sqrt((K + 4G/3) / rho) = sqrt(c0^2 + 4G / (3 rho0))
// (Meyers, Dynamic behavior of materials, 1994, ch. 2), not at the bulk speed c0 of the
// hydrodynamic run. The front (half of the particle-velocity jump v0/2 of equal materials) is
// located in the row-averaged velocity profile at 0.5 and 1.4 us, after it has formed; its
// smearing is then nearly steady and cancels in the difference. 1 % is the bound. The
// test discriminates: the bulk speed is 18 % below c_L.
void checkElasticWave(bool rz) {
  const double v0 = 1e-4, dx = 0.01;
  const double c0 = bulkSpeed();
  const double cL = strength::longitudinalSoundSpeed(c0, kShear, rho0());
  const double elastic = frontSpeed(slab(dx, 2, 1.0, 0.3, v0, 1.0, true, rz), 0.5, 1.4, 0.25 * v0);
  const double bulk = frontSpeed(slab(dx, 2, 1.0, 0.3, v0, 1.0, false, rz), 0.5, 1.4, 0.25 * v0);
  std::printf(
      "%s: c0 = %.5f, c_L = %.5f cm/us; measured: strength %.5f (%.2f %%), hydro %.5f (%.2f %%)\n",
      rz ? "r-z" : "planar", c0, cL, elastic, 100.0 * (elastic / cL - 1.0), bulk,
      100.0 * (bulk / c0 - 1.0));
  EXPECT_NEAR(elastic / cL, 1.0, 0.01);
  EXPECT_NEAR(bulk / c0, 1.0, 0.01);  // and without strength, the bulk speed
  EXPECT_GT(elastic / bulk, 1.15);
}

TEST(TvdStrength, ElasticWaveTravelsAtLongitudinalSpeed) { checkElasticWave(false); }
// In r-z the strip is a cylinder on the axis in a rigid tube: the hoop stress must balance the
// radial one, or the cylinder would not stay in uniaxial strain (checked: |v_r| stays small).
TEST(TvdStrength, ElasticWaveTravelsAtLongitudinalSpeedInRz) {
  checkElasticWave(true);
  const double v0 = 1e-4;
  TvdSolver solver(slab(0.01, 4, 1.0, 0.3, v0, 1.0, true, true));
  runTo(solver, 1.0);
  double vr = 0.0;
  for (std::size_t c = 0; c < solver.conserved().rho.size(); ++c)
    vr = std::max(vr, std::abs(solver.conserved().mx[c] / solver.conserved().rho[c]));
  std::printf("r-z: max |v_r| = %.3e cm/us at 1 us (v0 = %.1e)\n", vr, v0);
  EXPECT_LT(vr, 0.05 * v0);
}

// The hoop strain rate (r-z): a cylinder on the axis given v_r = a r (radial strain rate a,
// hoop rate v_r / r = a) gets in one step the deviator of the strain rate diag(a, 0, a)
// (rr, zz, tt), ds = 2G dt (a/3, -2a/3, a/3). The strength step sees the velocity after the
// hydrodynamic sweeps, which near the axis is not a r any more (the sweep's axis treatment
// doubles v_r of the axis cell in this step, a hydrodynamic matter); so the expected deviator
// is computed here from that velocity (the same sweeps run without strength with the same dt):
// central differences, the mirror at the axis, the hoop rate v_r / r at the cell centre. Bound
// 1e-9 relative: the same arithmetic up to round-off. Without the hoop rate the split would be
// another (s_zz / s_rr = -0.5 instead of -2), an error of order 1.
TEST(TvdStrength, HoopStrainRateInRz) {
  const double a = 1e-4;
  cases::Scene s = slab(0.01, 20, 0.1, 0.0, 0.0, 1.0, true, true);
  s.bodies = {body("rod", 0, cases::Rect{0.0, 0.2, -0.1, 0.0}, {rho0(), {}, 0.0})};
  s.domain.zmax = 0.0;
  s.domain.boundary[3] = cases::Boundary::Wall;
  TvdSolver solver(s);
  Conserved& U = solver.conservedForTesting();
  const GridSpec& g = solver.grid();
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      const double vr = a * (g.x0 + (i + 0.5) * g.dx);
      U.mx[c] = U.rho[c] * vr;
      U.E[c] += 0.5 * U.rho[c] * vr * vr;
    }
  cases::Scene h = s;
  h.effects.erase(Effect::Strength);
  TvdSolver hydro(h);
  hydro.conservedForTesting() = solver.conserved();
  const double dt = solver.advance(1e9);
  ASSERT_EQ(hydro.advance(dt), dt);
  const Snapshot snap = solver.snapshot();
  const Conserved& V = hydro.conserved();
  auto vr = [&](int i, int k) {
    const auto c = static_cast<std::size_t>(k) * g.nx + i;
    return V.mx[c] / V.rho[c];
  };
  const double scale = 2.0 * kShear * a * dt / 3.0;
  double worst = 0.0;
  int n = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx - 1; ++i) {
      const auto c = static_cast<std::size_t>(k) * g.nx + i;
      const double dudr = (vr(i + 1, k) - (i > 0 ? vr(i - 1, k) : -vr(i, k))) / (2.0 * g.dx);
      const double hoop = vr(i, k) / (g.x0 + (i + 0.5) * g.dx);
      const double third = (dudr + hoop) / 3.0;  // v_z stays 0 (walls at both z ends)
      const double exx = 2.0 * kShear * dt * (dudr - third);
      const double ezz = 2.0 * kShear * dt * (-third);
      const double ett = 2.0 * kShear * dt * (hoop - third);
      const double sxx = field(snap, "stress_deviator_xx").data[c];
      const double szz = field(snap, "stress_deviator_zz").data[c];
      const double stt = field(snap, "stress_deviator_tt").data[c];
      ++n;
      worst = std::max({worst, std::abs(sxx - exx) / scale, std::abs(szz - ezz) / scale,
                        std::abs(stt - ett) / scale});
    }
  std::printf("hoop rate: %d cells, 2G a dt/3 = %.4e; worst against the swept velocity %.2e\n", n,
              scale, worst);
  EXPECT_GT(n, 150);
  EXPECT_LT(worst, 1e-9);
}

// Planar flyer-plate impact (200 m/s, Al on Al) in an elastic-perfectly plastic metal: a
// two-wave structure whose elastic precursor carries the Hugoniot elastic limit
// sigma_HEL = Y0 (1 - nu) / (1 - 2 nu) = (K + 4G/3) Y0 / 2G (uniaxial strain yields at
// 2 G eps = Y0; Meyers 1994, ch. 7), and a plastic wave behind it at about 2.5 HEL. K is the
// EOS's rho0 c0^2. The plateau is read where the longitudinal-stress profile is flattest
// between the two fronts. Bound 3 % (the issue's): the linear formula leaves out the EOS's
// finite-strain and Gruneisen terms (+1 % at the yield point, SPH test).
TEST(TvdStrength, ElasticPrecursorCarriesTheHugoniotElasticLimit) {
  const double y0 = 0.003, dx = 0.01;
  const double c0 = bulkSpeed();
  const double k = rho0() * c0 * c0;
  const double nu = (3.0 * k - 2.0 * kShear) / (2.0 * (3.0 * k + kShear));
  const double hel = y0 * (1.0 - nu) / (1.0 - 2.0 * nu);
  TvdSolver solver(slab(dx, 2, 1.8, 0.6, 0.02, y0, true));
  runTo(solver, 2.5);
  const Profile p = profile(solver);
  const hvi::test::TwoWave w = hvi::test::twoWave(p.z, p.stress, hel);
  std::printf(
      "nu = %.4f, sigma_HEL = %.6f Mbar; plateau %.6f (%.2f %%) at z = %.3f, peak %.5f; "
      "fronts: elastic z = %.3f, plastic z = %.3f\n",
      nu, hel, w.plateau, 100.0 * (w.plateau / hel - 1.0), w.zPlateau, w.peak, w.zElastic,
      w.zPlastic);
  EXPECT_NEAR(w.plateau / hel, 1.0, 0.03);
  EXPECT_GT(w.peak, 2.0 * hel);
  EXPECT_GT(w.zPlastic - w.zElastic, 10.0 * dx);
}

// A 2 km/s block impact (some 30 x the yield: strongly plastic) with the Steinberg-Guinan
// 6061-T6 preset (G(P, T), melt), free surfaces into the single material's vacuum, walls around.
cases::Scene blocks(Geometry g, double v = 0.2) {
  const bool rz = g == Geometry::Axisymmetric;
  cases::Scene s = baseScene(rz ? 0.0 : -0.4, 0.4, -0.2, 0.3, 0.02, g);
  s.domain.boundary = {rz ? cases::Boundary::Axis : cases::Boundary::Wall, cases::Boundary::Wall,
                       cases::Boundary::Wall, cases::Boundary::Wall};
  // The study's zero cut-off: Tillotson tension at the free surfaces' nearly empty cells would
  // stop the hydrodynamic run itself (as without strength).
  s.effects.insert(Effect::TensionCutoff);
  s.effects.insert(Effect::Strength);
  cases::Material al = material("aluminium", eos::aluminiumStudy());
  al.strength = strength::findPreset("al6061_t6")->material;
  s.materials = {al};
  const double x0 = rz ? 0.0 : -0.16;
  s.bodies = {body("striker", 0, cases::Rect{x0, 0.16, 0.0, 0.1}, {rho0(), {0.0, -v}, 0.0}),
              body("plate", 0, cases::Rect{-0.4, 0.4, -0.1, 0.0}, {rho0(), {}, 0.0})};
  return s;
}

// Total energy: the strength step's face fluxes add to one cell what they take from the other,
// and the walls do no work (normal velocity and shear traction are zero there exactly), so the
// total changes only by what the ledger books (the hydrodynamic floors): the same round-off
// bound as the closed-box tests (1e-12; test_conservation.cpp). Planar x momentum likewise.
void checkEnergy(Geometry g) {
  TvdSolver solver(blocks(g));
  const Totals t0 = solver.totals();
  runTo(solver, 1.0);
  const Totals t1 = solver.totals();
  const Budget led = solver.ledger().sum();
  double epsMax = 0.0;
  const Snapshot snap = solver.snapshot();
  for (double e : field(snap, "plastic_strain").data) epsMax = std::max(epsMax, e);
  const double dE = (t1.energy() - t0.energy() - led.energy) / t0.energy();
  std::printf("%s blocks, %ld steps: energy %.2e (ledger %.2e), wall energy %.1e, max eps_p %.3f\n",
              toString(g).data(), solver.step(), dE, led.energy / t0.energy(),
              solver.ledger().boundary.energy, epsMax);
  EXPECT_NEAR(dE, 0.0, 1e-12);
  EXPECT_EQ(solver.ledger().boundary.energy, 0.0);
  EXPECT_GT(epsMax, 0.05);  // the test exercises the plastic return
  if (g == Geometry::Planar) {
    const double scale = t0.mass * 0.2;
    EXPECT_NEAR(t1.momentumX - t0.momentumX, solver.ledger().sum().momentumX, 1e-12 * scale);
  }
}
TEST(TvdStrength, TotalEnergyIsConserved) { checkEnergy(Geometry::Planar); }
TEST(TvdStrength, TotalEnergyIsConservedInRz) { checkEnergy(Geometry::Axisymmetric); }

// Restart: the deviator and the plastic strain follow the hydrodynamic state in the checkpoint
// and the run continues bit for bit (TvdCheckpoint.RestartIsBitForBit is the model).
TEST(TvdStrength, RestartIsBitForBit) {
  const cases::Scene s = blocks(Geometry::Planar);
  TvdSolver a(s);
  for (int i = 0; i < 31; ++i) a.advance(1e9);
  std::stringstream cp;
  a.writeCheckpoint(cp);
  for (int i = 0; i < 20; ++i) a.advance(1e9);
  TvdSolver b(s);
  b.readCheckpoint(cp);
  for (int i = 0; i < 20; ++i) b.advance(1e9);
  EXPECT_EQ(a.time(), b.time());
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mz, b.conserved().mz));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().E, b.conserved().E));
  const Snapshot sa = a.snapshot(), sb = b.snapshot();
  for (const char* f :
       {"stress_deviator_xx", "stress_deviator_zz", "stress_deviator_xz", "plastic_strain"})
    EXPECT_TRUE(hvi::test::sameBits(field(sa, f).data, field(sb, f).data)) << f;
  // A checkpoint of a run with strength is refused by one without, and the reverse.
  cases::Scene hydro = s;
  hydro.effects.erase(Effect::Strength);
  TvdSolver c(hydro);
  std::stringstream cp2;
  a.writeCheckpoint(cp2);
  EXPECT_THROW(c.readCheckpoint(cp2), InputError);
  std::stringstream cp3;
  c.writeCheckpoint(cp3);
  EXPECT_THROW(a.readCheckpoint(cp3), InputError);
}

// Snapshots carry the strength fields with the effect and not without it.
TEST(TvdStrength, SnapshotFields) {
  cases::Scene s = blocks(Geometry::Planar);
  TvdSolver a(s);
  for (int i = 0; i < 5; ++i) a.advance(1e9);
  const Snapshot snap = a.snapshot();
  for (const char* f : {"stress_deviator_xx", "stress_deviator_zz", "stress_deviator_xz",
                        "stress_deviator_tt", "plastic_strain", "temperature"})
    EXPECT_NO_THROW(field(snap, f)) << f;
  double tmin = 1e300;
  const Field& rho = field(snap, "density");
  const Field& t = field(snap, "temperature");
  for (std::size_t c = 0; c < t.data.size(); ++c)
    if (rho.data[c] > 2.0) tmin = std::min(tmin, t.data[c]);
  EXPECT_NEAR(tmin, 300.0, 1.0);  // material at rest is at the model's T0
  s.effects.erase(Effect::Strength);
  TvdSolver b(s);
  for (const Field& f : b.snapshot().fields) EXPECT_NE(f.name, "plastic_strain");
}

// The strength state moves with the material: a block in uniform motion (no velocity gradient:
// the deviator stays 0 exactly) carries a square patch of plastic strain. Sum rho eps_p V is
// conserved exactly while the patch is inside the domain (the advection's face fluxes are
// equal and opposite), and the patch's centroid moves with the velocity in x and z (the
// conservative upwind scheme moves the first moment at the flow speed; measured -0.15 % and
// -0.03 %, bound 1 % of the displacement, 1/25 of a cell: the limited slopes' corrections,
// which cancel only for a symmetric profile). A sweep direction that did not advect would
// leave its centroid in place. 32 x 32 cells: the sweeps run many lines in both directions; the
// patch's numerical tail stays clear of the outflow sides (at 20 x 20 it reached them: -6.5e-7).
TEST(TvdStrength, StrengthStateIsAdvectedWithTheMaterial) {
  const double vx = 0.05, vz = 0.03, t = 4.0;
  cases::Scene s = baseScene(0.0, 1.6, 0.0, 1.6, 0.05);
  s.effects.insert(Effect::Strength);
  s.materials = {strongAluminium(1.0)};
  s.bodies = {body("block", 0, cases::Rect{0.0, 1.6, 0.0, 1.6}, {rho0(), {vx, vz}, 0.0})};
  TvdSolver solver(s);
  const GridSpec& g = solver.grid();
  std::vector<double>& eps = solver.strengthStateForTesting(3);
  auto moments = [&](double& sum, double& mx, double& mz) {
    sum = mx = mz = 0.0;
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const double q = eps[static_cast<std::size_t>(k) * g.nx + i];
        sum += q;
        mx += q * (g.x0 + (i + 0.5) * g.dx);
        mz += q * (g.z0 + (k + 0.5) * g.dz);
      }
    mx /= sum;
    mz /= sum;
  };
  for (int k = 4; k < 8; ++k)
    for (int i = 4; i < 8; ++i) eps[static_cast<std::size_t>(k) * g.nx + i] = rho0() * 0.5;
  double s0, x0, z0, s1, x1, z1;
  moments(s0, x0, z0);
  runTo(solver, t);
  moments(s1, x1, z1);
  double smax = 0.0;
  for (int q = 0; q < 3; ++q)
    for (double v : solver.strengthStateForTesting(q)) smax = std::max(smax, std::abs(v));
  std::printf(
      "advection: sum %.2e relative, centroid moved (%.5f, %.5f) cm, expected (%.5f, %.5f); "
      "max |rho s| %.1e\n",
      s1 / s0 - 1.0, x1 - x0, z1 - z0, vx * t, vz * t, smax);
  EXPECT_NEAR(s1 / s0, 1.0, 1e-12);
  EXPECT_NEAR((x1 - x0) / (vx * t), 1.0, 0.01);
  EXPECT_NEAR((z1 - z0) / (vz * t), 1.0, 0.01);
  EXPECT_EQ(smax, 0.0);
}

// The four-line batches (issue 17) advect the strength state of their lanes as LineSolver does
// its line's: the run with batches equals the run without them bit for bit (the batches are
// bit for bit with LineSolver in the hydrodynamic state, TvdBatches tests), strength state
// included. The blocks scene has 40 x 25 cells: most lines of both sweeps go through batches.
TEST(TvdStrength, BatchesGiveThePerLineResult) {
  const cases::Scene s = blocks(Geometry::Planar);
  Options perLine;
  perLine.lineBatches = false;
  TvdSolver a(s), b(s, perLine);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(a.advance(1e9), b.advance(1e9));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().rho, b.conserved().rho));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mx, b.conserved().mx));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mz, b.conserved().mz));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().E, b.conserved().E));
  for (int k = 0; k < 4; ++k)
    EXPECT_TRUE(hvi::test::sameBits(a.strengthStateForTesting(k), b.strengthStateForTesting(k))) << "component " << k;
}

// Threads: the strength step is per cell and per face, the advection per line, the edge ledger
// in a fixed order, so the result does not depend on the thread count (the blocks scene at
// 0.004 cm, 25 000 cells: above the size that runs threaded, kParallelCells).
TEST(TvdStrength, ThreadCountDoesNotChangeTheResult) {
  cases::Scene s = blocks(Geometry::Planar);
  s.tvd.cellSize = 0.004;
  Options one, two;
  one.threads = 1;
  two.threads = 2;
  TvdSolver a(s, one), b(s, two);
  ASSERT_GE(a.grid().cells(), kParallelCells);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(a.advance(1e9), b.advance(1e9));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mz, b.conserved().mz));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().E, b.conserved().E));
  for (int k = 0; k < 4; ++k)
    EXPECT_TRUE(hvi::test::sameBits(a.strengthStateForTesting(k), b.strengthStateForTesting(k))) << "component " << k;
  EXPECT_EQ(a.ledger().boundary.momentumZ, b.ledger().boundary.momentumZ);
}

// A material without a strength table (a fluid) in a scene that names strength carries no
// deviator: the run is the hydrodynamic one bit for bit (c_L = sqrt(c^2 + 0) = c exactly in
// IEEE arithmetic, the strength step does nothing, the advection touches only its own arrays).
TEST(TvdStrength, FluidRunsTheHydrodynamicSolution) {
  cases::Scene s = blocks(Geometry::Planar);
  s.materials[0].strength.reset();
  cases::Scene h = s;
  h.effects.erase(Effect::Strength);
  TvdSolver a(s), b(h);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(a.advance(1e9), b.advance(1e9));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().rho, b.conserved().rho));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mx, b.conserved().mx));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().mz, b.conserved().mz));
  EXPECT_TRUE(hvi::test::sameBits(a.conserved().E, b.conserved().E));
}

// What the TVD solver does not do with strength is refused before the run, naming it.
TEST(TvdStrength, RefusesWhatIsNotBuilt) {
  // The whole-cell interfaces (the conservative ones carry strength: test_strength_cut.cpp).
  {
    cases::Scene s = blocks(Geometry::Planar);
    s.effects.insert(Effect::MaterialInterfaces);
    s.tvd.interfaces = cases::InterfaceMode::WholeCell;
    try {
      TvdSolver solver(s);
      ADD_FAILURE() << "strength with whole-cell interfaces was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("material_interfaces"), std::string::npos) << e.what();
    }
  }
  // Fracture without strength (a scene built in code; the scene validation says so for files).
  cases::Scene s = blocks(Geometry::Planar);
  s.effects.insert(Effect::Fracture);
  s.effects.erase(Effect::Strength);
  EXPECT_THROW(TvdSolver solver(s), InputError);
  EXPECT_TRUE(cases::supports(cases::SolverKind::Tvd, Effect::Strength));
  EXPECT_TRUE(cases::supports(cases::SolverKind::Tvd, Effect::Fracture));
}

}  // namespace
}  // namespace hvi::tvd
