//! @file Grid to grid: exact area-overlap (r-z: volume-overlap) averaging of cell data.
#include <algorithm>
#include <cmath>
#include <vector>

#include "hvi/common/error.hpp"
#include "resample_detail.hpp"

namespace hvi::compare::detail {
namespace {

//! For each target interval along one axis, the source intervals it overlaps and the weights:
//! overlap length, or int r dr = (b^2 - a^2) / 2 in the radial direction (exact for volumes).
struct Overlap {
  std::vector<int> start, src;
  std::vector<double> w;
  std::vector<double> full;  // weight of the whole target interval
};

Overlap overlap1d(double t0, double dt, int nt, double s0, double ds, int ns, bool radial) {
  auto weight = [radial](double a, double b) { return radial ? 0.5 * (b * b - a * a) : b - a; };
  Overlap o;
  o.start.reserve(nt + 1);
  o.start.push_back(0);
  for (int t = 0; t < nt; ++t) {
    const double a = t0 + t * dt, b = t0 + (t + 1) * dt;
    o.full.push_back(weight(a, b));
    const int first = std::max(0, static_cast<int>(std::floor((a - s0) / ds)));
    const int last = std::min(ns - 1, static_cast<int>(std::floor((b - s0) / ds)));
    for (int s = first; s <= last; ++s) {
      const double lo = std::max(a, s0 + s * ds), hi = std::min(b, s0 + (s + 1) * ds);
      if (hi > lo) {
        o.src.push_back(s);
        o.w.push_back(weight(lo, hi));
      }
    }
    o.start.push_back(static_cast<int>(o.src.size()));
  }
  return o;
}

}  // namespace

Resampled resampleGrid(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt) {
  Resampled out = emptyResult(s, grid);
  const GridSpec& g = s.grid;
  if (g.nx <= 0 || g.nz <= 0 || !(g.dx > 0.0) || !(g.dz > 0.0))
    throw InputError("compare: the grid snapshot has an empty grid (no cells or zero spacing)");
  const Field& rho = requireField(s, "density");
  const Field* mat = s.find("material");
  if (mat != nullptr) mat = &requireField(s, "material");
  const Field* obj = s.find("object");
  if (obj != nullptr) obj = &requireField(s, "object");
  if (mat == nullptr && out.materialNames.empty()) out.materialNames.push_back("material0");
  const bool rz = s.geometry == Geometry::Axisymmetric;
  const Overlap ox = overlap1d(grid.x0, grid.dx, grid.nx, g.x0, g.dx, g.nx, rz);
  const Overlap oz = overlap1d(grid.z0, grid.dz, grid.nz, g.z0, g.dz, g.nz, false);
  const std::size_t nMat = out.materialNames.size(), nObj = out.objectNames.size();

#pragma omp parallel
  {
    // Once per thread, reused for every cell: covered areas and masses per class.
    std::vector<double> matW(nMat), objW(nObj), matM(nMat), objM(nObj);
    const bool objects = !out.objectDensity.empty();
    const auto cells = static_cast<std::size_t>(grid.cells());
#pragma omp for schedule(static)
    for (int k = 0; k < grid.nz; ++k) {
      for (int i = 0; i < grid.nx; ++i) {
        double mass = 0.0, filled = 0.0;
        std::fill(matW.begin(), matW.end(), 0.0);
        std::fill(objW.begin(), objW.end(), 0.0);
        std::fill(matM.begin(), matM.end(), 0.0);
        std::fill(objM.begin(), objM.end(), 0.0);
        for (int a = oz.start[k]; a < oz.start[k + 1]; ++a) {
          const long row = static_cast<long>(oz.src[a]) * g.nx;
          for (int b = ox.start[i]; b < ox.start[i + 1]; ++b) {
            const long sc = row + ox.src[b];
            const double w = oz.w[a] * ox.w[b];
            mass += w * rho.data[sc];
            // Without a material field every cell holding matter is material 0.
            const int m = mat ? static_cast<int>(std::lround(mat->data[sc]))
                              : (rho.data[sc] > 0.0 ? 0 : -1);
            if (m < 0) continue;
            filled += w;
            matW[m] += w;
            matM[m] += w * rho.data[sc];
            const int ob = obj ? static_cast<int>(std::lround(obj->data[sc])) : -1;
            if (ob >= 0) objW[ob] += w, objM[ob] += w * rho.data[sc];
          }
        }
        const double vol = oz.full[k] * ox.full[i];
        const long cell = static_cast<long>(k) * grid.nx + i;
        // Uncovered parts of the target cell are vacuum: density 0, so mass is conserved.
        out.density[cell] = mass / vol;
        out.fraction[cell] = filled / vol;
        // Partial densities for every cell, material or not, so that each class's mass is
        // conserved like the total.
        for (std::size_t m = 0; m < nMat; ++m) out.materialDensity[m * cells + cell] = matM[m] / vol;
        if (objects)
          for (std::size_t o = 0; o < nObj; ++o) out.objectDensity[o * cells + cell] = objM[o] / vol;
        if (out.fraction[cell] >= opt.materialThreshold) {
          out.material[cell] = static_cast<int>(std::max_element(matW.begin(), matW.end()) -
                                                matW.begin());
          if (nObj > 0) {
            const auto it = std::max_element(objW.begin(), objW.end());
            out.object[cell] = *it > 0.0 ? static_cast<int>(it - objW.begin()) : -1;
          }
        }
      }
    }
  }
  return out;
}

}  // namespace hvi::compare::detail
