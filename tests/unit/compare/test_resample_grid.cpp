//! @file Grid resampling: exact mass conservation, identity, material by majority.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "hvi/compare/resample.hpp"
#include "synthetic.hpp"

namespace hvi::compare {
namespace {

Snapshot randomGrid(const GridSpec& g, Geometry geom, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> rho(0.0, 10.0);
  std::uniform_int_distribution<int> mat(-1, 1);
  Snapshot s;
  s.kind = Snapshot::Kind::Grid;
  s.geometry = geom;
  s.grid = g;
  std::vector<double> d, m;
  for (long c = 0; c < g.cells(); ++c) {
    d.push_back(rho(rng));
    m.push_back(mat(rng));
  }
  s.fields = {test::field("density", d), test::field("material", m)};
  return s;
}

double gridMass(const Resampled& r) {
  double m = 0.0;
  for (int k = 0; k < r.grid.nz; ++k)
    for (int i = 0; i < r.grid.nx; ++i)
      m += r.density[static_cast<long>(k) * r.grid.nx + i] * r.cellVolume(i);
  return m;
}

void checkConservation(Geometry geom) {
  // Different spacing, offset and aspect: the overlap weights partition every source cell, so
  // the target mass equals the source mass up to round-off (~1e-15 per addition).
  const GridSpec src{37, 23, geom == Geometry::Axisymmetric ? 0.0 : -0.211, 0.137, 0.013, 0.017};
  const Snapshot s = randomGrid(src, geom, 7);
  const double mass = gridMass(resample(s, src));
  const GridSpec dst{30, 25, 0.0, 0.1, 0.0211, 0.0193};
  GridSpec covering = dst;
  covering.x0 = geom == Geometry::Axisymmetric ? 0.0 : -0.25;
  const Resampled r = resample(s, covering);
  ASSERT_LE(covering.x0, src.x0);
  ASSERT_GE(covering.x0 + covering.nx * covering.dx, src.x0 + src.nx * src.dx);
  ASSERT_GE(covering.z0 + covering.nz * covering.dz, src.z0 + src.nz * src.dz);
  EXPECT_NEAR(gridMass(r), mass, 1e-13 * mass);
  ::testing::Test::RecordProperty("relative_mass_error",
                                  fmt::format("{:.3e}", std::abs(gridMass(r) / mass - 1.0)));
}

TEST(ResampleGrid, ConservesMassExactlyPlanar) { checkConservation(Geometry::Planar); }
TEST(ResampleGrid, ConservesMassExactlyAxisymmetric) { checkConservation(Geometry::Axisymmetric); }

TEST(ResampleGrid, PartialDensitiesConserveEveryClassExactly) {
  // Each class's partial density comes from the same overlap weights as the total, so every
  // material's mass is conserved like the total.
  const GridSpec src{37, 23, 0.0, 0.137, 0.013, 0.017};
  const Snapshot s = randomGrid(src, Geometry::Axisymmetric, 11);
  const auto& d = s.find("density")->data;
  const auto& m = s.find("material")->data;
  const Resampled own = resample(s, src);
  const GridSpec dst{30, 25, 0.0, 0.1, 0.0211, 0.0193};
  const Resampled r = resample(s, dst);
  const auto cells = static_cast<std::size_t>(dst.cells());
  ASSERT_EQ(r.materialDensity.size(), 2 * cells);
  for (int mat = 0; mat < 2; ++mat) {
    double source = 0.0, target = 0.0;
    for (int k = 0; k < src.nz; ++k)
      for (int i = 0; i < src.nx; ++i) {
        const long c = static_cast<long>(k) * src.nx + i;
        if (std::lround(m[c]) == mat) source += d[c] * own.cellVolume(i);
      }
    for (int k = 0; k < dst.nz; ++k)
      for (int i = 0; i < dst.nx; ++i)
        target += r.materialDensity[mat * cells + static_cast<std::size_t>(k) * dst.nx + i] *
                  r.cellVolume(i);
    EXPECT_NEAR(target, source, 1e-13 * source) << "material " << mat;
  }
}

TEST(ResampleGrid, OwnGridIsIdentity) {
  const GridSpec g{20, 30, 0.0, 1.0, 0.015, 0.015};
  const Snapshot s = randomGrid(g, Geometry::Axisymmetric, 3);
  const GridSpec c = coveringGrid(s, nativeSpacing(s));
  EXPECT_EQ(c.nx, g.nx);
  EXPECT_EQ(c.nz, g.nz);
  EXPECT_DOUBLE_EQ(c.x0, g.x0);
  EXPECT_DOUBLE_EQ(c.z0, g.z0);
  const Resampled r = resample(s, c);
  const auto& d = s.find("density")->data;
  const auto& m = s.find("material")->data;
  for (long i = 0; i < g.cells(); ++i) {
    EXPECT_DOUBLE_EQ(r.density[i], d[i]);
    EXPECT_EQ(r.material[i], static_cast<int>(m[i]));
  }
}

TEST(ResampleGrid, CoarseningKeepsTheBoundaryWithinOneCell) {
  // A plate 0.155 cm thick on a 0.005 cm grid, averaged onto 0.015 cm cells with an offset: the
  // material region's faces stay within one target cell of the plate's faces.
  test::Scene2 plate{test::box(-1.0, 1.0, 8.0, 8.155, 0)};
  plate.object = [](Vec2) { return 1; };
  const GridSpec fine{200, 100, -0.5, 7.85, 0.005, 0.005};
  const Snapshot s = test::gridOf(plate, fine);
  const GridSpec coarse{60, 30, -0.4937, 7.8541, 0.015, 0.015};
  const Resampled r = resample(s, coarse);
  double lo = 1e9, hi = -1e9;
  for (int k = 0; k < coarse.nz; ++k)
    if (r.material[static_cast<long>(k) * coarse.nx + 30] >= 0) {
      lo = std::min(lo, r.zCentre(k) - 0.5 * coarse.dz);
      hi = std::max(hi, r.zCentre(k) + 0.5 * coarse.dz);
      EXPECT_EQ(r.object[static_cast<long>(k) * coarse.nx + 30], 1);
    }
  EXPECT_NEAR(lo, 8.0, coarse.dz);
  EXPECT_NEAR(hi, 8.155, coarse.dz);
}

}  // namespace
}  // namespace hvi::compare
