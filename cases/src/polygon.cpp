//! @file Polygon simplicity and orientation, and the segment primitives they need.
#include "detail/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace hvi::cases::detail {
namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double v = cross(b - a, c - a);
  return (v > 0.0) - (v < 0.0);
}

bool onSegment(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.z, b.z) <= p.z &&
         p.z <= std::max(a.z, b.z);
}

}  // namespace

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
         (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

bool makeSimpleCounterClockwise(Polygon& poly, std::string& why) {
  auto& v = poly.vertices;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (v[i] == v[(i + 1) % n]) {
      why = "vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
            " are the same point";
      return false;
    }
  // O(n^2) edge pairs: scene polygons have tens of vertices.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share one vertex; they may not fold back onto each other.
        const std::size_t shared = (j == i + 1) ? j : i;
        const Vec2 p = v[(shared + n - 1) % n], q = v[shared], r = v[(shared + 1) % n];
        if (orientation(p, q, r) == 0 && dot(p - q, r - q) > 0.0) {
          why = "edges at vertex " + std::to_string(shared) + " fold back onto each other";
          return false;
        }
        continue;
      }
      if (segmentsIntersect(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) {
        why = "edge " + std::to_string(i) + " crosses or touches edge " + std::to_string(j);
        return false;
      }
    }
  // Relative to the first vertex: far from the origin the sum of absolute cross products would
  // lose the area of a small polygon to cancellation.
  double twiceArea = 0.0;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) twiceArea += cross(v[j] - v[0], v[i] - v[0]);
  double xmin = v[0].x, xmax = v[0].x, zmin = v[0].z, zmax = v[0].z;
  for (const Vec2 p : v) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    zmin = std::min(zmin, p.z), zmax = std::max(zmax, p.z);
  }
  const double diag2 = (xmax - xmin) * (xmax - xmin) + (zmax - zmin) * (zmax - zmin);
  // Collinear vertices give round-off areas (~1e-16 of diag^2), which the exact tests above do not
  // see: orientation() of nearly collinear points is +-1, not 0. A polygon narrower than 1e-9 of
  // its size cannot be resolved by either solver (the memory caps allow ~7000 cells a side), so
  // it is refused here rather than failing at set-up ("holds no particle", no marker area).
  if (!std::isfinite(twiceArea) || !(std::abs(twiceArea) > 1e-9 * diag2)) {
    why = "the polygon has zero area: its vertices are (nearly) collinear";
    return false;
  }
  if (twiceArea < 0.0) std::reverse(v.begin(), v.end());
  return true;
}

}  // namespace hvi::cases::detail
