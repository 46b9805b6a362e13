//! @file Interface normals of the cut cells from the marker lines.
#include "interface_normals.hpp"

#include <algorithm>
#include <cmath>

#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd::detail {
namespace {

// A segment lies on a domain edge if both its ends are within this distance (in cells) of the
// same edge line: markers kept on the axis are exactly on it, others may drift by rounding.
constexpr double kOnEdge = 1e-6;

bool onEdge(double a, double b, double edge) {
  return std::abs(a - edge) < kOnEdge && std::abs(b - edge) < kOnEdge;
}

}  // namespace

void interfaceNormals(const MarkerSet& markers, const GridSpec& grid, const std::vector<int>& owner,
                      std::vector<Vec2>& normal, std::vector<double>& length) {
  const auto cells = static_cast<std::size_t>(grid.cells());
  normal.assign(cells, Vec2{});
  length.assign(cells, 0.0);
  const double nx = grid.nx, nz = grid.nz;
  for (const auto& line : markers.lines()) {
    const std::size_t n = line.points.size();
    if (n < 2) continue;
    auto piece = [&](int i, int k, Vec2 pa, Vec2 pb) {
      if (i < 0 || k < 0) return;
      i = std::min(i, grid.nx - 1);  // a piece on the last grid line belongs to the last cell
      k = std::min(k, grid.nz - 1);
      const auto c = static_cast<std::size_t>(static_cast<long>(k) * grid.nx + i);
      const Vec2 d{(pb.x - pa.x) * grid.dx, (pb.z - pa.z) * grid.dz};
      const double sign = owner[c] == line.object ? 1.0 : -1.0;
      normal[c] += sign * Vec2{d.z, -d.x};  // the object lies left of the line's direction
      length[c] += norm(d);
    };
    for (std::size_t j = 0; j < n; ++j) {
      const Vec2 a = toCellUnits(grid, line.points[j]);
      const Vec2 b = toCellUnits(grid, line.points[j + 1 == n ? 0 : j + 1]);
      if (onEdge(a.x, b.x, 0.0) || onEdge(a.x, b.x, nx) || onEdge(a.z, b.z, 0.0) ||
          onEdge(a.z, b.z, nz))
        continue;
      splitAtBox(a, b, nx, nz, [&](Vec2 p, Vec2 q) {
        const Vec2 m = 0.5 * (p + q);
        if (m.x < 0.0 || m.x > nx || m.z < 0.0 || m.z > nz || p == q) return;
        forEachCellPiece(p, q, piece);
      });
    }
  }
  for (std::size_t c = 0; c < cells; ++c) {
    const double len = norm(normal[c]);
    normal[c] = len > 1e-9 * length[c] && len > 0.0 ? normal[c] / len : Vec2{};
  }
}

}  // namespace hvi::tvd::detail
