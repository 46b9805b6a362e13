//! @file Cell-linked list: binning by counting sort.
#include "hvi/sph/neighbours.hpp"

#include <algorithm>
#include <cmath>

#include "detail/arrays.hpp"
#include "detail/list_build.hpp"
#include "hvi/sph/kernel.hpp"

namespace hvi::sph {

int CellGrid::cellX(double x) const {
  return std::clamp(static_cast<int>((x - x0_) * inv_), 0, nx_ - 1);
}
int CellGrid::cellZ(double z) const {
  return std::clamp(static_cast<int>((z - z0_) * inv_), 0, nz_ - 1);
}

void CellGrid::build(const double* x, const double* z, const double* h, std::size_t n,
                     double cellSize) {
  if (n == 0) {
    // No points (every particle has left the domain, or an empty subset): one empty cell, so
    // lookups stay valid; the cell size of an empty set (0 from its largest h) is meaningless.
    x0_ = z0_ = 0.0;
    inv_ = 1.0;
    nx_ = nz_ = 1;
    start_.assign(2, 0);
    order_.clear();
    sx_.clear();
    sz_.clear();
    sh_.clear();
    return;
  }
  double xmin = x[0], xmax = x[0], zmin = z[0], zmax = z[0];
  for (std::size_t i = 1; i < n; ++i) {
    xmin = std::min(xmin, x[i]); xmax = std::max(xmax, x[i]);
    zmin = std::min(zmin, z[i]); zmax = std::max(zmax, z[i]);
  }
  // Sparse clouds (debris spread over a large domain) would need many empty cells; beyond
  // ~4 cells per point larger cells cost less than the empty ones.
  double size = cellSize;
  const double maxCells = 4.0 * static_cast<double>(n) + 1024.0;
  while (((xmax - xmin) / size + 1.0) * ((zmax - zmin) / size + 1.0) > maxCells) size *= 1.5;
  x0_ = xmin;
  z0_ = zmin;
  inv_ = 1.0 / size;
  nx_ = static_cast<int>((xmax - xmin) * inv_) + 1;
  nz_ = static_cast<int>((zmax - zmin) * inv_) + 1;
  const std::size_t ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(nz_);
  start_.assign(ncell + 1, 0);
  // The cell of a point is found twice (counting, placing) rather than stored: 4 B per point
  // less, the same cells (the same operations).
  const auto cellOf = [&](std::size_t i) {
    return static_cast<std::size_t>(cellZ(z[i]) * nx_ + cellX(x[i]));
  };
  for (std::size_t i = 0; i < n; ++i) ++start_[cellOf(i) + 1];
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  detail::growExactly(order_, n);
  detail::growExactly(sx_, n);
  detail::growExactly(sz_, n);
  detail::growExactly(sh_, n);
  // Stable counting sort: within a cell the points keep their index order (deterministic).
  // start_[c] runs through cell c as its points are placed, ending at cell c + 1's start;
  // shifted back by one cell afterwards.
  for (std::size_t i = 0; i < n; ++i) order_[static_cast<std::size_t>(start_[cellOf(i)]++)] = static_cast<int>(i);
  for (std::size_t c = ncell; c > 0; --c) start_[c] = start_[c - 1];
  start_[0] = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const int i = order_[s];
    sx_[s] = x[i];
    sz_[s] = z[i];
    sh_[s] = h[i];
  }
}

void buildNeighbourList(const double* x, const double* z, const double* h, std::size_t n,
                        std::size_t nReal, double radiusFactor, CellGrid& grid,
                        NeighbourList& list) {
  detail::buildList<GaussianKernel, false>(x, z, h, nullptr, nullptr, n, nReal, radiusFactor, grid, list,
                                           nullptr);
}

}  // namespace hvi::sph
