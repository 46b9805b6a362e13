//! @file Lattice filling: counts, alignment of touching bodies, masses, hexagonal option.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "hvi/common/error.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

TEST(Fill, ASiteOnTheSharedFaceGoesToTheFirstBody) {
  // Binary-exact numbers: the row z = 0.4375 = 3.5 dx lies on both faces.
  auto s = test::baseScene(Geometry::Planar, 0.0, 1.0, 0.0, 1.0, 0.125, {});
  s.materials = {test::aluminium()};
  s.bodies = {test::rectBody("striker", 0, 0.0, 1.0, 0.4375, 1.0),
              test::rectBody("plate", 0, 0.0, 1.0, 0.0, 0.4375)};
  test::resolveDensities(s);
  const ParticleSystem ps = fillBodies(s);
  std::size_t plate = 0, striker = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) (ps.object[i] == 1 ? plate : striker)++;
  EXPECT_EQ(striker, 8u * 5u);  // rows 0.4375 ... 0.9375
  EXPECT_EQ(plate, 8u * 3u);    // rows 0.0625, 0.1875, 0.3125
}

TEST(Fill, DiskTouchingPlateSitsOnOneLatticeWithoutOverlap) {
  // Variant 1's contact: the sphere touches the plate's upper face.
  auto s = test::baseScene(Geometry::Planar, -1.0, 1.0, 0.0, 1.0, 0.01, {});
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.155 + 0.2}, 0.2),
              test::rectBody("plate", 0, -0.5, 0.5, 0.0, 0.155)};
  test::resolveDensities(s);
  const ParticleSystem ps = fillBodies(s);
  std::set<std::pair<long, long>> sites;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    // Every particle on a cell centre of the global lattice anchored at the domain corner.
    const double fi = (ps.x[i] - s.domain.xmin) / 0.01 - 0.5;
    const double fk = (ps.z[i] - s.domain.zmin) / 0.01 - 0.5;
    EXPECT_NEAR(fi, std::round(fi), 1e-9);
    EXPECT_NEAR(fk, std::round(fk), 1e-9);
    EXPECT_TRUE(sites.insert({std::lround(fi), std::lround(fk)}).second) << "duplicate site";
  }
  std::size_t striker = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) striker += ps.object[i] == 0;
  // Lattice count of a disk of radius 20 dx: pi 400 within the perimeter's O(2 pi 20) sites.
  EXPECT_NEAR(static_cast<double>(striker), M_PI * 400.0, 2.0 * M_PI * 20.0);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    EXPECT_DOUBLE_EQ(ps.m[i], 2.79 * 1e-4);  // traditional planar mass rho0 dx^2, g/cm
    EXPECT_DOUBLE_EQ(ps.h[i], 0.01);
  }
}

TEST(Fill, RzRingMassesAndHexagonalDensity) {
  auto s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.0, 0.0, 1.0, 0.02, {});
  s.materials = {test::aluminium()};
  s.bodies = {test::rectBody("plate", 0, 0.0, 0.5, 0.0, 0.2, {0.0, -0.1}, 0.0, 0.01)};
  test::resolveDensities(s);
  ParticleSystem ps = fillBodies(s);
  EXPECT_EQ(ps.size(), 25u * 10u);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    EXPECT_NEAR(ps.m[i], 2.0 * M_PI * ps.x[i] * 2.79 * 4e-4, 1e-15);
    EXPECT_GT(ps.x[i], 0.0);  // nobody on the axis
    EXPECT_EQ(ps.vz[i], -0.1);
    EXPECT_EQ(ps.e[i], 0.01);
  }
  s.sph.lattice = cases::Lattice::Hexagonal;
  EXPECT_NEAR(latticeCellArea(s.sph), 4e-4, 1e-15);
  ps = fillBodies(s);
  // Same number of particles per area as the square lattice, within one row or column.
  EXPECT_NEAR(static_cast<double>(ps.size()), 250.0, 25.0);
}

TEST(Fill, EmptyBodyIsAnInputError) {
  auto s = test::baseScene(Geometry::Planar, 0.0, 1.0, 0.0, 1.0, 0.1, {});
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("speck", 0, {0.52, 0.52}, 0.01)};
  test::resolveDensities(s);
  EXPECT_THROW(fillBodies(s), InputError);
}

// A radial field (the Noh problems): every particle moves at the stream speed straight at the
// centre (planar) or at the axis (r-z), to round-off.
TEST(Fill, RadialVelocityField) {
  auto s = test::baseScene(Geometry::Planar, -1.0, 1.0, -1.0, 1.0, 0.05, {});
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::diskBody("gas", 0, {0.2, 0.1}, 0.5)};
  s.bodies[0].radial = true;
  s.bodies[0].radialSpeed = -1.0;
  s.bodies[0].radialCentre = {0.2, 0.1};
  test::resolveDensities(s);
  ParticleSystem ps = fillBodies(s);
  ASSERT_GT(ps.size(), 100u);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double dx = ps.x[i] - 0.2, dz = ps.z[i] - 0.1;
    EXPECT_NEAR(std::hypot(ps.vx[i], ps.vz[i]), 1.0, 1e-15);
    EXPECT_NEAR(ps.vx[i] * dz - ps.vz[i] * dx, 0.0, 1e-15);  // parallel to the radius
    EXPECT_LT(ps.vx[i] * dx + ps.vz[i] * dz, 0.0);          // inward
  }
  s = test::baseScene(Geometry::Axisymmetric, 0.0, 1.0, 0.0, 0.2, 0.05, {});
  s.materials = {test::idealGas(5.0 / 3.0)};
  s.bodies = {test::rectBody("gas", 0, 0.0, 1.0, 0.0, 0.2)};
  s.bodies[0].radial = true;
  s.bodies[0].radialSpeed = -1.0;
  test::resolveDensities(s);
  ps = fillBodies(s);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    EXPECT_EQ(ps.vx[i], -1.0);
    EXPECT_EQ(ps.vz[i], 0.0);
  }
}

}  // namespace
}  // namespace hvi::sph
