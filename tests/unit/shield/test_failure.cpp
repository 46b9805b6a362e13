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

// Every plate, not only the rear wall: a bumper with a 0.3 cm aperture at the axis and one of
// its fragments (a 0.2 cm disk, 0.1 cm thick) thrown 0.1 cm behind it at -0.3 cm/us, over an
// intact rear wall with debris on it.
RearWallConfig bumperConfig() {
  RearWallConfig c = config();
  c.name = "bumper";
  c.zMin = 1.4;
  c.zMax = 1.5;
  return c;
}
int bumperScene(double x, double z) {
  if (z > 1.4 && z < 1.5 && x > 0.3) return 1;
  if (z > 1.2 && z < 1.3 && x < 0.2) return 1;
  if (inWall(z)) return 2;
  if (z > 1.0 && z < 1.1 && x < 0.5) return 0;
  return -1;
}
double bumperFragmentMoves(double, double z) { return z > 1.1 && z < 1.4 ? -0.3 : 0.0; }

TEST(PlateFailure, HoleRadiusAndSpallFlagOfEachPlate) {
  const Snapshot s = grid(bumperScene, bumperFragmentMoves);
  const auto st = measurePlates(s, {bumperConfig(), config()});
  ASSERT_EQ(st.size(), 2u);
  // The bumper: open columns 0..5 (centres 0.025..0.275 cm), so the aperture ends at the
  // face r = 0.3; the fragment is spall (downrange of the bumper, moving away from it), with
  // its ring mass 2.7 pi 0.2^2 0.1.
  EXPECT_NEAR(st[0].holeRadius(), 0.3, 1e-12);
  ASSERT_TRUE(st[0].detachedSpall());
  ASSERT_EQ(st[0].spall.size(), 1u);
  EXPECT_NEAR(st[0].spall[0].velocityZ, -0.3, 1e-12);
  EXPECT_NEAR(st[0].spall[0].mass, 2.7 * std::numbers::pi * 0.04 * 0.1, 1e-9);
  EXPECT_EQ(st[0].mode(), "through_hole_and_spall");
  // The rear wall: closed at the axis, nothing detached; the same state as measured alone.
  EXPECT_DOUBLE_EQ(st[1].holeRadius(), 0.0);
  EXPECT_FALSE(st[1].detachedSpall());
  EXPECT_EQ(toJson(st[1]), toJson(measureRearWall(s, config())));
  // The plate's record entry carries the name, the hole radius and the flag.
  const nlohmann::json j = plateJson("bumper", st[0]);
  EXPECT_EQ(j.at("name"), "bumper");
  EXPECT_NEAR(j.at("hole_radius_cm").get<double>(), 0.3, 1e-12);
  EXPECT_TRUE(j.at("spalled").get<bool>());
  // A ring opening away from the axis (a circumferential tear) is a hole but no aperture on the
  // axis: hole radius 0; with an aperture too, the aperture's.
  RearWallState ring;
  ring.holes.push_back({1.0, 1.1, std::numbers::pi * (1.21 - 1.0)});
  EXPECT_TRUE(ring.throughHole());
  EXPECT_DOUBLE_EQ(ring.holeRadius(), 0.0);
  ring.holes.push_back({0.0, 0.4, std::numbers::pi * 0.16});
  EXPECT_DOUBLE_EQ(ring.holeRadius(), 0.4);
}

TEST(PlateFailure, ParticleSnapshotsOfEachPlate) {
  const auto st = measurePlates(particles(bumperScene, bumperFragmentMoves),
                                {bumperConfig(), config()});
  ASSERT_EQ(st.size(), 2u);
  // The kernel smears the aperture's edge over about one particle spacing.
  EXPECT_NEAR(st[0].holeRadius(), 0.3, kDx + 1e-9);
  ASSERT_EQ(st[0].spall.size(), 1u);
  EXPECT_NEAR(st[0].spall[0].mass, 2.7 * std::numbers::pi * 0.04 * 0.1, 1e-12);
  EXPECT_NEAR(st[0].spall[0].velocityZ, -0.3, 1e-12);
  EXPECT_DOUBLE_EQ(st[1].holeRadius(), 0.0);
  EXPECT_FALSE(st[1].perforated());
}

TEST(PlateFailure, SummaryKeepsTheLastHoleAndTheFirstSpall) {
  // Three snapshots of the bumper: an aperture of 0.2, 0.3 and 0.35 cm; spall seen only at 2 us
  // (the fragment has left the domain by 3 us). The rear wall stays intact.
  const auto bumper = [](double t, double r, bool spall) {
    RearWallState s;
    s.time = t;
    s.holes.push_back({0.0, r, std::numbers::pi * r * r});
    if (spall) s.spall.push_back({0.03, 0.1, 1.25, 1.2, 1.3, 0.2, -0.3, 16});
    return plateJson("bumper", s);
  };
  const auto rear = [](double t) {
    RearWallState s;
    s.time = t;
    return plateJson("rear_wall", s);
  };
  const nlohmann::json per = nlohmann::json::array(
      {nlohmann::json::array({bumper(1, 0.2, false), rear(1)}),
       nlohmann::json::array({bumper(2, 0.3, true), rear(2)}),
       nlohmann::json::array({bumper(3, 0.35, false), rear(3)})});
  const nlohmann::json sum = platesSummary(per);
  ASSERT_EQ(sum.size(), 2u);
  const auto& b = sum[0];
  EXPECT_EQ(b.at("name"), "bumper");
  EXPECT_DOUBLE_EQ(b.at("hole_radius_cm").get<double>(), 0.35);
  EXPECT_DOUBLE_EQ(b.at("hole_radius_time_us").get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(b.at("max_hole_radius_cm").get<double>(), 0.35);
  EXPECT_TRUE(b.at("perforated").get<bool>());
  EXPECT_DOUBLE_EQ(b.at("first_time_us").get<double>(), 1.0);
  EXPECT_TRUE(b.at("spalled").get<bool>());
  EXPECT_DOUBLE_EQ(b.at("spall_first_time_us").get<double>(), 2.0);
  ASSERT_EQ(b.at("spall").size(), 1u);
  EXPECT_DOUBLE_EQ(b.at("spall")[0].at("mass_g").get<double>(), 0.03);
  const auto& w = sum[1];
  EXPECT_EQ(w.at("name"), "rear_wall");
  EXPECT_DOUBLE_EQ(w.at("hole_radius_cm").get<double>(), 0.0);
  EXPECT_FALSE(w.at("spalled").get<bool>());
  EXPECT_TRUE(w.at("spall_first_time_us").is_null());
  EXPECT_FALSE(w.at("perforated").get<bool>());
}

TEST(PlateFailure, PlatesOfAShieldScene) {
  // A three-wall shield: bumper, wall_2 and rear_wall, each from the axis at rest; the
  // projectile (a moving disk) is no plate; a planar scene has none.
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
material = "al1100_o"
thickness = "0.1 cm"
gap = "0.5 cm"
[[walls]]
material = "al2024_t3"
thickness = "0.2 cm"
gap = "1 cm"
)",
                                      "s.toml");
  cases::Scene scene = cases::parseScene(sceneToml(spec), "generated");
  const auto plates = plateConfigsFromScene(scene);
  ASSERT_EQ(plates.size(), 3u);
  EXPECT_EQ(plates[0].name, "bumper");
  EXPECT_EQ(plates[1].name, "wall_2");
  EXPECT_EQ(plates[2].name, "rear_wall");
  for (const auto& p : plates) EXPECT_EQ(p.direction, -1);
  EXPECT_NEAR(plates[0].zMax - plates[0].zMin, 0.1, 1e-6);
  EXPECT_NEAR(plates[1].zMax - plates[2].zMax, 1.0 + 0.1, 1e-6);  // gap + own thickness
  EXPECT_NEAR(plates[0].rho0, 2.70, 1e-12);
  EXPECT_NEAR(plates[1].rho0, 2.71, 1e-12);
  EXPECT_NEAR(plates[2].rho0, 2.77, 1e-12);
  const auto rw = rearWallConfigFromScene(scene);
  ASSERT_TRUE(rw.has_value());
  EXPECT_EQ(rw->name, plates[2].name);
  EXPECT_DOUBLE_EQ(rw->zMin, plates[2].zMin);
  EXPECT_DOUBLE_EQ(rw->radius, plates[2].radius);
  scene.geometry = Geometry::Planar;
  EXPECT_TRUE(plateConfigsFromScene(scene).empty());
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
