//! @file Exact one-sided face apertures of marker objects (MarkerSet::faceApertures), checked
//! against analytic chords and, through the divergence theorem, against rasterize's fractions.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "helpers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {
using test::makeGrid;

Vec2 toCm(const GridSpec& g, Vec2 c) { return {g.x0 + c.x * g.dx, g.z0 + c.z * g.dz}; }
double overlap1d(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

//! An axis-aligned rectangle in cell units; sign +1: counter-clockwise line (winding +1 inside),
//! -1: clockwise (a hole, winding -1 inside).
struct CellRect {
  double u0, u1, w0, w1;
  int sign = 1;
};

MarkerLine rectLine(const GridSpec& g, const CellRect& r, int object = 0) {
  std::vector<Vec2> p{{r.u0, r.w0}, {r.u1, r.w0}, {r.u1, r.w1}, {r.u0, r.w1}};
  if (r.sign < 0) std::reverse(p.begin(), p.end());
  MarkerLine l{object, true, {}};
  for (Vec2 c : p) l.points.push_back(toCm(g, c));
  return l;
}

//! The exact aperture of a face on the line across = c (vertical if `vertical`), face [f, f+1]
//! along it, for the union by winding of rectangles: a rectangle covers the line's one-sided
//! limit from below (side 0) if u0 < c <= u1, from above (side 1) if u0 <= c < u1, and then
//! adds its sign on [w0, w1] along the line; the face is wet where the sum is nonzero. Found by
//! brute force over the breakpoints, independent of the sweep in the library.
double rectAperture(const std::vector<CellRect>& rects, bool vertical, int side, double c, int f) {
  std::vector<double> cuts{static_cast<double>(f), f + 1.0};
  struct Span {
    double a, b;
    int sign;
  };
  std::vector<Span> spans;
  for (const CellRect& r : rects) {
    const double lo = vertical ? r.u0 : r.w0, hi = vertical ? r.u1 : r.w1;
    const bool in = side == 0 ? (lo < c && c <= hi) : (lo <= c && c < hi);
    if (!in) continue;
    const double a = vertical ? r.w0 : r.u0, b = vertical ? r.w1 : r.u1;
    spans.push_back({a, b, r.sign});
    for (double v : {a, b})
      if (v > f && v < f + 1.0) cuts.push_back(v);
  }
  std::sort(cuts.begin(), cuts.end());
  double wet = 0.0;
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
    const double m = 0.5 * (cuts[j] + cuts[j + 1]);
    int w = 0;
    for (const Span& s : spans)
      if (s.a < m && m < s.b) w += s.sign;
    if (w != 0) wet += cuts[j + 1] - cuts[j];
  }
  return wet;
}

//! Every aperture of object 0 against rectAperture, within tol.
void expectRectApertures(const FaceApertures& ap, const std::vector<CellRect>& rects, double tol) {
  for (int side = 0; side < 2; ++side) {
    for (int k = 0; k < ap.nz; ++k)
      for (int i = 0; i <= ap.nx; ++i)
        ASSERT_NEAR(ap.ax(0, side, i, k), rectAperture(rects, true, side, i, k), tol)
            << "x face i " << i << " k " << k << " side " << side;
    for (int k = 0; k <= ap.nz; ++k)
      for (int i = 0; i < ap.nx; ++i)
        ASSERT_NEAR(ap.az(0, side, i, k), rectAperture(rects, false, side, k, i), tol)
            << "z face i " << i << " k " << k << " side " << side;
  }
}

//! Divergence theorem over the part of cell (i, k) inside a simple object (winding 0 or 1), in
//! cell units, with the fields (u - i, 0), (u - i - 1, 0), (0, w - k), (0, w - k - 1): each
//! vanishes on one face, is 1 or -1 on the opposite one, and has zero flux through the two
//! faces parallel to it, so the area fraction f is
//!   f = ax(side 0, i+1, k) + sum over pieces in [i, i+1) x [k, k+1) of (um - i) dw
//!     = ax(side 1, i, k)   + sum over pieces in (i, i+1] x [k, k+1) of (um - i - 1) dw
//!     = az(side 0, i, k+1) - sum over pieces in [i, i+1) x [k, k+1) of (wm - k) du
//!     = az(side 1, i, k)   - sum over pieces in [i, i+1) x (k, k+1] of (wm - k - 1) du
//! (the outward normal times length of a piece is (dw, -du); pieces have straight ends, so the
//! midpoint rule is exact). A piece on a face belongs to the cell whose weight vanishes there or
//! to the neighbour: the one-sided aperture already counts it. The face is seen from the cell's
//! side in every identity, so a side or sign error fails one of them. f comes from rasterize.
//! Tolerance 1e-12: rasterize's row prefix sums and the piece sums each add a few rounding
//! errors of the coordinates (<= ~50 cells, eps 2.2e-16) per piece, far below 1e-12.
void expectDivergenceIdentities(const MarkerSet& set, const GridSpec& g, const FaceApertures& ap,
                                int object) {
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> fraction;
  set.rasterize(g, owner, normal, fraction);
  const auto cells = static_cast<std::size_t>(g.cells());
  std::vector<double> right(cells), left(cells), top(cells), bottom(cells);
  auto add = [&](std::vector<double>& s, double i, double k, double v) {
    if (i < 0 || i >= g.nx || k < 0 || k >= g.nz) return;
    s[static_cast<std::size_t>(k) * g.nx + static_cast<std::size_t>(i)] += v;
  };
  for (const auto& l : set.lines()) {
    if (l.object != object) continue;
    const std::size_t n = l.points.size();
    for (std::size_t j = 0; j < n; ++j) {
      const Vec2 a = detail::toCellUnits(g, l.points[j]);
      const Vec2 b = detail::toCellUnits(g, l.points[(j + 1) % n]);
      if (a == b) continue;
      detail::forEachCellPiece(a, b, [&](int, int, Vec2 p, Vec2 q) {
        const double um = 0.5 * (p.x + q.x), wm = 0.5 * (p.z + q.z);
        const double du = q.x - p.x, dw = q.z - p.z;
        const double fi = std::floor(um), fk = std::floor(wm);
        const double ci = std::ceil(um) - 1.0, ck = std::ceil(wm) - 1.0;
        add(right, fi, fk, (um - fi) * dw);
        add(left, ci, fk, (um - ci - 1.0) * dw);
        add(top, fi, fk, -(wm - fk) * du);
        add(bottom, fi, ck, -(wm - ck - 1.0) * du);
      });
    }
  }
  int nonTrivial = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(k) * g.nx + i;
      const double f = fraction[static_cast<std::size_t>(object) * cells + c];
      if (f > 0.0 && f < 1.0) ++nonTrivial;
      ASSERT_NEAR(f, ap.ax(object, 0, i + 1, k) + right[c], 1e-12)
          << "right, cell " << i << " " << k;
      ASSERT_NEAR(f, ap.ax(object, 1, i, k) + left[c], 1e-12) << "left, cell " << i << " " << k;
      ASSERT_NEAR(f, ap.az(object, 0, i, k + 1) + top[c], 1e-12) << "top, cell " << i << " " << k;
      ASSERT_NEAR(f, ap.az(object, 1, i, k) + bottom[c], 1e-12) << "bottom, cell " << i << " " << k;
    }
  EXPECT_GT(nonTrivial, 0) << "no cut cell: the identities tested only full and empty cells";
}

// A square whose edges lie exactly on grid lines (dyadic grid: all coordinates exact). The
// apertures are exactly 1 on the inside limit and 0 on the outside limit of its edge faces, 1 on
// both sides of interior faces, 0 elsewhere; exact (no arithmetic produces a wet length other
// than whole faces). Both as 4 corners and as fromShapes' subdivided rectangle (markers on the
// edges, some exactly on grid lines), and for the rasterize identities (cells wholly in or out).
TEST(MarkerApertures, SquareOnGridLinesIsOneSided) {
  const GridSpec g = makeGrid(8, 9, -1.0, 2.0, 0.25);
  const CellRect r{2.0, 5.0, 1.0, 4.0};
  const auto corners = MarkerSet::fromLines({rectLine(g, r)}, 1, 0.5, Geometry::Planar);
  const auto split = MarkerSet::fromShapes(
      {cases::Rect{toCm(g, {2, 1}).x, toCm(g, {5, 1}).x, toCm(g, {2, 1}).z, toCm(g, {2, 4}).z}}, g,
      0.3, Geometry::Planar);
  ASSERT_GT(split.size(), 30u);
  for (const MarkerSet* set : {&corners, &split}) {
    FaceApertures ap;
    set->faceApertures(g, ap);
    ASSERT_EQ(ap.nx, 8);
    ASSERT_EQ(ap.nz, 9);
    ASSERT_EQ(ap.objects, 1);
    ASSERT_EQ(ap.x.size(), 2u * 9 * 9);
    ASSERT_EQ(ap.z.size(), 2u * 10 * 8);
    for (int side = 0; side < 2; ++side) {
      for (int k = 0; k < 9; ++k)
        for (int i = 0; i <= 8; ++i) {
          const bool across = side == 0 ? (i > 2 && i <= 5) : (i >= 2 && i < 5);
          EXPECT_EQ(ap.ax(0, side, i, k), across && k >= 1 && k < 4 ? 1.0 : 0.0)
              << "x face " << i << " " << k << " side " << side;
        }
      for (int k = 0; k <= 9; ++k)
        for (int i = 0; i < 8; ++i) {
          const bool across = side == 0 ? (k > 1 && k <= 4) : (k >= 1 && k < 4);
          EXPECT_EQ(ap.az(0, side, i, k), across && i >= 2 && i < 5 ? 1.0 : 0.0)
              << "z face " << i << " " << k << " side " << side;
        }
    }
    // The edges, named: the left edge x face (i = 2) is wet from cell 2 (side 1) only, the top
    // edge z face (k = 4) from cell 3 (side 0) only.
    EXPECT_EQ(ap.ax(0, 0, 2, 2), 0.0);
    EXPECT_EQ(ap.ax(0, 1, 2, 2), 1.0);
    EXPECT_EQ(ap.az(0, 0, 3, 4), 1.0);
    EXPECT_EQ(ap.az(0, 1, 3, 4), 0.0);
    expectRectApertures(ap, {r}, 0.0);
  }
}

// A square offset by fractions of a cell on a non-dyadic grid: the apertures are the overlaps of
// the chord [w0, w1] (or [u0, u1]) with each face. Tolerance 1e-13: the only error is the
// conversion of the corners to cm and back to cells (a few ulps of ~6 cells, ~1e-15) and one
// subtraction per face.
TEST(MarkerApertures, OffsetSquareGivesExactChords) {
  const GridSpec g = makeGrid(7, 8, -0.4, 0.3, 0.2);
  const CellRect r{1.3, 4.55, 2.2, 5.7};
  const auto set = MarkerSet::fromLines({rectLine(g, r)}, 1, 0.5, Geometry::Planar);
  FaceApertures ap;
  set.faceApertures(g, ap);
  expectRectApertures(ap, {r}, 1e-13);
  EXPECT_NEAR(ap.ax(0, 0, 2, 2), 0.8, 1e-13);   // face [2, 3] of the chord [2.2, 5.7]
  EXPECT_NEAR(ap.az(0, 1, 4, 5), 0.55, 1e-13);  // face [4, 5] of the chord [1.3, 4.55]
  expectDivergenceIdentities(set, g, ap, 0);
}

//! Chord of the square of centre c, half side s, rotated by th (cell units) on the line
//! across = v: the intersection of the two slabs |(p - c).e1| <= s, |(p - c).e2| <= s along the
//! line, e1 = (cos th, sin th), e2 = (-sin th, cos th) (0 < th < pi/2).
std::pair<double, double> rotatedSquareChord(Vec2 c, double s, double th, bool vertical, double v) {
  const double co = std::cos(th), si = std::sin(th);
  if (vertical) {  // p = (v, w): (v-cx) co + (w-cz) si and -(v-cx) si + (w-cz) co in [-s, s]
    const double d = v - c.x;
    return {c.z + std::max((-s - d * co) / si, (-s + d * si) / co),
            c.z + std::min((s - d * co) / si, (s + d * si) / co)};
  }
  const double d = v - c.z;  // p = (u, w = v)
  return {c.x + std::max((-s - d * si) / co, (d * co - s) / si),
          c.x + std::min((s - d * si) / co, (d * co + s) / si)};
}

void expectRotatedSquare(const GridSpec& g, Vec2 c, double s, double th, double tol) {
  std::vector<Vec2> p;
  for (Vec2 q : {Vec2{-s, -s}, Vec2{s, -s}, Vec2{s, s}, Vec2{-s, s}})
    p.push_back(toCm(g, c + Vec2{q.x * std::cos(th) - q.z * std::sin(th),
                                 q.x * std::sin(th) + q.z * std::cos(th)}));
  const auto set = MarkerSet::fromLines({{0, true, p}}, 1, 0.5, Geometry::Planar);
  FaceApertures ap;
  set.faceApertures(g, ap);
  int wet = 0;
  for (int side = 0; side < 2; ++side) {
    for (int i = 0; i <= g.nx; ++i) {
      const auto [lo, hi] = rotatedSquareChord(c, s, th, true, i);
      for (int k = 0; k < g.nz; ++k) {
        ASSERT_NEAR(ap.ax(0, side, i, k), overlap1d(lo, hi, k, k + 1), tol) << i << " " << k;
        wet += ap.ax(0, side, i, k) > 0.0;
      }
    }
    for (int k = 0; k <= g.nz; ++k) {
      const auto [lo, hi] = rotatedSquareChord(c, s, th, false, k);
      for (int i = 0; i < g.nx; ++i)
        ASSERT_NEAR(ap.az(0, side, i, k), overlap1d(lo, hi, i, i + 1), tol) << i << " " << k;
    }
  }
  EXPECT_GT(wet, 20);
  expectDivergenceIdentities(set, g, ap, 0);
}

// A square rotated by 30 degrees: the apertures are the analytic chords (slab intersection, an
// independent formula). Tolerance 1e-13: coordinates of ~10 cells carry ~1e-15 rounding, and
// the crossing interpolation (slope up to tan 60 = 1.7) amplifies it by a few.
TEST(MarkerApertures, RotatedSquareGivesExactChords) {
  expectRotatedSquare(makeGrid(10, 9, 0.7, -1.1, 0.13), {4.1, 3.7}, 2.3, std::numbers::pi / 6,
                      1e-13);
}

// Lines partly outside the grid count where they are: a rotated square over the grid's corner,
// a rectangle sticking out at three sides, and one enclosing the whole grid (all faces wet, no
// crossing inside the grid: the winding comes from crossings beyond it, unclamped).
TEST(MarkerApertures, LinesPartlyOutsideTheGrid) {
  expectRotatedSquare(makeGrid(6, 7, 0.0, 0.0, 0.1), {1.2, 6.1}, 2.0, 0.4, 1e-13);
  const GridSpec g = makeGrid(6, 7, 0.0, 0.0, 0.125);
  for (const CellRect& r : {CellRect{-3.0, 4.5, -2.25, 20.0}, CellRect{-5.0, 9.0, -3.0, 8.0}}) {
    const auto set = MarkerSet::fromLines({rectLine(g, r)}, 1, 0.5, Geometry::Planar);
    FaceApertures ap;
    set.faceApertures(g, ap);
    expectRectApertures(ap, {r}, 0.0);
  }
  const auto all =
      MarkerSet::fromLines({rectLine(g, {-5.0, 9.0, -3.0, 8.0})}, 1, 0.5, Geometry::Planar);
  FaceApertures ap;
  all.faceApertures(g, ap);
  for (double a : ap.x) EXPECT_EQ(a, 1.0);
  for (double a : ap.z) EXPECT_EQ(a, 1.0);
}

//! Chord of a convex counter-clockwise polygon (cell units) on the line across = v, from its
//! half-planes cross(t_j, p - v_j) >= 0 (independent of the crossing sweep); empty: lo > hi.
std::pair<double, double> convexChord(const std::vector<Vec2>& p, bool vertical, double v) {
  double lo = -1e300, hi = 1e300;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const Vec2 a = p[j], t = p[(j + 1) % p.size()] - a;
    // Along the line p(s) = (v, s) or (s, v): cross(t, p - a) = A s + B >= 0.
    const double A = vertical ? t.x : -t.z;
    const double B = vertical ? -t.x * a.z - t.z * (v - a.x) : t.x * (v - a.z) + t.z * a.x;
    if (A > 0.0)
      lo = std::max(lo, -B / A);
    else if (A < 0.0)
      hi = std::min(hi, -B / A);
    else if (B < 0.0)
      return {1.0, 0.0};
  }
  return {lo, hi};
}

// A disk (fromShapes: the inscribed regular polygon, centre on a grid line so that vertices lie
// on it). Every aperture equals the chord of the marker polygon from its half-planes (tolerance
// 1e-12: coordinates of ~40 cells, ~1e-14 rounding, amplified near the tangent points by the
// steep edges, slope up to cot(pi/N) ~ 30), and lies between the apertures of the circles of
// radii rin (distance of the nearest edge) and rout (farthest vertex), which the polygon lies
// between: exact containment, so only rounding tolerance. rout - rin = R (1 - cos(pi/N)).
TEST(MarkerApertures, DiskGivesTheChordsOfItsMarkerPolygon) {
  const GridSpec g = makeGrid(40, 36, 0.0, 0.0, 0.1);
  const Vec2 centre{2.0, 1.93};
  const double radius = 1.37;
  const auto set = MarkerSet::fromShapes({cases::Disk{centre, radius}}, g, 0.5, Geometry::Planar);
  ASSERT_EQ(set.lines().size(), 1u);
  std::vector<Vec2> p;
  for (Vec2 q : set.lines()[0].points) p.push_back(detail::toCellUnits(g, q));
  ASSERT_GT(p.size(), 60u);
  const Vec2 c = detail::toCellUnits(g, centre);
  double rin = 1e300, rout = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const Vec2 a = p[j], t = p[(j + 1) % p.size()] - a;
    rin = std::min(rin, cross(t, c - a) / norm(t));
    rout = std::max(rout, norm(a - c));
  }
  ASSERT_LT(rout - rin, 0.02);
  FaceApertures ap;
  set.faceApertures(g, ap);
  auto circle = [&](double r, bool vertical, double v, int f) {
    const double d = v - (vertical ? c.x : c.z);
    if (std::abs(d) >= r) return 0.0;
    const double h = std::sqrt(r * r - d * d), m = vertical ? c.z : c.x;
    return overlap1d(m - h, m + h, f, f + 1);
  };
  int cut = 0;
  for (int side = 0; side < 2; ++side)
    for (int fam = 0; fam < 2; ++fam) {
      const bool vertical = fam == 0;
      const int lines = vertical ? g.nx + 1 : g.nz + 1, faces = vertical ? g.nz : g.nx;
      for (int v = 0; v < lines; ++v) {
        const auto [lo, hi] = convexChord(p, vertical, v);
        for (int f = 0; f < faces; ++f) {
          const double a = vertical ? ap.ax(0, side, v, f) : ap.az(0, side, f, v);
          ASSERT_NEAR(a, overlap1d(lo, hi, f, f + 1), 1e-12) << fam << " " << v << " " << f;
          ASSERT_GE(a, circle(rin, vertical, v, f) - 1e-12) << fam << " " << v << " " << f;
          ASSERT_LE(a, circle(rout, vertical, v, f) + 1e-12) << fam << " " << v << " " << f;
          cut += a > 0.0 && a < 1.0;
        }
      }
    }
  EXPECT_GT(cut, 100);
  expectDivergenceIdentities(set, g, ap, 0);
}

// A hole (clockwise inner line of the same object) with edges on grid lines (u = 3, 5 and
// w = 5): wet on the material's side of those faces only; and two overlapping counter-clockwise
// lines of one object: the overlap (winding 2) counts once (nonzero rule), faces stay <= 1.
// Dyadic grid and coordinates: exact.
TEST(MarkerApertures, HoleAndOverlapFollowTheNonzeroRule) {
  const GridSpec g = makeGrid(9, 8, 1.0, -2.0, 0.5);
  {
    const std::vector<CellRect> rects{{1.0, 7.0, 1.0, 7.0}, {3.0, 5.0, 2.5, 5.0, -1}};
    const auto set = MarkerSet::fromLines({rectLine(g, rects[0]), rectLine(g, rects[1])}, 1, 0.5,
                                          Geometry::Planar);
    FaceApertures ap;
    set.faceApertures(g, ap);
    expectRectApertures(ap, rects, 0.0);
    EXPECT_EQ(ap.ax(0, 0, 3, 2), 1.0);  // x = 3 from the material (cell 2): wet
    EXPECT_EQ(ap.ax(0, 1, 3, 2), 0.5);  // from the hole (cell 3): only [2, 2.5]
    EXPECT_EQ(ap.az(0, 0, 4, 5), 0.0);  // z = 5 from the hole (cell 4)
    EXPECT_EQ(ap.az(0, 1, 4, 5), 1.0);  // from the material above
    expectDivergenceIdentities(set, g, ap, 0);
  }
  {
    const std::vector<CellRect> rects{{1.0, 5.0, 1.0, 5.0}, {3.25, 7.5, 2.0, 6.75}};
    const auto set = MarkerSet::fromLines({rectLine(g, rects[0]), rectLine(g, rects[1])}, 1, 0.5,
                                          Geometry::Planar);
    FaceApertures ap;
    set.faceApertures(g, ap);
    expectRectApertures(ap, rects, 0.0);
    EXPECT_EQ(ap.ax(0, 0, 4, 2), 1.0);   // inside both
    EXPECT_EQ(ap.ax(0, 1, 4, 6), 0.75);  // only the second: [6, 6.75]
  }
}

// Several objects: each has its own block, and they do not see each other (a body touching
// another along a grid line: each wet on its own side only).
TEST(MarkerApertures, ObjectsHaveSeparateBlocks) {
  const GridSpec g = makeGrid(8, 6, 0.0, 0.0, 0.25);
  const CellRect a{1.0, 4.0, 1.0, 5.0}, b{4.0, 7.0, 2.0, 3.5};
  const auto set =
      MarkerSet::fromLines({rectLine(g, a, 0), rectLine(g, b, 1)}, 3, 0.5, Geometry::Planar);
  FaceApertures ap;
  set.faceApertures(g, ap);
  ASSERT_EQ(ap.objects, 3);
  ASSERT_EQ(ap.x.size(), 3u * 2 * 9 * 6);
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < 6; ++k)
      for (int i = 0; i <= 8; ++i) {
        EXPECT_EQ(ap.ax(0, side, i, k), rectAperture({a}, true, side, i, k));
        EXPECT_EQ(ap.ax(1, side, i, k), rectAperture({b}, true, side, i, k));
        EXPECT_EQ(ap.ax(2, side, i, k), 0.0);
      }
  EXPECT_EQ(ap.ax(0, 0, 4, 2), 1.0);  // shared face x = 4: object 0 from the left
  EXPECT_EQ(ap.ax(0, 1, 4, 2), 0.0);
  EXPECT_EQ(ap.ax(1, 0, 4, 2), 0.0);
  EXPECT_EQ(ap.ax(1, 1, 4, 2), 1.0);  // object 1 from the right
  EXPECT_EQ(ap.ax(1, 1, 4, 3), 0.5);
  // Reused output (and scratch) on a smaller grid: sizes follow the grid, values are fresh.
  const GridSpec small = makeGrid(3, 2, 0.0, 0.0, 0.25);
  set.faceApertures(small, ap);
  ASSERT_EQ(ap.x.size(), 3u * 2 * 4 * 2);
  EXPECT_EQ(ap.ax(0, 1, 1, 1), 1.0);
  EXPECT_EQ(ap.ax(0, 0, 1, 0), 0.0);
}

//! Every grid line's wet span (FaceApertures::xSpan / zSpan) is tight: the faces outside it are
//! dry, its first and last face wet (an empty span: the whole line dry).
void expectTightSpans(const FaceApertures& ap) {
  for (int o = 0; o < ap.objects; ++o)
    for (int side = 0; side < 2; ++side)
      for (const bool xFaces : {true, false}) {
        const int lines = xFaces ? ap.nx + 1 : ap.nz + 1, faces = xFaces ? ap.nz : ap.nx;
        const auto& span = xFaces ? ap.xSpan : ap.zSpan;
        for (int line = 0; line < lines; ++line) {
          const int* s = &span[static_cast<std::size_t>(2L * ((2L * o + side) * lines + line))];
          auto wet = [&](int f) {
            return (xFaces ? ap.ax(o, side, line, f) : ap.az(o, side, f, line)) != 0.0;
          };
          for (int f = 0; f < faces; ++f)
            if (f < s[0] || f >= s[1]) {
              ASSERT_FALSE(wet(f)) << o << side << xFaces << line << f;
            }
          if (s[0] < s[1]) {
            EXPECT_TRUE(wet(s[0]) && wet(s[1] - 1)) << o << side << xFaces << line;
          }
        }
      }
}

// The apertures are written in place over the previous call's (only its wet spans cleared):
// after the bodies move by fractions of cells, in the plane and in r-z, the reused output holds
// the same bits as a fresh one, and its spans are tight.
TEST(MarkerApertures, ReusedOutputAfterMotionEqualsFresh) {
  const GridSpec g = makeGrid(60, 80, 0.0, 0.0, 0.05);
  for (const Geometry geo : {Geometry::Planar, Geometry::Axisymmetric}) {
    FaceApertures reused;
    for (int step = 0; step < 4; ++step) {
      const double dz = 0.37 * step, dx = geo == Geometry::Planar ? 0.21 * step : 0.0;
      const auto set = MarkerSet::fromShapes(
          {cases::Disk{{1.2 + dx, 2.9 - dz}, 0.5}, cases::Rect{0.0, 3.0, 1.0, 1.6 + 0.1 * step}}, g,
          0.5, geo);
      set.faceApertures(g, reused);
      FaceApertures fresh;
      set.faceApertures(g, fresh);
      ASSERT_TRUE(reused.x == fresh.x && reused.z == fresh.z) << step;
      ASSERT_TRUE(reused.xSpan == fresh.xSpan && reused.zSpan == fresh.zSpan) << step;
      expectTightSpans(fresh);
    }
  }
}

// The variant-1 geometry in r-z (sphere on the axis, plate from r = 0): the axis parts of the
// lines lie on the grid line x = 0, so cell 0's side (1) of those faces is wet and side 0 (no
// cell) is not; the divergence identities hold for both objects. Repeated calls give the same
// bits and keep the output's storage. Prints the cost per call.
TEST(MarkerApertures, AxisymmetricBodiesAndCost) {
  const GridSpec g = makeGrid(300, 400, 0.0, 5.0, 0.015);
  const auto set =
      MarkerSet::fromShapes({cases::Disk{{0.0, 8.63}, 0.475}, cases::Rect{0.0, 4.0, 8.0, 8.155}}, g,
                            0.5, Geometry::Axisymmetric);
  FaceApertures ap;
  set.faceApertures(g, ap);
  // Faces on the axis well inside the sphere (z = 8.63 +- 0.3 cm) and the plate.
  const int ks = static_cast<int>((8.63 - 5.0) / 0.015),
            kp = static_cast<int>((8.07 - 5.0) / 0.015);
  EXPECT_EQ(ap.ax(0, 1, 0, ks), 1.0);
  EXPECT_EQ(ap.ax(0, 0, 0, ks), 0.0);
  EXPECT_EQ(ap.ax(1, 1, 0, kp), 1.0);
  EXPECT_EQ(ap.ax(1, 0, 0, kp), 0.0);
  expectDivergenceIdentities(set, g, ap, 0);
  expectDivergenceIdentities(set, g, ap, 1);

  const auto x = ap.x, z = ap.z;
  const double* xData = ap.x.data();
  const int calls = 20;
  const auto t0 = std::chrono::steady_clock::now();
  for (int c = 0; c < calls; ++c) set.faceApertures(g, ap);
  const auto t1 = std::chrono::steady_clock::now();
  EXPECT_EQ(ap.x.data(), xData);
  EXPECT_TRUE(ap.x == x && ap.z == z);
  std::printf("[perf] %ld cells, %zu markers: faceApertures %.3f ms per call\n", g.cells(),
              set.size(), std::chrono::duration<double, std::milli>(t1 - t0).count() / calls);
}

}  // namespace
}  // namespace hvi::tvd
