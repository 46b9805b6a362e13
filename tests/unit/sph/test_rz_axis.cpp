//! @file r-z at the axis: a closed box of gas at uniform pressure stays at rest; a uniform
//! radial expansion is reproduced there as in the bulk.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/sph/fill.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// Gas at rho = 1, P = 1 (c = 1.29 cm/us) filling r < 0.3, |z| < 0.1 with walls all round and
// the axis: uniform pressure exerts no force, so nothing may move. The particles next to the
// axis test the hoop terms: there the pair sums see the mirror ghosts' |r| smoothed by the
// kernel and, uncorrected, push them outwards at ~1.8 P / (rho h) (docs/sph-rz.md).
double maxSpeedInPressurisedBox(int steps) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 0.3, -0.1, 0.1, 0.01,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  for (int k = 1; k < 4; ++k) s.domain.boundary[k] = cases::Boundary::Wall;
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 0.3, -0.1, 0.1, {}, 1.0, 1.5)};
  SphSolver solver(s);
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  const double v = test::maxSpeed(solver.stepper().particles());
  std::printf("r-z box at P = 1 Mbar: max speed after %d steps (t = %.3f us): %.3e cm/us\n", steps,
              solver.time(), v);
  return v;
}

TEST(RzAxis, UniformPressureBoxStaysAtRest) {
  // The corrected hoop term balances the radial pressure sum only up to the lattice's
  // deviation from the continuum (the correction is derived for a continuous distribution of
  // neighbours): measured 6e-3 c after 40 steps. Uncorrected (C = 1) the axis particles reach
  // 6e-2 c; 2e-2 c separates the two with margin on both sides.
  EXPECT_LT(maxSpeedInPressurisedBox(40), 2e-2 * 1.29);
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
ExpansionErrors uniformExpansion(double t) {
  const double dx = 0.01, a = 1.0;
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.0, 0.0, 10 * dx, dx,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
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
      "r-z uniform expansion to t = %.2f us (r x %.2f): density error at the axis %.3e, "
      "bulk %.3e\n",
      t, 1.0 + a * t, e.axis, e.bulk);
  return e;
}

TEST(RzAxis, UniformExpansionIsReproducedAtTheAxis) {
  // Measured: 1.97e-3 at the axis and in the bulk alike (the mirror ghosts make the axis
  // column see the lattice the bulk sees). The bulk error is the summation's on the stretched
  // lattice, not a time-integration error (positions are exact here, and with P = 0 the
  // predictor's density does not feed back). Allowed: the bulk's error plus half of it, and
  // the bulk itself within 5e-3 (a stretch of 1.2 at h = dx).
  const ExpansionErrors e = uniformExpansion(0.2);
  EXPECT_LT(e.axis, 1.5 * e.bulk);
  EXPECT_LT(e.bulk, 5e-3);
}

}  // namespace
}  // namespace hvi::sph
