//! @file Neighbour-list construction fused with the summation density (corrector).
#pragma once
#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <cstddef>
#include <vector>

#include "detail/force_lanes.hpp"
#include "detail/parallel.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/neighbours.hpp"

namespace hvi::sph::detail {

//! Half rows: copies of the full row `full` (cnt point indices, found in this order) those
//! j > i to `row` while they fit its capacity, records the row's reach
//! (NeighbourList::reach) and returns how many there are.
inline int copyHalfRow(const int* full, int cnt, int* row, int capacity, std::size_t i,
                       std::size_t nReal, int* reach) {
  const int self = static_cast<int>(i), reals = static_cast<int>(nReal);
  int kept = 0, far = self + 1;
  for (int k = 0; k < cnt; ++k) {
    const int j = full[k];
    if (j <= self) continue;
    if (kept < capacity) row[kept] = j;
    ++kept;
    if (j < reals) far = std::max(far, j + 1);
  }
  reach[i] = far;
  return kept;
}

//! Lists, for each real particle i < nReal, the points j != i (real or ghost) closer than
//! radiusFactor * h_ij, caching W_ij (0 beyond the kernel support) if list.cacheW. With `Density`, also
//! rho_i = mu_i W_ii + sum_j mu_j W_ij (docs/sph.md (5)) over i's own object (`obj` may be null
//! without `Density`). Each row is written by one thread in a fixed order, so the result does
//! not depend on the thread count.
template <class K, bool Density>
void buildList(const double* x, const double* z, const double* h, const double* mu,
               const int* obj, std::size_t n, std::size_t nReal, double radiusFactor,
               CellGrid& grid, NeighbourList& list, double* rho) {
  double hmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, h[i]);
  // Cells of half the largest search radius: the 5 x 5 block around a point covers the
  // radius with ~30% fewer candidates than 3 x 3 cells of the full radius.
  constexpr int kReach = 2;
  constexpr bool kGauss = std::is_same_v<K, GaussianKernel>;
  grid.build(x, z, h, n, radiusFactor * hmax / kReach);
  const int* order = grid.order();
  const double* sx = grid.sortedX();
  const double* sz = grid.sortedZ();
  const double* sh = grid.sortedH();
  const int nx = grid.nx(), nz = grid.nz();
  list.count.resize(nReal);
  // Half rows: each row is scanned whole into a scratch row per thread (its density sums the
  // full row, in its order, as without half rows), then its j > i are copied to the list,
  // whose rows are sized by the half counts (half the memory).
  const bool half = list.half;
  if (half && list.cacheW)
    throw std::logic_error("NeighbourList: half rows do not cache W");
  if (half) list.reach.resize(nReal);
  if (half && list.scanStride == 0) list.scanStride = 64;
  // A new list, or one whose particles changed in number (outflow), is sized by a first pass
  // that only counts (every row overflows a capacity of one), so its rows are as long as the
  // lattice needs, not a fixed guess.
  std::vector<std::size_t>& start = list.start;
  bool sizing = start.size() != nReal + 1;
  if (sizing) {
    start.resize(nReal + 1);
    for (std::size_t i = 0; i <= nReal; ++i) start[i] = i;
    list.stride = 1;
  }
  for (;;) {
    const std::size_t stride = list.stride;
    const std::size_t total = start[nReal];
    const bool cacheW = list.cacheW;
    if (list.index.size() < total) {
      // The rows are rewritten: the old ones are freed first, so that a wider list does not
      // hold both for a moment (that moment was a run's peak memory).
      list.index = std::vector<int>();
      list.w = std::vector<double>();
      list.index.resize(total);
      if (cacheW) list.w.resize(total);
    }
    if (!cacheW) list.w = std::vector<double>();
    int* index = list.index.data();
    double* wc = cacheW ? list.w.data() : nullptr;
    // Without the cache the W of a row live in a scratch row per thread (the density needs
    // them once); with neither the cache nor the density they are not computed.
    const bool needW = cacheW || Density;
    int* count = list.count.data();
    int overflow = 0, fullNeed = 0;
    const int scanCap = static_cast<int>(list.scanStride);
    int* reach = half ? list.reach.data() : nullptr;
    const long nr = static_cast<long>(nReal);
    const double rf2 = radiusFactor * radiusFactor;
    const ScanKernel scan = scanKernel();
    const DistanceWKernel distanceW = distanceWKernel();
    // 2 lanes (no AVX2) measured slower than the one-candidate-at-a-time loop with its branch
    // (docs/performance.md): that loop, then; the same pairs, W and densities.
    const bool lanes = laneWidth() >= 4;
#pragma omp parallel if (nr > kParallelPairs)
  {
    std::vector<double> scratch(cacheW || !needW ? 0 : half ? list.scanStride : stride);
    // The Gaussian's h_ij of the kept pairs, beside their r2 (in the W row) until distanceW.
    std::vector<double> hScratch(lanes && kGauss && needW ? (half ? list.scanStride : stride) : 0);
    std::vector<int> fullRow(half ? list.scanStride : 0);
#pragma omp for schedule(static) reduction(max : overflow, fullNeed)
    for (long il = 0; il < nr; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const double xi = x[i], zi = z[i], hi = h[i];
      const int cx = grid.cellX(xi), cz = grid.cellZ(zi);
      const std::size_t base = start[i];
      const int capacity = static_cast<int>(start[i + 1] - base);
      // Where the scan writes the full row, and its room.
      int* const rowOut = half ? fullRow.data() : index + base;
      const int room = half ? scanCap : capacity;
      if (!lanes) {
        const double ih2i = 1.0 / (hi * hi), radi2 = rf2 * hi * hi;
        int cnt = 0;
        double sum = 0.0;
        if constexpr (Density) sum = mu[i] * K::value(0.0, hi);
        for (int row = std::max(cz - kReach, 0); row <= std::min(cz + kReach, nz - 1); ++row) {
          const int s0 = grid.begin(row * nx + std::max(cx - kReach, 0));
          const int s1 = grid.begin(row * nx + std::min(cx + kReach, nx - 1) + 1);
          for (int s = s0; s < s1; ++s) {
            const int j = order[s];
            if (j == static_cast<int>(i)) continue;
            const double dx = xi - sx[s], dz = zi - sz[s];
            const double r2 = dx * dx + dz * dz;
            double ih2 = ih2i, rad2 = radi2, hij = hi;
            if (sh[s] != hi) {  // another object's h: rare, the division kept out of the way
              hij = 0.5 * (hi + sh[s]);
              ih2 = 1.0 / (hij * hij);
              rad2 = rf2 * hij * hij;
            }
            if (r2 >= rad2) continue;
            const double w = K::value(r2, hij, ih2);
            if (cnt < room) {
              rowOut[cnt] = j;
              if (cacheW) wc[base + static_cast<std::size_t>(cnt)] = w;
            }
            ++cnt;
            if constexpr (Density) {
              if (obj[j] == obj[i]) sum += mu[j] * w;
            }
          }
        }
        count[i] = cnt;
        if constexpr (Density) rho[i] = sum;
        if (!half) {
          if (cnt >= capacity) overflow = 1;
        } else if (cnt >= room) {
          fullNeed = std::max(fullNeed, cnt);
        } else {
          count[i] = copyHalfRow(rowOut, cnt, index + base, capacity, i, nReal, reach);
          if (count[i] > capacity) overflow = 1;
        }
        continue;
      }
      int* slot = rowOut;
      // The Gaussian's kept r2 come with the scan, in the W row, and become W below.
      double* wr = cacheW ? wc + base : scratch.data();
      const int last = room - 1;
      // Pass 1, without a branch on the distance: every candidate's sorted position is written
      // at the row's end and kept (the end advances) if it is within radiusFactor * h_ij. So a
      // row needs one spare slot; once the row is full the last slot is overwritten and the
      // pairs only counted, and the list is redone wider.
      int cnt = 0;
      for (int row = std::max(cz - kReach, 0); row <= std::min(cz + kReach, nz - 1); ++row) {
        const int s0 = grid.begin(row * nx + std::max(cx - kReach, 0));
        const int s1 = grid.begin(row * nx + std::min(cx + kReach, nx - 1) + 1);
        // h_ij = h_i bit for bit when h_j = h_i (then the radius is radiusFactor h_i).
        cnt = scan(sx, sz, sh, order, s0, s1, xi, zi, hi, rf2, static_cast<int>(i), slot,
                   kGauss && needW ? wr : nullptr, hScratch.data(), cnt, last);
      }
      count[i] = cnt;
      if (cnt > last) {  // no spare slot: redone with a wider row
        if (half)
          fullNeed = std::max(fullNeed, cnt);
        else
          overflow = 1;
        continue;
      }
      // Pass 2: W_ij of the kept pairs (computed for them only: about half the candidates of
      // the 5 x 5 cells are kept), then the sorted positions become point indices and the
      // density adds up in the order the pairs were found.
      if (kGauss && needW) distanceW(wr, hScratch.data(), cnt, hi);
      if (!kGauss && needW) {
        for (int k = 0; k < cnt; ++k) {
          const int s = slot[k];
          const double dx = xi - sx[s], dz = zi - sz[s];
          const double hij = 0.5 * (hi + sh[s]);
          wr[k] = K::value(dx * dx + dz * dz, hij, 1.0 / (hij * hij));
        }
      }
      double sum = 0.0;
      if constexpr (Density) sum = mu[i] * K::value(0.0, hi);
      for (int k = 0; k < cnt; ++k) {
        const int j = order[slot[k]];
        slot[k] = j;
        if constexpr (Density) {
          if (obj[j] == obj[i]) sum += mu[j] * wr[k];
        }
      }
      if constexpr (Density) rho[i] = sum;
      if (half) {
        count[i] = copyHalfRow(slot, cnt, index + base, capacity, i, nReal, reach);
        if (count[i] > capacity) overflow = 1;
      }
    }
  }
    if (fullNeed > 0) {
      // A full row did not fit the scratch row (its count only was found): all scratch rows
      // wider, and the build redone (the list's rows are laid out as before).
      list.scanStride = static_cast<std::size_t>(fullNeed + fullNeed / 4 + 4);
      if (!overflow) continue;
    }
    if (!overflow) return;
    // Compression (or a ghost-rich corner) filled a row: lay the rows out again, every row at
    // least a quarter + 4 above its count just found, and redo. A row's capacity never
    // shrinks. Widening only the full rows was tried: the compressed region's front then
    // filled a few new rows at nearly every step, and each such step built its list twice. The first sizing leaves 1/8 spare (the
    // lattice's own count plus the ghosts' corners); fixed points need only the scan's one
    // spare slot.
    std::size_t offset = 0, widest = 0;
    for (std::size_t i = 0; i < nReal; ++i) {
      const auto c = static_cast<std::size_t>(count[i]);
      const std::size_t old = start[i + 1] - start[i];
      const std::size_t cap = sizing && list.fixedPoints ? c + 1
                              : sizing                   ? c + c / 8 + 2
                                                         : std::max(old, c + c / 4 + 4);
      start[i] = offset;
      offset += cap;
      widest = std::max(widest, cap);
    }
    start[nReal] = offset;
    list.stride = widest;
    sizing = false;
  }
}

}  // namespace hvi::sph::detail
