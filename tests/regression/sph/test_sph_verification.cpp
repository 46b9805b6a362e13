//! @file SPH against exact solutions: Sod, an aluminium impact tube, cylindrical Noh in r-z.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "hvi/cases/names.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"
#include "hvi/verify/noh.hpp"
#include "hvi/verify/riemann.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// Quasi-1-D problems run in a strip of 8 particle rows between two walls (mirrors), so every
// row sees an infinite lattice in z and all rows stay identical.
cases::Scene strip(double xmin, double xmax, int cellsPerUnit, double hFactor, bool modified,
                   std::initializer_list<Effect> extra = {}) {
  const double dx = 1.0 / cellsPerUnit;
  auto s =
      test::baseScene(Geometry::Planar, xmin, xmax, 0.0, 8 * dx, dx, {Effect::ArtificialViscosity});
  for (Effect e : extra) s.effects.insert(e);
  if (modified) s.effects.insert(Effect::MassAdjustment);
  s.sph.hFactor = hFactor;
  for (auto& b : s.domain.boundary) b = cases::Boundary::Wall;
  return s;
}

double runTo(SphSolver& solver, double t) {
  while (solver.time() < t) solver.advance(t);
  return solver.time();
}

// L1 norm of the density error over the tube's length: sum |rho - rho_exact| times each
// particle's area, divided by the strip width.
double sodL1(int cells, double hFactor, bool modified) {
  auto s = strip(0.0, 1.0, cells, hFactor, modified);
  s.materials = {test::idealGas(1.4)};
  const double w = 8.0 / cells;
  s.bodies = {test::rectBody("left", 0, 0.0, 0.5, 0.0, w, {}, 1.0, 2.5),
              test::rectBody("right", 0, 0.5, 1.0, 0.0, w, {}, 0.125, 2.0)};
  SphSolver solver(s);
  const double t = runTo(solver, 0.2);
  const verify::ExactRiemann exact(s.materials[0].eos, {1.0, 0.0, 2.5}, s.materials[0].eos,
                                   {0.125, 0.0, 2.0});
  const ParticleSystem p = solver.stepper().particles();
  double l1 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    l1 += std::abs(p.rho[i] - exact.sample((p.x[i] - 0.5) / t).rho) * p.m[i] / p.rho[i];
  l1 /= w;
  std::printf("Sod %s SPH, h = %.1f dx, %d particles per unit length: L1(rho) = %.4e\n",
              modified ? "modified" : "traditional", hFactor, cells, l1);
  return l1;
}

TEST(SphVerification, SodShockTubeConverges) {
  // Modified SPH as the scenes run it (two bodies, mass iteration), h = 1.5 dx. Constant h
  // cannot follow the rarefaction's 2.3x one-dimensional stretch: at h = dx the particles end
  // 2.3 h apart in x and the error stalls at ~4e-2; at 1.5 dx its floor is ~1.7e-2 (measured
  // with traditional SPH, 100 -> 400 cells), which modified SPH approaches from above as its
  // contact start-up error (boosted surface masses of the two bodies) shrinks with dx.
  const double m100 = sodL1(100, 1.5, true), m200 = sodL1(200, 1.5, true);
  EXPECT_LT(m200, 0.035);        // measured 2.9e-2
  EXPECT_LT(m200, 0.75 * m100);  // measured ratio 0.66
  // With h = 2 dx the stretched region is resolved, and SPH converges at about first order
  // (the norm is dominated by the smeared shock and contact). The mass iteration is too
  // ill-conditioned at h = 2 dx (the kernel's transform at the lattice's Nyquist mode is
  // 5e-5), so this runs traditional SPH, i.e. the same scheme with equal masses.
  const double t100 = sodL1(100, 2.0, false), t200 = sodL1(200, 2.0, false);
  EXPECT_LT(t200, 0.01);         // measured 7.1e-3
  EXPECT_LT(t200, 0.65 * t100);  // measured ratio 0.52 (first order: 0.5)
}

TEST(SphVerification, AluminiumImpactTubeMatchesExactRiemann) {
  // 6 km/s aluminium-on-aluminium, Tillotson with tension cut-off, modified SPH, dx = 0.005 cm.
  const double u0 = 0.6, t = 0.2;
  auto s = strip(-0.5, 0.5, 200, 1.0, true, {Effect::TensionCutoff});
  s.materials = {test::aluminium()};
  const double w = 8.0 / 200;
  s.bodies = {test::rectBody("striker", 0, -0.5, 0.0, 0.0, w, {u0, 0.0}),
              test::rectBody("target", 0, 0.0, 0.5, 0.0, w)};
  test::resolveDensities(s);
  SphSolver solver(s);
  runTo(solver, t);
  const auto al = s.materials[0].eos;
  const verify::ExactRiemann exact(al, {2.79, u0, 0.0}, al, {2.79, 0.0, 0.0});
  const double xl = exact.leftWave().headSpeed * t, xr = exact.rightWave().headSpeed * t;
  const double xc = exact.starVelocity() * t;
  // Shocked plateau: 6 h away from the shocks (their viscous width is ~3 h) and from the
  // contact (whose start-up transient, the SPH analogue of wall heating, spans ~4 h).
  const double h = 0.005, margin = 6.0 * h;
  double rho = 0.0, p = 0.0;
  int n = 0;
  const ParticleSystem ps = solver.stepper().particles();
  double shockL = 0.0, shockR = 0.0;  // positions where rho crosses the mid value
  const double mid = 0.5 * (2.79 + exact.starDensityRight());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double x = ps.x[i];
    if ((x > xl + margin && x < xc - margin) || (x > xc + margin && x < xr - margin)) {
      rho += ps.rho[i];
      p += ps.p[i];
      ++n;
    }
    if (ps.rho[i] > mid) {
      shockL = std::min(shockL, x);
      shockR = std::max(shockR, x);
    }
  }
  rho /= n;
  p /= n;
  std::printf(
      "Al tube: plateau rho %.4f (exact %.4f), P %.4f Mbar (exact %.4f); shocks at "
      "%.4f, %.4f cm (exact %.4f, %.4f)\n",
      rho, exact.starDensityRight(), p, exact.starPressure(), shockL, shockR, xl, xr);
  ASSERT_GT(n, 100);
  // The plateau is a Rankine-Hugoniot state: viscosity smears the shock but does not move
  // the jump conditions, so the remaining error is the start-up transient left behind the
  // shocks, O(dx): measured 0.2% in rho and 0.15% in P; 1% allowed.
  EXPECT_NEAR(rho, exact.starDensityRight(), 0.01 * exact.starDensityRight());
  EXPECT_NEAR(p, exact.starPressure(), 0.01 * exact.starPressure());
  // Shock positions within 2 h (the mid-value crossing of a ~3 h wide profile).
  EXPECT_NEAR(shockL, xl, 2.0 * h);
  EXPECT_NEAR(shockR, xr, 2.0 * h);
}

// A dense striker on aluminium, one-dimensional: the hard case dense_striker's contact
// (tungsten-like Mie-Gruneisen, Steinberg 1996, at 7 km/s on Tillotson aluminium, tension
// cut-off) in a strip, dx = 0.005 cm, to t = 0.2 us. The density ratio of 7 across the contact
// is where METHOD.md's symmetric energy equation cools the tungsten below e = 0
// (docs/hard_cases.md): each side is charged half of the other's pressure work.
struct ContactTube {
  double minE = 0.0;                            // over all particles
  double pContactW = 0.0, rhoContactW = 0.0;    // the tungsten particle next to the contact
  double pContactAl = 0.0, rhoContactAl = 0.0;  // the aluminium particle next to the contact
  double worstNearP = 0.0;  // max |P/P* - 1| over particles 2-6 spacings from the contact
  double plateauP = 0.0, plateauRhoW = 0.0, plateauRhoAl = 0.0;
  double energyDrift = 0.0;                // (E - E0) / E0
  double rhoStarW = 0.0, rhoStarAl = 0.0;  // exact
};

ContactTube tungstenOnAluminium(cases::EnergyForm energy) {
  const double u0 = 0.7, t = 0.2, dx = 0.005;
  auto s = strip(-0.5, 0.5, 200, 1.0, true, {Effect::TensionCutoff});
  s.sph.energy = energy;
  eos::MieGruneisen w;
  w.rho0 = 19.3;
  w.c0 = 0.4029;
  w.s = 1.237;
  w.gamma0 = 1.67;
  s.materials = {{"tungsten", w}, test::aluminium()};
  const double width = 8.0 / 200;
  s.bodies = {test::rectBody("striker", 0, -0.5, 0.0, 0.0, width, {u0, 0.0}),
              test::rectBody("target", 1, 0.0, 0.5, 0.0, width)};
  test::resolveDensities(s);
  SphSolver solver(s);
  const double e0 = solver.totals().energy();
  runTo(solver, t);
  ContactTube r;
  r.energyDrift = solver.totals().energy() / e0 - 1.0;
  const auto mats = sceneMaterials(s);  // with the scene's tension cut-off
  const verify::ExactRiemann exact(mats[0], {19.3, u0, 0.0}, mats[1], {2.79, 0.0, 0.0});
  const double ps = exact.starPressure(), xc = exact.starVelocity() * t;
  r.rhoStarW = exact.starDensityLeft();
  r.rhoStarAl = exact.starDensityRight();
  const double xl = exact.leftWave().headSpeed * t, xr = exact.rightWave().headSpeed * t;
  const ParticleSystem p = solver.stepper().particles();
  // Per particle row (the rows stay identical in this 1-D flow): the two particles that face
  // each other at the contact.
  std::map<long, double> xw, xa;
  const auto row = [&](std::size_t i) { return std::lround(p.z[i] / dx); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.object[i] == 0) xw.try_emplace(row(i), -1e9), xw[row(i)] = std::max(xw[row(i)], p.x[i]);
    if (p.object[i] == 1) xa.try_emplace(row(i), 1e9), xa[row(i)] = std::min(xa[row(i)], p.x[i]);
  }
  int nw = 0, na = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i];
    r.minE = std::min(r.minE, p.e[i]);
    const bool faceW = x == xw[row(i)], faceAl = x == xa[row(i)];
    if (faceW) {
      r.pContactW += p.p[i];
      r.rhoContactW += p.rho[i];
      ++nw;
    }
    if (faceAl) {
      r.pContactAl += p.p[i];
      r.rhoContactAl += p.rho[i];
      ++na;
    }
    if (!faceW && !faceAl && std::abs(x - xc) < 6.0 * dx)
      r.worstNearP = std::max(r.worstNearP, std::abs(p.p[i] / ps - 1.0));
  }
  r.pContactW /= nw;
  r.rhoContactW /= nw;
  r.pContactAl /= na;
  r.rhoContactAl /= na;
  // Plateaus: 6 h from the shocks and 10 h from the contact (its start-up transient).
  int n = 0, nW = 0, nA = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i];
    const bool left = x > xl + 6 * dx && x < xc - 10 * dx;
    const bool right = x > xc + 10 * dx && x < xr - 6 * dx;
    if (!left && !right) continue;
    r.plateauP += p.p[i];
    ++n;
    if (left) {
      r.plateauRhoW += p.rho[i];
      ++nW;
    } else {
      r.plateauRhoAl += p.rho[i];
      ++nA;
    }
  }
  r.plateauP /= n;
  r.plateauRhoW /= nW;
  r.plateauRhoAl /= nA;
  std::printf(
      "W on Al tube, %s energy: min e %.3e; contact W rho %.3f (exact %.3f) P %.3f, Al rho %.3f "
      "(exact %.3f) P %.3f (exact P* %.4f); worst |P/P*-1| 2-6 dx from the contact %.3f; "
      "plateau P %.4f, rho W %.3f, Al %.4f; energy drift %.2e\n",
      cases::toString(energy).data(), r.minE, r.rhoContactW, exact.starDensityLeft(), r.pContactW,
      r.rhoContactAl, exact.starDensityRight(), r.pContactAl, ps, r.worstNearP, r.plateauP,
      r.plateauRhoW, r.plateauRhoAl, r.energyDrift);
  EXPECT_NEAR(r.plateauP, ps, 0.01 * ps);
  EXPECT_NEAR(r.plateauRhoW, exact.starDensityLeft(), 0.01 * exact.starDensityLeft());
  EXPECT_NEAR(r.plateauRhoAl, exact.starDensityRight(), 0.01 * exact.starDensityRight());
  return r;
}

TEST(SphVerification, DenseStrikerContactKeepsInternalEnergyPositive) {
  const ContactTube c = tungstenOnAluminium(cases::EnergyForm::Compatible);
  const ContactTube s = tungstenOnAluminium(cases::EnergyForm::Symmetric);
  // Compatible energy (docs/sph.md, "Energy"): a particle is charged only its own pressure's
  // work and its share of viscous heating, so nothing is cooled below e = 0 (untouched
  // material sits at e = 0 up to round-off: measured -2e-29). The symmetric form cools the
  // tungsten face particle to e = -5.6e-3 cm^2/us^2 (the defect this form removes).
  EXPECT_GT(c.minE, -1e-12);
  EXPECT_LT(s.minE, -1e-3);
  // Total energy: the compatible step conserves it to round-off (measured 1.4e-15); the
  // symmetric step drifts by O(dt^2) (measured 4.6e-5; 1e-4 as in Conservation.*).
  EXPECT_LT(std::abs(c.energyDrift), 1e-12);
  EXPECT_LT(std::abs(s.energyDrift), 1e-4);
  // The face particles: the summation density sums over a particle's own body, whose masses
  // were fitted at rho0 (docs/sph.md, "Density at a contact"): a face compressed by
  // eta = rho* / rho0 reads rho0 (1 + eta) / 2, not rho*. Measured within 4% of that (W 22.21
  // for 22.83, Al 3.98 for 3.84); 10% allowed. Their pressure stays well above zero
  // (no zero-pressure gap; the Al cold curve at 3.84 g/cm^3 alone gives 0.21 P*).
  const double etaW = c.rhoStarW / 19.3, etaAl = c.rhoStarAl / 2.79;
  EXPECT_NEAR(c.rhoContactW, 19.3 * (1 + etaW) / 2, 0.1 * 19.3 * (1 + etaW) / 2);
  EXPECT_NEAR(c.rhoContactAl, 2.79 * (1 + etaAl) / 2, 0.1 * 2.79 * (1 + etaAl) / 2);
  EXPECT_GT(c.pContactW, 0.2 * c.plateauP);
  EXPECT_GT(c.pContactAl, 0.2 * c.plateauP);
  // Beyond the face particles (2 to 6 spacings from the contact) the pressure is the contact's
  // P* up to the impact's start-up transient (wall heating): measured 15% at worst with the
  // compatible form, 40% with the symmetric one (whose cooled face pushes its neighbours).
  EXPECT_LT(c.worstNearP, 0.2);
}

struct NohResult {
  double l1, preShock, plateauP, plateauRho;
};

// Cylindrical Noh in r-z: gas (gamma 5/3, rho 1, e 0) flowing onto the axis at 1 cm/us, in a
// slab of 10 rows between walls, r from 0 to 1, compared at t = 0.6 (shock at r = 0.2).
NohResult noh(int cells, double alpha = 1.0, cases::RzForm form = cases::RzForm::Ring,
              double axisCorrection = 0.0) {
  const double dx = 1.0 / cells, hz = 10 * dx, t = 0.6;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.2, 0.0, hz, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 1.0, 0.0, hz, {-1.0, 0.0}, 1.0, 0.0)};
  s.sph.alpha = alpha;
  s.sph.rzForm = form;
  s.sph.rzAxisCorrection = axisCorrection;
  SphSolver solver(s);
  runTo(solver, t);
  const verify::NohSolution exact{5.0 / 3.0, 1.0, 1.0, 1};
  const ParticleSystem p = solver.stepper().particles();
  NohResult r{0.0, 0.0, 0.0, 0.0};
  int nPre = 0, nPost = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.x[i];
    const auto e = exact.sample(x, t);
    // Planar area of the particle: ring mass / (2 pi r rho).
    if (x < 0.4)
      r.l1 += std::abs(p.rho[i] - e.rho) * p.m[i] / (2 * std::numbers::pi * x * p.rho[i]);
    if (x > 0.25 && x < 0.35) {
      r.preShock = std::max(r.preShock, std::abs(p.rho[i] / e.rho - 1.0));
      ++nPre;
    }
    if (x > 0.05 && x < 0.17) {
      r.plateauP += p.p[i];
      r.plateauRho += p.rho[i];
      ++nPost;
    }
  }
  r.l1 /= hz;
  r.plateauP /= nPost;
  r.plateauRho /= nPost;
  std::printf(
      "Noh r-z, %d cells per cm, alpha %.1f: L1(rho, r < 0.4) = %.4f, max pre-shock error "
      "%.2e, plateau P %.4f (exact %.4f), plateau rho %.3f (exact %.1f)\n",
      cells, alpha, r.l1, r.preShock, r.plateauP, exact.sample(0.1, t).p, r.plateauRho,
      exact.sample(0.1, t).rho);
  EXPECT_GT(nPre, 0);
  return r;
}

TEST(SphVerification, CylindricalNohInRz) {
  const NohResult a = noh(50), b = noh(100);
  // Ahead of the shock the flow is a pure cylindrical convergence, rho = 1 + t/r: this checks
  // the hoop terms of continuity and momentum (docs/sph-rz.md). Measured 1e-3 at 100 cells;
  // 1% allowed for the density summation's O(h^2 rho'') error.
  EXPECT_LT(b.preShock, 0.01);
  // The plateau pressure (exact 16/3): measured within 1%, 3% allowed; the density there is
  // lowered near the axis by wall heating (a known SPH/Noh artefact, ~5% at 0.1 cm).
  EXPECT_NEAR(b.plateauP, 16.0 / 3.0, 0.03 * 16.0 / 3.0);
  EXPECT_NEAR(b.plateauRho, 16.0, 0.05 * 16.0);
  // L1 over r < 0.4 (exact integral of rho there: 6.9) falls with resolution.
  EXPECT_LT(b.l1, 0.8 * a.l1);
}

// Issue 14 item 1: with weak viscosity the innermost column used to reach the axis, be
// reflected outwards, and the explicit -rho v_r / r of the predictor (with (dt/2) v_r / r > 1)
// made its density negative (alpha = 0.5 stopped at step 88 of the study scene). With the
// weights' change taken exactly (docs/sph-rz.md, "In time") the run reaches t = 0.6 at alpha
// 0.5, 1 and 2. The plateau density (exact 16) over 0.05 < r < 0.17 is lowered by the wall
// heating at the axis, more with stronger viscosity (whose heating it is): measured at 100
// cells per cm 15.42 / 15.28 / 15.08 at alpha 0.5 / 1 / 2 (3.6 / 4.5 / 5.8% low). 7% allowed
// here (5% at alpha 1 above): the dip's measured size plus a margin; a column reflected off
// the axis rarefies the plateau by far more, and before the fix alpha 0.5 did not finish.
TEST(SphVerification, CylindricalNohRunsAtEveryAlpha) {
  for (double alpha : {0.5, 2.0}) {
    NohResult r{};
    ASSERT_NO_THROW(r = noh(100, alpha)) << "alpha " << alpha;
    EXPECT_NEAR(r.plateauRho, 16.0, 0.07 * 16.0) << "alpha " << alpha;
    EXPECT_NEAR(r.plateauP, 16.0 / 3.0, 0.03 * 16.0 / 3.0) << "alpha " << alpha;
    EXPECT_LT(r.preShock, 0.01) << "alpha " << alpha;
  }
}

// The symmetric r-z form (docs/sph-rz.md, "Symmetric ring weights") on the same problem and
// bounds, at alpha 0.5, 1 and 2: its continuity and hoop terms are other discretisations of
// the same -rho v_r / r and P / (rho r), so the same exact solution and errors apply.
TEST(SphVerification, CylindricalNohSymmetricForm) {
  for (double alpha : {0.5, 1.0, 2.0}) {
    NohResult r{};
    ASSERT_NO_THROW(r = noh(100, alpha, cases::RzForm::Symmetric)) << "alpha " << alpha;
    std::printf("symmetric form, alpha %.1f: plateau rho %.3f, P %.4f, pre-shock %.2e\n", alpha,
                r.plateauRho, r.plateauP, r.preShock);
    EXPECT_NEAR(r.plateauRho, 16.0, 0.07 * 16.0) << "alpha " << alpha;
    EXPECT_NEAR(r.plateauP, 16.0 / 3.0, 0.03 * 16.0 / 3.0) << "alpha " << alpha;
    EXPECT_LT(r.preShock, 0.01) << "alpha " << alpha;
  }
}

// The symmetric form with the corrected axial gradient within 3 h of the axis
// (sph.rz_axis_correction, docs/sph-rz.md "Corrected axial gradient"): the flow is radial, so
// only L's z row off the lattice's symmetry (the walls' rows) can change it; the same bounds.
TEST(SphVerification, CylindricalNohWithAxisCorrection) {
  for (double alpha : {0.5, 1.0, 2.0}) {
    NohResult r{};
    ASSERT_NO_THROW(r = noh(100, alpha, cases::RzForm::Symmetric, 3.0)) << "alpha " << alpha;
    std::printf("axis correction 3 h, alpha %.1f: plateau rho %.3f, P %.4f, pre-shock %.2e\n",
                alpha, r.plateauRho, r.plateauP, r.preShock);
    EXPECT_NEAR(r.plateauRho, 16.0, 0.07 * 16.0) << "alpha " << alpha;
    EXPECT_NEAR(r.plateauP, 16.0 / 3.0, 0.03 * 16.0 / 3.0) << "alpha " << alpha;
    EXPECT_LT(r.preShock, 0.01) << "alpha " << alpha;
  }
}

}  // namespace
}  // namespace hvi::sph
