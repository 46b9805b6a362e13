//! @file Particles to grid: Shepard-normalised Gaussian SPH interpolation with a cell list, each
//! particle with its own length (adaptive to the local spacing by default; docs/compare.md).
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
  std::vector<double> x, z, h, vol, rho;  // vol: area (planar) or meridional area (r-z)
  std::vector<double> invH2, norm, cut2;  // 1 / h^2, 1 / (pi h^2), (support h)^2
  std::vector<int> mat, obj;
  double bx0 = 0.0, bz0 = 0.0, bin = 1.0;
  int nbx = 1, nbz = 1;
  std::vector<int> start;  // particles of bin c are [start[c], start[c+1])
};

//! Sorts the particles into square bins `support * max h` wide (stably: within a bin in their
//! present order) and sets the kernel constants of each from its h.
void binCloud(Cloud& c, double support) {
  const std::size_t n = c.x.size();
  double hmax = 0.0, xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
  for (std::size_t j = 0; j < n; ++j) {
    hmax = std::max(hmax, c.h[j]);
    xmin = std::min(xmin, c.x[j]), xmax = std::max(xmax, c.x[j]);
    zmin = std::min(zmin, c.z[j]), zmax = std::max(zmax, c.z[j]);
  }
  c.bin = support * std::max(hmax, 1e-300);
  c.bx0 = xmin, c.bz0 = zmin;
  c.nbx = n ? static_cast<int>((xmax - xmin) / c.bin) + 1 : 1;
  c.nbz = n ? static_cast<int>((zmax - zmin) / c.bin) + 1 : 1;
  c.start.assign(static_cast<std::size_t>(c.nbx) * c.nbz + 1, 0);
  auto binOf = [&](std::size_t j) {
    const int i = std::clamp(static_cast<int>((c.x[j] - c.bx0) / c.bin), 0, c.nbx - 1);
    const int k = std::clamp(static_cast<int>((c.z[j] - c.bz0) / c.bin), 0, c.nbz - 1);
    return k * c.nbx + i;
  };
  for (std::size_t j = 0; j < n; ++j) ++c.start[binOf(j) + 1];
  for (std::size_t b = 1; b < c.start.size(); ++b) c.start[b] += c.start[b - 1];
  std::vector<int> fill(c.start.begin(), c.start.end() - 1);
  std::vector<std::size_t> to(n);
  for (std::size_t j = 0; j < n; ++j) to[j] = fill[binOf(j)]++;
  auto permute = [&](auto& v) {
    auto w = v;
    for (std::size_t j = 0; j < n; ++j) w[to[j]] = v[j];
    v.swap(w);
  };
  for (auto* v : {&c.x, &c.z, &c.h, &c.vol, &c.rho}) permute(*v);
  permute(c.mat);
  permute(c.obj);
  c.invH2.resize(n), c.norm.resize(n), c.cut2.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    const double hq = c.h[q];
    c.invH2[q] = 1.0 / (hq * hq);
    c.norm[q] = 1.0 / (std::numbers::pi * hq * hq);
    c.cut2[q] = support * support * hq * hq;
  }
}

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

//! The adaptive reading (SphReconstruction::Adaptive, docs/compare.md "Sparse particles"). With s
//! the distance to a particle's second-nearest neighbour (mirror images included in r-z; at most
//! maxFactor h), the particle stands for the share of space V' = max(V, s^2) around it, read with
//! length max(h, sqrt(V')) at density rho V / V', which keeps its mass. In a body's lattice at
//! rest or compressed, s is the (smaller) lattice spacing, at most h and sqrt(V): nothing
//! changes. Second, not first, neighbour: a pair of fragments is one point of the spray.
void adaptToSpacing(Cloud& c, double support, double maxFactor, bool mirror) {
  const long n = static_cast<long>(c.x.size());
  std::vector<double> s(n);
#pragma omp parallel for schedule(dynamic, 256)
  for (long q = 0; q < n; ++q) {
    const double reach = maxFactor * c.h[q];
    double d1 = reach * reach, d2 = d1;  // the two smallest squared distances so far
    auto scan = [&](double qx, bool image) {
      const int i0 = std::max(0, static_cast<int>(std::floor((qx - reach - c.bx0) / c.bin)));
      const int i1 =
          std::min(c.nbx - 1, static_cast<int>(std::floor((qx + reach - c.bx0) / c.bin)));
      const int k0 = std::max(0, static_cast<int>(std::floor((c.z[q] - reach - c.bz0) / c.bin)));
      const int k1 =
          std::min(c.nbz - 1, static_cast<int>(std::floor((c.z[q] + reach - c.bz0) / c.bin)));
      for (int k = k0; k <= k1; ++k)
        for (int p = c.start[k * c.nbx + i0]; i0 <= i1 && p < c.start[k * c.nbx + i1 + 1]; ++p) {
          if (p == q && !image) continue;
          const double ddx = qx - c.x[p], ddz = c.z[q] - c.z[p];
          const double r2 = ddx * ddx + ddz * ddz;
          if (r2 < d1) {
            d2 = d1, d1 = r2;
          } else if (r2 < d2) {
            d2 = r2;
          }
        }
    };
    scan(c.x[q], false);
    if (mirror && c.x[q] < reach) scan(-c.x[q], true);
    s[q] = std::sqrt(d2);
  }
  for (long q = 0; q < n; ++q) {
    const double share = s[q] * s[q];
    if (share > c.vol[q]) c.rho[q] *= c.vol[q] / share, c.vol[q] = share;
    c.h[q] = std::max(c.h[q], std::sqrt(c.vol[q]));
  }
  binCloud(c, support);
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

  Cloud c;
  const auto n = static_cast<long>(s.positions.size());
  for (long j = 0; j < n; ++j) {
    const Vec2 p = s.positions[j];
    // A particle with no mass or an unusable state contributes nothing (deleted particles).
    if (!(rho.data[j] > 0.0) || !(h.data[j] > 0.0) || !(mass->data[j] > 0.0) ||
        mat.data[j] < 0.0 || !std::isfinite(p.x) || !std::isfinite(p.z))
      continue;
    const double hj = h.data[j];
    c.x.push_back(p.x), c.z.push_back(p.z), c.h.push_back(hj), c.rho.push_back(rho.data[j]);
    // Planar: area m / rho. r-z: meridional area m / (rho r), scaled below by the convention.
    const double v = volume ? volume->data[j] : mass->data[j] / rho.data[j];
    c.vol.push_back((rz && !volume) ? v / std::max(std::abs(p.x), 1e-6 * hj) : v);
    c.mat.push_back(static_cast<int>(std::lround(mat.data[j])));
    c.obj.push_back(obj ? static_cast<int>(std::lround(obj->data[j])) : -1);
  }
  const long kept = static_cast<long>(c.x.size());
  binCloud(c, opt.kernelSupport);
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
  if (opt.sphReconstruction == SphReconstruction::Adaptive && kept > 0)
    adaptToSpacing(c, opt.kernelSupport, opt.adaptiveMaxFactor, rz);
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
    // Once per thread, reused for every cell: kernel weights and weighted densities per class.
    std::vector<double> matW(nMat), objW(nObj), matRho(nMat), objRho(nObj);
    const bool objects = !out.objectDensity.empty();
    const auto cells = static_cast<std::size_t>(grid.cells());
#pragma omp for schedule(dynamic, 4)
    for (int k = 0; k < grid.nz; ++k) {
      const double pz = out.zCentre(k);
      for (int i = 0; i < grid.nx; ++i) {
        const double px = out.xCentre(i);
        double sumW = 0.0, sumRho = 0.0;
        std::fill(matW.begin(), matW.end(), 0.0);
        std::fill(objW.begin(), objW.end(), 0.0);
        std::fill(matRho.begin(), matRho.end(), 0.0);
        std::fill(objRho.begin(), objRho.end(), 0.0);
        gather(c, px, pz, mirror, [&](int q, double w) {
          sumW += w;
          sumRho += w * c.rho[q];
          matW[c.mat[q]] += w;
          matRho[c.mat[q]] += w * c.rho[q];
          if (c.obj[q] >= 0) objW[c.obj[q]] += w, objRho[c.obj[q]] += w * c.rho[q];
        });
        const long cell = static_cast<long>(k) * grid.nx + i;
        out.fraction[cell] = sumW;
        if (sumW >= opt.materialThreshold) {
          out.density[cell] = sumRho / sumW;
          out.material[cell] = argmax(matW);
          out.object[cell] = argmax(objW);
          for (std::size_t m = 0; m < nMat; ++m)
            out.materialDensity[m * cells + cell] = matRho[m] / sumW;
          if (objects)
            for (std::size_t o = 0; o < nObj; ++o)
              out.objectDensity[o * cells + cell] = objRho[o] / sumW;
        }
      }
    }
  }
  return out;
}

}  // namespace hvi::compare::detail
