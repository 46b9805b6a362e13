//! @file Cutting the marker lines at the outflow sides of the grid (docs/markers.md, "Cutting at
//! outflow sides").
#include <algorithm>
#include <cmath>

#include "hvi/tvd/markers.hpp"

namespace hvi::tvd {
namespace {

//! One Sutherland-Hodgman pass of the closed chain `in` against the half-plane of side `side`
//! (0: x >= c, 1: x <= c, 2: z >= c, 3: z <= c) into `out`. A crossing point gets the side's
//! coordinate exactly and the other one as a + t (b - a) with the ends ordered by the
//! coordinate, so both runs of an edge give the same point and an edge along the r-z axis keeps
//! x = 0. The chain keeps its direction, so the region inside keeps its orientation.
void clipSide(const std::vector<Vec2>& in, std::vector<Vec2>& out, int side, double c) {
  out.clear();
  const bool xSide = side < 2;
  const bool low = side % 2 == 0;
  auto coord = [&](Vec2 p) { return xSide ? p.x : p.z; };
  auto inside = [&](Vec2 p) { return low ? coord(p) >= c : coord(p) <= c; };
  auto crossing = [&](Vec2 a, Vec2 b) {
    if (coord(a) > coord(b)) std::swap(a, b);  // the same point for either direction
    const double t = (c - coord(a)) / (coord(b) - coord(a));
    return xSide ? Vec2{c, a.z + t * (b.z - a.z)} : Vec2{a.x + t * (b.x - a.x), c};
  };
  const std::size_t n = in.size();
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2 a = in[j], b = in[(j + 1) % n];
    const bool ia = inside(a), ib = inside(b);
    if (ia) out.push_back(a);
    // A strict crossing only: an end on the side is inside and is kept as it is.
    if (ia != ib && coord(a) != c && coord(b) != c) out.push_back(crossing(a, b));
  }
  // Repeated points (a vertex on the side next to a crossing there) would be zero-length edges.
  auto same = [](Vec2 a, Vec2 b) { return a.x == b.x && a.z == b.z; };
  out.erase(std::unique(out.begin(), out.end(), same), out.end());
  while (out.size() > 1 && same(out.front(), out.back())) out.pop_back();
}

}  // namespace

long MarkerSet::clipToSides(const GridSpec& grid, std::array<bool, 4> sides) {
  if (!(sides[0] || sides[1] || sides[2] || sides[3])) return 0;
  const double bound[4] = {grid.x0, grid.x0 + grid.nx * grid.dx, grid.z0,
                           grid.z0 + grid.nz * grid.dz};
  auto beyond = [&](Vec2 p) {
    return (sides[0] && p.x < bound[0]) || (sides[1] && p.x > bound[1]) ||
           (sides[2] && p.z < bound[2]) || (sides[3] && p.z > bound[3]);
  };
  long removed = 0;
  std::size_t kept = 0;
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    MarkerLine& line = lines_[l];
    if (std::any_of(line.points.begin(), line.points.end(), beyond)) {
      for (int side = 0; side < 4 && line.points.size() >= 3; ++side) {
        if (!sides[static_cast<std::size_t>(side)]) continue;
        clipSide(line.points, scratchPoints_, side, bound[side]);
        line.points.swap(scratchPoints_);
      }
    }
    // A line with nothing left inside (fewer than 3 points, or no area: all of it was beyond,
    // or it only ran along the side) holds no material: it is removed.
    bool empty = line.points.size() < 3;
    if (!empty) {
      // Relative to the first point, so that a line lying along a side sums exact zeros.
      const Vec2 o = line.points.front();
      double a2 = 0.0;
      const std::size_t n = line.points.size();
      for (std::size_t j = 1; j + 1 < n; ++j)
        a2 += cross(line.points[j] - o, line.points[j + 1] - o);
      empty = a2 == 0.0;
    }
    if (empty) {
      ++removed;
      continue;
    }
    if (kept != l) lines_[kept] = std::move(line);
    ++kept;
  }
  lines_.resize(kept);
  return removed;
}

long MarkerSet::removeObject(int o) {
  const auto before = static_cast<long>(lines_.size());
  std::erase_if(lines_, [o](const MarkerLine& l) { return l.object == o; });
  return before - static_cast<long>(lines_.size());
}

}  // namespace hvi::tvd
