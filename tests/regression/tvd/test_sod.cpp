//! @file Sod shock tube along x, along z and at 45 degrees against the exact Riemann solver.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hvi/verify/riemann.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

constexpr double kGamma = 1.4;
constexpr double kTime = 0.2;

eos::Eos gas() { return eos::IdealGas{kGamma, 1.0}; }
BodyInit sodLeft() { return {1.0, {}, 1.0 / ((kGamma - 1.0) * 1.0)}; }
BodyInit sodRight() { return {0.125, {}, 0.1 / ((kGamma - 1.0) * 0.125)}; }

verify::ExactRiemann exact() {
  return verify::ExactRiemann(gas(), {1.0, 0.0, sodLeft().e}, gas(), {0.125, 0.0, sodRight().e});
}

// L1 norm of the density error along a unit tube, integral |rho - rho_exact| dx, on a strip
// two cells wide.
double sodAlongAxis(int n, bool alongZ) {
  const double h = 1.0 / n, w = 2 * h;
  cases::Scene s = alongZ ? baseScene(0.0, w, 0.0, 1.0, h) : baseScene(0.0, 1.0, 0.0, w, h);
  s.materials.push_back(material("gas", gas()));
  const cases::Rect lo = alongZ ? cases::Rect{0, w, 0, 0.5} : cases::Rect{0, 0.5, 0, w};
  const cases::Rect hi = alongZ ? cases::Rect{0, w, 0.5, 1} : cases::Rect{0.5, 1, 0, w};
  s.bodies.push_back(body("left", 0, lo, sodLeft()));
  s.bodies.push_back(body("right", 0, hi, sodRight()));
  TvdSolver solver(s);
  runTo(solver, kTime);
  const auto ex = exact();
  double err = 0.0;
  for (int j = 0; j < n; ++j) {
    const double x = (j + 0.5) * h;
    for (int across = 0; across < 2; ++across) {
      const double r = alongZ ? rhoAt(solver, across, j) : rhoAt(solver, j, across);
      err += 0.5 * std::abs(r - ex.sample((x - 0.5) / kTime).rho) * h;
    }
  }
  return err;
}

// The tube along the diagonal of the unit square: the initial discontinuity is the line
// x + z = 1, the exact solution depends on s = (x + z) / sqrt(2) only. Measured: the L1
// error integral |rho - rho_exact| ds along the main diagonal, from the cells (i, i), whose
// centres lie on it at spacing sqrt(2) h. Outflow boundaries disturb the solution only near the
// two corners where the discontinuity meets the boundary, more than 0.5 away from the diagonal
// (sound travels < 0.25 by t = 0.2).
double sodDiagonal(int n) {
  const double h = 1.0 / n;
  cases::Scene s = baseScene(0.0, 1.0, 0.0, 1.0, h);
  s.materials.push_back(material("gas", gas()));
  s.bodies.push_back(body("left", 0, cases::Polygon{{{0, 0}, {1, 0}, {0, 1}}}, sodLeft()));
  s.bodies.push_back(body("right", 0, cases::Polygon{{{1, 0}, {1, 1}, {0, 1}}}, sodRight()));
  TvdSolver solver(s);
  runTo(solver, kTime);
  const auto ex = exact();
  const double s0 = std::sqrt(0.5);
  double err = 0.0;
  for (int i = 0; i < n; ++i) {
    const double si = std::sqrt(2.0) * (i + 0.5) * h;
    err += std::abs(rhoAt(solver, i, i) - ex.sample((si - s0) / kTime).rho) * std::sqrt(2.0) * h;
  }
  return err;
}

// Requirements (Athena++'s sod_shock regression): L1 < 0.011 at 128 cells and
// err(256)/err(128) <= 0.6. A second-order TVD scheme converges at order ~1 on the shock and
// rarefaction corners and ~2/3 on the contact (t^(1/3) spreading), so the mixed L1 error of Sod
// falls by a ratio between 0.5 and 0.63; 0.6 demands the second-order behaviour.
TEST(TvdSod, AlongX) {
  const double e128 = sodAlongAxis(128, false), e256 = sodAlongAxis(256, false);
  std::printf("Sod along x: L1(128) = %.5f, L1(256) = %.5f, ratio %.3f\n", e128, e256, e256 / e128);
  EXPECT_LT(e128, 0.011);
  EXPECT_LE(e256 / e128, 0.6);
}

// The z sweep must give the same numbers as the x sweep (same kernel, other stride).
TEST(TvdSod, AlongZ) {
  const double e128 = sodAlongAxis(128, true), e256 = sodAlongAxis(256, true);
  std::printf("Sod along z: L1(128) = %.5f, L1(256) = %.5f, ratio %.3f\n", e128, e256, e256 / e128);
  EXPECT_LT(e128, 0.011);
  EXPECT_LE(e256 / e128, 0.6);
  EXPECT_NEAR(e128, sodAlongAxis(128, false), 1e-12);
}

TEST(TvdSod, At45Degrees) {
  const double e128 = sodDiagonal(128), e256 = sodDiagonal(256);
  std::printf("Sod at 45 degrees (diagonal): L1(128) = %.5f, L1(256) = %.5f, ratio %.3f\n", e128,
              e256, e256 / e128);
  EXPECT_LT(e128, 0.011);
  EXPECT_LE(e256 / e128, 0.6);
}

}  // namespace
}  // namespace hvi::tvd
