//! @file compareSnapshots: self-comparison, a shifted disk, a density bump, thresholds.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hvi/compare/compare.hpp"
#include "synthetic.hpp"

namespace hvi::compare {
namespace {

using std::numbers::pi;
using test::Scene2;

Scene2 disk(double cx, double cz, double radius) {
  Scene2 s{[=](Vec2 p) { return std::hypot(p.x - cx, p.z - cz) <= radius ? 0 : -1; }};
  s.object = [](Vec2) { return 0; };
  return s;
}

//! Intersection over union of two disks of radius R whose centres are s apart.
double diskIou(double r, double s) {
  const double inter = 2 * r * r * std::acos(s / (2 * r)) - 0.5 * s * std::sqrt(4 * r * r - s * s);
  return inter / (2 * pi * r * r - inter);
}

const ClassStats& stats(const ConfusionTable& t, const std::string& name) {
  for (const auto& s : t.stats)
    if (s.name == name) return s;
  throw std::runtime_error("no class " + name);
}

TEST(Compare, SnapshotWithItselfAgreesExactly) {
  Scene2 s{[](Vec2 p) { return p.z > 0.3 ? 0 : (p.z > 0.1 ? 1 : -1); }};
  s.object = [](Vec2 p) { return p.z > 0.3 ? 0 : 1; };
  s.density = [](Vec2 p) { return 2.0 + p.x; };
  const Snapshot a = test::lattice(s, 0.0, 0.5, 0.0, 0.5, 0.01);
  const Report r = compareSnapshots(a, a);
  EXPECT_EQ(r.whole.l1, 0.0);
  EXPECT_EQ(r.whole.max, 0.0);
  EXPECT_EQ(r.material.relL1, 0.0);
  EXPECT_EQ(r.materials.mismatchFraction, 0.0);
  ASSERT_TRUE(r.objects);
  EXPECT_EQ(r.objects->minIou.value(), 1.0);
  EXPECT_EQ(r.materials.minIou.value(), 1.0);
  EXPECT_EQ(stats(*r.objects, "striker").iou.value(), 1.0);
  EXPECT_GT(stats(*r.objects, "striker").cellsA, 100);
  EXPECT_TRUE(passes(r, Thresholds{0.0, 1.0}));
  EXPECT_NEAR(r.grid.dx, 0.01, 1e-12);  // the native particle spacing
}

TEST(Compare, ClassesAreMatchedByName) {
  // B numbers its objects the other way round; the comparison must not care.
  Scene2 s{test::box(0.0, 0.4, 0.0, 0.4)};
  s.object = [](Vec2 p) { return p.x < 0.2 ? 0 : 1; };
  const GridSpec g{50, 50, -0.05, -0.05, 0.01, 0.01};
  const Snapshot a = test::gridOf(s, g);
  Snapshot b = a;
  b.objectNames = {"shield", "striker"};
  for (double& o : b.fields[2].data)
    if (o >= 0) o = 1 - o;
  const Report r = compareSnapshots(a, b);
  EXPECT_EQ(r.objects->minIou.value(), 1.0);
  EXPECT_EQ(r.objects->mismatchFraction, 0.0);
}

TEST(Compare, DiskShiftedByTwoCells) {
  // Disks of radius R = 50 cells, B shifted by 2 cells. Counting cell centres inside a disk
  // misses its area by O(R^{2/3}) cells (Gauss circle problem, about 3 R^{2/3} = 41 cells or
  // 0.5 % of the area here), so the IoU carries at most about twice that: tolerance 0.01. The
  // expected 1 - IoU is 0.05, so a 1- or 3-cell shift (IoU 0.975, 0.925) would fail.
  const double dx = 0.01, radius = 0.5, shift = 0.02;
  const GridSpec g{140, 140, -0.7, -0.7, dx, dx};
  const Snapshot a = test::gridOf(disk(0.0, 0.0, radius), g);
  const Snapshot b = test::gridOf(disk(shift, 0.0, radius), g);
  const Report r = compareSnapshots(a, b);
  const double expected = diskIou(radius, shift);
  EXPECT_NEAR(stats(*r.objects, "striker").iou.value(), expected, 0.01);
  EXPECT_NEAR(stats(r.materials, "aluminium").iou.value(), expected, 0.01);
  RecordProperty("iou_measured", fmt::format("{:.6f}", *r.objects->minIou));
  RecordProperty("iou_analytic", fmt::format("{:.6f}", expected));
  // The mismatched cells are the two crescents, 2 (pi R^2 - I) = 2 pi R^2 (1 - IoU)/(1 + IoU);
  // each disk's cell count is off by the Gauss-circle error (< 41 cells), the crescents by twice.
  const double crescents = 2 * pi * radius * radius * (1 - expected) / (1 + expected);
  EXPECT_NEAR(r.materials.mismatchFraction * g.cells() * dx * dx, crescents, 2 * 41 * dx * dx);
  std::string why;
  EXPECT_FALSE(passes(r, Thresholds{std::nullopt, 0.99}, &why));
  EXPECT_NE(why.find("IoU"), std::string::npos);
  EXPECT_TRUE(passes(r, Thresholds{std::nullopt, 0.9}));

  // The difference snapshot marks exactly the mismatched cells.
  const Field* mis = r.difference.find("material_mismatch");
  ASSERT_NE(mis, nullptr);
  double marked = 0;
  for (double v : mis->data) marked += v;
  EXPECT_NEAR(marked, r.objects->mismatchFraction * g.cells(), 1e-9);
  for (const char* f : {"density_a", "density_b", "density_diff", "material_a", "material_b"})
    EXPECT_NE(r.difference.find(f), nullptr) << f;
}

TEST(Compare, ParticlesAgainstGridOfTheSameDisk) {
  // SPH lattice (dx = 0.01) against a TVD-like grid (0.015): the common grid takes the coarser
  // spacing and the grid's faces. Only cells cut by the circle can disagree: at most 2 pi R / d
  // of them, so IoU >= 1 - 2 d / R = 0.94 for R = 0.5, d = 0.015.
  const double radius = 0.5;
  const Snapshot sph = test::lattice(disk(0.0, 0.0, radius), -0.6, 0.6, -0.6, 0.6, 0.01);
  const Snapshot tvd =
      test::gridOf(disk(0.0, 0.0, radius), GridSpec{80, 80, -0.6, -0.6, 0.015, 0.015});
  const Report r = compareSnapshots(sph, tvd);
  EXPECT_NEAR(r.grid.dx, 0.015, 1e-12);
  EXPECT_GE(r.objects->minIou.value(), 1.0 - 2 * 0.015 / radius);
  // Both sides hold exactly rho0 in material cells (Shepard of a uniform field; the grid is the
  // common grid) and 0 in vacuum, so |A| + |B| = |A or B| + |A and B| gives the exact identity
  // relL1 = 2 (1 - IoU) / (1 + IoU).
  const double iou = r.materials.minIou.value();
  EXPECT_NEAR(r.material.relL1, 2 * (1 - iou) / (1 + iou), 1e-12);
  RecordProperty("sph_vs_grid_iou", fmt::format("{:.6f}", *r.objects->minIou));
}

TEST(Compare, DensityBumpGivesTheAnalyticNorms) {
  // B = A + a rho0 exp(-r^2 / sigma^2) inside a 1 x 0.6 cm plate: integral pi sigma^2 a rho0,
  // square integral pi sigma^2 / 2 (a rho0)^2. The midpoint rule on a Gaussian with
  // sigma = 5 cells is exact to exp(-pi^2 sigma^2 / dx^2) ~ 1e-107 and the plate edge cuts it at
  // exp(-34): tolerance 1e-9 relative, i.e. round-off.
  const double rho0 = 2.79, amp = 0.1, sigma = 0.05, dx = 0.01, cx = 0.005, cz = 0.005;
  Scene2 plate{test::box(-0.5, 0.5, -0.3, 0.3)};
  plate.density = [=](Vec2) { return rho0; };
  Scene2 bumped = plate;
  bumped.density = [=](Vec2 p) {
    const double r2 = std::pow(p.x - cx, 2) + std::pow(p.z - cz, 2);
    return rho0 * (1 + amp * std::exp(-r2 / (sigma * sigma)));
  };
  const GridSpec g{120, 80, -0.6, -0.4, dx, dx};
  const Report r = compareSnapshots(test::gridOf(plate, g), test::gridOf(bumped, g));
  const double gridArea = g.cells() * dx * dx, plateArea = 1.0 * 0.6;
  const double integral = pi * sigma * sigma * amp * rho0;
  EXPECT_NEAR(r.whole.l1, integral / gridArea, 1e-9 * integral / gridArea);
  EXPECT_NEAR(r.whole.l2, amp * rho0 * std::sqrt(pi * sigma * sigma / 2 / gridArea), 1e-9);
  EXPECT_NEAR(r.whole.max, amp * rho0, 1e-12);
  EXPECT_NEAR(r.material.l1, integral / plateArea, 1e-9 * integral / plateArea);
  const double rel = integral / (rho0 * plateArea + 0.5 * integral);
  EXPECT_NEAR(r.material.relL1, rel, 1e-9 * rel);
  EXPECT_EQ(r.material.cells, 100L * 60L);
  EXPECT_EQ(r.objects ? r.objects->mismatchFraction : r.materials.mismatchFraction, 0.0);
  EXPECT_NEAR(r.massB - r.massA, integral, 1e-9 * integral);
  std::string why;
  EXPECT_FALSE(passes(r, Thresholds{0.5 * rel, std::nullopt}, &why));
  EXPECT_NE(why.find("L1"), std::string::npos);
  EXPECT_TRUE(passes(r, Thresholds{2.0 * rel, 1.0}));
  const Field* diff = r.difference.find("density_diff");
  ASSERT_NE(diff, nullptr);
  EXPECT_NEAR(*std::max_element(diff->data.begin(), diff->data.end()), amp * rho0, 1e-12);
}

TEST(Compare, ReportSerialises) {
  const GridSpec g{40, 40, -0.2, -0.2, 0.01, 0.01};
  const Report r =
      compareSnapshots(test::gridOf(disk(0, 0, 0.1), g), test::gridOf(disk(0.01, 0, 0.1), g));
  const nlohmann::json j = toJson(r);
  for (const char* k :
       {"a", "b", "grid", "mass", "density", "materials", "objects", "features_diff"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["objects"]["min_iou"].get<double>(), *r.objects->minIou);
  EXPECT_NE(formatTable(r).find("IoU"), std::string::npos);
}

}  // namespace
}  // namespace hvi::compare
