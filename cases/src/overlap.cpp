//! @file Overlap of body shapes: exact for disks and rectangles, sampled for polygons.
#include "detail/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "detail/polygon.hpp"

namespace hvi::cases::detail {
namespace {

Polygon asPolygon(const Shape& s) {
  if (const auto* r = std::get_if<Rect>(&s))
    return Polygon{
        {{r->xmin, r->zmin}, {r->xmax, r->zmin}, {r->xmax, r->zmax}, {r->xmin, r->zmax}}};
  return std::get<Polygon>(s);
}

double polygonDepth(const Polygon& poly, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  const auto& v = poly.vertices;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    d = std::min(d, distanceToSegment(p, v[j], v[i]));
  return contains(Shape{poly}, p) ? d : -d;
}

bool diskRect(const Disk& d, const Rect& r, double tol) {
  const Vec2 q{std::clamp(d.centre.x, r.xmin, r.xmax), std::clamp(d.centre.z, r.zmin, r.zmax)};
  return norm(d.centre - q) < d.radius - tol;
}

bool diskPolygon(const Disk& d, const Polygon& p, double tol) {
  // The distance from the centre to the polygon's region is below the radius.
  return -polygonDepth(p, d.centre) < d.radius - tol;
}

bool sampled(const Shape& a, const Shape& b, double tol) {
  // A polygon vertex deeper than tol in the other shape: the polygon's interior comes
  // arbitrarily close to its vertices, so the interiors overlap.
  for (const Shape* s : {&a, &b}) {
    const Shape& other = (s == &a) ? b : a;
    if (const auto* p = std::get_if<Polygon>(s))
      for (const Vec2 v : p->vertices)
        if (depth(other, v) > tol) return true;
  }
  const Box ba = boundingBox(a), bb = boundingBox(b);
  const double x0 = std::max(ba.xmin, bb.xmin), x1 = std::min(ba.xmax, bb.xmax);
  const double z0 = std::max(ba.zmin, bb.zmin), z1 = std::min(ba.zmax, bb.zmax);
  constexpr int kSamples = 128;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const Vec2 p{x0 + (i + 0.5) * (x1 - x0) / kSamples, z0 + (j + 0.5) * (z1 - z0) / kSamples};
      if (depth(a, p) > tol && depth(b, p) > tol) return true;
    }
  return false;
}

}  // namespace

double depth(const Shape& s, Vec2 p) {
  if (const auto* d = std::get_if<Disk>(&s)) return d->radius - norm(p - d->centre);
  if (const auto* r = std::get_if<Rect>(&s))
    return std::min({p.x - r->xmin, r->xmax - p.x, p.z - r->zmin, r->zmax - p.z});
  return polygonDepth(std::get<Polygon>(s), p);
}

bool overlaps(const Shape& a, const Shape& b, double tol) {
  const Box ba = boundingBox(a), bb = boundingBox(b);
  if (std::min(ba.xmax, bb.xmax) - std::max(ba.xmin, bb.xmin) <= tol ||
      std::min(ba.zmax, bb.zmax) - std::max(ba.zmin, bb.zmin) <= tol)
    return false;
  const auto* da = std::get_if<Disk>(&a);
  const auto* db = std::get_if<Disk>(&b);
  const auto* ra = std::get_if<Rect>(&a);
  const auto* rb = std::get_if<Rect>(&b);
  if (da && db) return norm(da->centre - db->centre) < da->radius + db->radius - tol;
  if (ra && rb) return true;  // the bounding boxes are the rectangles
  if (da && rb) return diskRect(*da, *rb, tol);
  if (ra && db) return diskRect(*db, *ra, tol);
  if (da) return diskPolygon(*da, asPolygon(b), tol);
  if (db) return diskPolygon(*db, asPolygon(a), tol);
  return sampled(a, b, tol);
}

}  // namespace hvi::cases::detail
