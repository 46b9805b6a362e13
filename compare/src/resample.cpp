//! @file Resampling dispatch, native spacing and the covering grid.
#include "hvi/compare/resample.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hvi/common/error.hpp"
#include "resample_detail.hpp"

namespace hvi::compare {

double Resampled::cellVolume(int i) const {
  const double area = grid.dx * grid.dz;
  // Per radian, the annulus r in [a, b] has (b^2 - a^2) / 2 = r_centre (b - a): exact.
  return geometry == Geometry::Axisymmetric ? xCentre(i) * area : area;
}

namespace detail {

const Field& requireField(const Snapshot& s, const std::string& name) {
  const Field* f = s.find(name);
  if (f == nullptr)
    throw InputError(fmt::format("compare: the {} snapshot (solver '{}', t = {} us) has no field "
                                 "'{}'; resampling needs density, material{}",
                                 s.kind == Snapshot::Kind::Grid ? "grid" : "particle", s.solver,
                                 s.time, name,
                                 s.kind == Snapshot::Kind::Grid ? "" : ", mass, smoothing_length"));
  if (f->components != 1 || static_cast<long>(f->data.size()) != s.count())
    throw InputError(fmt::format("compare: field '{}' has {} values of {} components; expected one "
                                 "scalar per {} ({})",
                                 name, f->data.size(), f->components,
                                 s.kind == Snapshot::Kind::Grid ? "cell" : "particle", s.count()));
  return *f;
}

std::vector<std::string> classNames(const std::vector<std::string>& given,
                                    const std::vector<double>* ids, const std::string& prefix) {
  std::vector<std::string> names = given;
  long maxId = -1;
  if (ids != nullptr)
    for (double v : *ids) maxId = std::max(maxId, std::lround(v));
  for (long i = static_cast<long>(names.size()); i <= maxId; ++i)
    names.push_back(fmt::format("{}{}", prefix, i));
  return names;
}

Resampled emptyResult(const Snapshot& s, const GridSpec& grid) {
  if (grid.nx <= 0 || grid.nz <= 0 || !(grid.dx > 0.0) || !(grid.dz > 0.0))
    throw InputError(fmt::format("compare: target grid {} x {} cells of {} x {} cm is empty; "
                                 "cell counts and spacings must be positive",
                                 grid.nx, grid.nz, grid.dx, grid.dz));
  if (s.geometry == Geometry::Axisymmetric && grid.x0 < -1e-12 * grid.dx)
    throw InputError(fmt::format("compare: r-z target grid starts at r = {} cm; it must not "
                                 "reach below the axis r = 0", grid.x0));
  Resampled r;
  r.grid = grid;
  r.geometry = s.geometry;
  r.time = s.time;
  r.solver = s.solver;
  const auto n = static_cast<std::size_t>(grid.cells());
  r.density.assign(n, 0.0);
  r.fraction.assign(n, 0.0);
  r.material.assign(n, -1);
  r.object.assign(n, -1);
  const Field* mat = s.find("material");
  const Field* obj = s.find("object");
  r.materialNames = classNames(s.materialNames, mat ? &mat->data : nullptr, "material");
  r.objectNames = classNames(s.objectNames, obj ? &obj->data : nullptr, "object");
  r.hasObject = obj != nullptr;
  r.materialDensity.assign(n * std::max<std::size_t>(1, r.materialNames.size()), 0.0);
  if (r.hasObject) r.objectDensity.assign(n * r.objectNames.size(), 0.0);
  return r;
}

}  // namespace detail

const char* toString(SphReconstruction r) {
  return r == SphReconstruction::Constant ? "constant" : "adaptive";
}

SphReconstruction parseSphReconstruction(const std::string& name) {
  if (name == "constant") return SphReconstruction::Constant;
  if (name == "adaptive") return SphReconstruction::Adaptive;
  throw InputError(fmt::format("compare: SPH reconstruction '{}' is not known (allowed: constant, "
                               "adaptive)",
                               name));
}

Resampled resample(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt) {
  if (!(opt.materialThreshold > 0.0 && opt.materialThreshold <= 1.0))
    throw InputError(fmt::format("compare: material threshold {} must lie in (0, 1]",
                                 opt.materialThreshold));
  if (!(opt.adaptiveMaxFactor >= 1.0 && opt.adaptiveMaxFactor <= 16.0))
    throw InputError(fmt::format("compare: adaptive reconstruction factor {} must lie in [1, 16]",
                                 opt.adaptiveMaxFactor));
  return s.kind == Snapshot::Kind::Particles ? detail::resampleParticles(s, grid, opt)
                                             : detail::resampleGrid(s, grid, opt);
}

namespace {

struct Box {
  double xmin, xmax, zmin, zmax;
};

double maxSmoothingLength(const Snapshot& s) {
  const Field& h = detail::requireField(s, "smoothing_length");
  double hmax = 0.0;
  for (double v : h.data) hmax = std::max(hmax, v);
  return hmax;
}

Box extent(const Snapshot& s) {
  if (s.kind == Snapshot::Kind::Grid) {
    const GridSpec& g = s.grid;
    return {g.x0, g.x0 + g.nx * g.dx, g.z0, g.z0 + g.nz * g.dz};
  }
  if (s.positions.empty())
    throw InputError(fmt::format("compare: the particle snapshot (solver '{}', t = {} us) has no "
                                 "particles", s.solver, s.time));
  const double pad = 2.0 * maxSmoothingLength(s);
  Box b{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
        std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
  for (const Vec2& p : s.positions) {
    b.xmin = std::min(b.xmin, p.x);
    b.xmax = std::max(b.xmax, p.x);
    b.zmin = std::min(b.zmin, p.z);
    b.zmax = std::max(b.zmax, p.z);
  }
  return {b.xmin - pad, b.xmax + pad, b.zmin - pad, b.zmax + pad};
}

bool sameSpacing(const Snapshot& s, double d) {
  return s.kind == Snapshot::Kind::Grid && std::abs(s.grid.dx - d) <= 1e-9 * d &&
         std::abs(s.grid.dz - d) <= 1e-9 * d;
}

GridSpec cover(Box box, Geometry geom, const Snapshot* anchor, double d) {
  if (!(d > 0.0) || !std::isfinite(d))
    throw InputError(fmt::format("compare: grid spacing {} cm must be positive", d));
  const bool rz = geom == Geometry::Axisymmetric;
  if (rz) box.xmin = 0.0;  // the resampled field always reaches the axis
  double ax = rz ? 0.0 : box.xmin, az = box.zmin;
  if (anchor != nullptr) {
    ax = anchor->grid.x0;
    az = anchor->grid.z0;
  }
  // Whole cells from the anchor down to the box corner; the 1e-9 keeps round-off from adding one.
  GridSpec g;
  g.dx = g.dz = d;
  g.x0 = ax - std::max(0.0, std::ceil((ax - box.xmin) / d - 1e-9)) * d;
  g.z0 = az - std::max(0.0, std::ceil((az - box.zmin) / d - 1e-9)) * d;
  if (rz) g.x0 = std::max(g.x0, 0.0);
  const double cellsX = std::ceil((box.xmax - g.x0) / d - 1e-9);
  const double cellsZ = std::ceil((box.zmax - g.z0) / d - 1e-9);
  // ~110 bytes per cell in a comparison (two resampled fields and the difference snapshot), plus
  // 16 per class (materials and objects: each side's partial densities).
  if (cellsX * cellsZ > 2.0e7)
    throw InputError(fmt::format("compare: a {} cm grid over [{}, {}] x [{}, {}] cm has {:.3g} "
                                 "cells; choose a coarser --spacing",
                                 d, box.xmin, box.xmax, box.zmin, box.zmax, cellsX * cellsZ));
  g.nx = std::max(1, static_cast<int>(cellsX));
  g.nz = std::max(1, static_cast<int>(cellsZ));
  return g;
}

}  // namespace

double nativeSpacing(const Snapshot& s) {
  if (s.kind == Snapshot::Kind::Grid) return std::max(s.grid.dx, s.grid.dz);
  const auto n = static_cast<long>(s.positions.size());
  if (n < 2)
    throw InputError("compare: cannot infer a particle spacing from fewer than two particles");
  // Bins of twice the largest h hold every nearest neighbour of a lattice with h >= spacing / 2.
  const double bin = 2.0 * maxSmoothingLength(s);
  const Box b = extent(s);
  const int nbx = static_cast<int>((b.xmax - b.xmin) / bin) + 1;
  const int nbz = static_cast<int>((b.zmax - b.zmin) / bin) + 1;
  std::vector<int> start(static_cast<std::size_t>(nbx) * nbz + 1, 0), order(n);
  auto binOf = [&](Vec2 p) {
    const int i = std::clamp(static_cast<int>((p.x - b.xmin) / bin), 0, nbx - 1);
    const int k = std::clamp(static_cast<int>((p.z - b.zmin) / bin), 0, nbz - 1);
    return k * nbx + i;
  };
  for (const Vec2& p : s.positions) ++start[binOf(p) + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (long j = 0; j < n; ++j) order[fill[binOf(s.positions[j])]++] = static_cast<int>(j);

  const long stride = std::max(1L, n / 4096);  // a sample is enough for a median
  std::vector<double> nearest;
  for (long j = 0; j < n; j += stride) {
    const Vec2 p = s.positions[j];
    const int c = binOf(p), bi = c % nbx, bk = c / nbx;
    double best = std::numeric_limits<double>::max();
    for (int k = std::max(0, bk - 1); k <= std::min(nbz - 1, bk + 1); ++k)
      for (int i = std::max(0, bi - 1); i <= std::min(nbx - 1, bi + 1); ++i)
        for (int q = start[k * nbx + i]; q < start[k * nbx + i + 1]; ++q) {
          const double d2 = dot(s.positions[order[q]] - p, s.positions[order[q]] - p);
          if (order[q] != j && d2 > 0.0) best = std::min(best, d2);
        }
    if (best < std::numeric_limits<double>::max()) nearest.push_back(std::sqrt(best));
  }
  if (nearest.empty())
    throw InputError("compare: no two particles lie within 2 h of each other; cannot infer the "
                     "particle spacing (give --spacing)");
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

GridSpec coveringGrid(const Snapshot& s, double spacing) {
  return cover(extent(s), s.geometry, sameSpacing(s, spacing) ? &s : nullptr, spacing);
}

GridSpec coveringGrid(const Snapshot& a, const Snapshot& b, double spacing) {
  if (a.geometry != b.geometry)
    throw InputError(fmt::format("compare: cannot compare a {} snapshot with a {} one",
                                 toString(a.geometry), toString(b.geometry)));
  const Box ea = extent(a), eb = extent(b);
  const Box u{std::min(ea.xmin, eb.xmin), std::max(ea.xmax, eb.xmax), std::min(ea.zmin, eb.zmin),
              std::max(ea.zmax, eb.zmax)};
  const Snapshot* anchor = sameSpacing(a, spacing) ? &a : sameSpacing(b, spacing) ? &b : nullptr;
  return cover(u, a.geometry, anchor, spacing);
}

}  // namespace hvi::compare
