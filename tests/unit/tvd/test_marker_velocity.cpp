//! @file Conservative cut-cell interfaces (issue 13): each marker line moves with its own body's
//! velocity (tvd::Options::ownBodyVelocity, docs/tvd.md "Marker velocity: each line its own
//! body's"). A body at rest with another one approaching across a gap of 1.5 cells is untouched
//! until they meet: nothing crosses vacuum, so its state, its lines and its energy stay exact.
//! A sliver thinner than a cell (spray: it fills no cell) moving towards another body keeps its
//! own velocity and thickness, though the vacuum cell between carries both bodies' mean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

struct Untouched {
  double lineMove = 0.0;      // largest displacement of a plate marker, cm
  double densityError = 0.0;  // largest |rho_p / rho0 - 1| over the plate's cells
  double speed = 0.0;         // largest speed of the plate's phase, cm/us
  double energy = 0.0;        // largest |specific internal energy| of the plate, cm^2/us^2
  long steps = 0;
};

// Aluminium plate at rest (top on a cell face at z = 0) and an aluminium block 1.5 cells above
// it closing at 6.7 km/s (CASES.md variant 1's speed), run to 0.9 of the closing time. The
// block's lower line reaches into the gap row from the first step, so the plate's top markers
// have cells of the other body and of vacuum in their stencil from then on.
Untouched approach(Geometry g, bool own) {
  const bool rz = g == Geometry::Axisymmetric;
  const double h = 0.02, gap = 1.5 * h, v = 0.67;
  cases::Scene s = cutScene(rz ? 0.0 : -0.6, 0.6, -0.3, 0.4, h, g);
  if (rz) s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.materials.push_back(material("striker", eos::aluminiumStudy()));
  s.bodies.push_back(
      body("plate", 0, cases::Rect{rz ? 0.0 : -0.5, 0.5, -0.2, 0.0}, {2.79, {}, 0.0}));
  s.bodies.push_back(
      body("block", 1, cases::Rect{rz ? 0.0 : -0.3, 0.3, gap, gap + 0.2}, {2.79, {0.0, -v}, 0.0}));
  Options o;
  o.ownBodyVelocity = own;
  TvdSolver solver(s, o);
  std::vector<Vec2> start;
  for (const auto& line : solver.markers().lines())
    if (line.object == 0) start.insert(start.end(), line.points.begin(), line.points.end());
  runTo(solver, 0.9 * gap / v);
  Untouched u;
  u.steps = solver.step();
  std::size_t n = 0;
  for (const auto& line : solver.markers().lines()) {
    if (line.object != 0) continue;
    // Without the rule the redistribution may add or drop points on the moved line; compare
    // with the nearest start point.
    for (Vec2 p : line.points) {
      double best = 1e300;
      for (Vec2 q : start) best = std::min(best, std::hypot(p.x - q.x, p.z - q.z));
      u.lineMove = std::max(u.lineMove, best);
      ++n;
    }
  }
  EXPECT_GT(n, 0u);
  const Phases& ph = solver.phases();
  for (long c = ph.cellLo(); c < ph.cellHi(); ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const double a = ph.alpha[0][cc], m = ph.q[0].rho[cc];
    if (!(a > 0.0) || !(m > 0.0)) continue;
    u.densityError = std::max(u.densityError, std::abs(m / a / 2.79 - 1.0));
    const double speed = std::hypot(ph.q[0].mx[cc], ph.q[0].mz[cc]) / m;
    u.speed = std::max(u.speed, speed);
    u.energy = std::max(u.energy, std::abs(ph.q[0].E[cc] / m - 0.5 * speed * speed));
  }
  return u;
}

TEST(TvdMarkerVelocity, APlateAtRestIsUntouchedByABodyApproaching) {
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const char* name = g == Geometry::Planar ? "planar" : "r-z";
    const Untouched own = approach(g, true);
    const Untouched mixed = approach(g, false);
    std::printf(
        "  %s, %ld steps: own velocity: line moved %.2e cm, density %.2e, speed %.2e, e %.2e; "
        "every cell's (before): %.2e cm, %.2e, %.2e, %.2e\n",
        name, own.steps, own.lineMove, own.densityError, own.speed, own.energy, mixed.lineMove,
        mixed.densityError, mixed.speed, mixed.energy);
    // Nothing reaches the plate through vacuum: its state stays at rest to round-off (r-z: the
    // hoop terms' round-off of a uniform state, ~1e-16), issue 13's rest bound for the speed
    // (1e-10 of the sound speed, 0.53 cm/us), and its lines with it.
    EXPECT_LT(own.lineMove, 1e-12) << name;
    EXPECT_LT(own.densityError, 1e-12) << name;
    EXPECT_LT(own.speed, 1e-10 * 0.53) << name;
    EXPECT_LT(own.energy, 1e-12) << name;
    // The earlier motion moved the plate's top with the block's velocity extended into the gap
    // (more than a hundredth of a cell in these few steps) and compressed its top row cold: the
    // test tells the two apart.
    EXPECT_GT(mixed.lineMove, 1e-2 * 0.02) << name;
    EXPECT_GT(mixed.densityError, 1e-3) << name;
  }
}


struct Sliver {
  double densityError = 0.0;  // largest |rho_p / (alpha rho0) - 1| over the sliver's cells
  double speedError = 0.0;    // largest |v_p - v| / v over the sliver's cells
  double thickness = 0.0;     // the sliver's mass over its start mass per unit area, relative
  long steps = 0;
};

// An aluminium sliver 0.4 cells thick (it fills no cell) at z in [1.3, 1.7] cells, closing at
// v on a plate at rest whose top lies mid-cell at -0.5 cells (its top row half full: no cell
// the two fill together), run until the sliver has moved one cell (0.2 cells short of the
// plate's row). The vacuum row between takes the mean of its neighbours, the plate's 0 and the
// sliver's -v (Ownership::extendIntoVacuum), and lies in the stencil of the sliver's lower
// markers from the first step.
Sliver sliver(Geometry g, bool own) {
  const bool rz = g == Geometry::Axisymmetric;
  const double h = 0.02, v = 0.1;
  cases::Scene s = cutScene(rz ? 0.0 : -0.6, 0.6, -0.3, 0.4, h, g);
  if (rz) s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.materials.push_back(material("spray", eos::aluminiumStudy()));
  s.bodies.push_back(
      body("plate", 0, cases::Rect{rz ? 0.0 : -0.5, 0.5, -0.2, -0.5 * h}, {2.79, {}, 0.0}));
  s.bodies.push_back(body("sliver", 1, cases::Rect{rz ? 0.0 : -0.3, 0.3, 1.3 * h, 1.7 * h},
                          {2.79, {0.0, -v}, 0.0}));
  Options o;
  o.ownBodyVelocity = own;
  TvdSolver solver(s, o);
  const Phases& ph = solver.phases();
  auto volumeOf = [&](long c) {
    // r-z: the cell's ring volume per radian over the planar one is its centre radius.
    return rz ? (static_cast<double>(c % solver.grid().nx) + 0.5) * h : 1.0;
  };
  auto mass = [&] {
    double m = 0.0;
    for (long c = ph.cellLo(); c < ph.cellHi(); ++c)
      m += ph.q[1].rho[static_cast<std::size_t>(c)] * volumeOf(c);
    return m;
  };
  // The sliver's mass per covered volume is its thickness times rho0: with its mass conserved,
  // the covered volume (sum of alpha) falls as it is squeezed.
  auto covered = [&] {
    double a = 0.0;
    for (long c = ph.cellLo(); c < ph.cellHi(); ++c)
      a += ph.alpha[1][static_cast<std::size_t>(c)] * volumeOf(c);
    return a;
  };
  const double m0 = mass(), a0 = covered();
  runTo(solver, h / v);
  Sliver r;
  r.steps = solver.step();
  r.thickness = std::abs(covered() / a0 - 1.0);
  EXPECT_NEAR(mass() / m0, 1.0, 1e-12);
  for (long c = ph.cellLo(); c < ph.cellHi(); ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const double a = ph.alpha[1][cc], m = ph.q[1].rho[cc];
    if (!(a > 0.0) || !(m > 0.0)) continue;
    r.densityError = std::max(r.densityError, std::abs(m / a / 2.79 - 1.0));
    r.speedError = std::max(r.speedError,
                            std::hypot(ph.q[1].mx[cc] / m, ph.q[1].mz[cc] / m + v) / v);
  }
  return r;
}

TEST(TvdMarkerVelocity, ASliverKeepsItsOwnVelocityBesideAnotherBody) {
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const char* name = g == Geometry::Planar ? "planar" : "r-z";
    const Sliver own = sliver(g, true);
    const Sliver every = sliver(g, false);
    std::printf(
        "  %s, %ld steps: own velocity: density %.2e, speed %.2e, covered volume %.2e; "
        "every cell's: %.2e, %.2e, %.2e\n",
        name, own.steps, own.densityError, own.speedError, own.thickness, every.densityError,
        every.speedError, every.thickness);
    // Uniform motion through vacuum is exact to round-off in this mode ("Uniform motion: the
    // settle's routing"; the disk carried 20 diameters keeps its state to 2.5e-13): the sliver
    // is a block in uniform motion as long as its lines move with it.
    EXPECT_LT(own.densityError, 1e-12) << name;
    EXPECT_LT(own.speedError, 1e-12) << name;
    EXPECT_LT(own.thickness, 1e-12) << name;
    // Reading every cell, the lower line moves with ~0.9 v (a fifth of its stencil is the
    // vacuum row at -v/2): the sliver is squeezed by ~0.1 v t over its 0.4 cells, a quarter.
    EXPECT_GT(every.thickness, 0.05) << name;
    EXPECT_GT(every.densityError, 0.05) << name;
  }
}

}  // namespace
}  // namespace hvi::tvd
