//! @file A line stretched into a tangle (a debris cloud's spray) is coarsened, not refused
//! (MarkerSet::checkGrowth; docs/markers.md, "Lines stretched into a tangle").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "helpers.hpp"

namespace hvi::tvd {
namespace {
using test::makeGrid;

// A comb: a bar 0.8 x 0.1 cm with 1000 teeth 0.8 cm tall and 0.0004 cm wide (a twenty-fifth of
// a cell) on a 100 x 100 grid of 0.01 cm cells. At the 0.5-cell spacing its 1 600 cm of outline
// holds ~320 000 points, above the budget of 16 per cell plus 65 536 (225 536). The
// redistribution must coarsen the line (double its spacings) until it is under half the budget,
// instead of stopping the run, and keep the area it encloses: the collapse of short edges is
// area-preserving (each collapsed pair becomes one point on the chord that keeps the area) and
// the splits put points on the segments, so only round-off and the collapses that fall back to a
// midpoint (a needle whose neighbours almost coincide) change it: measured 1e-7 of the area;
// bound 1e-4 (the teeth hold 0.32 of it; a fallback moves at most a sliver of a tooth).
TEST(MarkerGrowth, TangledLineIsCoarsenedAndKeepsItsArea) {
  const GridSpec g = makeGrid(100, 100, 0.0, 0.0, 0.01);
  MarkerLine comb;
  comb.object = 0;
  const int teeth = 1000;
  const double x0 = 0.1, width = 0.8, base = 0.05, top = 0.9, pitch = width / teeth, tooth = 0.0004;
  comb.points.push_back({x0, base});
  comb.points.push_back({x0 + width, base});
  // The teeth's sides already hold points at the marker spacing (0.005 cm), as a line the flow
  // stretched does: the redistribution cannot thin them by splitting less.
  const int along = static_cast<int>(std::lround((top - 0.1) / 0.005));
  for (int t = teeth - 1; t >= 0; --t) {  // counter-clockwise: along the top from right to left
    const double xr = x0 + (t + 1) * pitch, xl = xr - tooth;
    for (int q = 0; q < along; ++q) comb.points.push_back({xr, 0.1 + q * 0.005});
    comb.points.push_back({xr, top});
    for (int q = along; q > 0; --q) comb.points.push_back({xl, 0.1 + q * 0.005});
    comb.points.push_back({xl, 0.1});
  }
  // A plate beside it (object 1): only the tangle is coarsened. (A first version counted a
  // stretched line's present points, which no spacing reduces, and so coarsened every line to
  // the limit: the Whipple rear wall became a decagon and the run stopped on a NaN.)
  MarkerLine plate;
  plate.object = 1;
  plate.points = {{0.1, 0.92}, {0.9, 0.92}, {0.9, 0.98}, {0.1, 0.98}};
  MarkerSet set = MarkerSet::fromLines({comb, plate}, 2, 0.5, Geometry::Planar);
  const double area0 = set.area(0);
  ASSERT_GT(area0, 0.0);
  ASSERT_NO_THROW(set.redistribute(g));
  const std::size_t budget = 16 * static_cast<std::size_t>(g.cells()) + (std::size_t{1} << 16);
  std::printf("  %zu points after (budget %zu), scale %.0f, %ld coarsenings, area %.6e -> %.6e\n",
              set.size(), budget, set.largestScale(), set.coarsenings(), area0, set.area(0));
  EXPECT_GT(set.largestScale(), 1.0);
  EXPECT_LE(set.size(), budget / 2);
  EXPECT_NEAR(set.area(0), area0, 1e-4 * area0);
  for (const MarkerLine& l : set.lines())
    if (l.object == 1) {
      EXPECT_EQ(l.scale, 1.0);
      EXPECT_GE(l.points.size(), 1.72 / 0.01);  // its 1.72 cm at most a cell apart
    }
  // The scale is part of the line: a checkpoint restores it, and the next redistribution keeps
  // the count (no growth, no second coarsening).
  std::stringstream ss;
  set.write(ss);
  MarkerSet back;
  back.read(ss);
  EXPECT_EQ(back.largestScale(), set.largestScale());
  const std::size_t n = set.size();
  back.redistribute(g);
  EXPECT_EQ(back.size(), n);
  EXPECT_EQ(back.coarsenings(), 0);
}

}  // namespace
}  // namespace hvi::tvd
