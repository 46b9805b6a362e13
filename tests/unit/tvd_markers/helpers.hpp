//! @file Small helpers shared by the marker-line tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "hvi/tvd/markers.hpp"

namespace hvi::tvd::test {

inline GridSpec makeGrid(int nx, int nz, double x0, double z0, double d) {
  GridSpec g;
  g.nx = nx;
  g.nz = nz;
  g.x0 = x0;
  g.z0 = z0;
  g.dx = d;
  g.dz = d;
  return g;
}

//! Cell-centred samples of an analytic velocity field.
struct Field {
  std::vector<double> vx, vz;
  template <class F>
  Field(const GridSpec& g, F&& f) : vx(static_cast<std::size_t>(g.cells())), vz(vx.size()) {
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) {
        const Vec2 v = f(Vec2{g.x0 + (i + 0.5) * g.dx, g.z0 + (k + 0.5) * g.dz});
        const auto c = static_cast<std::size_t>(k) * g.nx + i;
        vx[c] = v.x;
        vz[c] = v.z;
      }
  }
};

struct Spacing {
  double min = 1e300, max = 0.0;
};
inline Spacing spacing(const MarkerSet& s) {
  Spacing r;
  for (const auto& l : s.lines()) {
    const auto& p = l.points;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const double d = norm(p[(j + 1) % p.size()] - p[j]);
      r.min = std::min(r.min, d);
      r.max = std::max(r.max, d);
    }
  }
  return r;
}

}  // namespace hvi::tvd::test
