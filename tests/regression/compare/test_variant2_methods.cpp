//! @file Variant 2 with modified SPH and with TVD at 16 cells across the striker: `hvi compare`
//! must find the two methods in agreement to within the interface mismatch the resolution allows.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "variant2_runs.hpp"

namespace hvi::compare::regression {
namespace {

//! Interface mismatch allowed between the methods, in cells. Each method places a material
//! boundary only to within about a cell (SPH: the kernel of width h = dx and the Shepard/0.5
//! fraction cut put the surface up to ~0.5 dx off the particles; TVD: the minmod contact and the
//! marker-line reconstruction smear it over 1-2 cells), so two correct results may differ by
//! ~1 cell at every interface, and by 2 where both errors add.
constexpr double kMismatchCells = 2.0;

const Field& field(const Snapshot& s, const char* name) {
  const Field* f = s.find(name);
  if (!f) throw std::runtime_error(std::string("no field ") + name);
  return *f;
}

//! Cells of class `cls` (object_b + 1) in B and the length of its boundary, in cells. The
//! boundary is counted in cell faces and scaled by pi/4, the mean ratio of a straight line's
//! length to its staircase (Cauchy-Crofton), so it estimates the true perimeter.
struct Shape {
  double cells = 0.0;
  double perimeter = 0.0;
};

Shape shapeOf(const Snapshot& diff, int cls) {
  const auto& o = field(diff, "object_b").data;
  const int nx = diff.grid.nx, nz = diff.grid.nz;
  auto at = [&](int i, int k) {
    return (i < 0 || k < 0 || i >= nx || k >= nz) ? 0 : static_cast<int>(o[k * nx + i]) + 1;
  };
  Shape s;
  long faces = 0;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      if (at(i, k) != cls) continue;
      s.cells += 1.0;
      faces += (at(i - 1, k) != cls) + (at(i + 1, k) != cls) + (at(i, k - 1) != cls) +
               (at(i, k + 1) != cls);
    }
  s.perimeter = faces * std::numbers::pi / 4.0;
  return s;
}

//! IoU of two shapes whose boundaries lie kMismatchCells apart all round, one half of that
//! outside and one half inside the measured shape: intersection cells - perimeter * delta / 2,
//! union cells + perimeter * delta / 2.
double iouBound(const Shape& s) {
  const double band = 0.5 * s.perimeter * kMismatchCells;
  return (s.cells - band) / (s.cells + band);
}

//! Relative L1 density difference over cells that are material in both: the disagreement of the
//! densities themselves, apart from where the boundaries are.
double interiorRelL1(const Snapshot& diff) {
  const auto& ra = field(diff, "density_a").data;
  const auto& rb = field(diff, "density_b").data;
  const auto& ma = field(diff, "material_a").data;
  const auto& mb = field(diff, "material_b").data;
  double num = 0.0, den = 0.0;
  for (std::size_t c = 0; c < ra.size(); ++c)
    if (ma[c] >= 0 && mb[c] >= 0) {
      num += std::abs(rb[c] - ra[c]);
      den += 0.5 * (ra[c] + rb[c]);
    }
  return den > 0 ? num / den : 0.0;
}

double feature(const nlohmann::json& j, const char* key) {
  if (j.is_null() || !j.contains(key) || j[key].is_null())
    throw std::runtime_error(std::string("feature missing: ") + key);
  return j[key].get<double>();
}

TEST(Variant2Methods, ModifiedSphAndTvdAgreeToTheResolution) {
  const fs::path root = testRoot();
  ASSERT_EQ(runVariant2("variant2_sph_modified_coarse", root / "sph"), 0);
  ASSERT_EQ(runVariant2("variant2_tvd_coarse", root / "tvd"), 0);

  const Loaded sph = loadRun(root / "sph");
  const Loaded tvd = loadRun(root / "tvd");
  CompareOptions opt;  // spacing: the coarser native one, the TVD cell, so TVD is not resampled
  opt.features = sph.features;
  opt.featuresB = tvd.features;
  const Report r = compareSnapshots(sph.snapshot, tvd.snapshot, opt);
  ASSERT_NEAR(r.grid.dx, kCell, 1e-12);
  ASSERT_TRUE(r.objects.has_value());

  // Object agreement: the cells classed differently (symmetric difference of the TVD and SPH
  // shapes), spread over the TVD shape's boundary, is the mean interface mismatch; it must stay
  // within kMismatchCells. Measured at 2 us (three TVD versions of the project):
  // striker 0.74-1.0 cell (IoU 0.78-0.82), shield 0.41-0.74 cell (IoU 0.78-0.87).
  double worstBound = 1.0;
  for (std::size_t c = 1; c < r.objects->classes.size(); ++c) {
    const auto& st = r.objects->stats[c];
    ASSERT_TRUE(st.iou.has_value()) << st.name;
    const Shape s = shapeOf(r.difference, static_cast<int>(c));
    const double symmetric = static_cast<double>(st.cellsA + st.cellsB - 2 * st.intersection);
    const double mismatch = symmetric / s.perimeter;
    worstBound = std::min(worstBound, iouBound(s));
    std::printf(
        "object %-8s cells SPH %ld TVD %ld  boundary %.0f cells  IoU %.4f  mismatch %.2f "
        "cells (bound %.1f; IoU at the bound %.3f)\n",
        st.name.c_str(), st.cellsA, st.cellsB, s.perimeter, *st.iou, mismatch, kMismatchCells,
        iouBound(s));
    EXPECT_LE(mismatch, kMismatchCells) << st.name;
    EXPECT_GE(*st.iou, iouBound(s)) << st.name;
  }

  // Density. For bodies of one uniform density rel L1 = 2 (1 - IoU) / (1 + IoU) exactly
  // (docs/compare.md): that part is the boundary mismatch bounded above. The rest is the
  // disagreement of the densities where both have material. Both methods are first order at
  // shocks, contacts and free surfaces, so each density field is off by O(dx / R) = 0.125
  // (R = 0.5 cm, the striker's radius) in the disturbed region, about half of the material at
  // 2 us; kInterior = 0.125 covers the sum of two such errors over half the material.
  // Measured: interior 0.061-0.063, total 0.156-0.211 with a boundary part of 0.12-0.18.
  constexpr double kInterior = 0.125;
  const auto& mat = r.materials.stats.at(1);
  ASSERT_TRUE(mat.iou.has_value());
  const double interior = interiorRelL1(r.difference);
  const double shapeL1 = 2.0 * (1.0 - *mat.iou) / (1.0 + *mat.iou);
  std::printf("material IoU %.4f  rel L1 %.4f (boundary part %.4f, interior %.4f)\n", *mat.iou,
              r.material.relL1, shapeL1, interior);
  EXPECT_LE(interior, kInterior);
  EXPECT_LE(r.material.relL1, shapeL1 + kInterior);

  // Features, each measured to one cell on the common grid: +-1 cell from each side, so 2 cells
  // for the hole and the remnant. A front moving into vacuum is also smeared by each method
  // (SPH: the kernel, h = dx; TVD: numerical diffusion ahead of the front down to the vacuum
  // cut-off), about one cell each: 4 cells for the leading edge (measured: SPH 3 cells ahead
  // at this resolution, 2 cells at 0.08 and 0.05 cm). The bubble radius (outermost material
  // below the rear face) is printed, not bounded: it picks up how far the plate sags beside the
  // hole, which differs between the methods (4-5 cells at 0.05 cm and at 3 us).
  const nlohmann::json fa = toJson(*r.featuresA), fb = toJson(*r.featuresB);
  const double cell = r.grid.dx;
  for (const char* key : {"hole_radius", "cloud_leading_edge_z", "bubble_radius", "striker_z_min",
                          "striker_z_max", "striker_centroid_z"})
    std::printf("%-22s SPH %8.4f  TVD %8.4f  TVD - SPH %+.2f cells\n", key, feature(fa, key),
                feature(fb, key), (feature(fb, key) - feature(fa, key)) / cell);
  std::printf("%-22s SPH %8.4f  TVD %8.4f  g/cm^3\n", "peak_density", feature(fa, "peak_density"),
              feature(fb, "peak_density"));
  const struct {
    const char* key;
    double cells;
  } bounds[] = {{"hole_radius", 2},
                {"cloud_leading_edge_z", 4},
                {"striker_z_min", 2},
                {"striker_z_max", 2},
                {"striker_centroid_z", 2}};
  for (const auto& b : bounds)
    EXPECT_LE(std::abs(feature(fb, b.key) - feature(fa, b.key)), b.cells * cell + 1e-9) << b.key;

  // The command gives the same numbers, and passes with its thresholds at the bounds above.
  const CommandResult cmd =
      compareCommand(root / "sph", root / "tvd", root / "cmp", worstBound, shapeL1 + kInterior);
  EXPECT_EQ(cmd.status, 0) << cmd.json["thresholds"].dump();
  EXPECT_NEAR(cmd.json["objects"]["min_iou"].get<double>(), *r.objects->minIou, 1e-12);
  EXPECT_NEAR(cmd.json["density"]["material"]["rel_l1"].get<double>(), r.material.relL1, 1e-12);
}

}  // namespace
}  // namespace hvi::compare::regression
