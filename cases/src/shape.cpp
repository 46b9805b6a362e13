//! @file Point-in-shape, area and bounds of the body shapes.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "hvi/cases/scene.hpp"

namespace hvi::cases {
namespace {
struct Contains {
  Vec2 p;
  bool operator()(const Disk& d) const { return norm(p - d.centre) <= d.radius; }
  bool operator()(const Rect& r) const {
    return p.x >= r.xmin && p.x <= r.xmax && p.z >= r.zmin && p.z <= r.zmax;
  }
  bool operator()(const Polygon& poly) const {
    // Even-odd crossing rule.
    bool in = false;
    const auto& v = poly.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if ((v[i].z > p.z) != (v[j].z > p.z) &&
          p.x < (v[j].x - v[i].x) * (p.z - v[i].z) / (v[j].z - v[i].z) + v[i].x)
        in = !in;
    }
    return in;
  }
};
struct Area {
  double operator()(const Disk& d) const { return std::numbers::pi * d.radius * d.radius; }
  double operator()(const Rect& r) const { return (r.xmax - r.xmin) * (r.zmax - r.zmin); }
  double operator()(const Polygon& poly) const {
    double a = 0.0;
    const auto& v = poly.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) a += cross(v[j], v[i]);
    return 0.5 * std::abs(a);
  }
};
struct Bounds {
  Box operator()(const Disk& d) const {
    return {d.centre.x - d.radius, d.centre.x + d.radius, d.centre.z - d.radius,
            d.centre.z + d.radius};
  }
  Box operator()(const Rect& r) const { return {r.xmin, r.xmax, r.zmin, r.zmax}; }
  Box operator()(const Polygon& poly) const {
    Box b{1e300, -1e300, 1e300, -1e300};
    for (auto v : poly.vertices) {
      b.xmin = std::min(b.xmin, v.x); b.xmax = std::max(b.xmax, v.x);
      b.zmin = std::min(b.zmin, v.z); b.zmax = std::max(b.zmax, v.z);
    }
    return b;
  }
};
}  // namespace

bool contains(const Shape& s, Vec2 p) { return std::visit(Contains{p}, s); }
double area(const Shape& s) { return std::visit(Area{}, s); }
Box boundingBox(const Shape& s) { return std::visit(Bounds{}, s); }

}  // namespace hvi::cases
