//! @file Rear-wall failure on hand-made snapshots: intact wall, through-hole, detached spall.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

#include "hvi/cases/load.hpp"
#include "hvi/io/output.hpp"
#include "hvi/shield/failure.hpp"
#include "hvi/shield/shield.hpp"

namespace hvi::shield {
namespace {

// An r-z grid of 40 x 40 cells of 0.05 cm over [0, 2] x [0, 2]: objects projectile (0), bumper
// (1), rear_wall (2). The rear wall starts as z in [0.8, 1.0] (4 cells), radius 2 cm, rho 2.7.
constexpr double kDx = 0.05;
constexpr int kN = 40;
using Paint = std::function<int(double x, double z)>;        // object at a cell centre, -1 vacuum
using Velocity = std::function<double(double x, double z)>;  // v_z there, cm/us

Snapshot grid(const Paint& paint, const Velocity& vz, double rho = 2.7) {
  Snapshot s = makeSnapshot("tvd", Snapshot::Kind::Grid, Geometry::Axisymmetric, 5.0, 100);
  s.grid = {kN, kN, 0.0, 0.0, kDx, kDx};
  const std::size_t n = static_cast<std::size_t>(kN) * kN;
  Field dens = makeField(Quantity::Density, s.geometry, n),
        mat = makeField(Quantity::Material, s.geometry, n, -1);
  Field obj = makeField(Quantity::Object, s.geometry, n, -1),
        vel = makeField(Quantity::Velocity, s.geometry, n);
  for (int k = 0; k < kN; ++k)
    for (int i = 0; i < kN; ++i) {
      const double x = (i + 0.5) * kDx, z = (k + 0.5) * kDx;
      const std::size_t c = static_cast<std::size_t>(k) * kN + i;
      const int o = paint(x, z);
      if (o < 0) continue;
      dens.data[c] = rho;
      mat.data[c] = 0;
      obj.data[c] = o;
      vel.data[2 * c + 1] = vz(x, z);
    }
  s.fields = {dens, mat, obj, vel};
  s.materialNames = {"aluminium"};
  s.objectNames = {"projectile", "bumper", "rear_wall"};
  return s;
}

RearWallConfig config() {
  RearWallConfig c;
  c.zMin = 0.8;
  c.zMax = 1.0;
  c.radius = 2.0;
  c.rho0 = 2.7;
  return c;
}

bool inWall(double z) { return z > 0.8 && z < 1.0; }
double still(double, double) { return 0.0; }

TEST(RearWallFailure, IntactWallWithDebrisOnIt) {
  // Debris (projectile material) lies on the wall; the wall is whole: no failure.
  const Snapshot s = grid(
      [](double x, double z) { return inWall(z)                         ? 2
                                      : (z > 1.0 && z < 1.2 && x < 0.5) ? 0
                                                                        : -1; },
      still);
  const RearWallState st = measureRearWall(s, config());
  EXPECT_FALSE(st.perforated());
  EXPECT_EQ(st.mode(), "intact");
  EXPECT_NEAR(st.thinnestFraction, 1.0, 1e-12);
}

TEST(RearWallFailure, ThroughHoleAtTheAxis) {
  // No wall within r < 0.3 cm (6 columns); the wall around it bulges (moved down by a cell).
  const Snapshot s = grid(
      [](double x, double z) {
        if (x < 0.3) return -1;
        const double shift = x < 0.6 ? 0.05 : 0.0;
        return (z > 0.8 - shift && z < 1.0 - shift) ? 2 : -1;
      },
      still);
  const RearWallState st = measureRearWall(s, config());
  ASSERT_TRUE(st.throughHole());
  EXPECT_EQ(st.mode(), "through_hole");
  ASSERT_EQ(st.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(st.holes[0].rInner, 0.0);
  EXPECT_NEAR(st.holes[0].rOuter, 0.3, 1e-12);
  EXPECT_NEAR(st.holes[0].area, std::numbers::pi * 0.09, 1e-12);
  EXPECT_DOUBLE_EQ(st.thinnestFraction, 0.0);
}

TEST(RearWallFailure, LooseRimIsNotAHole) {
  // The outermost two columns of the plate are gone (its free edge came loose, as SPH rear walls
  // show at the plate radius): the wall inside is whole, so nothing is perforated.
  const Snapshot s =
      grid([](double x, double z) { return inWall(z) && x < 1.9 ? 2 : -1; }, still);
  const RearWallState st = measureRearWall(s, config());
  EXPECT_TRUE(st.holes.empty());
  EXPECT_FALSE(st.perforated());
  // No wall left anywhere inside the plate radius is the plate gone: perforated.
  const Snapshot gone = grid([](double, double) { return -1; }, still);
  EXPECT_TRUE(measureRearWall(gone, config()).perforated());
}

TEST(RearWallFailure, ThinnedWallIsNotAHole) {
  // Half the thickness left near the axis (2 of 4 cells): areal fraction 0.5 > 0.1.
  const Snapshot s =
      grid([](double x, double z) { return (inWall(z) && (x > 0.3 || z > 0.9)) ? 2 : -1; }, still);
  const RearWallState st = measureRearWall(s, config());
  EXPECT_FALSE(st.perforated());
  EXPECT_NEAR(st.thinnestFraction, 0.5, 1e-12);
  EXPECT_LT(st.thinnestRadius, 0.3);
}

TEST(RearWallFailure, DetachedSpallMovingAway) {
  // A disk of r < 0.4 cm, 0.1 cm thick, 0.1 cm behind the rear face, moving at -0.1 cm/us
  // (away, downrange); the wall, thinned above it, is still closed.
  const auto paint = [](double x, double z) {
    if (inWall(z) && (x > 0.4 || z > 0.9)) return 2;
    if (x < 0.4 && z > 0.6 && z < 0.7) return 2;
    return -1;
  };
  const Snapshot s = grid(paint, [](double, double z) { return z < 0.8 ? -0.1 : 0.0; });
  const RearWallState st = measureRearWall(s, config());
  EXPECT_FALSE(st.throughHole());
  ASSERT_TRUE(st.detachedSpall());
  EXPECT_EQ(st.mode(), "detached_spall");
  ASSERT_EQ(st.spall.size(), 1u);
  const Fragment& f = st.spall[0];
  EXPECT_EQ(f.cells, 8 * 2);
  EXPECT_NEAR(f.velocityZ, -0.1, 1e-12);
  EXPECT_NEAR(f.centroidZ, 0.65, 1e-12);
  EXPECT_NEAR(f.rOuter, 0.4, 1e-12);
  // Mass of the ring: rho * pi r^2 * thickness = 2.7 * pi * 0.16 * 0.1.
  EXPECT_NEAR(f.mass, 2.7 * std::numbers::pi * 0.16 * 0.1, 1e-9);
  // Still or moving back towards the wall, the same piece is not spall.
  const Snapshot back = grid(paint, [](double, double z) { return z < 0.8 ? 0.05 : 0.0; });
  EXPECT_FALSE(measureRearWall(back, config()).detachedSpall());
}

TEST(RearWallFailure, PieceThrownUprangeIsNotSpall) {
  // Rear-wall material thrown back up the impact axis (backsplash) is not spall.
  const Snapshot s = grid(
      [](double x, double z) { return inWall(z)                         ? 2
                                      : (x < 0.3 && z > 1.3 && z < 1.4) ? 2
                                                                        : -1; },
      [](double, double z) { return z > 1.2 ? 0.2 : 0.0; });
  EXPECT_FALSE(measureRearWall(s, config()).perforated());
}

// The same walls as SPH particles on a square lattice of 0.05 cm (r-z ring masses
// 2 pi r rho dx dz, h = dx): the particle path resamples onto a grid of the particle spacing.
Snapshot particles(const Paint& paint, const Velocity& vz) {
  Snapshot s = makeSnapshot("sph", Snapshot::Kind::Particles, Geometry::Axisymmetric, 5.0, 100);
  std::vector<double> rho, h, mass, mat, obj, vx, vzs;
  for (int k = 0; k < kN; ++k)
    for (int i = 0; i < kN; ++i) {
      const double x = (i + 0.5) * kDx, z = (k + 0.5) * kDx;
      const int o = paint(x, z);
      if (o < 0) continue;
      s.positions.push_back({x, z});
      rho.push_back(2.7);
      h.push_back(kDx);
      mass.push_back(2.0 * std::numbers::pi * x * 2.7 * kDx * kDx);
      mat.push_back(0);
      obj.push_back(o);
      vx.push_back(0.0);
      vzs.push_back(vz(x, z));
    }
  addField(s, Quantity::Density, rho);
  addField(s, Quantity::SmoothingLength, h);
  addField(s, Quantity::Mass, mass);
  addField(s, Quantity::Material, mat);
  addField(s, Quantity::Object, obj);
  addField(s, Quantity::Velocity, vx, vzs);
  s.materialNames = {"aluminium"};
  s.objectNames = {"projectile", "bumper", "rear_wall"};
  return s;
}

TEST(RearWallFailure, ParticleSnapshots) {
  // Intact: no hole, no spall.
  EXPECT_EQ(measureRearWall(particles([](double, double z) { return inWall(z) ? 2 : -1; }, still),
                            config())
                .mode(),
            "intact");
  // No particles within r < 0.3 cm: a hole whose edge is found within a particle spacing
  // (the kernel smears the edge over about one spacing).
  const RearWallState hole = measureRearWall(
      particles([](double x, double z) { return inWall(z) && x > 0.3 ? 2 : -1; }, still), config());
  ASSERT_TRUE(hole.throughHole());
  EXPECT_DOUBLE_EQ(hole.holes[0].rInner, 0.0);
  EXPECT_NEAR(hole.holes[0].rOuter, 0.3, kDx + 1e-9);
  // A disk of particles 0.1 cm behind the wall moving away: detached spall with its particles'
  // mass, 2.7 pi 0.4^2 0.1 (the ring masses of the lattice sum to it exactly).
  const RearWallState sp = measureRearWall(
      particles(
          [](double x, double z) { return inWall(z) || (x < 0.4 && z > 0.6 && z < 0.7) ? 2 : -1; },
          [](double, double z) { return z < 0.8 ? -0.1 : 0.0; }),
      config());
  EXPECT_FALSE(sp.throughHole());
  ASSERT_EQ(sp.spall.size(), 1u);
  EXPECT_NEAR(sp.spall[0].velocityZ, -0.1, 1e-12);
  EXPECT_NEAR(sp.spall[0].mass, 2.7 * std::numbers::pi * 0.16 * 0.1, 1e-12);
  EXPECT_NEAR(sp.spall[0].centroidZ, 0.65, 1e-12);
}

TEST(RearWallFailure, VerdictTakesTheFirstFailedSnapshot) {
  RearWallState ok, bad;
  ok.time = 1.0;
  bad.time = 2.0;
  bad.holes.push_back({0.0, 0.2, std::numbers::pi * 0.04});
  const nlohmann::json v =
      failureVerdict(nlohmann::json::array({toJson(ok), toJson(bad), toJson(ok)}));
  EXPECT_TRUE(v.at("perforated").get<bool>());
  EXPECT_DOUBLE_EQ(v.at("first_time_us").get<double>(), 2.0);
  EXPECT_EQ(v.at("mode"), "through_hole");
  EXPECT_FALSE(failureVerdict(nlohmann::json::array({toJson(ok)})).at("perforated").get<bool>());
}

TEST(RearWallFailure, FromAnHdf5SnapshotOfAShieldScene) {
  // The config comes from the scene stored in the file: a generated shield scene.
  const ShieldSpec spec = parseShield(R"(
radius = "1 cm"
[projectile]
material = "al2017_t4"
diameter = "0.2 cm"
speed = "7 km/s"
[[walls]]
material = "al6061_t6"
thickness = "0.1 cm"
[[walls]]
material = "al2024_t3"
thickness = "0.2 cm"
gap = "1 cm"
)",
                                      "s.toml");
  const std::string toml = sceneToml(spec);
  const cases::Scene scene = cases::parseScene(toml, "generated");
  const auto cfg = rearWallConfigFromScene(scene);
  ASSERT_TRUE(cfg.has_value());
  EXPECT_NEAR(cfg->zMax - cfg->zMin, 0.2, 1e-6);
  EXPECT_EQ(cfg->direction, -1);
  EXPECT_NEAR(cfg->rho0, 2.77, 1e-12);
  // A wall with a hole of 0.25 cm radius, on the scene's own grid (spacing 0.0333 cm).
  const double h = scene.tvd.cellSize;
  Snapshot s = makeSnapshot("tvd", Snapshot::Kind::Grid, Geometry::Axisymmetric, 3.0, 10);
  const int nx = static_cast<int>(std::lround(scene.domain.xmax / h));
  const int nz = static_cast<int>(std::lround(scene.domain.zmax / h));
  s.grid = {nx, nz, 0.0, 0.0, h, h};
  const std::size_t n = static_cast<std::size_t>(nx) * nz;
  Field dens = makeField(Quantity::Density, s.geometry, n),
        mat = makeField(Quantity::Material, s.geometry, n, -1);
  Field obj = makeField(Quantity::Object, s.geometry, n, -1),
        vel = makeField(Quantity::Velocity, s.geometry, n);
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5) * h, z = (k + 0.5) * h;
      const std::size_t c = static_cast<std::size_t>(k) * nx + i;
      if (z > cfg->zMin && z < cfg->zMax && x > 0.25) {
        dens.data[c] = 2.77;
        mat.data[c] = 2;
        obj.data[c] = 2;
      }
    }
  s.fields = {dens, mat, obj, vel};
  s.materialNames = {"al2017_t4", "al6061_t6", "al2024_t3"};
  s.objectNames = {"projectile", "bumper", "rear_wall"};
  const auto file = std::filesystem::temp_directory_path() / "hvi_shield_failure_test.h5";
  io::writeHdf5(file, s, toml);
  const RearWallState st = measureRearWall(file);
  std::filesystem::remove(file);
  ASSERT_TRUE(st.throughHole());
  // The hole ends at the first cell face past 0.25 cm: 8 cells of 1/30 cm = 0.2667 cm.
  EXPECT_NEAR(st.holes[0].rOuter, std::ceil(0.25 / h) * h, 1e-9);
}

}  // namespace
}  // namespace hvi::shield
