//! @file Building marker lines around the body shapes of a scene.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "hvi/common/error.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {

//! The exact outline of a shape as a counter-clockwise polygon; a disk becomes the inscribed
//! regular polygon with sides at most h (side count a multiple of 4 so that its bottom, right,
//! top and left points are vertices and lie exactly on the axis-parallel diameters).
struct Outline {
  double h;
  std::vector<Vec2> operator()(const cases::Disk& d) const {
    if (!(d.radius > 0.0) || !std::isfinite(d.radius))
      throw InputError(fmt::format("marker lines: disk radius {} must be positive", d.radius));
    int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi * d.radius / h));
    n = std::max(8, (n + 3) / 4 * 4);
    std::vector<Vec2> p(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
      const double th = -0.5 * std::numbers::pi + 2.0 * std::numbers::pi * j / n;
      p[static_cast<std::size_t>(j)] = {d.centre.x + d.radius * std::cos(th),
                                        d.centre.z + d.radius * std::sin(th)};
    }
    const auto q = static_cast<std::size_t>(n / 4);
    p[0].x = p[2 * q].x = d.centre.x;
    p[q].z = p[3 * q].z = d.centre.z;
    return p;
  }
  std::vector<Vec2> operator()(const cases::Rect& r) const {
    if (!(r.xmax > r.xmin) || !(r.zmax > r.zmin))
      throw InputError(fmt::format(
          "marker lines: rectangle [{}, {}] x [{}, {}] must have xmax > xmin and zmax > zmin",
          r.xmin, r.xmax, r.zmin, r.zmax));
    return {{r.xmin, r.zmin}, {r.xmax, r.zmin}, {r.xmax, r.zmax}, {r.xmin, r.zmax}};
  }
  std::vector<Vec2> operator()(const cases::Polygon& poly) const {
    std::vector<Vec2> p = poly.vertices;
    const double a = detail::twiceSignedArea(p);
    if (p.size() < 3 || !(std::abs(a) > 0.0))
      throw InputError(fmt::format(
          "marker lines: polygon with {} vertices and zero area; need >= 3 vertices enclosing "
          "an area",
          p.size()));
    if (a < 0.0) std::reverse(p.begin(), p.end());
    return p;
  }
};

//! Keeps the part of polygon p at x >= 0 (Sutherland-Hodgman against one half-plane). The
//! crossing points get x = 0 exactly; where the body is cut, the result runs along the axis.
std::vector<Vec2> clipToHalfPlane(const std::vector<Vec2>& p) {
  std::vector<Vec2> out;
  const std::size_t n = p.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 s = p[j], e = p[i];
    const bool sIn = s.x >= 0.0, eIn = e.x >= 0.0;
    if (sIn != eIn) {
      const double t = s.x / (s.x - e.x);
      out.push_back({0.0, s.z + t * (e.z - s.z)});
    }
    if (eIn) out.push_back(e);
  }
  return out;
}

//! Drops consecutive (and wrap-around) duplicate points.
void dropDuplicates(std::vector<Vec2>& p) {
  std::size_t w = 0;
  for (std::size_t r = 0; r < p.size(); ++r)
    if (w == 0 || !(p[r] == p[w - 1])) p[w++] = p[r];
  while (w > 1 && p[w - 1] == p[0]) --w;
  p.resize(w);
}

//! Subdivides every edge longer than h into equal parts (points on the edge: area unchanged).
std::vector<Vec2> subdivide(const std::vector<Vec2>& p, double h) {
  std::vector<Vec2> out;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % n];
    out.push_back(a);
    const int m = static_cast<int>(std::ceil(norm(b - a) / h));
    for (int q = 1; q < m; ++q) out.push_back(a + (static_cast<double>(q) / m) * (b - a));
  }
  return out;
}

void checkSpacing(const GridSpec& grid, double spacingCells) {
  if (!(grid.dx > 0.0) || !(grid.dz > 0.0) || grid.nx <= 0 || grid.nz <= 0)
    throw InputError(fmt::format("marker lines: grid {} x {} with cell {} x {} cm is empty",
                                 grid.nx, grid.nz, grid.dx, grid.dz));
  if (!(spacingCells > 0.0) || !(spacingCells <= 10.0))
    throw InputError(fmt::format(
        "tvd.markerSpacing = {} cells; allowed: 0 < spacing <= 10 (default 0.5)", spacingCells));
}

}  // namespace

MarkerSet MarkerSet::fromLines(std::vector<MarkerLine> lines, int objects, double spacingCells,
                               Geometry g) {
  if (!(spacingCells > 0.0))
    throw InputError(fmt::format("marker lines: spacing {} cells must be positive", spacingCells));
  MarkerSet set;
  for (const auto& l : lines)
    if (l.object < 0 || l.object >= objects)
      throw InputError(
          fmt::format("marker lines: line object {} outside [0, {})", l.object, objects));
  set.lines_ = std::move(lines);
  set.objects_ = objects;
  set.geometry_ = g;
  set.spacingCells_ = spacingCells;
  set.setSpacingBounds(0.5 * spacingCells, 2.0 * spacingCells);
  return set;
}

MarkerSet MarkerSet::fromShapes(const std::vector<cases::Shape>& shapes, const GridSpec& grid,
                                double spacingCells, Geometry g) {
  checkSpacing(grid, spacingCells);
  const double h = spacingCells * detail::cellSize(grid);
  std::vector<MarkerLine> lines;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    std::vector<Vec2> p = std::visit(Outline{h}, shapes[s]);
    if (g == Geometry::Axisymmetric) {
      // Snap round-off-level radii to the axis so a body centred on it does not get a sliver.
      const cases::Box box = cases::boundingBox(shapes[s]);
      const double tol = 1e-12 * std::max({std::abs(box.xmin), std::abs(box.xmax), h});
      for (auto& q : p)
        if (std::abs(q.x) <= tol) q.x = 0.0;
      p = clipToHalfPlane(p);
    }
    dropDuplicates(p);
    if (p.size() < 3 || !(detail::twiceSignedArea(p) > 0.0))
      throw InputError(fmt::format(
          "marker lines: body {} has no area at r >= 0 (r-z geometry keeps only x >= 0)", s));
    lines.push_back({static_cast<int>(s), true, subdivide(p, h)});
  }
  return fromLines(std::move(lines), static_cast<int>(shapes.size()), spacingCells, g);
}

MarkerSet MarkerSet::fromBodies(const cases::Scene& scene, const GridSpec& grid) {
  std::vector<cases::Shape> shapes;
  shapes.reserve(scene.bodies.size());
  for (const auto& b : scene.bodies) shapes.push_back(b.shape);
  return fromShapes(shapes, grid, scene.tvd.markerSpacing, scene.geometry);
}

void MarkerSet::setSpacingBounds(double minCells, double maxCells) {
  if (!(minCells > 0.0) || !(maxCells >= 2.0 * minCells))
    throw InputError(fmt::format(
        "marker redistribution bounds min = {}, max = {} cells; need 0 < min and max >= 2 min "
        "(so that splitting a long segment never makes a short one)",
        minCells, maxCells));
  minCells_ = minCells;
  maxCells_ = maxCells;
}

}  // namespace hvi::tvd
