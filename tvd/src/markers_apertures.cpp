//! @file Exact one-sided face apertures of the marker objects (docs/markers.md, "Face apertures").
//!
//! On a grid line the winding number of a point is the signed count of the object's segments
//! that cross the line before it (below it on a vertical line, left of it on a horizontal one).
//! Per object and grid line the crossings are bucketed (counting sort over the lines), sorted
//! along the line and swept once: the runs where the winding is nonzero are the wet parts of the
//! line, added face by face. The two one-sided limits differ only in which segments ending
//! exactly on the line count as crossing it (half-open rules below), so one sorted bucket serves
//! both. Cost O(segments + crossings + faces), plus the sort of each line's crossings.
#include <algorithm>
#include <cmath>

#include "hvi/tvd/marker_geometry.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd {
namespace {

//! One family of grid lines in cell units: lines at across = 0 .. lines-1, each cut into faces
//! [f, f+1] along it, f = 0 .. faces-1; face (line, f) of a side is out[side * sideStride +
//! line * lineStride + f * faceStride].
struct Family {
  bool vertical;  // x faces: across = u (x), along = w (z); else across = w, along = u
  int lines, faces;
  long lineStride, faceStride, sideStride;
  //! Winding change, along the line, of a crossing in the +across direction. The object lies to
  //! the left of travel: a segment crossing a vertical line in +x has it above (+1); one crossing
  //! a horizontal line in +z has it at smaller x, i.e. before the crossing along the line (-1).
  int forward;
  double across(Vec2 p) const { return vertical ? p.x : p.z; }
  double along(Vec2 p) const { return vertical ? p.z : p.x; }
};

//! Adds the wet run [lo, hi] (along the line, cells) to the line's faces, capped at 1 (the sum
//! of disjoint runs in a face can exceed 1 by rounding only), and widens the line's wet span
//! [first, end) of faces to hold the run.
void addRun(double lo, double hi, const Family& fam, double* line, int& first, int& end) {
  lo = std::max(lo, 0.0);
  hi = std::min(hi, static_cast<double>(fam.faces));
  if (!(hi > lo)) return;
  const int f0 = static_cast<int>(std::floor(lo));
  const int f1 = static_cast<int>(std::ceil(hi)) - 1;
  first = std::min(first, f0);
  end = std::max(end, f1 + 1);
  for (int f = f0; f <= f1; ++f) {
    double& a = line[static_cast<long>(f) * fam.faceStride];
    a = std::min(1.0, a + (std::min(hi, f + 1.0) - std::max(lo, static_cast<double>(f))));
  }
}

}  // namespace

void MarkerSet::rowSpan(const GridSpec& g, int& lo, int& hi) const {
  double wl = 1e300, wh = -1e300;
  for (const auto& l : lines_)
    for (Vec2 p : l.points) {
      const double w = std::clamp(detail::toCellUnits(g, p).z, 0.0, static_cast<double>(g.nz));
      wl = std::min(wl, w);
      wh = std::max(wh, w);
    }
  if (wl > wh || g.nz <= 0) {
    lo = hi = 0;
    return;
  }
  auto rowOf = [&](double v) { return std::clamp(static_cast<int>(std::floor(v)), 0, g.nz - 1); };
  lo = rowOf(wl);
  hi = rowOf(wh) + 1;
}

void MarkerSet::faceApertures(const GridSpec& grid, FaceApertures& out) const {
  const int nx = std::max(grid.nx, 0), nz = std::max(grid.nz, 0);
  const long xPerSide = static_cast<long>(nx + 1) * nz, zPerSide = static_cast<long>(nz + 1) * nx;
  const auto xSize = static_cast<std::size_t>(2L * objects_ * xPerSide);
  const auto zSize = static_cast<std::size_t>(2L * objects_ * zPerSide);
  const auto xSpans = static_cast<std::size_t>(4L * objects_ * (nx + 1));
  const auto zSpans = static_cast<std::size_t>(4L * objects_ * (nz + 1));
  // The same layout as the previous call: its wet spans bound every nonzero face, so only they
  // are cleared (line by line, just before the line is written); else everything is.
  const bool sized = out.nx == nx && out.nz == nz && out.objects == objects_ &&
                     out.x.size() == xSize && out.z.size() == zSize && out.xSpan.size() == xSpans &&
                     out.zSpan.size() == zSpans;
  out.nx = nx;
  out.nz = nz;
  out.objects = objects_;
  if (!sized) {
    out.x.assign(xSize, 0.0);
    out.z.assign(zSize, 0.0);
    out.xSpan.assign(xSpans, 0);
    out.zSpan.assign(zSpans, 0);
  }
  if (nx == 0 || nz == 0) return;
  const Family families[2] = {
      {true, nx + 1, nz, 1, nx + 1, xPerSide, +1},
      {false, nz + 1, nx, nx, 1, zPerSide, -1},
  };
  const auto starts = static_cast<std::size_t>(std::max(nx, nz) + 2);
  if (crossingStart_.size() < starts) crossingStart_.resize(starts);

  for (int obj = 0; obj < objects_; ++obj) {
    for (int fi = 0; fi < 2; ++fi) {
      const Family& fam = families[fi];
      double* base = (fam.vertical ? out.x.data() : out.z.data()) + 2L * obj * fam.sideStride;
      int* span = (fam.vertical ? out.xSpan.data() : out.zSpan.data()) + 4L * obj * fam.lines;
      long* start = crossingStart_.data();
      std::fill(start, start + fam.lines + 1, 0L);

      // Calls f(line, crossing) for every grid line the segment a-b crosses or touches with an
      // end. Side 0 (the limit from below across) counts a segment with min < line <= max, side
      // 1 one with min <= line < max; a segment along a line is in neither. The crossing is
      // interpolated between the ends ordered by `across`, so it is exact at an end on the line
      // and the same for the segment run either way (coinciding opposite edges cancel exactly).
      auto forCrossings = [&](Vec2 a, Vec2 b, auto&& f) {
        if (!std::isfinite(a.x) || !std::isfinite(a.z) || !std::isfinite(b.x) ||
            !std::isfinite(b.z))
          return;  // only a broken state has such markers (advect throws on them)
        const double ca = fam.across(a), cb = fam.across(b);
        if (ca == cb) return;
        const Vec2 p = ca < cb ? a : b, q = ca < cb ? b : a;
        const double lo = fam.across(p), hi = fam.across(q);
        const double first = std::max(std::ceil(lo), 0.0);
        const double last = std::min(std::floor(hi), static_cast<double>(fam.lines - 1));
        if (first > last) return;
        const int winding = cb > ca ? fam.forward : -fam.forward;
        const double slope = (fam.along(q) - fam.along(p)) / (hi - lo);
        for (int line = static_cast<int>(first); line <= static_cast<int>(last); ++line) {
          const double c = line;
          const double at = c == lo   ? fam.along(p)
                            : c == hi ? fam.along(q)
                                      : fam.along(p) + (c - lo) * slope;
          f(line, LineCrossing{at, winding, (c > lo ? 1 : 0) | (c < hi ? 2 : 0)});
        }
      };
      auto forSegments = [&](auto&& f) {
        for (const auto& l : lines_) {
          if (l.object != obj) continue;
          const std::size_t n = l.points.size();
          if (n < 3) continue;  // as rasterize: a line needs three points to enclose anything
          for (std::size_t j = 0; j < n; ++j)
            forCrossings(detail::toCellUnits(grid, l.points[j]),
                         detail::toCellUnits(grid, l.points[j + 1 == n ? 0 : j + 1]), f);
        }
      };

      // Counting sort: counts into start[line + 1], prefix sums, then filling with start[line]++
      // leaves start[line] at the end of the line's bucket (its beginning is start[line - 1]).
      forSegments([&](int line, const LineCrossing&) { ++start[line + 1]; });
      for (int line = 0; line < fam.lines; ++line) start[line + 1] += start[line];
      const auto total = static_cast<std::size_t>(start[fam.lines]);
      if (crossings_.size() < total) crossings_.resize(total);
      LineCrossing* cross = crossings_.data();
      forSegments([&](int line, const LineCrossing& c) { cross[start[line]++] = c; });

      const long work = static_cast<long>(fam.lines) * fam.faces;
#pragma omp parallel for schedule(static) if (work >= kParallelStream)
      for (int line = 0; line < fam.lines; ++line) {
        LineCrossing* b = cross + (line == 0 ? 0 : start[line - 1]);
        LineCrossing* e = cross + start[line];
        // A total order (equal keys are identical crossings), so the result does not depend on
        // the sort's internal order or on the thread count.
        std::sort(b, e, [](const LineCrossing& u, const LineCrossing& v) {
          if (u.at != v.at) return u.at < v.at;
          if (u.winding != v.winding) return u.winding < v.winding;
          return u.sides < v.sides;
        });
        for (int side = 0; side < 2; ++side) {
          double* a = base + side * fam.sideStride + line * fam.lineStride;
          int* s = span + 2L * (static_cast<long>(side) * fam.lines + line);
          for (long f = s[0]; f < s[1]; ++f) a[f * fam.faceStride] = 0.0;
          int w = 0;
          double runStart = 0.0;
          int first = fam.faces, end = 0;
          for (const LineCrossing* c = b; c != e; ++c) {
            if (!((c->sides >> side) & 1)) continue;
            const int next = w + c->winding;
            if (w == 0 && next != 0) runStart = c->at;
            if (w != 0 && next == 0) addRun(runStart, c->at, fam, a, first, end);
            w = next;
          }
          s[0] = first;
          s[1] = end;
          // A closed line crosses every line as often each way (the half-open rule classifies
          // each vertex as before or after the line), so w ends at 0.
        }
      }
    }
  }
}

}  // namespace hvi::tvd
