//! @file Geometry kernels of the marker lines (shoelace sums, splitting segments at the grid box
//! and by cells): shared by the marker-line sources and tested directly by tests/unit/tvd_markers.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "hvi/common/snapshot.hpp"
#include "hvi/common/vec2.hpp"

namespace hvi::tvd::detail {

//! Twice the signed area of a closed chain (positive counter-clockwise in the x-z plane).
inline double twiceSignedArea(const std::vector<Vec2>& p) {
  double a = 0.0;
  const std::size_t n = p.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) a += cross(p[j], p[i]);
  return n < 3 ? 0.0 : a;
}

//! Six times the signed first moment integral of x dA of a closed chain (Pappus numerator).
inline double sixTimesMomentX(const std::vector<Vec2>& p) {
  double m = 0.0;
  const std::size_t n = p.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) m += (p[j].x + p[i].x) * cross(p[j], p[i]);
  return n < 3 ? 0.0 : m;
}

//! The cell size markers are spaced against: the smaller of dx and dz (they are equal in the
//! TVD solver; the minimum keeps the bounds meaningful if they are not).
inline double cellSize(const GridSpec& g) { return std::min(g.dx, g.dz); }

//! Grid-local coordinates in cell units: cell (i, k) is [i, i+1] x [k, k+1].
inline Vec2 toCellUnits(const GridSpec& g, Vec2 p) {
  return {(p.x - g.x0) / g.dx, (p.z - g.z0) / g.dz};
}

//! Splits segment a-b (cell units) at the four lines bounding [0, nx] x [0, nz] and calls
//! f(pa, pb) for each sub-segment in order; each lies entirely inside or outside the box in x
//! and in z, so a monotone clamp maps it to a straight segment. A cut point sits exactly on the
//! line it cuts: computed as a + t d it may land a rounding error outside, and a sub-segment
//! inside the box would then begin with a sliver in the row or column beyond the grid.
template <class F>
inline void splitAtBox(Vec2 a, Vec2 b, double nx, double nz, F&& f) {
  struct Cut {
    double t;
    int axis;  // 0: a line x = level, 1: a line z = level
    double level;
  };
  Cut cuts[4];
  int n = 0;
  const Vec2 d = b - a;
  auto addCut = [&](double a0, double d0, double level, int axis) {
    if (d0 == 0.0) return;
    const double t = (level - a0) / d0;
    if (t > 0.0 && t < 1.0) cuts[n++] = {t, axis, level};
  };
  addCut(a.x, d.x, 0.0, 0);
  addCut(a.x, d.x, nx, 0);
  addCut(a.z, d.z, 0.0, 1);
  addCut(a.z, d.z, nz, 1);
  for (int s = 1; s < n; ++s)  // insertion sort of at most 4 values
    for (int r = s; r > 0 && cuts[r].t < cuts[r - 1].t; --r) std::swap(cuts[r], cuts[r - 1]);
  Vec2 p0 = a;
  for (int s = 0; s <= n; ++s) {
    Vec2 p1 = b;
    if (s < n) {
      p1 = a + cuts[s].t * d;
      (cuts[s].axis == 0 ? p1.x : p1.z) = cuts[s].level;
    }
    f(p0, p1);
    p0 = p1;
  }
}

//! Splits segment a-b (cell units, both ends finite) into pieces that each lie in one cell and
//! calls f(i, k, pa, pb) per piece, in order along the segment. Crossing points sit exactly on
//! the grid line they cross, and the first and last piece end exactly at a and b, so sums of
//! piece extents telescope to the segment's extent. O(number of cells crossed).
template <class F>
inline void forEachCellPiece(Vec2 a, Vec2 b, F&& f) {
  const Vec2 d = b - a;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const int stepU = d.x > 0.0 ? 1 : -1;
  const int stepW = d.z > 0.0 ? 1 : -1;
  double nextU = d.x > 0.0 ? std::floor(a.x) + 1.0 : std::ceil(a.x) - 1.0;
  double nextW = d.z > 0.0 ? std::floor(a.z) + 1.0 : std::ceil(a.z) - 1.0;
  double tu = d.x != 0.0 ? (nextU - a.x) / d.x : inf;
  double tw = d.z != 0.0 ? (nextW - a.z) / d.z : inf;
  double t0 = 0.0;
  Vec2 p0 = a;
  for (;;) {
    const double t1 = std::min({tu, tw, 1.0});
    Vec2 p1;
    if (t1 >= 1.0) {
      p1 = b;
    } else {
      p1 = a + t1 * d;
      if (t1 == tu) p1.x = nextU;
      if (t1 == tw) p1.z = nextW;
    }
    if (t1 > t0) {
      const int i = static_cast<int>(std::floor(0.5 * (p0.x + p1.x)));
      const int k = static_cast<int>(std::floor(0.5 * (p0.z + p1.z)));
      f(i, k, p0, p1);
    }
    if (!(t1 < 1.0)) break;
    if (t1 == tu) {
      nextU += stepU;
      tu = (nextU - a.x) / d.x;
    }
    if (t1 == tw) {
      nextW += stepW;
      tw = (nextW - a.z) / d.z;
    }
    t0 = t1;
    p0 = p1;
  }
}

}  // namespace hvi::tvd::detail
