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

  // Each operation's allocations are counted on their own, so a failure names the operation.
  const int calls = 20;
  long before = gAllocations.load();
  auto t0 = std::chrono::steady_clock::now();
  for (int c = 0; c < calls; ++c) set.rasterize(g, owner, normal);
  auto t1 = std::chrono::steady_clock::now();
  EXPECT_EQ(gAllocations.load() - before, 0) << "rasterize";
  before = gAllocations.load();
  for (int c = 0; c < calls; ++c) set.advect(g, f.vx.data(), f.vz.data(), 1e-3);
  auto t2 = std::chrono::steady_clock::now();
  EXPECT_EQ(gAllocations.load() - before, 0) << "advect";
  before = gAllocations.load();
  set.rasterize(g, owner, normal, fraction);
  EXPECT_EQ(gAllocations.load() - before, 0) << "rasterize with fractions";
  // Repeated on unmoved lines, redistribute finds nothing to do after its first call; this
  // times it, and checks it does not allocate for the check alone.
  before = gAllocations.load();
  for (int c = 0; c < calls; ++c) set.redistribute(g);
  auto t3 = std::chrono::steady_clock::now();
  EXPECT_EQ(gAllocations.load() - before, 0) << "redistribute on settled lines";

  // Real work: a radial compression (v_r = -0.5 r) moves the markers closer each step, so
  // redistribute collapses short edges (and copies every line through the scratch buffer) with
  // no line growing. Only a line's growth past its largest marker count may allocate
  // (docs/tvd.md), so this must allocate nothing. 300 steps of dt = 5e-3 us compress by
  // exp(-0.75) ~ 0.47, below the collapse length of half the spacing.
  Field squeeze(g, [](Vec2 p) { return Vec2{-0.5 * p.x, 0.0}; });
  const std::size_t markersBefore = set.size();
  long redistributeAllocations = 0;
  for (int step = 0; step < 300; ++step) {
    set.advect(g, squeeze.vx.data(), squeeze.vz.data(), 5e-3);
    before = gAllocations.load();
    set.redistribute(g);
    redistributeAllocations += gAllocations.load() - before;
  }
  ASSERT_LT(set.size(), markersBefore) << "no edge was collapsed: the loop tested nothing";
  EXPECT_EQ(redistributeAllocations, 0) << "redistribute while collapsing edges";
  auto ms = [&](auto a, auto b) {
    return std::chrono::duration<double, std::milli>(b - a).count() / calls;
  };
  std::printf(
      "[perf] %ld cells, %zu markers: rasterize %.3f ms, advect %.3f ms, redistribute "
      "%.3f ms per call\n",
      g.cells(), markersBefore, ms(t0, t1), ms(t1, t2), ms(t2, t3));
}

}  // namespace
}  // namespace hvi::tvd
