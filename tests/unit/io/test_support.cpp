//! @file Shared fixtures of the io tests.
#include "test_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace hvi::io::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  path_ = fs::temp_directory_path() /
          fmt::format("hvi-io-{}-{}-{}", ::getpid(), info ? info->test_suite_name() : "x",
                      info ? info->name() : "x");
  fs::remove_all(path_);
  fs::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> ScratchDir::entries() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

namespace {
// Deterministic values in [0, 1) with all mantissa bits in use.
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
};
}  // namespace

Snapshot particleSnapshot(long n, double time, long step) {
  Snapshot s;
  s.kind = Snapshot::Kind::Particles;
  s.geometry = Geometry::Axisymmetric;
  s.time = time;
  s.step = step;
  s.solver = "sph";
  Lcg r{42};
  s.positions.resize(static_cast<std::size_t>(n));
  for (auto& p : s.positions) p = {r.next() * 2.0, r.next() * 3.0 - 1.5};
  Field rho{"density", "g/cm^3", 1, {}};
  Field vel{"velocity", "cm/us", 2, {}};
  Field stress{"deviatoric_stress", "Mbar", 4, {}};
  Field mat{"material", "1", 1, {}};
  for (long i = 0; i < n; ++i) {
    rho.data.push_back(2.7 + r.next());
    vel.data.push_back(r.next() - 0.5);
    vel.data.push_back(0.6 * r.next());
    for (int c = 0; c < 4; ++c) stress.data.push_back(1e-3 * (r.next() - 0.5));
    mat.data.push_back(i % 3 == 0 ? -1.0 : static_cast<double>(i % 2));
  }
  const double special[] = {-0.0,
                            std::bit_cast<double>(0x7ff8'0000'dead'beefULL),
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::max()};
  for (std::size_t i = 0; i < std::size(special) && i < rho.data.size(); ++i) rho.data[i] = special[i];
  s.fields = {rho, vel, stress, mat};
  s.materialNames = {"Al 6061-T6", "Al 1100"};
  s.objectNames = {"projectile", "bumper"};
  return s;
}

Snapshot gridSnapshot(int nx, int nz, double time, long step) {
  Snapshot s;
  s.kind = Snapshot::Kind::Grid;
  s.geometry = Geometry::Planar;
  s.time = time;
  s.step = step;
  s.solver = "tvd";
  s.grid = {nx, nz, -0.75, 0.125, 0.01, 0.02};
  Field rho{"density", "g/cm^3", 1, {}};
  Field p{"pressure", "Mbar", 1, {}};
  Field vel{"velocity", "cm/us", 2, {}};
  Field alpha{"volume_fraction", "1", 3, {}};
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      rho.data.push_back(1000.0 * k + i);
      p.data.push_back(std::sin(0.1 * i) * std::cos(0.05 * k));
      vel.data.push_back(0.1 * i);
      vel.data.push_back(-0.2 * k);
      alpha.data.push_back(0.25);
      alpha.data.push_back(0.5);
      alpha.data.push_back(0.25);
    }
  s.fields = {rho, p, vel, alpha};
  Polyline circle{0, true, {}};
  for (int j = 0; j < 40; ++j)
    circle.points.push_back({0.3 * std::cos(0.05 * std::numbers::pi * j), 0.5 + 0.3 * std::sin(0.05 * std::numbers::pi * j)});
  Polyline plate{1, false, {{-0.5, 1.0}, {0.0, 1.0}, {0.5, 1.0 + 1e-17}}};
  Polyline empty{2, true, {}};
  s.markers = {circle, plate, empty};
  s.materialNames = {"Al", "vacuum-filler"};
  s.objectNames = {"sphere", "plate", "debris"};
  return s;
}

std::string sampleScene() {
  return "# resolved scene\n[domain]\nx = [0.0, 2.0] # cm\nname = \"sphère \\\"A\\\"\"\n"
         "note = 'µs, Mbar — cm-g-us'\n";
}

void expectBitEqual(const Snapshot& a, const Snapshot& b) {
  EXPECT_TRUE(sameBits(a.time, b.time));
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.solver, b.solver);
  EXPECT_EQ(a.geometry, b.geometry);
  EXPECT_EQ(a.kind, b.kind);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    ASSERT_TRUE(sameBits(a.positions[i].x, b.positions[i].x)) << "particle " << i;
    ASSERT_TRUE(sameBits(a.positions[i].z, b.positions[i].z)) << "particle " << i;
  }
  EXPECT_EQ(a.grid.nx, b.grid.nx);
  EXPECT_EQ(a.grid.nz, b.grid.nz);
  EXPECT_TRUE(sameBits(a.grid.x0, b.grid.x0));
  EXPECT_TRUE(sameBits(a.grid.z0, b.grid.z0));
  EXPECT_TRUE(sameBits(a.grid.dx, b.grid.dx));
  EXPECT_TRUE(sameBits(a.grid.dz, b.grid.dz));
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (std::size_t f = 0; f < a.fields.size(); ++f) {
    EXPECT_EQ(a.fields[f].name, b.fields[f].name);
    EXPECT_EQ(a.fields[f].unit, b.fields[f].unit);
    EXPECT_EQ(a.fields[f].components, b.fields[f].components);
    ASSERT_EQ(a.fields[f].data.size(), b.fields[f].data.size());
    for (std::size_t i = 0; i < a.fields[f].data.size(); ++i)
      ASSERT_TRUE(sameBits(a.fields[f].data[i], b.fields[f].data[i]))
          << a.fields[f].name << "[" << i << "]";
  }
  ASSERT_EQ(a.markers.size(), b.markers.size());
  for (std::size_t m = 0; m < a.markers.size(); ++m) {
    EXPECT_EQ(a.markers[m].object, b.markers[m].object);
    EXPECT_EQ(a.markers[m].closed, b.markers[m].closed);
    ASSERT_EQ(a.markers[m].points.size(), b.markers[m].points.size());
    for (std::size_t i = 0; i < a.markers[m].points.size(); ++i) {
      EXPECT_TRUE(sameBits(a.markers[m].points[i].x, b.markers[m].points[i].x));
      EXPECT_TRUE(sameBits(a.markers[m].points[i].z, b.markers[m].points[i].z));
    }
  }
  EXPECT_EQ(a.materialNames, b.materialNames);
  EXPECT_EQ(a.objectNames, b.objectNames);
}

}  // namespace hvi::io::test
