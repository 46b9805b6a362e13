//! @file Particles to grid: Shepard-normalised Gaussian SPH interpolation with a cell list.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "hvi/common/error.hpp"
#include "resample_detail.hpp"

namespace hvi::compare::detail {
namespace {

//! Particles in bin order (structure of arrays) with the bin index over them.
struct Cloud {
  std::vector<double> x, z, invH2, norm, vol, rho;  // norm = 1 / (pi h^2), invH2 = 1 / h^2
  std::vector<double> cut2;                         // (support h)^2
  std::vector<int> mat, obj;
  double bx0 = 0.0, bz0 = 0.0, bin = 1.0;
  int nbx = 1, nbz = 1;
  std::vector<int> start;  // particles of bin c are [start[c], start[c+1])
};

//! Calls f(j, w) for each particle j whose kernel reaches (px, pz), w = V_j W(|p - x_j|, h_j);
//! in r-z also for the images mirrored across the axis, which a point near r = 0 must see.
template <class F>
void gather(const Cloud& c, double px, double pz, bool mirror, F&& f) {
  auto scan = [&](double qx) {
    const int i0 = std::max(0, static_cast<int>(std::floor((qx - c.bx0) / c.bin)) - 1);
    const int i1 = std::min(c.nbx - 1, static_cast<int>(std::floor((qx - c.bx0) / c.bin)) + 1);
    const int k0 = std::max(0, static_cast<int>(std::floor((pz - c.bz0) / c.bin)) - 1);
    const int k1 = std::min(c.nbz - 1, static_cast<int>(std::floor((pz - c.bz0) / c.bin)) + 1);
    for (int k = k0; k <= k1; ++k)
      for (int q = c.start[k * c.nbx + i0]; i0 <= i1 && q < c.start[k * c.nbx + i1 + 1]; ++q) {
        const double ddx = qx - c.x[q], ddz = pz - c.z[q];
        const double r2 = ddx * ddx + ddz * ddz;
        if (r2 < c.cut2[q]) f(q, c.vol[q] * c.norm[q] * std::exp(-r2 * c.invH2[q]));
      }
  };
  scan(px);
  if (mirror && px < c.bin) scan(-px);
}

Cloud buildCloud(const Snapshot& s, const ResampleOptions& opt) {
  const Field& rho = requireField(s, "density");
  const Field& h = requireField(s, "smoothing_length");
  const Field& mat = requireField(s, "material");
  const Field* obj = s.find("object");
  if (obj != nullptr) obj = &requireField(s, "object");
  const Field* volume = s.find("volume");
  const Field* mass = volume != nullptr ? &requireField(s, "volume") : &requireField(s, "mass");
  const bool rz = s.geometry == Geometry::Axisymmetric;

  const auto n = static_cast<long>(s.positions.size());
  double hmax = 0.0, xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
  long kept = 0;
  std::vector<char> keep(n, 0);
  for (long j = 0; j < n; ++j) {
    const Vec2 p = s.positions[j];
    // A particle with no mass or an unusable state contributes nothing (deleted particles).
    if (!(rho.data[j] > 0.0) || !(h.data[j] > 0.0) || !(mass->data[j] > 0.0) ||
        mat.data[j] < 0.0 || !std::isfinite(p.x) || !std::isfinite(p.z))
      continue;
    keep[j] = 1;
    ++kept;
    hmax = std::max(hmax, h.data[j]);
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    zmin = std::min(zmin, p.z), zmax = std::max(zmax, p.z);
  }
  Cloud c;
  c.bin = opt.kernelSupport * std::max(hmax, 1e-300);
  c.bx0 = xmin, c.bz0 = zmin;
  c.nbx = kept ? static_cast<int>((xmax - xmin) / c.bin) + 1 : 1;
  c.nbz = kept ? static_cast<int>((zmax - zmin) / c.bin) + 1 : 1;
  c.start.assign(static_cast<std::size_t>(c.nbx) * c.nbz + 1, 0);
  auto binOf = [&](Vec2 p) {
    const int i = std::clamp(static_cast<int>((p.x - c.bx0) / c.bin), 0, c.nbx - 1);
    const int k = std::clamp(static_cast<int>((p.z - c.bz0) / c.bin), 0, c.nbz - 1);
    return k * c.nbx + i;
  };
  for (long j = 0; j < n; ++j)
    if (keep[j]) ++c.start[binOf(s.positions[j]) + 1];
  for (std::size_t b = 1; b < c.start.size(); ++b) c.start[b] += c.start[b - 1];
  std::vector<int> fill(c.start.begin(), c.start.end() - 1);
  for (auto* v : {&c.x, &c.z, &c.invH2, &c.norm, &c.vol, &c.rho, &c.cut2}) v->resize(kept);
  c.mat.resize(kept);
  c.obj.resize(kept);
  for (long j = 0; j < n; ++j) {
    if (!keep[j]) continue;
    const int q = fill[binOf(s.positions[j])]++;
    const double hj = h.data[j];
    c.x[q] = s.positions[j].x, c.z[q] = s.positions[j].z;
    c.invH2[q] = 1.0 / (hj * hj);
    c.norm[q] = 1.0 / (std::numbers::pi * hj * hj);
    c.cut2[q] = opt.kernelSupport * opt.kernelSupport * hj * hj;
    c.rho[q] = rho.data[j];
    // Planar: area m / rho. r-z: meridional area m / (rho r), scaled below by the convention.
    const double v = volume ? volume->data[j] : mass->data[j] / rho.data[j];
    c.vol[q] = (rz && !volume) ? v / std::max(std::abs(c.x[q]), 1e-6 * hj) : v;
    c.mat[q] = static_cast<int>(std::lround(mat.data[j]));
    c.obj[q] = obj ? static_cast<int>(std::lround(obj->data[j])) : -1;
  }
  if (rz && !volume && kept > 0) {
    double ring = 2.0 * std::numbers::pi;
    if (opt.rzMass == RzMass::PerRadian) ring = 1.0;
    if (opt.rzMass == RzMass::Auto) {
      // The kernel sum of the volumes is ~1 inside a body (~1/2 at its surface): with m / (rho r)
      // it is ~2 pi for ring masses and ~1 for per-radian masses; sqrt(2 pi) separates the two.
      const long stride = std::max(1L, kept / 2048);
      std::vector<double> sums;
      for (long q = 0; q < kept; q += stride) {
        double sum = 0.0;
        gather(c, c.x[q], c.z[q], true, [&](int, double w) { sum += w; });
        sums.push_back(sum);
      }
      std::nth_element(sums.begin(), sums.begin() + sums.size() / 2, sums.end());
      if (sums[sums.size() / 2] < std::sqrt(2.0 * std::numbers::pi)) ring = 1.0;
    }
    for (double& v : c.vol) v /= ring;
  }
  return c;
}

int argmax(const std::vector<double>& w) {
  int best = -1;
  double wBest = 0.0;
  for (std::size_t m = 0; m < w.size(); ++m)
    if (w[m] > wBest) best = static_cast<int>(m), wBest = w[m];
  return best;
}

}  // namespace

Resampled resampleParticles(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt) {
  Resampled out = emptyResult(s, grid);
  const Cloud c = buildCloud(s, opt);
  if (c.x.empty()) return out;
  const bool mirror = s.geometry == Geometry::Axisymmetric;
  const std::size_t nMat = out.materialNames.size(), nObj = out.objectNames.size();

#pragma omp parallel
  {
    std::vector<double> matW(nMat), objW(nObj);  // once per thread, reused for every cell
#pragma omp for schedule(dynamic, 4)
    for (int k = 0; k < grid.nz; ++k) {
      const double pz = out.zCentre(k);
      for (int i = 0; i < grid.nx; ++i) {
        const double px = out.xCentre(i);
        double sumW = 0.0, sumRho = 0.0;
        std::fill(matW.begin(), matW.end(), 0.0);
        std::fill(objW.begin(), objW.end(), 0.0);
        gather(c, px, pz, mirror, [&](int q, double w) {
          sumW += w;
          sumRho += w * c.rho[q];
          matW[c.mat[q]] += w;
          if (c.obj[q] >= 0) objW[c.obj[q]] += w;
        });
        const long cell = static_cast<long>(k) * grid.nx + i;
        out.fraction[cell] = sumW;
        if (sumW >= opt.materialThreshold) {
          out.density[cell] = sumRho / sumW;
          out.material[cell] = argmax(matW);
          out.object[cell] = argmax(objW);
        }
      }
    }
  }
  return out;
}

}  // namespace hvi::compare::detail
