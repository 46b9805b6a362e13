//! @file Exact coverage, ownership and normals of rasterised marker lines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "helpers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {
using test::makeGrid;

double sumFraction(const std::vector<double>& f, int object, const GridSpec& g) {
  double s = 0.0;
  for (long c = 0; c < g.cells(); ++c) s += f[static_cast<std::size_t>(object * g.cells() + c)];
  return s * g.dx * g.dz;
}
double overlap1d(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// The splitting kernel: pieces tile the segment, each inside the cell it is reported in.
TEST(MarkerKernel, CellPiecesTileTheSegment) {
  const Vec2 a{0.3, 4.7}, b{7.25, -2.1};
  Vec2 last = a;
  double length = 0.0;
  int pieces = 0;
  detail::forEachCellPiece(a, b, [&](int i, int k, Vec2 p, Vec2 q) {
    EXPECT_EQ(p, last);
    for (Vec2 r : {p, q}) {
      EXPECT_GE(r.x, i - 1e-12);
      EXPECT_LE(r.x, i + 1 + 1e-12);
      EXPECT_GE(r.z, k - 1e-12);
      EXPECT_LE(r.z, k + 1 + 1e-12);
    }
    length += norm(q - p);
    last = q;
    ++pieces;
  });
  EXPECT_EQ(last, b);
  EXPECT_NEAR(length, norm(b - a), 1e-13);
  // Cells crossed: 7 vertical + 7 horizontal grid lines, plus the first cell.
  EXPECT_EQ(pieces, 15);
}

// Splitting at the grid box: a cut point lies exactly on the box line it cuts, so a sub-segment
// inside the box has no sliver beyond it. Computed as a + t d the cut used to land a rounding
// error outside, and the first cell piece of an inside sub-segment then had i or k = -1: the
// normals pass wrote before the owner array (the variant-2 TVD run to 15 us crashed on it).
TEST(MarkerKernel, BoxCutsLieExactlyOnTheBox) {
  const double nx = 150.0, nz = 162.0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  int inside = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec2 a{nx * u(rng), nz * u(rng)}, b{nx * u(rng), nz * u(rng)};
    Vec2 last = a;
    detail::splitAtBox(a, b, nx, nz, [&](Vec2 p, Vec2 q) {
      ASSERT_EQ(p, last);
      last = q;
      const Vec2 m = 0.5 * (p + q);
      if (m.x < 0.0 || m.x > nx || m.z < 0.0 || m.z > nz || p == q) return;
      ++inside;
      for (Vec2 r : {p, q}) {
        ASSERT_TRUE(r.x >= 0.0 && r.x <= nx && r.z >= 0.0 && r.z <= nz)
            << "trial " << trial << ": (" << r.x << ", " << r.z << ") outside the box";
      }
      detail::forEachCellPiece(p, q, [&](int i, int k, Vec2, Vec2) {
        ASSERT_TRUE(i >= 0 && i <= nx && k >= 0 && k <= nz) << "trial " << trial;
      });
    });
    ASSERT_EQ(last, b);
  }
  EXPECT_GT(inside, 10000);  // most random segments reach into the box
}

// A rectangle: every cell's fraction is the product of the 1-D overlaps (exact), so the only
// error is round-off in the accumulation (tolerance 1e-12 of a cell).
TEST(MarkerRasterize, RectangleFractionsExactPerCell) {
  const GridSpec g = makeGrid(50, 40, -0.1, 0.05, 0.02);
  const cases::Rect r{0.123, 0.771, 0.205, 0.5433};
  const auto set = MarkerSet::fromShapes({r}, g, 0.5, Geometry::Planar);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  double maxErr = 0.0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double x0 = g.x0 + i * g.dx, z0 = g.z0 + k * g.dz;
      const double exact = overlap1d(x0, x0 + g.dx, r.xmin, r.xmax) *
                           overlap1d(z0, z0 + g.dz, r.zmin, r.zmax) / (g.dx * g.dz);
      maxErr = std::max(maxErr, std::abs(f[static_cast<std::size_t>(k * g.nx + i)] - exact));
      EXPECT_EQ(owner[static_cast<std::size_t>(k * g.nx + i)], exact >= 0.5 - 1e-12 ? 0 : -1);
    }
  EXPECT_LT(maxErr, 1e-12);
  const double area = (r.xmax - r.xmin) * (r.zmax - r.zmin);
  EXPECT_NEAR(sumFraction(f, 0, g), area, 1e-12 * area);
  EXPECT_NEAR(set.area(0), area, 1e-14);
  std::printf("[rect] max per-cell fraction error %.2e\n", maxErr);
}

// A disk: the markers form the inscribed regular N-gon, whose area N/2 R^2 sin(2 pi / N) is
// known in closed form; the rasterised coverage must equal it to round-off.
TEST(MarkerRasterize, DiskCoverageEqualsPolygonArea) {
  const GridSpec g = makeGrid(100, 100, 0.0, 0.0, 0.01);
  const double R = 0.3;
  const auto set = MarkerSet::fromShapes({cases::Disk{{0.51, 0.47}, R}}, g, 0.5, Geometry::Planar);
  const double n = static_cast<double>(set.size());
  const double polygon = 0.5 * n * R * R * std::sin(2.0 * std::numbers::pi / n);
  EXPECT_NEAR(set.area(0), polygon, 1e-14);
  // Inscribed polygon deficit = pi R^2 (1 - sin(x)/x), x = 2 pi/n: ~ (2 pi^3/3) R^2/n^2.
  EXPECT_NEAR(polygon, std::numbers::pi * R * R, 21.0 * R * R / (n * n));
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  EXPECT_NEAR(sumFraction(f, 0, g), polygon, 1e-12 * polygon);
  // Cells well inside are full, well outside empty.
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double r = norm(Vec2{(i + 0.5) * g.dx - 0.51, (k + 0.5) * g.dz - 0.47});
      const double fc = f[static_cast<std::size_t>(k * g.nx + i)];
      if (r < R - 0.8 * g.dx) {
        EXPECT_NEAR(fc, 1.0, 1e-12);
      }
      if (r > R + 0.8 * g.dx) {
        EXPECT_EQ(fc, 0.0);
      }
    }
}

// A non-convex polygon (an arrow) partly outside the grid: the coverage is that of the part
// inside the grid, which for this shape is the polygon clipped at x = 0 (computed by hand).
TEST(MarkerRasterize, NonConvexPolygonAndClippingAtGridEdge) {
  const GridSpec g = makeGrid(37, 29, 0.0, 0.0, 0.0313);
  const cases::Polygon arrow{
      {{-0.2, 0.3}, {0.5, 0.3}, {0.5, 0.1}, {0.9, 0.45}, {0.5, 0.8}, {0.5, 0.6}, {-0.2, 0.6}}};
  const auto set = MarkerSet::fromShapes({arrow}, g, 0.5, Geometry::Planar);
  const double full = 0.7 * 0.3 + 0.5 * 0.7 * 0.4;
  EXPECT_NEAR(set.area(0), full, 1e-14);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  const double inside = full - 0.2 * 0.3;
  EXPECT_NEAR(sumFraction(f, 0, g), inside, 1e-12 * inside);
}

// An object bounded by two lines (a disk with a hole: counter-clockwise outer line, clockwise
// inner line) and a self-crossing bow tie (winding +1 and -1 lobes, nonzero rule: both count).
TEST(MarkerRasterize, HolesAndSelfIntersectionUseNonzeroWinding) {
  const GridSpec g = makeGrid(64, 64, 0.0, 0.0, 1.0 / 64);
  auto circle = [](Vec2 c, double R, int n, bool ccw) {
    std::vector<Vec2> p;
    for (int j = 0; j < n; ++j) {
      const double t = 2.0 * std::numbers::pi * j / n * (ccw ? 1.0 : -1.0);
      p.push_back(c + R * Vec2{std::cos(t), std::sin(t)});
    }
    return p;
  };
  const Vec2 c{0.5, 0.5};
  std::vector<MarkerLine> ring{{0, true, circle(c, 0.4, 400, true)},
                               {0, true, circle(c, 0.2, 200, false)}};
  const auto set = MarkerSet::fromLines(ring, 1, 0.5, Geometry::Planar);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  EXPECT_NEAR(sumFraction(f, 0, g), set.area(0), 1e-12);
  EXPECT_EQ(owner[32 * 64 + 32], -1);  // the hole
  EXPECT_EQ(owner[32 * 64 + 51], 0);   // the ring, r = 0.3
  // Cell [0.6875, 0.703] x [0.5, 0.516] is cut by the hole's rim at x = 0.7 and 80 % hole, so
  // vacuum owns it and its normal points out of the vacuum, into the ring (+x).
  EXPECT_EQ(owner[32 * 64 + 44], -1);
  EXPECT_GT(normal[32 * 64 + 44].x, 0.99);
  // Cell [0.672, 0.6875] x ... lies wholly in the ring, so it is not cut.
  EXPECT_EQ(normal[32 * 64 + 43], Vec2{});

  // Bow tie: lobes of equal area A with opposite winding; shoelace gives 0, coverage 2A.
  std::vector<MarkerLine> bow{{0, true, {{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.9}}}};
  const auto tie = MarkerSet::fromLines(bow, 1, 0.5, Geometry::Planar);
  EXPECT_NEAR(tie.area(0), 0.0, 1e-15);
  tie.rasterize(g, owner, normal, f);
  EXPECT_NEAR(sumFraction(f, 0, g), 2.0 * 0.5 * 0.8 * 0.4, 1e-12);
}

// Ownership of a cell covered half (tie: the object), slightly more, slightly less.
TEST(MarkerRasterize, HalfCoveredCellOwnership) {
  const GridSpec g = makeGrid(4, 4, 0.0, 0.0, 1.0);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  auto ownerOfCell2 = [&](double xmax) {
    const auto s =
        MarkerSet::fromShapes({cases::Rect{0.0, xmax, 0.0, 4.0}}, g, 0.5, Geometry::Planar);
    s.rasterize(g, owner, normal);
    return owner[1 * 4 + 2];
  };
  EXPECT_EQ(ownerOfCell2(2.5), 0);  // exactly half: tie goes to the object
  EXPECT_EQ(ownerOfCell2(2.5 + 1e-9), 0);
  EXPECT_EQ(ownerOfCell2(2.5 - 1e-9), -1);
  EXPECT_EQ(ownerOfCell2(2.4), -1);
  EXPECT_EQ(ownerOfCell2(2.6), 0);
}

// Normals of a rectangle's cut cells: along +-x on the vertical sides, +-z on the horizontal
// ones, out of the owner (outward where the object owns the cell, inward where vacuum does).
TEST(MarkerRasterize, RectangleNormalsAlongTheAxes) {
  const GridSpec g = makeGrid(20, 20, 0.0, 0.0, 0.1);
  const cases::Rect r{0.33, 1.56, 0.47, 1.22};  // cut cells 70, 60 % full (x); 30, 20 % (z)
  const auto set = MarkerSet::fromShapes({r}, g, 0.5, Geometry::Planar);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  set.rasterize(g, owner, normal);
  int checked = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(k * g.nx + i);
      const double x0 = i * g.dx, z0 = k * g.dz;
      auto cuts = [](double lo, double v, double d) { return v > lo && v < lo + d; };
      const bool inX = x0 + g.dx > r.xmin && x0<r.xmax, inZ = z0 + g.dz> r.zmin && z0 < r.zmax;
      const bool left = cuts(x0, r.xmin, g.dx) && inZ, right = cuts(x0, r.xmax, g.dx) && inZ;
      const bool bottom = cuts(z0, r.zmin, g.dz) && inX, top = cuts(z0, r.zmax, g.dz) && inX;
      const int nCuts = left + right + bottom + top;
      if (nCuts == 0) {
        EXPECT_EQ(normal[c], Vec2{});
        continue;
      }
      if (nCuts > 1) continue;  // corner cells: a mean of two directions
      const double s = owner[c] == 0 ? 1.0 : -1.0;
      const Vec2 expected = left     ? Vec2{-s, 0}
                            : right  ? Vec2{s, 0}
                            : bottom ? Vec2{0, -s}
                                     : Vec2{0, s};
      EXPECT_NEAR(normal[c].x, expected.x, 1e-14) << i << "," << k;
      EXPECT_NEAR(normal[c].z, expected.z, 1e-14) << i << "," << k;
      ++checked;
    }
  EXPECT_EQ(checked, 2 * (7 + 11));  // rows 5..11 on each vertical side, columns 4..14
  // Corner cell (3, 4): owned by vacuum (21 % covered), cut by the bottom side (0.07 long) and
  // the left side (0.03 long): the mean of their outward normals, reversed.
  const Vec2 nc = normal[4 * 20 + 3];
  const double lx = 0.4 - 0.33, lz = 0.5 - 0.47;       // bottom piece length, left piece length
  const Vec2 e = Vec2{-lz, -lx} / norm(Vec2{lz, lx});  // owner is vacuum here: sign -1
  EXPECT_NEAR(nc.x, -e.x, 1e-13);
  EXPECT_NEAR(nc.z, -e.z, 1e-13);
}

// Two rectangles pressed together along x = 0.5, a face that halves a column of cells: owners
// are disjoint, no vacuum gap opens between them, the tie column goes to the lower index, and
// the normal there points from the owner into its neighbour.
TEST(MarkerRasterize, TouchingRectanglesGiveDisjointOwners) {
  const GridSpec g = makeGrid(25, 25, 0.0, 0.0, 0.04);
  const cases::Rect a{0.1, 0.5, 0.2, 0.6}, b{0.5, 0.9, 0.2, 0.6};
  const auto set = MarkerSet::fromShapes({a, b}, g, 0.5, Geometry::Planar);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  int countA = 0, countB = 0;
  for (int k = 5; k < 15; ++k)  // rows wholly inside z in [0.2, 0.6]
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(k * g.nx + i);
      const double xc = (i + 0.5) * g.dx;
      if (i != 12 && xc > 0.1 && xc < 0.5) {
        EXPECT_EQ(owner[c], 0);
      }
      if (i != 12 && xc > 0.5 && xc < 0.9) {
        EXPECT_EQ(owner[c], 1);
      }
      if (i == 12) {  // x in [0.48, 0.52]: half and half
        EXPECT_NEAR(f[c], 0.5, 1e-12);
        EXPECT_NEAR(f[static_cast<std::size_t>(g.cells()) + c], 0.5, 1e-12);
        EXPECT_EQ(owner[c], 0);
        EXPECT_NEAR(normal[c].x, 1.0, 1e-14);
      }
      countA += owner[c] == 0;
      countB += owner[c] == 1;
      EXPECT_FALSE(f[c] > 0.0 && f[static_cast<std::size_t>(g.cells()) + c] > 0.0 && i != 12);
    }
  // A: columns 2 (half A, half vacuum: tie to A) to 12 (half A, half B: tie to A) = 11;
  // B: columns 13 to 22 (half B, half vacuum) = 10; 10 rows.
  EXPECT_EQ(countA, 10 * 11);
  EXPECT_EQ(countB, 10 * 10);
}

// Overlapping disks (two media pressed through each other): each object's coverage is still
// its own area, and every cell goes to the largest of the object and vacuum fractions.
TEST(MarkerRasterize, OverlapResolvedByLargestArea) {
  const GridSpec g = makeGrid(80, 60, 0.0, 0.0, 0.0125);
  const auto set = MarkerSet::fromShapes(
      {cases::Disk{{0.35, 0.37}, 0.22}, cases::Disk{{0.62, 0.4}, 0.2}}, g, 0.5, Geometry::Planar);
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> f;
  set.rasterize(g, owner, normal, f);
  EXPECT_NEAR(sumFraction(f, 0, g), set.area(0), 1e-12);
  EXPECT_NEAR(sumFraction(f, 1, g), set.area(1), 1e-12);
  int contested = 0;
  for (long c = 0; c < g.cells(); ++c) {
    const double f0 = f[static_cast<std::size_t>(c)];
    const double f1 = f[static_cast<std::size_t>(g.cells() + c)];
    const double vac = std::max(0.0, 1.0 - f0 - f1);
    const int o = owner[static_cast<std::size_t>(c)];
    const double fo = o == 0 ? f0 : o == 1 ? f1 : vac;
    EXPECT_GE(fo + 1e-12, std::max({f0, f1, vac})) << c;
    contested += f0 > 0.0 && f1 > 0.0;
  }
  EXPECT_GT(contested, 50);
}

// The cut-cell mode's form (rasterizeFractions: no normals, owners from the fractions in one
// pass, arrays per object written in place) gives the owners and fractions of rasterize bit for
// bit, ties included: overlapping disks (cells two objects share), a rectangle whose edge halves
// a column of cells (the object/vacuum tie) and one whose edge meets another's (object ties).
TEST(MarkerRasterize, FractionsFormMatchesTheFullForm) {
  const GridSpec g = makeGrid(40, 48, 0.0, 0.0, 0.025);
  auto shapes = [](double shift) {
    return std::vector<cases::Shape>{cases::Disk{{0.40 + shift, 0.50}, 0.21},
                                     cases::Disk{{0.62 + shift, 0.55}, 0.17},
                                     cases::Rect{0.1125 + shift, 0.35 + shift, 0.05, 0.30},
                                     cases::Rect{0.35 + shift, 0.70 + shift, 0.05, 0.30}};
  };
  std::vector<std::vector<double>> lent;  // the in-place buffers, kept across the two sets
  for (const double shift : {0.0, 0.0375}) {
    const auto set = MarkerSet::fromShapes(shapes(shift), g, 0.5, Geometry::Planar);
    std::vector<int> owner, ownerF;
    std::vector<Vec2> normal;
    std::vector<double> f;
    set.rasterize(g, owner, normal, f);
    std::vector<std::vector<double>> fresh;
    set.rasterizeFractions(g, ownerF, fresh, 0, g.nz);
    int lo = 0, hi = 0;
    set.rowSpan(g, lo, hi);
    set.rasterizeFractions(g, ownerF, lent, lo, hi);  // the second set: over the first's
    ASSERT_EQ(fresh.size(), 4u);
    ASSERT_EQ(lent.size(), 4u);
    int shared = 0;
    for (long c = 0; c < g.cells(); ++c) {
      const auto cc = static_cast<std::size_t>(c);
      int objects = 0;
      for (std::size_t o = 0; o < 4; ++o) {
        const double full = f[o * static_cast<std::size_t>(g.cells()) + cc];
        EXPECT_EQ(fresh[o][cc], full) << "object " << o << " cell " << c;
        EXPECT_EQ(lent[o][cc], full) << "object " << o << " cell " << c;
        objects += full > 0.0 ? 1 : 0;
      }
      shared += objects > 1 ? 1 : 0;
      EXPECT_EQ(ownerF[cc], owner[cc]) << "cell " << c;
    }
    EXPECT_GT(shared, 20);  // the overlaps the tie rules decide are there
  }
}

}  // namespace
}  // namespace hvi::tvd
