//! @file Cylindrical Noh implosion in r-z and cylindrical Sedov blast in x-z against exact
//! solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "hvi/verify/noh.hpp"
#include "hvi/verify/sedov.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// ---------------------------------------------------------------------------------------------
// Noh: cold gamma = 5/3 gas (rho0 = 1, P = 0) flowing to the axis at u0 = 1 in r-z geometry
// (a thin slab in z, walls there): the radial sweep with the r-weighted faces and volumes and
// the P/r source is the only thing that makes this cylindrical. At t = 0.6 the shock is at
// r = 0.2 with density 16 behind it and 1 + t/r ahead.
struct NohResult {
  double l1 = 0.0;       // integral |rho - rho_exact| dr over [0, 0.4], relative to the exact
  double shock = 0.0;    // radius where rho crosses 10 (between 4 ahead and 16 behind)
  double plateau = 0.0;  // mean density over r in [0.08, 0.17]
};

NohResult noh(int n) {
  const double h = 1.0 / n, t = 0.6;
  cases::Scene s = baseScene(0.0, 1.0, 0.0, 4 * h, h, Geometry::Axisymmetric);
  s.domain.boundary = {cases::Boundary::Axis, cases::Boundary::Outflow, cases::Boundary::Wall,
                       cases::Boundary::Wall};
  s.materials.push_back(material("gas", eos::IdealGas{5.0 / 3.0, 1.0}));
  s.bodies.push_back(body("gas", 0, cases::Rect{0, 1, 0, 4 * h}, {1.0, {-1.0, 0.0}, 0.0}));
  TvdSolver solver(s);
  runTo(solver, t);
  const verify::NohSolution ex{5.0 / 3.0, 1.0, 1.0, 1};
  NohResult r;
  double norm = 0.0;
  int np = 0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * h;
    const double rho = rhoAt(solver, i, 1);
    if (x < 0.4) {
      r.l1 += std::abs(rho - ex.sample(x, t).rho) * h;
      norm += ex.sample(x, t).rho * h;
    }
    if (x > 0.08 && x < 0.17) {
      r.plateau += rho;
      ++np;
    }
    const double next = rhoAt(solver, i + 1, 1);
    if (r.shock == 0.0 && x > 0.1 && rho >= 10.0 && next < 10.0)
      r.shock = x + h * (rho - 10.0) / (rho - next);
  }
  r.l1 /= norm;
  r.plateau /= np;
  return r;
}

TEST(TvdNoh, CylindricalInRz) {
  const NohResult a = noh(100), b = noh(200);
  std::printf(
      "Noh cylindrical (r-z), t = 0.6: exact shock 0.2, plateau 16\n"
      "  100 cells: relative L1(rho, r<0.4) %.4f, shock %.4f, plateau %.3f\n"
      "  200 cells: relative L1(rho, r<0.4) %.4f, shock %.4f, plateau %.3f\n",
      a.l1, a.shock, a.plateau, b.l1, b.shock, b.plateau);
  // The shock speed follows from the conservation laws with the r-z terms: a wrong area or
  // source term moves it by far more than a cell. Bounds: 1.5 cells.
  EXPECT_NEAR(a.shock, 0.2, 1.5 / 100);
  EXPECT_NEAR(b.shock, 0.2, 1.5 / 200);
  // Behind the shock the density is 16 less the wall-heating deficit every shock-capturing
  // scheme leaves from the start-up at the axis (Noh 1987), which spreads over a fixed number
  // of cells: the plateau error must fall at first order (measured 1.35 and 0.72) and be
  // below 6% at 200 cells.
  EXPECT_LT(std::abs(b.plateau - 16.0), 0.06 * 16.0);
  EXPECT_LT(std::abs(b.plateau - 16.0) / std::abs(a.plateau - 16.0), 0.65);
  // The relative L1 error (dip, captured shock) falls at first order too (measured 0.148,
  // 0.085).
  EXPECT_LT(a.l1, 0.2);
  EXPECT_LT(b.l1 / a.l1, 0.65);
}

// ---------------------------------------------------------------------------------------------
// Sedov: energy E = 1 per unit length released at the origin of gamma = 1.4 gas (rho0 = 1,
// P ~ 0), computed on the quarter plane x, z >= 0 with reflecting walls on the two axes. The
// grid starts from the exact solution at t0 = 0.2 (shock radius 0.45) and runs to t = 0.4
// (0.63): a point deposit would spend most of the run on its first steps at huge sound speed
// and test only the start-up. The exact density falls to zero at the centre at finite
// pressure (sound speed 1e6 at r = 0.001); the start state takes rho >= 0.05 there, which adds
// 1e-3 of the mass in a region that carries no weight in the error norm. A 2-D test: the blast must
// stay circular through the split x and z sweeps.
struct SedovResult {
  double l1 = 0.0;       // integral |rho - rho_exact| dA / integral rho_exact dA, r < 1.1 R
  double radius = 0.0;   // radius of the density maximum along the diagonal
  double radiusX = 0.0;  // ... along the x axis
  double asym = 0.0;     // integral |rho(i, k) - rho(k, i)| dA / integral rho dA
};

SedovResult sedov(int n) {
  constexpr double gamma = 1.4, energy = 1.0, t0 = 0.2, t = 0.4, pAmbient = 1e-6;
  const double L = 0.75, h = L / n;
  cases::Scene s = baseScene(0.0, L, 0.0, L, h);
  s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Outflow, cases::Boundary::Wall,
                       cases::Boundary::Outflow};
  s.tStart = t0;
  s.materials.push_back(material("gas", eos::IdealGas{gamma, 1.0}));
  s.bodies.push_back(body("gas", 0, cases::Rect{0, L, 0, L}, {1.0, {}, 0.0}));
  TvdSolver solver(s);
  const verify::SedovSolution ex(gamma, 1.0, energy, 1);
  Conserved& U = solver.conservedForTesting();
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h, z = (k + 0.5) * h, rad = std::hypot(x, z);
      const verify::SedovSample e = ex.sample(rad, t0);
      const double rho = rad < ex.shockRadius(t0) ? std::max(e.rho, 0.05) : 1.0;
      const double u = rad < ex.shockRadius(t0) ? e.u : 0.0;
      const double p = std::max(rad < ex.shockRadius(t0) ? e.p : 0.0, pAmbient);
      const auto c = static_cast<std::size_t>(k) * n + i;
      U.rho[c] = rho;
      U.mx[c] = rho * u * x / rad;
      U.mz[c] = rho * u * z / rad;
      U.E[c] = p / (gamma - 1.0) + 0.5 * rho * u * u;
    }
  runTo(solver, t);
  const double R = ex.shockRadius(t);
  SedovResult r;
  double norm = 0.0, total = 0.0, bestD = 0.0, bestX = 0.0;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h, z = (k + 0.5) * h, rad = std::hypot(x, z);
      const double rho = rhoAt(solver, i, k);
      total += rho;
      r.asym += std::abs(rho - rhoAt(solver, k, i));
      if (rad < 1.1 * R) {
        const double exact = rad < R ? ex.sample(rad, t).rho : 1.0;
        r.l1 += std::abs(rho - exact);
        norm += exact;
      }
      if (i == k && rho > bestD) {
        bestD = rho;
        r.radius = rad;
      }
      if (k == 0 && rho > bestX) {
        bestX = rho;
        r.radiusX = x;
      }
    }
  r.l1 /= norm;
  r.asym /= total;
  return r;
}

TEST(TvdSedov, CylindricalBlastInXz) {
  const SedovResult a = sedov(60), b = sedov(120);
  const verify::SedovSolution ex(1.4, 1.0, 1.0, 1);
  const double R = ex.shockRadius(0.4);
  std::printf(
      "Sedov cylindrical (x-z quarter plane), t = 0.2 -> 0.4: exact shock radius %.4f\n"
      "   60 cells: relative L1(rho) %.4f, peak radius diagonal %.4f / x axis %.4f, "
      "x<->z asymmetry %.2e\n"
      "  120 cells: relative L1(rho) %.4f, peak radius diagonal %.4f / x axis %.4f, "
      "x<->z asymmetry %.2e\n",
      R, a.l1, a.radius, a.radiusX, a.asym, b.l1, b.radius, b.radiusX, b.asym);
  // The density peak of a captured shock lies within ~2 cells of the exact front, along the
  // grid axis and along the diagonal alike (a split scheme that distorted the blast would
  // shift them apart).
  EXPECT_NEAR(a.radius, R, 2.0 * 0.75 / 60);
  EXPECT_NEAR(b.radius, R, 2.0 * 0.75 / 120);
  EXPECT_NEAR(a.radiusX, R, 2.0 * 0.75 / 60);
  EXPECT_NEAR(b.radiusX, R, 2.0 * 0.75 / 120);
  // The error is that of the captured shock and its spike (6 rho0 falling steeply behind),
  // first order, plus the start-up error of a discontinuity in the initial data, which decays
  // more slowly; measured 0.17 -> 0.12 (ratio 0.67). Bound: it must fall (ratio < 0.85) and
  // stay below 20%.
  EXPECT_LT(b.l1, 0.2);
  EXPECT_LT(b.l1 / a.l1, 0.85);
  // Strang alternation keeps the blast symmetric under x <-> z to the splitting error, which
  // falls with h.
  EXPECT_LT(b.asym, 0.01);
  EXPECT_LT(b.asym, a.asym);
}

}  // namespace
}  // namespace hvi::tvd
