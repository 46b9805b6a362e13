//! @file Marker advection and redistribution in flows with known behaviour.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "helpers.hpp"
#include "hvi/common/error.hpp"

namespace hvi::tvd {
namespace {
using test::Field;
using test::makeGrid;
using test::spacing;
constexpr double pi = std::numbers::pi;

// Uniform flow is an exact translation: the lerp-form interpolation returns the constant bit
// for bit, so every marker gets the same displacement dt*v, and segment lengths (hence the
// redistribution) do not change. What remains is one rounding per coordinate per step
// (|error| <= ulp(1)/2 for coordinates below 1 cm), so after N steps every marker is within
// N ulp(1)/2 of where it started and the relative area change is at most
// perimeter * N ulp / area = 2 N ulp / R.
TEST(MarkerAdvect, UniformFlowThereAndBackIsExactTranslation) {
  const GridSpec g = makeGrid(100, 100, 0.0, 0.0, 0.01);
  const double R = 0.1;
  auto set = MarkerSet::fromShapes({cases::Disk{{0.25, 0.3}, R}}, g, 0.5, Geometry::Planar);
  const auto start = set.lines()[0].points;
  const double a0 = set.area(0);
  const std::size_t n0 = set.size();
  const Vec2 v{0.7, 0.4};  // cm/us; 0.6 cm = 3 diameters each way
  const int steps = 200;
  const double dt = 0.6 / norm(v) / steps;
  Field there(g, [&](Vec2) { return v; }), back(g, [&](Vec2) { return -v; });
  double worstArea = 0.0;
  for (int s = 0; s < 2 * steps; ++s) {
    const Field& f = s < steps ? there : back;
    set.advect(g, f.vx.data(), f.vz.data(), dt);
    set.redistribute(g);
    worstArea = std::max(worstArea, std::abs(set.area(0) / a0 - 1.0));
  }
  const double ulp = std::nextafter(1.0, 2.0) - 1.0;
  EXPECT_LT(worstArea, 2.0 * 2 * steps * ulp / R);
  ASSERT_EQ(set.size(), n0);
  double drift = 0.0;
  for (std::size_t j = 0; j < n0; ++j)
    drift = std::max(drift, norm(set.lines()[0].points[j] - start[j]));
  EXPECT_LE(drift, std::sqrt(2.0) * 2 * steps * 0.5 * ulp);
  const auto sp = spacing(set);
  EXPECT_GE(sp.min, set.minSpacingCells() * g.dx);
  EXPECT_LE(sp.max, set.maxSpacingCells() * g.dx);
  std::printf("[uniform] max |dA/A| = %.2e, max drift = %.2e cm, markers %zu\n", worstArea, drift,
              n0);
}

// Solid-body rotation v = omega x (p - c) is linear, so bilinear interpolation is exact (no
// interpolation error) and one midpoint step is the linear map M = I + th J + th^2/2 J^2,
// th = omega dt, with det M = 1 + th^4 / 4 exactly. The polygon area is therefore multiplied
// by (1 + th^4/4)^N: the measured change must match that to round-off.
TEST(MarkerAdvect, SolidBodyRotationOneTurn) {
  const GridSpec g = makeGrid(64, 64, 0.0, 0.0, 1.0 / 64);
  const Vec2 c{0.5, 0.5};
  const double omega = 2.0 * pi;  // one turn per microsecond
  const int steps = 400;
  const double dt = 1.0 / steps, th = omega * dt;
  Field f(g, [&](Vec2 p) { return omega * Vec2{-(p.z - c.z), p.x - c.x}; });
  auto set = MarkerSet::fromShapes({cases::Disk{{0.5, 0.75}, 0.15}}, g, 0.5, Geometry::Planar);
  const double a0 = set.area(0);
  const std::size_t n0 = set.size();
  for (int s = 0; s < steps; ++s) {
    set.advect(g, f.vx.data(), f.vz.data(), dt);
    set.redistribute(g);
  }
  const double predicted = std::pow(1.0 + std::pow(th, 4) / 4.0, steps) - 1.0;
  const double measured = set.area(0) / a0 - 1.0;
  EXPECT_NEAR(measured, predicted, 1e-12);
  EXPECT_EQ(set.size(), n0);
  const auto sp = spacing(set);
  EXPECT_GE(sp.min, set.minSpacingCells() * g.dx);
  EXPECT_LE(sp.max, set.maxSpacingCells() * g.dx);
  std::printf("[rotation] dA/A = %.3e (predicted %.3e), markers %zu\n", measured, predicted,
              set.size());
}

// Simple shear vx = S (z - zc): linear and divergence free, and the midpoint step is exact
// (vz = 0), so advection keeps the area to round-off; insertions lie on the segments and do not
// change it either. Only removals do: dropping marker q between kept a and b changes the area by
// the triangle |(q - a) x (b - a)| / 2, which is below min * (max + min) * kappa * min / 4 for a
// line of curvature kappa. The disk (R = 0.1) is stretched by S t = 20 into a filament 4 cm long
// and 1 cell thick; its tips have radius ~ R / (S t)^3, and the compressive phase that triggers
// removals happens early (S t < 2) when kappa ~ 1/R. With ~400 removals of min = 0.0025 cm:
// |dA| <= 400 * 0.0025 * 0.0125 * 0.0025 / 4 / R = 8e-7 cm^2, i.e. 2.5e-5 of the area.
TEST(MarkerAdvect, ShearStretchesDiskIntoFilament) {
  const double d = 0.01, R = 0.1;
  const GridSpec g = makeGrid(500, 30, -2.5, -0.15, d);
  const double S = 10.0;  // 1/us
  Field f(g, [&](Vec2 p) { return Vec2{S * p.z, 0.0}; });
  auto set = MarkerSet::fromShapes({cases::Disk{{0.0, 0.0}, R}}, g, 0.5, Geometry::Planar);
  const double a0 = set.area(0);
  const std::size_t n0 = set.size();
  const double dt = 0.4 * d / (S * R);                       // 0.4 cell per step at the disk's edge
  const int steps = static_cast<int>(std::round(2.0 / dt));  // S t = 20
  double worst = 0.0;
  for (int s = 0; s < steps; ++s) {
    set.advect(g, f.vx.data(), f.vz.data(), dt);
    set.redistribute(g);
    worst = std::max(worst, std::abs(set.area(0) / a0 - 1.0));
    const auto sp = spacing(set);
    ASSERT_GE(sp.min, set.minSpacingCells() * d * (1 - 1e-12)) << s;
    ASSERT_LE(sp.max, set.maxSpacingCells() * d * (1 + 1e-12)) << s;
  }
  double xmin = 1e9, xmax = -1e9, perimeter = 0.0;
  const auto& p = set.lines()[0].points;
  for (std::size_t j = 0; j < p.size(); ++j) {
    xmin = std::min(xmin, p[j].x);
    xmax = std::max(xmax, p[j].x);
    perimeter += norm(p[(j + 1) % p.size()] - p[j]);
  }
  // Length of the sheared disk: an ellipse whose major semi-axis is R (St/2 + sqrt(1+(St/2)^2)).
  const double gamma = S * steps * dt;
  const double semi = R * (0.5 * gamma + std::sqrt(1.0 + 0.25 * gamma * gamma));
  EXPECT_NEAR(0.5 * (xmax - xmin), semi * gamma / std::sqrt(1.0 + gamma * gamma), 0.02 * semi);
  EXPECT_LT(worst, 2.5e-5);
  // Markers grow with the perimeter, not faster: count <= perimeter / min spacing.
  EXPECT_LE(static_cast<double>(set.size()), perimeter / (set.minSpacingCells() * d));
  std::printf(
      "[shear] St = %.1f: max |dA/A| = %.2e, markers %zu -> %zu (x%.1f), perimeter "
      "%.2f -> %.2f cm (x%.1f), mean spacing %.3f cells\n",
      gamma, worst, n0, set.size(), double(set.size()) / n0, 2 * pi * R, perimeter,
      perimeter / (2 * pi * R), perimeter / set.size() / d);
}

// Rider-Kothe single-vortex deformation (stream function sin^2(pi x) sin^2(pi z) / pi): a
// nonlinear incompressible shear that winds a disk into a thin spiral filament; the flow is
// reversed at T/2 so the disk should come back. The cell-centred field interpolated
// bilinearly is divergence-free only to O(dx^2), so the area error and the shape error must
// fall about 4x per grid halving (second order); the time error (midpoint, O(dt^2)) falls too
// as dt scales with dx, and so does the chord error of the markers (spacing ~ dx). T = 4: the
// disk is wound into a spiral filament about 1.5 turns long before it is unwound.
struct VortexResult {
  double areaErr, shapeErr;
  std::size_t maxMarkers, start;
};
VortexResult singleVortex(int n, double T) {
  const GridSpec g = makeGrid(n, n, 0.0, 0.0, 1.0 / n);
  auto vel = [](Vec2 p) {
    const double sx = std::sin(pi * p.x), sz = std::sin(pi * p.z);
    return Vec2{-2.0 * sx * sx * sz * std::cos(pi * p.z), 2.0 * sz * sz * sx * std::cos(pi * p.x)};
  };
  Field fwd(g, vel), rev(g, [&](Vec2 p) { return -vel(p); });
  const Vec2 c{0.5, 0.75};
  const double R = 0.15;
  auto set = MarkerSet::fromShapes({cases::Disk{c, R}}, g, 0.5, Geometry::Planar);
  const double a0 = set.area(0);
  VortexResult r{0.0, 0.0, set.size(), set.size()};
  const int steps = static_cast<int>(2 * T * n);  // max |v| = 1 cm/us: CFL 0.5
  const double dt = T / steps;
  for (int s = 0; s < steps; ++s) {
    const Field& f = s < steps / 2 ? fwd : rev;
    set.advect(g, f.vx.data(), f.vz.data(), dt);
    set.redistribute(g);
    r.maxMarkers = std::max(r.maxMarkers, set.size());
  }
  r.areaErr = std::abs(set.area(0) / a0 - 1.0);
  const auto sp = spacing(set);
  EXPECT_GE(sp.min, set.minSpacingCells() * g.dx);
  EXPECT_LE(sp.max, set.maxSpacingCells() * g.dx);
  for (Vec2 p : set.lines()[0].points) r.shapeErr = std::max(r.shapeErr, std::abs(norm(p - c) - R));
  return r;
}

TEST(MarkerAdvect, SingleVortexReversalConvergesSecondOrder) {
  VortexResult r[3];
  for (int level = 0; level < 3; ++level) {
    r[level] = singleVortex(32 << level, 4.0);
    std::printf("[vortex] n=%d: |dA/A| = %.2e, max |r-R| = %.2e cm, markers %zu -> max %zu\n",
                32 << level, r[level].areaErr, r[level].shapeErr, r[level].start,
                r[level].maxMarkers);
  }
  // Second order means a factor 4 per halving; 3 leaves room for the pre-asymptotic range
  // (a first-order error would give 2).
  for (int level = 1; level < 3; ++level) {
    EXPECT_LT(r[level].shapeErr, r[level - 1].shapeErr / 3.0);
    EXPECT_LT(r[level].areaErr, r[level - 1].areaErr / 3.0);
  }
  // Markers track the perimeter: the spiral is ~6x the circle's perimeter at its longest.
  EXPECT_LT(r[2].maxMarkers, 8 * r[2].start);
}

// A reflecting wall mirrors the cells (the solver's ghost = the cell with the normal velocity
// negated), so the marker velocity continues the normal component oddly across it, as on the
// r-z axis (advect's oddWalls; the solver uses the nearest values with the pinning below,
// docs/markers.md). A normal velocity linear in the distance to the wall, v_n = a (n - n_wall),
// with a constant tangential one c, is then interpolated exactly also between the wall and the
// first cell centre (the ghost's -v_n(first centre) is v_n half a cell beyond the wall), where the
// nearest-value continuation gave v_n(first centre) instead. One midpoint step maps the distance
// d to the wall to d (1 + a dt + (a dt)^2 / 2) exactly and the tangential coordinate by c dt;
// the marker on the wall stays on it, after many steps too. Bound: rounding of coordinates
// below 1 cm (a few ulp); the nearest values are off by a (0.5 dx - d) dt, 8e-5 cm for the
// marker 0.1 cells from the wall.
TEST(MarkerAdvect, WallContinuesTheNormalVelocityOddly) {
  const GridSpec g = makeGrid(10, 12, 0.1, -0.2, 0.01);
  const double x1 = g.x0 + g.nx * g.dx, z1 = g.z0 + g.nz * g.dz;  // as advect computes them
  const double c = 0.3, dt = 0.01;
  const std::array<double, 5> dist{0.0, 0.1 * g.dx, 0.3 * g.dx, 0.45 * g.dx, 1.3 * g.dx};
  for (int side = 0; side < 4; ++side)
    for (const double a : {2.0, -2.0}) {
      const bool alongX = side < 2;  // the wall's normal is x
      const double wall = side == 0 ? g.x0 : side == 1 ? x1 : side == 2 ? g.z0 : z1;
      const double inward = side % 2 == 0 ? 1.0 : -1.0;
      // v_n = a (n - n_wall): the flow leaves (a > 0) or approaches (a < 0) the wall.
      Field f(g, [&](Vec2 p) {
        const double n = alongX ? p.x : p.z;
        const double vn = a * (n - wall);
        return alongX ? Vec2{vn, c} : Vec2{c, vn};
      });
      MarkerLine line{0, true, {}};
      const double t0 = 0.13;  // tangential coordinate, inside the grid either way
      for (std::size_t j = 0; j < dist.size(); ++j) {
        const double n = wall + inward * dist[j], t = t0 + 0.01 * static_cast<double>(j);
        line.points.push_back(alongX ? Vec2{n, t - 0.3} : Vec2{t, n});
      }
      std::array<bool, 4> walls{};
      walls[static_cast<std::size_t>(side)] = true;
      auto one = MarkerSet::fromLines({line}, 1, 0.5, Geometry::Planar);
      auto nearest = one;
      one.advect(g, f.vx.data(), f.vz.data(), dt, walls, {}, true);
      nearest.advect(g, f.vx.data(), f.vz.data(), dt, walls);
      const double grow = 1.0 + a * dt + 0.5 * (a * dt) * (a * dt);
      double worst = 0.0, worstNearest = 0.0;
      for (std::size_t j = 0; j < dist.size(); ++j) {
        const Vec2 p0 = line.points[j], p = one.lines()[0].points[j];
        const Vec2 q = nearest.lines()[0].points[j];
        const double n0 = alongX ? p0.x : p0.z, n = alongX ? p.x : p.z, nq = alongX ? q.x : q.z;
        const double t = alongX ? p.z - p0.z : p.x - p0.x;
        const double expected = wall + (n0 - wall) * grow;
        worst = std::max({worst, std::abs(n - expected), std::abs(t - c * dt)});
        if (j < 4) worstNearest = std::max(worstNearest, std::abs(nq - expected));
        if (j == 0) {
          EXPECT_EQ(n, wall) << "side " << side;
        }
      }
      EXPECT_LT(worst, 1e-15) << "side " << side << " a " << a;
      EXPECT_GT(worstNearest, 1e-5) << "side " << side;  // the test tells the two forms apart
      // Many steps, also with the nearest values (the solver's default, oddWalls off): the
      // marker on the wall stays on it, none crosses it.
      for (int s = 0; s < 50; ++s) {
        one.advect(g, f.vx.data(), f.vz.data(), dt, walls, {}, true);
        nearest.advect(g, f.vx.data(), f.vz.data(), dt, walls);
      }
      for (const Vec2& p : nearest.lines()[0].points)
        EXPECT_GE(inward * ((alongX ? p.x : p.z) - wall), 0.0);
      EXPECT_EQ(alongX ? nearest.lines()[0].points[0].x : nearest.lines()[0].points[0].z, wall);
      const auto& pts = one.lines()[0].points;
      EXPECT_EQ(alongX ? pts[0].x : pts[0].z, wall) << "side " << side;
      for (const Vec2& p : pts) EXPECT_GE(inward * ((alongX ? p.x : p.z) - wall), 0.0);
      std::printf("[wall side %d, a %+.0f] max error %.1e cm (nearest values: %.1e)\n", side, a,
                  worst, worstNearest);
    }
}

// A velocity field that flings part of a line across the grid (one cell moving at 10^4 cm/us)
// would make the redistribution fill the stretched segments with points: 10^6 cells of line at
// the 0.5-cell spacing, against the 16 per cell (+65536) a material boundary can need on this
// 20x20 grid. The run stops before any point is made, naming the line, and the set is unchanged.
TEST(MarkerAdvect, ALineFlungAcrossTheGridStopsBeforeFillingMemory) {
  const GridSpec g = makeGrid(20, 20, 0.0, 0.0, 0.01);
  auto set = MarkerSet::fromShapes({cases::Disk{{0.1, 0.1}, 0.05}}, g, 0.5, Geometry::Planar);
  set.redistribute(g);  // an ordinary line passes
  Field f(g, [&](Vec2 p) {
    return p.x > 0.14 && p.x < 0.15 ? Vec2{0.0, 1.0e4} : Vec2{};  // one column of cells
  });
  set.advect(g, f.vx.data(), f.vz.data(), 1.0);
  const std::size_t n = set.size();
  try {
    set.redistribute(g);
    ADD_FAILURE() << "no error for a line stretched across 10^6 cells";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("object 0"), std::string::npos) << e.what();
  }
  EXPECT_EQ(set.size(), n);
}

}  // namespace
}  // namespace hvi::tvd
