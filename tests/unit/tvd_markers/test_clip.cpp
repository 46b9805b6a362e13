//! @file Cutting marker lines at outflow sides (MarkerSet::clipToSides; docs/markers.md,
//! "Cutting at outflow sides"). Clipping a closed polygon to the grid's half-planes does not
//! change the region inside the grid, so every cell fraction and every face aperture seen from
//! inside must be what it was to round-off, while no point is left beyond a cut side.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "helpers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {
using test::makeGrid;
using test::spacing;

// Fractions and the apertures seen from inside the grid (the boundary faces from their cell).
struct Coverage {
  std::vector<double> fraction, ax, az;
};
Coverage coverage(const MarkerSet& s, const GridSpec& g) {
  Coverage c;
  std::vector<int> owner;
  std::vector<Vec2> normal;
  s.rasterize(g, owner, normal, c.fraction);
  FaceApertures fa;
  s.faceApertures(g, fa);
  for (int o = 0; o < s.objects(); ++o)
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i <= g.nx; ++i) c.ax.push_back(fa.ax(o, i == g.nx ? 0 : 1, i, k));
  for (int o = 0; o < s.objects(); ++o)
    for (int k = 0; k <= g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) c.az.push_back(fa.az(o, k == g.nz ? 0 : 1, i, k));
  return c;
}

double worstDiff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double w = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) w = std::max(w, std::abs(a[j] - b[j]));
  return w;
}

// Planar: a disk across the xmax/zmax corner, a U-shaped polygon (non-convex) whose two arms
// cross the zmax side and whose base crosses the xmin side, and a ring (a clockwise hole)
// across zmin. The cut sides are xmin, xmax, zmax and zmin; every point ends inside, every line
// keeps its orientation, the fractions and apertures are unchanged to 1e-13 of a cell, and the
// area of each object equals the area the rasterisation covers inside the grid.
TEST(MarkerClip, CutsExactlyAtOutflowSides) {
  const GridSpec g = makeGrid(24, 20, -1.2, -1.0, 0.1);
  const double x1 = g.x0 + g.nx * g.dx, z1 = g.z0 + g.nz * g.dz;
  std::vector<MarkerLine> lines;
  {
    MarkerLine disk{0, true, {}};
    for (int j = 0; j < 96; ++j) {
      const double t = 2.0 * std::numbers::pi * j / 96;
      disk.points.push_back({1.0 + 0.43 * std::cos(t), 0.85 + 0.43 * std::sin(t)});
    }
    lines.push_back(disk);
    // U: counter-clockwise, arms up through z1 = 1.0, base through x0 = -1.2.
    lines.push_back(MarkerLine{1,
                               true,
                               {{-1.43, -0.37},
                                {0.21, -0.37},
                                {0.21, 1.33},
                                {0.03, 1.33},
                                {0.03, 0.17},
                                {-0.61, 0.17},
                                {-0.61, 1.27},
                                {-0.77, 1.27},
                                {-0.77, -0.11},
                                {-1.43, -0.11}}});
    // Ring across zmin: outer counter-clockwise, hole clockwise.
    MarkerLine outer{2, true, {}}, hole{2, true, {}};
    for (int j = 0; j < 64; ++j) {
      const double t = 2.0 * std::numbers::pi * j / 64;
      outer.points.push_back({0.55 + 0.33 * std::cos(t), -0.93 + 0.33 * std::sin(t)});
      hole.points.push_back({0.55 + 0.17 * std::cos(-t), -0.93 + 0.17 * std::sin(-t)});
    }
    lines.push_back(outer);
    lines.push_back(hole);
  }
  MarkerSet s = MarkerSet::fromLines(lines, 3, 0.5, Geometry::Planar);
  std::vector<double> sign;
  for (const auto& l : s.lines())
    sign.push_back(std::copysign(1.0, detail::twiceSignedArea(l.points)));
  const Coverage before = coverage(s, g);
  EXPECT_EQ(s.clipToSides(g, {true, true, true, true}), 0);
  ASSERT_EQ(s.lines().size(), 4u);
  for (std::size_t l = 0; l < s.lines().size(); ++l) {
    EXPECT_EQ(std::copysign(1.0, detail::twiceSignedArea(s.lines()[l].points)), sign[l])
        << "line " << l;
    for (Vec2 p : s.lines()[l].points) {
      EXPECT_GE(p.x, g.x0);
      EXPECT_LE(p.x, x1);
      EXPECT_GE(p.z, g.z0);
      EXPECT_LE(p.z, z1);
    }
  }
  const Coverage after = coverage(s, g);
  EXPECT_LT(worstDiff(before.fraction, after.fraction), 1e-13);
  EXPECT_LT(worstDiff(before.ax, after.ax), 1e-13);
  EXPECT_LT(worstDiff(before.az, after.az), 1e-13);
  // Each object's area is now exactly what the grid covers of it.
  const double cell = g.dx * g.dz;
  for (int o = 0; o < 3; ++o) {
    double inGrid = 0.0;
    for (long c = 0; c < g.cells(); ++c)
      inGrid += after.fraction[static_cast<std::size_t>(o * g.cells() + c)];
    EXPECT_NEAR(s.area(o), inGrid * cell, 1e-13 * g.cells() * cell) << "object " << o;
  }
  // A second cut changes nothing.
  const std::vector<MarkerLine> once = s.lines();
  EXPECT_EQ(s.clipToSides(g, {true, true, true, true}), 0);
  for (std::size_t l = 0; l < once.size(); ++l) EXPECT_EQ(s.lines()[l].points, once[l].points);
  // The redistribution then keeps the spacing bounds with the cut's short edges.
  s.redistribute(g);
  const auto sp = spacing(s);
  EXPECT_GE(sp.min, s.minSpacingCells() * g.dx * (1.0 - 1e-12));
  EXPECT_LE(sp.max, s.maxSpacingCells() * g.dx * (1.0 + 1e-12));
}

// Only the sides asked for are cut, and a line with nothing left inside them is removed.
TEST(MarkerClip, RemovesALineThatLeftAndKeepsOtherSides) {
  const GridSpec g = makeGrid(10, 10, 0.0, 0.0, 0.1);
  MarkerSet s =
      MarkerSet::fromShapes({cases::Rect{0.2, 0.4, 1.05, 1.3}, cases::Rect{0.5, 1.2, 0.3, 0.5}}, g,
                            0.5, Geometry::Planar);
  // xmax not cut: the second rectangle keeps its part beyond x = 1.
  EXPECT_EQ(s.clipToSides(g, {true, false, true, true}), 1);
  ASSERT_EQ(s.lines().size(), 1u);
  EXPECT_EQ(s.lines()[0].object, 1);
  EXPECT_NEAR(s.area(0), 0.0, 0.0);
  EXPECT_NEAR(s.area(1), 0.7 * 0.2, 1e-15);
}

// r-z: a half-disk on the axis across zmax (the axis side xmin is never an outflow side). The
// points on the axis keep x = 0 exactly (a cut point of an edge along the axis too), the part
// inside keeps its area as the rasterisation covers it, and the fractions are unchanged.
TEST(MarkerClip, AxisPointsStayOnTheAxisInRz) {
  const GridSpec g = makeGrid(12, 16, 0.0, -0.8, 0.1);
  const double z1 = g.z0 + g.nz * g.dz;
  MarkerSet s =
      MarkerSet::fromShapes({cases::Disk{{0.0, 0.62}, 0.41}}, g, 0.5, Geometry::Axisymmetric);
  int onAxis = 0;
  for (Vec2 p : s.lines()[0].points) onAxis += p.x == 0.0 && p.z <= z1;
  const Coverage before = coverage(s, g);
  EXPECT_EQ(s.clipToSides(g, {false, true, true, true}), 0);
  const Coverage after = coverage(s, g);
  EXPECT_LT(worstDiff(before.fraction, after.fraction), 1e-13);
  EXPECT_LT(worstDiff(before.az, after.az), 1e-13);
  int onAxisAfter = 0;
  for (Vec2 p : s.lines()[0].points) {
    EXPECT_LE(p.z, z1);
    EXPECT_GE(p.x, 0.0);
    onAxisAfter += p.x == 0.0;
  }
  EXPECT_EQ(onAxisAfter, onAxis + 1);  // the axis edge's cut point at z1, at x = 0 exactly
  // The half-disk's part below z1: the segment of a circle (the marker polygon inscribed).
  double inGrid = 0.0;
  for (double f : after.fraction) inGrid += f;
  EXPECT_NEAR(s.area(0), inGrid * g.dx * g.dz, 1e-13);
  EXPECT_GT(s.area(0), 0.0);
}

}  // namespace
}  // namespace hvi::tvd
