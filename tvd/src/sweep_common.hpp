//! @file What the whole-cell and the cut-cell sweep drivers share: line geometry, the report
//! of a failed cell, the boundary sides.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/geometry.hpp"
#include "hvi/common/snapshot.hpp"
#include "line_work.hpp"

namespace hvi::tvd::detail {

//! The lines of one sweep direction (0: x, 1: z) of a grid.
struct SweepShape {
  bool xdir;    //!< lines along x
  int N;        //!< cells per line
  int lines;    //!< lines
  long step;    //!< cell index stride along a line
  bool rz;      //!< r-z geometry
  bool radial;  //!< radial lines of an r-z grid (areas r_f, hoop source)
  double h;     //!< cell size
};
inline SweepShape sweepShape(const GridSpec& g, Geometry geometry, int direction) {
  const bool xdir = direction == 0, rz = geometry == Geometry::Axisymmetric;
  return {xdir,
          xdir ? g.nx : g.nz,
          xdir ? g.nz : g.nx,
          xdir ? 1L : static_cast<long>(g.nx),
          rz,
          xdir && rz,
          g.dx};
}

inline Side sideOf(cases::Boundary b) {
  return b == cases::Boundary::Outflow ? Side::Outflow : Side::Reflect;
}

//! Widens [a, b) to the domain edge when within two cells of it and says what lies beyond each
//! end.
inline void finishWindow(int N, Side low, Side high, int& a, int b, LineSetup& setup) {
  if (a <= 2) a = 0;
  if (b >= N - 2) b = N;
  setup.n = b - a;
  setup.left = a == 0 ? low : Side::Loaded;
  setup.right = b == N ? high : Side::Loaded;
  setup.leftEdge = a == 0;
  setup.rightEdge = b == N;
}

//! The span of a line the kernel updates: from its first to its last occupied cell (the rest of
//! a marker run's line is empty), widened to the domain edge when within two cells of it, and
//! what lies beyond each end. False if no cell is occupied. Cells outside [lo, hi) are known to
//! be empty and not looked at.
template <class Occupied>
inline bool lineWindow(int N, Side low, Side high, Occupied occupied, int& a, LineSetup& setup,
                       int lo = 0, int hi = -1) {
  if (hi < 0) hi = N;
  a = lo;
  int b = hi;
  while (a < hi && !occupied(a)) ++a;
  if (a == hi) return false;
  while (!occupied(b - 1)) --b;
  finishWindow(N, low, high, a, b, setup);
  return true;
}

//! The cell a buffer position `pos` (possibly beyond the line's ends) takes its data from: its
//! mirror image beyond a reflecting end, the edge cell beyond an outflow end. `mirrored` tells
//! a reflection (the normal components change sign).
inline int ghostSource(int pos, int N, Side low, Side high, bool& mirrored) {
  mirrored = false;
  if (pos < 0) {
    mirrored = low == Side::Reflect;
    return mirrored ? -1 - pos : 0;
  }
  if (pos >= N) {
    mirrored = high == Side::Reflect;
    return mirrored ? 2 * N - 1 - pos : N - 1;
  }
  return pos;
}

//! Geometry of a loaded line in line units (cells a .. a+n-1 at buffer 2 .. n+1): r-z radial
//! lines have face areas r_f and volumes r_j dr, every other line 1 and dr. Returns the factor
//! from line units to the solver's (planar per cm of depth, r-z with 2 pi r).
inline double lineGeometry(bool radial, bool rz, double h, int a, int n, int line,
                           const std::vector<double>& faceX, const std::vector<double>& cellX,
                           std::vector<double>& area, std::vector<double>& invVol,
                           std::vector<double>& invR) {
  if (radial) {
    for (int f = 1; f <= n + 1; ++f) area[f] = faceX[static_cast<std::size_t>(a - 1 + f)];
    for (int j = 2; j <= n + 1; ++j) {
      const double r = cellX[static_cast<std::size_t>(a - 2 + j)];
      invVol[j] = 1.0 / (r * h);
      invR[j] = 1.0 / r;
    }
    return 2.0 * std::numbers::pi * h;
  }
  std::fill(area.begin(), area.begin() + n + 4, 1.0);
  std::fill(invVol.begin(), invVol.begin() + n + 4, 1.0 / h);
  return rz ? 2.0 * std::numbers::pi * cellX[static_cast<std::size_t>(line)] * h : h;
}

//! The report of a cell the line kernel could not keep physical (buffer index fail.j of a
//! line loaded from cell a).
inline std::string failureMessage(long step, bool xdir, double dt, int a, int line,
                                  const GridSpec& g, const LineFailure& fail) {
  const int pos = a - 2 + fail.j;
  const int i = xdir ? pos : line, k = xdir ? line : pos;
  return fmt::format(
      "tvd: step {} ({} sweep, dt = {:.4g} us): cell (i={}, k={}) at x = {:.6g}, z = {:.6g} "
      "cm: {} (rho = {:.6g} g/cm^3, e = {:.6g} cm^2/us^2)",
      step, xdir ? "x" : "z", dt, i, k, g.x0 + (i + 0.5) * g.dx, g.z0 + (k + 0.5) * g.dz, fail.what,
      fail.rho, fail.e);
}

}  // namespace hvi::tvd::detail
