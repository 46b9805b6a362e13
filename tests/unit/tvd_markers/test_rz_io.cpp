//! @file r-z construction and advection on the axis; scene construction; checkpoint round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "helpers.hpp"
#include "hvi/common/error.hpp"

namespace hvi::tvd {
namespace {
using test::Field;
using test::makeGrid;
using test::spacing;
constexpr double pi = std::numbers::pi;

int axisPoints(const MarkerSet& s) {
  int n = 0;
  for (const auto& l : s.lines())
    for (Vec2 p : l.points) n += p.x == 0.0;
  return n;
}
double minX(const MarkerSet& s) {
  double m = 1e300;
  for (const auto& l : s.lines())
    for (Vec2 p : l.points) m = std::min(m, p.x);
  return m;
}
//! The line runs along the axis once: its points at x = 0 (at least two) form one contiguous
//! run in the cyclic order, so the line is attached to the axis from its bottom to its top.
bool axisRunSpansBody(const MarkerLine& l) {
  const auto& p = l.points;
  int onAxis = 0, runStarts = 0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const bool here = p[j].x == 0.0, before = p[(j + p.size() - 1) % p.size()].x == 0.0;
    onAxis += here;
    runStarts += here && !before;
  }
  return onAxis >= 2 && runStarts == 1;
}

// A sphere centred on the axis: the r-z section is a half disk whose straight side lies on the
// axis, with points there at x = 0 exactly. Its area is half the inscribed polygon's, and its
// volume of revolution approaches 4/3 pi R^3 with the polygon's O(1/N^2) deficit (~pi^2/N^2).
TEST(MarkerRz, SphereOnAxisConstruction) {
  const GridSpec g = makeGrid(40, 80, 0.0, 0.0, 0.025);
  const double R = 0.5;
  const auto set =
      MarkerSet::fromShapes({cases::Disk{{0.0, 1.0}, R}}, g, 0.5, Geometry::Axisymmetric);
  ASSERT_EQ(set.lines().size(), 1u);
  EXPECT_TRUE(axisRunSpansBody(set.lines()[0]));
  EXPECT_EQ(minX(set), 0.0);
  const double h = 0.5 * g.dx;
  EXPECT_GE(axisPoints(set), static_cast<int>(2 * R / h) + 1);
  EXPECT_LE(spacing(set).max, h * (1 + 1e-12));
  // Full polygon of N = 4 ceil(2 pi R / h / 4) sides, half of it kept.
  const double n = 4.0 * std::ceil(2.0 * pi * R / h / 4.0);
  EXPECT_NEAR(set.area(0), 0.25 * n * R * R * std::sin(2.0 * pi / n), 1e-14);
  const double sphere = 4.0 / 3.0 * pi * R * R * R;
  EXPECT_NEAR(set.volume(0), sphere, 12.0 / (n * n) * sphere);
  EXPECT_LT(set.volume(0), sphere);

  // A plate from the axis: its left side is the axis. A body across the axis is cut at x = 0.
  const auto plate =
      MarkerSet::fromShapes({cases::Rect{0.0, 0.8, 1.6, 1.7}, cases::Rect{-0.3, 0.4, 0.1, 0.3}}, g,
                            0.5, Geometry::Axisymmetric);
  EXPECT_TRUE(axisRunSpansBody(plate.lines()[0]));
  EXPECT_TRUE(axisRunSpansBody(plate.lines()[1]));
  EXPECT_NEAR(plate.area(1), 0.4 * 0.2, 1e-15);
  EXPECT_EQ(minX(plate), 0.0);
  EXPECT_NEAR(plate.volume(0), pi * 0.8 * 0.8 * 0.1, 1e-13);
  EXPECT_THROW(
      MarkerSet::fromShapes({cases::Disk{{-1.0, 1.0}, 0.5}}, g, 0.5, Geometry::Axisymmetric),
      InputError);
}

// Incompressible r-z stagnation flow vx = a r, vz = -2 a (z - zc): linear, and the odd axis
// ghost keeps vx = a r exact down to r = 0, so a midpoint step maps r -> Mr r, z -> Mz z with
// Mr = 1 + e + e^2/2, Mz = 1 - 2e + 2e^2 (e = a dt), and the volume of revolution scales by
// Mr^2 Mz exactly. The sphere flattens into an oblate body; its axis points stay at r = 0.
TEST(MarkerRz, SphereOnAxisInStagnationFlow) {
  const GridSpec g = makeGrid(48, 64, 0.0, 0.0, 0.025);
  const double a = 0.5, zc = 0.8, R = 0.3;
  Field f(g, [&](Vec2 p) { return Vec2{a * p.x, -2.0 * a * (p.z - zc)}; });
  const int steps = 100;
  const double dt = 0.01, e = a * dt;
  const double perStep = std::pow(1 + e + e * e / 2, 2) * (1 - 2 * e + 2 * e * e);

  auto bare = MarkerSet::fromShapes({cases::Disk{{0.0, zc}, R}}, g, 0.5, Geometry::Axisymmetric);
  auto redist = bare;
  const double v0 = bare.volume(0);
  const int axis0 = axisPoints(bare);
  for (int s = 0; s < steps; ++s) {
    bare.advect(g, f.vx.data(), f.vz.data(), dt);
    redist.advect(g, f.vx.data(), f.vz.data(), dt);
    redist.redistribute(g);
    ASSERT_EQ(minX(redist), 0.0) << s;
    ASSERT_TRUE(axisRunSpansBody(redist.lines()[0])) << s;
  }
  const double predicted = std::pow(perStep, steps);
  EXPECT_NEAR(bare.volume(0) / v0, predicted, 1e-12);
  EXPECT_EQ(axisPoints(bare), axis0);
  // With redistribution: markers merge as the body flattens, each merge placed so that the
  // volume of revolution is unchanged, so only round-off remains.
  const double vErr = std::abs(redist.volume(0) / v0 / predicted - 1.0);
  EXPECT_LT(vErr, 1e-12);
  // No vacuum channel along the axis: the first column is owned by the body over its extent.
  std::vector<int> owner;
  std::vector<Vec2> normal;
  redist.rasterize(g, owner, normal);
  double zlo = 1e9, zhi = -1e9;
  for (Vec2 p : redist.lines()[0].points)
    if (p.x == 0.0) {
      zlo = std::min(zlo, p.z);
      zhi = std::max(zhi, p.z);
    }
  int column = 0;
  for (int k = 0; k < g.nz; ++k) {
    const double z = (k + 0.5) * g.dz;
    if (z > zlo + g.dz && z < zhi - g.dz) {
      EXPECT_EQ(owner[static_cast<std::size_t>(k * g.nx)], 0) << k;
      ++column;
    }
  }
  EXPECT_GE(column, 2);
  const auto sp = spacing(redist);
  EXPECT_GE(sp.min, redist.minSpacingCells() * g.dx);
  EXPECT_LE(sp.max, redist.maxSpacingCells() * g.dx);
  std::printf(
      "[rz stagnation] V/V0 = %.6f (predicted %.6f), redistributed volume error %.2e, "
      "axis points %d -> %d, markers %zu -> %zu\n",
      bare.volume(0) / v0, predicted, vErr, axis0, axisPoints(redist), bare.size(), redist.size());
}

// A radially inward velocity that is not zero in the first cell (as a crude solver field could
// be), strong enough to crush the body onto the axis: markers approach the axis but never cross
// it, and the axis markers stay at x = 0.
TEST(MarkerRz, InwardFlowNeverCrossesTheAxis) {
  const GridSpec g = makeGrid(40, 40, 0.0, 0.0, 0.025);
  Field f(g, [](Vec2) { return Vec2{-1.0, 0.3}; });
  auto set = MarkerSet::fromShapes({cases::Disk{{0.0, 0.4}, 0.25}}, g, 0.5, Geometry::Axisymmetric);
  for (int s = 0; s < 100; ++s) {
    set.advect(g, f.vx.data(), f.vz.data(), 0.005);
    set.redistribute(g);
    ASSERT_GE(minX(set), 0.0);
    ASSERT_TRUE(axisRunSpansBody(set.lines()[0]));
  }
  EXPECT_GE(axisPoints(set), 2);
}

TEST(MarkerScene, FromBodiesAndBadInput) {
  cases::Scene scene;
  scene.geometry = Geometry::Planar;
  scene.tvd.markerSpacing = 0.4;
  cases::Body striker, plate;
  striker.shape = cases::Disk{{0.0, 1.0}, 0.475};
  plate.shape = cases::Rect{-2.0, 2.0, 0.2, 0.355};
  scene.bodies = {striker, plate};
  const GridSpec g = makeGrid(300, 100, -2.25, 0.0, 0.015);
  const auto set = MarkerSet::fromBodies(scene, g);
  EXPECT_EQ(set.objects(), 2);
  ASSERT_EQ(set.lines().size(), 2u);
  EXPECT_EQ(set.lines()[0].object, 0);
  EXPECT_EQ(set.lines()[1].object, 1);
  EXPECT_LE(spacing(set).max, 0.4 * 0.015 * (1 + 1e-12));
  EXPECT_GT(set.area(0), 0.0);
  EXPECT_NEAR(set.area(1), 4.0 * 0.155, 1e-13);
  scene.tvd.markerSpacing = 0.0;
  EXPECT_THROW(MarkerSet::fromBodies(scene, g), InputError);
  scene.tvd.markerSpacing = 0.5;
  scene.bodies[0].shape = cases::Disk{{0.0, 1.0}, -1.0};
  EXPECT_THROW(MarkerSet::fromBodies(scene, g), InputError);
  MarkerSet s2 = set;
  EXPECT_THROW(s2.setSpacingBounds(0.3, 0.5), InputError);  // max < 2 min
}

// A checkpoint restores the set bit for bit, so a restarted run continues identically.
TEST(MarkerCheckpoint, WriteReadRoundTripIsExact) {
  const GridSpec g = makeGrid(32, 32, 0.0, 0.0, 1.0 / 32);
  Field f(g, [](Vec2 p) { return Vec2{-std::sin(pi * p.z), std::sin(pi * p.x)}; });
  auto set = MarkerSet::fromShapes({cases::Disk{{0.4, 0.6}, 0.2}, cases::Rect{0.1, 0.9, 0.1, 0.25}},
                                   g, 0.5, Geometry::Axisymmetric);
  set.setSpacingBounds(0.2, 0.9);
  for (int s = 0; s < 20; ++s) {
    set.advect(g, f.vx.data(), f.vz.data(), 0.01);
    set.redistribute(g);
  }
  std::stringstream buf;
  set.write(buf);
  MarkerSet back;
  back.read(buf);
  ASSERT_EQ(back.lines().size(), set.lines().size());
  EXPECT_EQ(back.objects(), set.objects());
  EXPECT_EQ(back.geometry(), set.geometry());
  EXPECT_EQ(back.minSpacingCells(), 0.2);
  EXPECT_EQ(back.maxSpacingCells(), 0.9);
  for (std::size_t l = 0; l < set.lines().size(); ++l) {
    EXPECT_EQ(back.lines()[l].object, set.lines()[l].object);
    EXPECT_EQ(back.lines()[l].closed, set.lines()[l].closed);
    EXPECT_EQ(back.lines()[l].points, set.lines()[l].points);
  }
  for (int s = 0; s < 20; ++s) {
    for (MarkerSet* m : {&set, &back}) {
      m->advect(g, f.vx.data(), f.vz.data(), 0.01);
      m->redistribute(g);
    }
  }
  for (std::size_t l = 0; l < set.lines().size(); ++l)
    EXPECT_EQ(back.lines()[l].points, set.lines()[l].points);

  std::stringstream junk("not a marker set at all");
  EXPECT_THROW(back.read(junk), InputError);
  std::stringstream full;
  set.write(full);
  std::stringstream cut(full.str().substr(0, full.str().size() / 2));
  EXPECT_THROW(back.read(cut), InputError);
  EXPECT_EQ(back.lines()[0].points, set.lines()[0].points);  // a failed read changes nothing
}

}  // namespace
}  // namespace hvi::tvd
