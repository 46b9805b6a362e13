//! @file Cell-linked list against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "hvi/sph/kernel.hpp"
#include "hvi/sph/neighbours.hpp"

namespace hvi::sph {
namespace {

TEST(Neighbours, SameSetsAsBruteForceWithMixedSmoothingLengths) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 1500, nReal = 1200;
  std::vector<double> x(n), z(n), h(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 2.0 * u(rng);
    z[i] = u(rng);
    h[i] = i % 3 ? 0.02 : 0.035;
  }
  // A far outlier must not break the grid (it enlarges the cells instead of allocating
  // millions of empty ones).
  x[n - 1] = 500.0;
  CellGrid grid;
  NeighbourList list;
  const double rf = 3.3;
  buildNeighbourList(x.data(), z.data(), h.data(), n, nReal, rf, grid, list);
  for (std::size_t i = 0; i < nReal; ++i) {
    std::vector<int> expect;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double r2 = (x[i] - x[j]) * (x[i] - x[j]) + (z[i] - z[j]) * (z[i] - z[j]);
      const double rad = rf * 0.5 * (h[i] + h[j]);
      if (r2 < rad * rad) expect.push_back(static_cast<int>(j));
    }
    std::vector<int> got(list.index.begin() + static_cast<long>(list.start[i]),
                         list.index.begin() + static_cast<long>(list.start[i]) + list.count[i]);
    // The cached W_ij (the build computes them in vector lanes): kernel.hpp's value bit for bit.
    for (int k = 0; k < list.count[i]; ++k) {
      const std::size_t e = list.start[i] + static_cast<std::size_t>(k);
      const auto j = static_cast<std::size_t>(list.index[e]);
      const double r2 = (x[i] - x[j]) * (x[i] - x[j]) + (z[i] - z[j]) * (z[i] - z[j]);
      ASSERT_EQ(list.w[e], GaussianKernel::value(r2, 0.5 * (h[i] + h[j]))) << i << " " << j;
    }
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, expect) << "particle " << i;
  }
}

TEST(Neighbours, ARowExactlyAsLongAsTheStrideKeepsItsLastNeighbour) {
  // The builder writes each candidate at the row's end before knowing whether it is kept, so a
  // row needs one slot more than its neighbours: with the stride set to the exact count, the
  // rejected candidates after the last kept one must not overwrite it. 7 x 7 points at spacing
  // 0.01 cm, h = 0.01 cm, radius 1.5 h: the centre sees its 8 nearest neighbours (distance 0.01
  // and 0.0141 < 0.015); its search block (cells of 0.0075 cm, two either side) also holds the
  // row z + 0.02 and the column x + 0.02, rejected and scanned after the last kept pair.
  std::vector<double> x, z, h;
  for (int i = 0; i < 7; ++i)
    for (int k = 0; k < 7; ++k) {
      x.push_back(i * 0.01);
      z.push_back(k * 0.01);
      h.push_back(0.01);
    }
  CellGrid grid;
  NeighbourList list;
  list.start = {0, 8};  // one row of capacity 8
  list.stride = 8;
  const std::size_t centre = 24;
  std::swap(x[0], x[centre]);  // the centre becomes the one real point
  std::swap(z[0], z[centre]);
  buildNeighbourList(x.data(), z.data(), h.data(), x.size(), 1, 1.5, grid, list);
  ASSERT_EQ(list.count[0], 8);
  std::vector<int> got(list.index.begin(), list.index.begin() + 8);
  std::sort(got.begin(), got.end());
  std::vector<int> expect;
  for (std::size_t j = 1; j < x.size(); ++j)
    if (std::abs(x[j] - x[0]) < 0.011 && std::abs(z[j] - z[0]) < 0.011)
      expect.push_back(static_cast<int>(j));
  EXPECT_EQ(got, expect);
}

TEST(Neighbours, EachRowIsSizedByItsOwnCount) {
  // A lattice with one compressed corner: the corner's rows are long, the others keep rows of
  // their own length (a single stride for all rows made every row as long as the longest).
  std::vector<double> x, z, h;
  for (int i = 0; i < 30; ++i)
    for (int k = 0; k < 30; ++k) {
      // 100 points 0.002 apart off the lattice's corner: each sees the other 99.
      const bool dense = i < 10 && k < 10;
      x.push_back(dense ? i * 0.002 - 0.06 : i * 0.01);
      z.push_back(dense ? k * 0.002 - 0.06 : k * 0.01);
      h.push_back(0.01);
    }
  CellGrid grid;
  NeighbourList list;
  buildNeighbourList(x.data(), z.data(), h.data(), x.size(), x.size(), 3.3, grid, list);
  ASSERT_EQ(list.start.size(), x.size() + 1);
  int longest = 0;
  for (int c : list.count) longest = std::max(longest, c);
  std::size_t narrowest = list.stride, widest = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t cap = list.start[i + 1] - list.start[i];
    ASSERT_GT(cap, static_cast<std::size_t>(list.count[i])) << i;  // the scan's spare slot
    narrowest = std::min(narrowest, cap);
    widest = std::max(widest, cap);
  }
  EXPECT_EQ(list.stride, widest);  // the passes' scratch rows
  EXPECT_GT(static_cast<std::size_t>(longest), narrowest);
  EXPECT_EQ(longest, 99);
  // The interior of the coarse lattice (~36 neighbours) holds far fewer slots than the
  // compressed corner needs.
  const std::size_t mid = 15 * 30 + 15;
  EXPECT_LT(list.start[mid + 1] - list.start[mid], static_cast<std::size_t>(longest));
  EXPECT_LT(list.start.back(), x.size() * list.stride);
}

TEST(Neighbours, RowsGrowWhenCompressed) {
  // 400 points in a box of side 0.02 with h = 0.02: everyone sees everyone (399 neighbours),
  // far more than the initial row stride.
  std::vector<double> x, z, h;
  for (int i = 0; i < 20; ++i)
    for (int k = 0; k < 20; ++k) {
      x.push_back(i * 0.001);
      z.push_back(k * 0.001);
      h.push_back(0.02);
    }
  CellGrid grid;
  NeighbourList list;
  buildNeighbourList(x.data(), z.data(), h.data(), x.size(), x.size(), 3.0, grid, list);
  EXPECT_GE(list.stride, 399u);
  for (int c : list.count) EXPECT_EQ(c, 399);
}

}  // namespace
}  // namespace hvi::sph
