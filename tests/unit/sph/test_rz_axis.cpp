//! @file r-z at the axis: a closed box of gas at uniform pressure stays at rest; a uniform
//! radial expansion is reproduced there as in the bulk.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/cases/names.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// Gas at rho = 1, P = 1 (c = 1.29 cm/us) filling r < 0.3, |z| < 0.1 with walls all round and
// the axis: uniform pressure exerts no force, so nothing may move. The particles next to the
// axis test the hoop terms: there the pair sums see the mirror ghosts' |r| smoothed by the
// kernel and, uncorrected, push them outwards at ~1.8 P / (rho h) (docs/sph-rz.md).
double maxSpeedInPressurisedBox(int steps, cases::RzForm form, double axisCorrection = 0.0) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.3, -0.1, 0.1, 0.01,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  for (int k = 1; k < 4; ++k) s.domain.boundary[k] = cases::Boundary::Wall;
  s.sph.rzForm = form;
  s.sph.rzAxisCorrection = axisCorrection;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.3, -0.1, 0.1, {}, 1.0, 1.5)};
  SphSolver solver(s);
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  const double v = test::maxSpeed(solver.stepper().particles());
  std::printf(
      "r-z box at P = 1 Mbar (%s form, axis correction %.1f h): max speed after %d steps "
      "(t = %.3f us): %.3e cm/us\n",
      form == cases::RzForm::Ring ? "ring" : "symmetric", axisCorrection, steps, solver.time(), v);
  return v;
}

TEST(RzAxis, UniformPressureBoxStaysAtRest) {
  // The corrected hoop term balances the radial pressure sum only up to the lattice's
  // deviation from the continuum (the correction is derived for a continuous distribution of
  // neighbours): measured 6e-3 c after 40 steps. Uncorrected (C = 1) the axis particles reach
  // 6e-2 c; 2e-2 c separates the two with margin on both sides.
  EXPECT_LT(maxSpeedInPressurisedBox(40, cases::RzForm::Ring), 2e-2 * 1.29);
  // The symmetric form balances the hoop term by construction (no C): measured 5.4e-3 cm/us =
  // 4.2e-3 c; the same bound.
  EXPECT_LT(maxSpeedInPressurisedBox(40, cases::RzForm::Symmetric), 2e-2 * 1.29);
  // The corrected axial gradient (sph.rz_axis_correction, docs/sph-rz.md) corrects only the
  // z row of the pair gradient, so the radial balance is the symmetric form's: the same bound.
  EXPECT_LT(maxSpeedInPressurisedBox(40, cases::RzForm::Symmetric, 3.0), 2e-2 * 1.29);
}

// Cold gas (P = 0) in a slab between walls, expanding radially as v_r = a r (a = 1 / us). No
// force acts (P = 0, and Monaghan's viscosity is off for separating pairs), so every particle
// keeps its velocity and r = r0 (1 + a t) exactly; the exact density is uniform,
// rho0 / (1 + a t)^2. What is tested is the density near the axis, where the sums run over the
// mirror ghosts and the weights mu = m / (2 pi r) vary fastest (the predictor's exact weight
// change, docs/sph-rz.md "In time", included): it must be the bulk's, whose error is the
// summation's on a lattice stretched in r by 1 + a t at constant h.
struct ExpansionErrors {
  double axis, bulk;
};
ExpansionErrors uniformExpansion(double t, cases::RzForm form, double axisCorrection = 0.0) {
  const double dx = 0.01, a = 1.0;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.0, 0.0, 10 * dx, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
  s.sph.rzForm = form;
  s.sph.rzAxisCorrection = axisCorrection;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.5, 0.0, 10 * dx, {}, 1.0, 0.0)};
  ParticleSystem ps = fillBodies(s);
  for (std::size_t i = 0; i < ps.size(); ++i) ps.vx[i] = a * ps.x[i];
  SphSolver solver(s, ps);
  while (solver.time() < t) solver.advance(t);
  const ParticleSystem p = solver.stepper().particles();
  const double exact = 1.0 / ((1.0 + a * t) * (1.0 + a * t));
  ExpansionErrors e{0.0, 0.0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r0 = p.x[i] / (1.0 + a * t), err = std::abs(p.rho[i] / exact - 1.0);
    if (r0 < 2 * dx) e.axis = std::max(e.axis, err);
    if (r0 > 0.15 && r0 < 0.3) e.bulk = std::max(e.bulk, err);
  }
  std::printf(
      "r-z uniform expansion (%s form) to t = %.2f us (r x %.2f): density error at the axis "
      "%.3e, bulk %.3e\n",
      form == cases::RzForm::Ring ? "ring" : "symmetric", t, 1.0 + a * t, e.axis, e.bulk);
  return e;
}

TEST(RzAxis, UniformExpansionIsReproducedAtTheAxis) {
  // Measured: 1.97e-3 at the axis and in the bulk alike (the mirror ghosts make the axis
  // column see the lattice the bulk sees). The bulk error is the summation's on the stretched
  // lattice, not a time-integration error (positions are exact here, and with P = 0 the
  // predictor's density does not feed back). Allowed: the bulk's error plus half of it, and
  // the bulk itself within 5e-3 (a stretch of 1.2 at h = dx).
  const ExpansionErrors e = uniformExpansion(0.2, cases::RzForm::Ring);
  EXPECT_LT(e.axis, 1.5 * e.bulk);
  EXPECT_LT(e.bulk, 5e-3);
  // The symmetric form's weights |r_j| / (s_i s_j) vary by a factor ~3 across the kernel next
  // to the axis (0.6 to 1.8 at r = 1.4 h): their lattice error, which the mass iteration
  // cancels for the initial lattice, returns when the lattice is stretched. Measured 7.75e-3 at
  // the axis (3.9 times the bulk's 1.98e-3) and 2.74e-3 at t = 0.1 (stretch 1.1; bulk 4.6e-4):
  // it falls with the stretch, more slowly than the bulk's. Allowed 5 times the bulk's at 1.2.
  const ExpansionErrors f = uniformExpansion(0.2, cases::RzForm::Symmetric);
  EXPECT_LT(f.axis, 5.0 * f.bulk);
  EXPECT_LT(f.bulk, 5e-3);
  const ExpansionErrors g = uniformExpansion(0.1, cases::RzForm::Symmetric);
  EXPECT_LT(g.axis, 0.6 * f.axis);  // falls with the stretch
  // With the corrected axial gradient: no force acts here either (P = 0, separating pairs), so
  // the positions stay exact and the density is the symmetric form's (the same bits: the
  // correction enters the pair gradient only, never the summation density).
  const ExpansionErrors c = uniformExpansion(0.2, cases::RzForm::Symmetric, 3.0);
  EXPECT_EQ(c.axis, f.axis);
  EXPECT_EQ(c.bulk, f.bulk);
}

// Gas at rho = 1 at rest with P = 1 + g z (e linear in z, g = 1 Mbar/cm) in a closed r-z box:
// the exact acceleration is a_z = -(1/rho) dP/dz = -g everywhere, the axis included. In the
// ring form the first column's neighbour sum carries their ring radii r_j / r_i, which the
// kernel smooths to f(r) / r with f(r) = E|r + X| (docs/sph-rz.md, "The axial needle"): the
// axial pressure force there is f(r) / r times too strong, 1.399 at r = h / 2 for the Gaussian
// (f = r erf(r/h) + h e^{-r^2/h^2} / sqrt(pi)). The symmetric form's weights average to 1.
struct AxialGradient {
  double axis, bulk;    // mean a_z / exact, first column and 0.1 < r < 0.2
  double second = 0.0;  // the second column
};
AxialGradient axialGradient(cases::RzForm form, double axisCorrection = 0.0, double b = 0.0) {
  const double dx = 0.01, g = 1.0;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.3, -0.2, 0.2, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  for (int k = 1; k < 4; ++k) s.domain.boundary[k] = cases::Boundary::Wall;
  s.sph.rzForm = form;
  s.sph.rzAxisCorrection = axisCorrection;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.3, -0.2, 0.2, {}, 1.0, 1.5)};
  ParticleSystem ps = fillBodies(s);
  // P = 1 + (g + b r) z: with b != 0 the axial gradient depends on the radius (b in 1/cm).
  for (std::size_t i = 0; i < ps.size(); ++i) ps.e[i] = 1.5 * (1.0 + (g + b * ps.x[i]) * ps.z[i]);
  SphSolver solver(s, ps);
  solver.advance(1e9);  // one step: v = dt a^{n+1/2}, a^{n+1/2} = a^0 to O(dt)
  const ParticleSystem p = solver.stepper().particles();
  double sa = 0.0, sb = 0.0, s2 = 0.0;
  int na = 0, nb = 0, n2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (std::abs(p.z[i]) > 0.1) continue;  // away from the walls
    // Exact at the particle's radius at t = 0 (it moves by O(dt^2)).
    const double ratio = p.vz[i] / solver.time() / (-(g + b * p.x[i]));
    if (p.x[i] < dx) sa += ratio, ++na;
    if (p.x[i] > dx && p.x[i] < 2 * dx) s2 += ratio, ++n2;
    if (p.x[i] > 0.1 && p.x[i] < 0.2) sb += ratio, ++nb;
  }
  const AxialGradient r{sa / na, sb / nb, s2 / n2};
  std::printf(
      "r-z %s form (axis correction %.1f h), P = 1 + (1 + %.0f r) z: a_z / exact at the "
      "axis column %.4f, second %.4f, bulk %.4f\n",
      form == cases::RzForm::Ring ? "ring" : "symmetric", axisCorrection, b, r.axis, r.second,
      r.bulk);
  return r;
}

// The ring form's first-column ratio on the square lattice (h = dx, columns at (k + 1/2) dx,
// mirror ghosts at -(k + 1/2) dx, equal weights): sum_j |r_j| dz_j dW/dz / (r_i sum_j dz_j dW/dz)
// for a pressure linear in z. The continuum value f(h/2) / (h/2) is 1.399.
double ringLatticeRatio() {
  const double ri = 0.5;
  double num = 0.0, den = 0.0;
  for (int a = -6; a <= 6; ++a)
    for (int b = -6; b <= 6; ++b) {
      const double xj = a + 0.5, zj = b, dx = ri - xj, dz = -zj, r2 = dx * dx + dz * dz;
      if (a == 0 && b == 0) continue;
      const double w = GaussianKernel::value(r2, 1.0);
      if (w == 0.0) continue;
      const double gz = GaussianKernel::gradFactor(w, r2, 1.0) * dz;
      num += std::abs(xj) * zj * gz;
      den += zj * gz;
    }
  return num / den / ri;
}

TEST(RzAxis, AxialPressureGradientAtTheAxis) {
  // Bulk: both forms within 1 % of the exact gradient (measured 0.9975 each). The first column:
  // the ring form measures 1.462 against the lattice's 1.473 (the mass iteration's weights next
  // to the axis are not quite equal: 2 % allowed); the symmetric form 0.999 (2 % allowed, the
  // same lattice allowance).
  const AxialGradient ring = axialGradient(cases::RzForm::Ring);
  const double lattice = ringLatticeRatio();
  std::printf("ring form on the lattice: %.4f\n", lattice);
  EXPECT_NEAR(ring.bulk, 1.0, 0.01);
  EXPECT_NEAR(ring.axis / lattice, 1.0, 0.02);
  const AxialGradient sym = axialGradient(cases::RzForm::Symmetric);
  EXPECT_NEAR(sym.bulk, 1.0, 0.01);
  EXPECT_NEAR(sym.axis, 1.0, 0.02);
}

TEST(RzAxis, CorrectedAxialGradientAtTheAxis) {
  // sph.rz_axis_correction = 3 h (docs/sph-rz.md, "Corrected axial gradient"). A linear
  // pressure: the corrected gradient is exact to the lattice's 2 %, as the plain one (measured
  // 1.0012 on the first column, plain 0.9989).
  const AxialGradient c = axialGradient(cases::RzForm::Symmetric, 3.0);
  EXPECT_NEAR(c.bulk, 1.0, 0.01);
  EXPECT_NEAR(c.axis, 1.0, 0.02);
  // The 0.02 cm needle's cause: an axial gradient that grows with r (b = 20 / cm), read by the
  // symmetric weights, whose first moment in r_j - r_i is positive next to the axis, as at a
  // larger radius: measured 1.0781 on the first column and 1.0278 on the second (bulk 0.9985).
  // The correction matrix M = sum V (x_j - x_i) (x) grad W sees only the weights' second
  // moments; inside the material next to the axis it is the identity but for the lattice
  // (L_zz = 1.0004, L_zx = 0 by symmetry at r = 1.5 h), so it leaves this error as it is
  // (measured 1.0806 and 1.0304): whatever the correction changes in variant 1, it is not this.
  const AxialGradient p = axialGradient(cases::RzForm::Symmetric, 0.0, 20.0);
  const AxialGradient q = axialGradient(cases::RzForm::Symmetric, 3.0, 20.0);
  EXPECT_GT(p.axis, 1.05);
  EXPECT_NEAR(q.axis, p.axis, 0.01);
  EXPECT_NEAR(q.second, p.second, 0.01);
}

}  // namespace
}  // namespace hvi::sph

namespace hvi::sph {
namespace {

// A planar shock running along the axis: cold gas (gamma = 5/3, rho = 1) flowing at 1 cm/us
// in -z onto a wall at z = 0, the planar Noh problem turned along z (shock at z = t/3, gas at
// rest behind it). The exact flow has v_r = 0 everywhere, so any radial velocity is the
// scheme's; in planar geometry the same lattice keeps v_x = 0 by symmetry. Returned: the rms
// of v_r over the particles within 3 h of the axis and over those between 10 h and 20 h.
struct RadialErrors {
  double axis, bulk;
};
RadialErrors axialShock(double alpha, double kappa, cases::RzForm form = cases::RzForm::Symmetric) {
  const double dx = 0.01, t = 0.15;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.25, 0.0, 0.25, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  s.domain.boundary[1] = s.domain.boundary[2] = cases::Boundary::Wall;
  s.sph.rzForm = form;
  s.sph.alpha = alpha;
  s.sph.rzViscousHoop = kappa;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.25, 0.0, 0.25, {0.0, -1.0}, 1.0, 1e-4)};
  SphSolver solver(s);
  while (solver.time() < t) solver.advance(t);
  const ParticleSystem p = solver.stepper().particles();
  double sa = 0.0, sb = 0.0;
  int na = 0, nb = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.x[i] < 3 * dx) sa += p.vx[i] * p.vx[i], ++na;
    if (p.x[i] > 10 * dx && p.x[i] < 20 * dx) sb += p.vx[i] * p.vx[i], ++nb;
  }
  const RadialErrors e{std::sqrt(sa / na), std::sqrt(sb / nb)};
  std::printf("axial shock, rz_form %s, alpha %.1f, viscous hoop %.2f, t = %.2f us: rms v_r "
              "%.3e (r < 3h), %.3e (10-20 h) cm/us\n",
              cases::toString(form).data(), alpha, kappa, t, e.axis, e.bulk);
  return e;
}

// docs/sph-rz.md, "The speed bound: which particles, which force". Measured at alpha = 1 (rms
// v_r next to the axis / at 10-20 h, cm/us): ring form 8.2e-2 / 7.0e-3; symmetric form
// 2.53e-2 / 7.1e-3; symmetric with kappa = 0.25 2.59e-2 / 4.5e-4 (kappa 0.5: 3.3e-2 / 6.8e-3,
// kappa 1: 5.3e-2 / 2.0e-2).
TEST(RzAxis, AxialShockStaysPlanar) {
  const RadialErrors ring = axialShock(1.0, 0.0, cases::RzForm::Ring);
  const RadialErrors sym = axialShock(1.0, 0.0);
  const RadialErrors hoop = axialShock(1.0, 0.25);
  // The symmetric form halves the ring form's error at the axis (the first columns' weights,
  // "The axial needle"): measured 0.31; 0.7 required.
  EXPECT_LT(sym.axis, 0.7 * ring.axis);
  // Without a viscous hoop Monaghan's Pi has no hoop stress, and the weight skew of its radial
  // pair sum pulls the shocked gas inwards with ~Q_rr / r, in the bulk too; a share kappa ~ 1/3
  // of Pi in the hoop term cancels the skew (docs/sph-rz.md). Measured: 16 times smaller at
  // kappa = 0.25; a factor 3 required. Next to the axis another error dominates (not the
  // target): kappa must not make it worse (measured +2.4 %; 10 % allowed for lattice noise).
  EXPECT_LT(hoop.bulk, sym.bulk / 3.0);
  EXPECT_LT(hoop.axis, 1.1 * sym.axis);
}

// The snapshot's `volume` (symmetric form): each particle's meridional area m / (2 pi s^2 rho),
// the weight its density sum gives it, which readers (hvi compare, the study) use as its area.
// In the box of gas at rest (walls and the axis all round, so every sum is complete) the areas
// must tile the box, r < 0.3 cm by 0.2 cm: measured sum -0.44 % of its area, each area 0.775 to
// 1.077 dx^2 (the lowest where the adjusted masses meet the walls and the axis). Bounds: the
// sum within 1 %, each within 25 % of dx^2; a ring area m / (2 pi r rho) of a particle that
// reached r -> 0 would be unbounded.
TEST(RzAxis, SymmetricFormSnapshotAreasTileTheBody) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.3, -0.1, 0.1, 0.01,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  for (int k = 1; k < 4; ++k) s.domain.boundary[k] = cases::Boundary::Wall;
  s.sph.rzForm = cases::RzForm::Symmetric;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.3, -0.1, 0.1, {}, 1.0, 1.5)};
  SphSolver solver(s);
  const Snapshot snap = solver.snapshot();
  const Field* area = snap.find("volume");
  ASSERT_NE(area, nullptr);
  double sum = 0.0, lo = 1e300, hi = 0.0;
  for (double a : area->data) {
    sum += a;
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  std::printf("symmetric-form areas: sum %.6f of 0.06 cm^2, each in [%.4e, %.4e] (dx^2 = 1e-4)\n",
              sum, lo, hi);
  EXPECT_NEAR(sum, 0.06, 0.06 * 0.01);
  EXPECT_GT(lo, 1e-4 * 0.75);
  EXPECT_LT(hi, 1e-4 * 1.25);
  // The ring form keeps its particles off the axis and writes no such field.
  s.sph.rzForm = cases::RzForm::Ring;
  EXPECT_EQ(SphSolver(s).snapshot().find("volume"), nullptr);
}

}  // namespace
}  // namespace hvi::sph
