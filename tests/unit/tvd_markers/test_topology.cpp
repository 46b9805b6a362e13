//! @file The topology policy: thin sheets, specks and self-crossing lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "helpers.hpp"

namespace hvi::tvd {
namespace {
using test::Field;
using test::makeGrid;
using test::spacing;

// A sheet thinner than half a cell inside one row of cells is represented by its markers but
// owns no cell (vacuum covers more of every cell); its two faces cut the same cells with
// opposite normals, which cancel, so those cells report no direction. At 0.6 cell thickness it
// owns the row.
TEST(MarkerTopology, ThinSheetRasterisesToVacuumOrOneRow) {
  const GridSpec g = makeGrid(20, 10, 0.0, 0.0, 0.1);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  const auto thin =
      MarkerSet::fromShapes({cases::Rect{0.25, 1.75, 0.42, 0.45}}, g, 0.5, Geometry::Planar);
  thin.rasterize(g, owner, normal, f);
  for (long c = 0; c < g.cells(); ++c) EXPECT_EQ(owner[static_cast<std::size_t>(c)], -1);
  for (int i = 3; i < 17; ++i) {  // interior of the sheet, row 4
    EXPECT_NEAR(f[static_cast<std::size_t>(4 * g.nx + i)], 0.3, 1e-12);
    EXPECT_EQ(normal[static_cast<std::size_t>(4 * g.nx + i)], Vec2{});
  }
  const auto thick =
      MarkerSet::fromShapes({cases::Rect{0.25, 1.75, 0.42, 0.48}}, g, 0.5, Geometry::Planar);
  thick.rasterize(g, owner, normal);
  for (int i = 3; i < 17; ++i) EXPECT_EQ(owner[static_cast<std::size_t>(4 * g.nx + i)], 0);
}

// Redistribution deletes a closed line whose area is below tinyLoopCells of a cell and which
// fits in 2 x 2 cells (a speck that can never own a cell), and keeps a long thin line of the
// same small area (a filament that may still matter to its neighbours' normals).
TEST(MarkerTopology, SpecksAreRemovedFilamentsKept) {
  const GridSpec g = makeGrid(50, 50, 0.0, 0.0, 0.02);
  const double c = g.dx;
  std::vector<MarkerLine> lines{
      {0,
       true,
       {{0.5, 0.5}, {0.5 + 0.2 * c, 0.5}, {0.5 + 0.2 * c, 0.5 + 0.2 * c}, {0.5, 0.5 + 0.2 * c}}},
      {0, true, {{0.1, 0.2}, {0.9, 0.2}, {0.9, 0.2 + 0.001 * c}, {0.1, 0.2 + 0.001 * c}}},
      {1, true, {{0.2, 0.6}, {0.4, 0.6}, {0.4, 0.8}, {0.2, 0.8}}}};
  auto set = MarkerSet::fromLines(lines, 2, 0.5, Geometry::Planar);
  set.redistribute(g);
  ASSERT_EQ(set.lines().size(), 2u);
  EXPECT_EQ(set.lines()[0].object, 0);
  // Its two end caps (width w below the minimum spacing) each collapse to a point; where the
  // area-preserving position would move the point by more than the minimum spacing the
  // midpoint is used, losing at most a triangle of base w and height max spacing per end.
  const double w = 0.001 * c;
  EXPECT_NEAR(set.area(0), 0.8 * w, w * set.maxSpacingCells() * c);
  EXPECT_NEAR(set.area(1), 0.04, 1e-15);
  const auto sp = spacing(set);
  EXPECT_LE(sp.max, set.maxSpacingCells() * c);
  EXPECT_GE(sp.min, set.minSpacingCells() * c);
  EXPECT_GE(set.lines()[0].points.size(),
            2 * static_cast<std::size_t>(0.8 / (set.maxSpacingCells() * c)));
}

// Lines are never reconnected: two disks pushed through each other by opposite uniform flows
// keep their own lines (crossing each other), each object's area stays exact, and the
// crossing region goes to whichever object covers more of each cell.
TEST(MarkerTopology, CrossingLinesAreNotReconnected) {
  const GridSpec g = makeGrid(60, 40, 0.0, 0.0, 0.025);
  auto set = MarkerSet::fromShapes({cases::Disk{{0.5, 0.5}, 0.2}, cases::Disk{{1.0, 0.5}, 0.2}}, g,
                                   0.5, Geometry::Planar);
  const double a0 = set.area(0), a1 = set.area(1);
  // Velocity +x on the left half, -x on the right: the disks overlap by 0.2 cm after t = 0.2.
  Field f(g, [](Vec2 p) { return Vec2{p.x < 0.75 ? 0.5 : -0.5, 0.0}; });
  for (int s = 0; s < 20; ++s) {
    set.advect(g, f.vx.data(), f.vz.data(), 0.01);
    set.redistribute(g);
  }
  EXPECT_EQ(set.lines().size(), 2u);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> frac;
  set.rasterize(g, owner, normal, frac);
  double s0 = 0.0, s1 = 0.0;
  for (long c = 0; c < g.cells(); ++c) {
    s0 += frac[static_cast<std::size_t>(c)];
    s1 += frac[static_cast<std::size_t>(g.cells() + c)];
  }
  EXPECT_NEAR(s0 * g.dx * g.dz, set.area(0), 1e-12);
  EXPECT_NEAR(s1 * g.dx * g.dz, set.area(1), 1e-12);
  // The flow is piecewise uniform away from x = 0.75, so the areas change only where the
  // disks cross the velocity jump (there the interpolated field compresses them).
  EXPECT_LT(set.area(0), a0);
  EXPECT_LT(set.area(1), a1);
}

}  // namespace
}  // namespace hvi::tvd
