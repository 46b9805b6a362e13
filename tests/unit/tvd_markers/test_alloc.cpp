//! @file The per-step operations do not allocate after the first call; their cost per call.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "helpers.hpp"

namespace {
std::atomic<long> gAllocations{0};
}

// Counting replacements of the global allocation functions (test executable only).
void* operator new(std::size_t n) {
  ++gAllocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return ::operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace hvi::tvd {
namespace {
using test::Field;
using test::makeGrid;

// The variant-1 geometry at the study's resolution (dr = dz = 0.015 cm): a 0.95 cm sphere on a
// 0.155 cm plate of radius 4 cm, r-z, on a 300 x 400 grid.
TEST(MarkerPerformance, PerStepCallsDoNotAllocate) {
  const GridSpec g = makeGrid(300, 400, 0.0, 5.0, 0.015);
  auto set =
      MarkerSet::fromShapes({cases::Disk{{0.0, 8.63}, 0.475}, cases::Rect{0.0, 4.0, 8.0, 8.155}}, g,
                            0.5, Geometry::Axisymmetric);
  Field f(g, [](Vec2 p) { return Vec2{0.05 * p.x, -0.67 * (p.z > 8.155)}; });
  std::vector<int> owner;
  std::vector<Vec2> normal;
  std::vector<double> fraction;
  set.rasterize(g, owner, normal, fraction);  // first calls size the buffers
  set.advect(g, f.vx.data(), f.vz.data(), 1e-3);
  set.redistribute(g);

  const int calls = 20;
  const long before = gAllocations.load();
  auto t0 = std::chrono::steady_clock::now();
  for (int c = 0; c < calls; ++c) set.rasterize(g, owner, normal);
  auto t1 = std::chrono::steady_clock::now();
  for (int c = 0; c < calls; ++c) set.advect(g, f.vx.data(), f.vz.data(), 1e-3);
  auto t2 = std::chrono::steady_clock::now();
  set.rasterize(g, owner, normal, fraction);
  EXPECT_EQ(gAllocations.load() - before, 0);
  for (int c = 0; c < calls; ++c) set.redistribute(g);
  auto t3 = std::chrono::steady_clock::now();
  auto ms = [&](auto a, auto b) {
    return std::chrono::duration<double, std::milli>(b - a).count() / calls;
  };
  std::printf(
      "[perf] %ld cells, %zu markers: rasterize %.3f ms, advect %.3f ms, redistribute "
      "%.3f ms per call\n",
      g.cells(), set.size(), ms(t0, t1), ms(t1, t2), ms(t2, t3));
}

}  // namespace
}  // namespace hvi::tvd
