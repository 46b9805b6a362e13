//! @file Moving the markers with the bilinearly interpolated cell-centred velocity.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "hvi/common/error.hpp"
#include "hvi/tvd/markers.hpp"

namespace hvi::tvd {
namespace {

//! Bilinear interpolation of cell-centred data in the lerp form a + f (b - a), so a constant
//! field is reproduced bit for bit. Beyond the outermost cell centres the nearest values are
//! used; on the r-z axis side the radial component is continued oddly (ghost = -vx), which
//! makes vx vanish on the axis and keeps linear fields v = a r exact; so is the normal
//! component across a side in `walls` (xmin, xmax, zmin, zmax).
struct VelocityField {
  const GridSpec& g;
  const double* vx;
  const double* vz;
  bool axis;
  std::array<bool, 4> walls{};

  static double lerp(double a, double b, double f) { return a + f * (b - a); }

  Vec2 operator()(Vec2 p, const double* own) const {
    const double s = (p.x - g.x0) / g.dx - 0.5;
    const double r = (p.z - g.z0) / g.dz - 0.5;
    const double fi = std::floor(s), fk = std::floor(r);
    const double fx = s - fi, fz = r - fk;
    // Clamp in floating point first: a far-away marker must not overflow the int conversion.
    const int i = static_cast<int>(std::clamp(fi, -1.0, static_cast<double>(g.nx)));
    const int k = static_cast<int>(std::clamp(fk, -1.0, static_cast<double>(g.nz)));
    const int i0 = std::clamp(i, 0, g.nx - 1), i1 = std::clamp(i + 1, 0, g.nx - 1);
    const int k0 = std::clamp(k, 0, g.nz - 1), k1 = std::clamp(k + 1, 0, g.nz - 1);
    const long r0 = static_cast<long>(k0) * g.nx, r1 = static_cast<long>(k1) * g.nx;
    long c00 = r0 + i0, c10 = r0 + i1, c01 = r1 + i0, c11 = r1 + i1;
    if (own != nullptr) {
      // Only the cells of the stencil the body may read (its own live cells, and cells that
      // live bodies fill together: a contact): an unmarked cell (vacuum, another body's free
      // surface or spray, the body's own cells below the time-step density) takes the value of
      // its row partner, else its column partner, else the diagonal one, so a constant field
      // stays exact. This holds for spray too, a body that fills no cell near the marker: a
      // vacuum cell there carries the mean of its neighbours, other bodies' included. A stencil
      // with no marked cell reads every cell, as before the rule.
      const bool m00 = own[c00] > 0.0, m10 = own[c10] > 0.0, m01 = own[c01] > 0.0,
                 m11 = own[c11] > 0.0;
      if ((m00 || m10 || m01 || m11) && !(m00 && m10 && m01 && m11)) {
        const long a00 = c00, a10 = c10, a01 = c01, a11 = c11;
        if (!m00) c00 = m10 ? a10 : m01 ? a01 : a11;
        if (!m10) c10 = m00 ? a00 : m11 ? a11 : a01;
        if (!m01) c01 = m11 ? a11 : m00 ? a00 : a10;
        if (!m11) c11 = m01 ? a01 : m10 ? a10 : a00;
      }
    }
    // Odd ghosts of the normal component across the axis and the walls.
    const double sx = ((axis || walls[0]) && i < 0) ? -1.0 : 1.0;
    const double sxHi = (walls[1] && i >= g.nx - 1) ? -1.0 : 1.0;
    const double sz = (walls[2] && k < 0) ? -1.0 : 1.0;
    const double szHi = (walls[3] && k >= g.nz - 1) ? -1.0 : 1.0;
    const double ux0 = lerp(sx * vx[c00], sxHi * vx[c10], fx);
    const double ux1 = lerp(sx * vx[c01], sxHi * vx[c11], fx);
    const double uz0 = sz * lerp(vz[c00], vz[c10], fx);
    const double uz1 = szHi * lerp(vz[c01], vz[c11], fx);
    return {lerp(ux0, ux1, fz), lerp(uz0, uz1, fz)};
  }
};

}  // namespace

void MarkerSet::advect(const GridSpec& grid, const double* vx, const double* vz, double dt,
                       std::array<bool, 4> walls, std::array<bool, 4> open, bool oddWalls,
                       const std::vector<std::vector<double>>* own) {
  const bool rz = geometry_ == Geometry::Axisymmetric;
  const bool anyOpen = open[0] || open[1] || open[2] || open[3];
  const double x0 = grid.x0, x1 = grid.x0 + grid.nx * grid.dx;
  const double z0 = grid.z0, z1 = grid.z0 + grid.nz * grid.dz;
  // Beyond an open side a marker stays where it is: what it bounded has left.
  auto beyond = [&](Vec2 p) {
    return anyOpen && ((open[0] && p.x < x0) || (open[1] && p.x > x1) || (open[2] && p.z < z0) ||
                       (open[3] && p.z > z1));
  };
  // The odd continuation applies only when the grid's left face is the axis.
  const VelocityField v{grid, vx, vz, rz && std::abs(grid.x0) <= 1e-12 * grid.dx,
                        oddWalls ? walls : std::array<bool, 4>{}};
  const bool anyWall = walls[0] || walls[1] || walls[2] || walls[3];
  // A marker on a wall keeps its normal coordinate (the mirror holds the material there), one
  // inside does not cross the wall; one already beyond it (a body overlapping the side) is left.
  // "On" within 1e-12 cells: the far sides' coordinates x0 + nx dx carry a rounding that a
  // body's edge given in the scene does not.
  const double tx = 1e-12 * grid.dx, tz = 1e-12 * grid.dz;
  auto atWall = [&](Vec2 p, Vec2& q) {
    if (walls[0] && p.x >= x0 - tx) q.x = p.x <= x0 + tx ? p.x : std::max(q.x, x0);
    if (walls[1] && p.x <= x1 + tx) q.x = p.x >= x1 - tx ? p.x : std::min(q.x, x1);
    if (walls[2] && p.z >= z0 - tz) q.z = p.z <= z0 + tz ? p.z : std::max(q.z, z0);
    if (walls[3] && p.z <= z1 + tz) q.z = p.z >= z1 - tz ? p.z : std::min(q.z, z1);
  };
  std::atomic<long> bad{-1};
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    auto& pts = lines_[l].points;
    const long n = static_cast<long>(pts.size());
    const auto object = static_cast<std::size_t>(lines_[l].object);
    const double* mine = own != nullptr && object < own->size() && !(*own)[object].empty()
                             ? (*own)[object].data()
                             : nullptr;
#pragma omp parallel for schedule(static) if (n > 2048)
    for (long j = 0; j < n; ++j) {
      const Vec2 p = pts[static_cast<std::size_t>(j)];
      const bool onAxis = rz && p.x == 0.0;
      if (beyond(p)) continue;
      // Explicit midpoint rule along the path in the (time-centred) velocity field.
      Vec2 half = p + (0.5 * dt) * v(p, mine);
      if (rz) half.x = onAxis ? 0.0 : std::max(half.x, 0.0);
      if (anyWall) atWall(p, half);
      Vec2 q = p + dt * v(half, mine);
      if (rz) q.x = onAxis ? 0.0 : std::max(q.x, 0.0);
      if (anyWall) atWall(p, q);
      if (std::isfinite(q.x) && std::isfinite(q.z))
        pts[static_cast<std::size_t>(j)] = q;
      else
        bad.store(j);
    }
    if (bad.load() >= 0) {
      const auto j = static_cast<std::size_t>(bad.load());
      throw SimulationError(
          fmt::format("marker {} of line {} (object {}) at ({}, {}) would move to a non-finite "
                      "position with dt = {} "
                      "us: the velocity field is not finite near it",
                      j, l, lines_[l].object, pts[j].x, pts[j].z, dt));
    }
  }
}

}  // namespace hvi::tvd
