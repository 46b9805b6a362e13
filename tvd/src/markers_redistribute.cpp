//! @file Keeping marker spacing within bounds as lines stretch and compress.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hvi/common/error.hpp"

#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {

//! Six times the signed integral of x dA over triangle (p, u, v).
double moment6(Vec2 p, Vec2 u, Vec2 v) { return cross(u - p, v - p) * (p.x + u.x + v.x); }

//! The point m that replaces the edge (a, q) of the chain prev, a, q, next so that the volume
//! the line encloses is unchanged: the area in planar geometry, the integral of r dA (volume of
//! revolution) in r-z. Off the axis m = mid + s n, n normal to next - prev, mid the edge
//! midpoint; s solves a linear (planar) or quadratic (r-z, smaller root) equation. In r-z an
//! edge with an end on the axis collapses onto the axis, m = (0, z), with z solving a linear
//! equation. Where the solution does not exist or would move m more than `limit` from the
//! plain choice (a needle whose neighbours almost coincide) the plain choice is kept: the
//! midpoint, or the axis point.
Vec2 collapse(Vec2 prev, Vec2 a, Vec2 q, Vec2 next, double limit, bool rz) {
  const Vec2 mid = 0.5 * (a + q);
  const Vec2 base = next - prev;
  const double b2 = dot(base, base);
  if (!(b2 > 0.0)) return mid;
  const Vec2 n{base.z, -base.x};  // cross(n, base) = b2
  const double have = cross(mid - prev, base);
  if (!rz) {
    const double want = cross(a - prev, q - prev) + cross(q - prev, base);
    const Vec2 shift = ((want - have) / b2) * n;
    return dot(shift, shift) <= limit * limit ? mid + shift : mid;
  }
  const double want = moment6(prev, a, q) + moment6(prev, q, next);
  if (a.x == 0.0 || q.x == 0.0) {
    const Vec2 plain = a.x == 0.0 && q.x == 0.0 ? Vec2{0.0, mid.z} : a.x == 0.0 ? a : q;
    // (cross(m - prev, base)) (prev.x + next.x) = want, linear in m.z for m on the axis.
    const double xs = prev.x + next.x;
    if (!(xs > 0.0) || base.x == 0.0) return plain;
    const double z = prev.z + (-prev.x * base.z - want / xs) / base.x;
    return std::abs(z - plain.z) <= limit ? Vec2{0.0, z} : plain;
  }
  // (have + s b2) (x0 + s n.x) = want: A s^2 + B s + C = 0, root nearest s = 0.
  const double x0 = prev.x + mid.x + next.x;
  const double A = b2 * n.x, B = have * n.x + x0 * b2, C = have * x0 - want;
  const double disc = B * B - 4.0 * A * C;
  if (!(disc >= 0.0) || B == 0.0) return mid;
  const double s = -2.0 * C / (B + std::copysign(std::sqrt(disc), B));
  const Vec2 m = mid + s * n;
  return s * s * b2 <= limit * limit && m.x > 0.0 ? m : mid;
}

//! Collapses edges shorter than minLen (in place), each into one area-preserving point, walking
//! the line once and re-checking backwards after each collapse. Keeps at least 3 points.
void removeShort(std::vector<Vec2>& p, double minLen, bool rz) {
  const std::size_t n = p.size();
  if (n <= 3) return;
  std::size_t w = 1;  // p[0, w) are kept; p[j, n) are still to be read
  for (std::size_t j = 1; j < n; ++j) {
    p[w++] = p[j];
    // Collapse the last kept edge while it is short.
    while (w >= 2 && w + (n - j - 1) > 3 && norm(p[w - 1] - p[w - 2]) < minLen) {
      const Vec2 prev = w >= 3 ? p[w - 3] : p[n - 1];
      const Vec2 next = j + 1 < n ? p[j + 1] : p[0];
      p[w - 2] = collapse(prev, p[w - 2], p[w - 1], next, minLen, rz);
      --w;
    }
  }
  // The closing edge, from the last kept point back to the first.
  while (w > 3 && norm(p[w - 1] - p[0]) < minLen) {
    p[0] = collapse(p[w - 2], p[w - 1], p[0], p[1], minLen, rz);
    --w;
  }
  p.resize(w);
}

//! Copies p into out, splitting every segment longer than maxLen into m equal parts with
//! m = ceil(L / h) clamped to [ceil(L / maxLen), floor(L / minLen)] (never empty when
//! maxLen >= 2 minLen and L > maxLen), so each part lies in [minLen, maxLen]. The new points
//! lie on the old segment, so the enclosed area does not change.
void splitLong(const std::vector<Vec2>& p, std::vector<Vec2>& out, double h, double minLen,
               double maxLen) {
  out.clear();
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = p[i], b = p[i + 1 == n ? 0 : i + 1];
    out.push_back(a);
    const double len = norm(b - a);
    if (!(len > maxLen)) continue;
    const double m =
        std::clamp(std::ceil(len / h), std::ceil(len / maxLen), std::floor(len / minLen));
    const int parts = static_cast<int>(m);
    for (int q = 1; q < parts; ++q) out.push_back(a + (static_cast<double>(q) / parts) * (b - a));
  }
}

//! The number of points splitLong would make of p, counted without making them.
std::size_t splitCount(const std::vector<Vec2>& p, double h, double minLen, double maxLen) {
  const std::size_t n = p.size();
  double count = static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = norm(p[i + 1 == n ? 0 : i + 1] - p[i]);
    if (len > maxLen)
      count += std::clamp(std::ceil(len / h), std::ceil(len / maxLen), std::floor(len / minLen)) - 1.0;
  }
  return count < 1e18 ? static_cast<std::size_t>(count) : std::size_t{1} << 60;
}

}  // namespace

void MarkerSet::redistribute(const GridSpec& grid) {
  const double c = detail::cellSize(grid);
  const double h = spacingCells_ * c, minLen = minCells_ * c, maxLen = maxCells_ * c;
  const bool rz = geometry_ == Geometry::Axisymmetric;
  checkGrowth(grid, h, minLen, maxLen);
  std::size_t kept = 0;
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    MarkerLine& line = lines_[l];
    const double s = line.scale;
    // Split first, so a collapse sees near neighbours (the end of a filament thinner than the
    // minimum spacing then loses at most a sliver of max spacing by its width), collapse, and
    // split again where a collapse lengthened a neighbouring edge beyond maxLen.
    splitLong(line.points, scratchPoints_, s * h, s * minLen, s * maxLen);
    removeShort(scratchPoints_, s * minLen, rz);
    splitLong(scratchPoints_, line.points, s * h, s * minLen, s * maxLen);
    // A speck below the grid scale can never own a cell; dropping it keeps the count bounded.
    bool speck = line.points.size() < 3;
    if (!speck) {
      const double a = 0.5 * std::abs(detail::twiceSignedArea(line.points));
      if (a < tinyLoopCells_ * c * c) {
        auto [xl, xh] = std::minmax_element(line.points.begin(), line.points.end(),
                                            [](Vec2 u, Vec2 v) { return u.x < v.x; });
        auto [zl, zh] = std::minmax_element(line.points.begin(), line.points.end(),
                                            [](Vec2 u, Vec2 v) { return u.z < v.z; });
        speck = xh->x - xl->x < 2.0 * c && zh->z - zl->z < 2.0 * c;
      }
    }
    if (!speck) {
      if (kept != l) std::swap(lines_[kept], lines_[l]);
      ++kept;
    }
  }
  lines_.resize(kept);
}

// Lines stretch, and the redistribution fills them with points at the marker spacing. A body's
// lines hold of the order of its perimeter in cells over the spacing, far fewer than the cells;
// a line that would need more than kMaxPointsPerCell points per grid cell in all has been
// stretched into a tangle by the flow it follows (a debris cloud's spray: the Whipple shield's
// projectile line at 0.042 cm cells grew from 4 978 points at 23 us to 535 349 at 32.5 us). Such
// a line is coarsened instead of filling the memory: its spacings are doubled (the collapse of
// short edges keeps the volume it encloses, so the phase keeps its volume and mass; what is lost
// is the shape below the new spacing, of a tangle the grid does not resolve anyway), longest
// lines first, until the total is under half the budget, each line at most to kMaxLineScale times
// the set's spacing. A run whose lines cannot be brought under the budget so stops with a
// diagnostic before the points are made (a shield run once filled its memory).
void MarkerSet::checkGrowth(const GridSpec& grid, double h, double minLen, double maxLen) {
  constexpr std::size_t kMaxPointsPerCell = 16, kAllowance = std::size_t{1} << 16;
  const std::size_t limit = kMaxPointsPerCell * static_cast<std::size_t>(grid.cells()) + kAllowance;
  auto split = [&](const MarkerLine& l) {
    return splitCount(l.points, l.scale * h, l.scale * minLen, l.scale * maxLen);
  };
  // Every step: what the splits make of the present points bounds what the redistribution
  // holds after it.
  std::size_t total = 0;
  for (const auto& l : lines_) total += split(l);
  if (total <= limit) return;
  // Over the budget: a line already stretched holds its points now, and only its perimeter over
  // the minimum spacing (every edge the collapse leaves is at least that long) falls when its
  // spacing grows. Each line's count is the smaller of the two, computed once, and again only
  // for the line coarsened.
  std::vector<double> perimeter(lines_.size(), 0.0);
  std::vector<std::size_t> count(lines_.size());
  auto recount = [&](std::size_t i) {
    const double bound = std::ceil(perimeter[i] / (lines_[i].scale * minLen)) + 3.0;
    const std::size_t n = split(lines_[i]);
    count[i] = bound < static_cast<double>(n) ? static_cast<std::size_t>(bound) : n;
  };
  total = 0;
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const auto& p = lines_[i].points;
    for (std::size_t j = 0; j < p.size(); ++j)
      perimeter[i] += norm(p[j + 1 == p.size() ? 0 : j + 1] - p[j]);
    recount(i);
    total += count[i];
  }
  if (total <= limit) return;
  // Coarsen the line with the most points, again and again, until under half the budget.
  while (total > limit / 2) {
    std::size_t longest = lines_.size();
    for (std::size_t i = 0; i < lines_.size(); ++i)
      if (lines_[i].scale < kMaxLineScale &&
          (longest == lines_.size() || count[i] >= count[longest]))
        longest = i;
    if (longest == lines_.size() || count[longest] == 0) break;
    lines_[longest].scale *= 2.0;
    ++coarsenings_;
    total -= count[longest];
    recount(longest);
    total += count[longest];
  }
  if (total <= limit) return;
  const auto most = std::max_element(count.begin(), count.end());
  const MarkerLine& longest = lines_[static_cast<std::size_t>(most - count.begin())];
  auto [xl, xh] = std::minmax_element(longest.points.begin(), longest.points.end(),
                                      [](Vec2 u, Vec2 v) { return u.x < v.x; });
  auto [zl, zh] = std::minmax_element(longest.points.begin(), longest.points.end(),
                                      [](Vec2 u, Vec2 v) { return u.z < v.z; });
  throw SimulationError(fmt::format(
      "tvd: the marker lines would need {} points, more than {} per grid cell ({} cells), even "
      "with the longest lines coarsened to {} times the marker spacing: a line is stretched "
      "without bound by the velocity field; the longest (object {}) would need {} points and "
      "spans x = [{:.6g}, {:.6g}], z = [{:.6g}, {:.6g}] cm",
      total, kMaxPointsPerCell, grid.cells(), kMaxLineScale, longest.object, *most, xl->x, xh->x,
      zl->z, zh->z));
}

double MarkerSet::largestScale() const {
  double s = 1.0;
  for (const auto& l : lines_) s = std::max(s, l.scale);
  return s;
}

}  // namespace hvi::tvd
