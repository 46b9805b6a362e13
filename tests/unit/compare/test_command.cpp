//! @file `hvi compare A B` end to end: inputs, outputs and exit status.
#include <gtest/gtest.h>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "hvi/compare/command.hpp"
#include "hvi/io/output.hpp"
#include "synthetic.hpp"

namespace hvi::compare {
namespace {
namespace fs = std::filesystem;

test::Scene2 disk(double cx) {
  test::Scene2 s{[=](Vec2 p) { return std::hypot(p.x - cx, p.z) <= 0.3 ? 0 : -1; }};
  s.object = [](Vec2) { return 0; };
  return s;
}

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(HVI_BINARY_DIR) / "test_tmp" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "a");
    fs::create_directories(root_ / "b");
    const GridSpec g{80, 80, -0.4, -0.4, 0.01, 0.01};
    write(root_ / "a" / "snap_0.h5", disk(0.0), g, 0.0, 0);
    write(root_ / "a" / "snap_20.h5", disk(0.0), g, 1.0, 20);
    write(root_ / "b" / "snap_0.h5", disk(0.0), g, 0.0, 0);
    write(root_ / "b" / "snap_31.h5", disk(0.03), g, 1.0, 31);  // shifted by 3 cells
    record(root_ / "a", {{0.0, "snap_0"}, {1.0, "snap_20"}});
    record(root_ / "b", {{0.0, "snap_0"}, {1.0, "snap_31"}});
  }
  //! The run's record, as hvi run writes it: only the snapshots listed here belong to the run.
  static void record(const fs::path& dir, const std::vector<std::pair<double, std::string>>& snaps) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [t, stem] : snaps) list.push_back({{"time", t}, {"file", stem}});
    std::ofstream(dir / "timeseries.json") << nlohmann::json{{"snapshots", list}}.dump();
  }
  static std::string sceneText(const char* name) {
    std::ifstream in(fs::path(HVI_SOURCE_DIR) / "cases" / "scenes" / name);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  static void write(const fs::path& f, const test::Scene2& s, const GridSpec& g, double t,
                    long step) {
    Snapshot snap = test::gridOf(s, g);
    snap.time = t;
    snap.step = step;
    io::writeHdf5(f, snap, "");
  }
  CompareCliOptions opts(const char* out) const {
    CompareCliOptions o;
    o.out = root_ / out;
    o.quiet = true;
    return o;
  }
  fs::path root_;
};

TEST_F(CompareCommand, LastSnapshotsOfTwoRunFolders) {
  CompareCliOptions o = opts("out");
  ASSERT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 0);
  ASSERT_TRUE(fs::exists(o.out / "compare_diff.vti"));
  std::ifstream in(o.out / "compare.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_NE(j["a"]["file"].get<std::string>().find("snap_20.h5"), std::string::npos);
  EXPECT_NE(j["b"]["file"].get<std::string>().find("snap_31.h5"), std::string::npos);
  EXPECT_LT(j["objects"]["min_iou"].get<double>(), 0.95);
  EXPECT_TRUE(j["thresholds"]["pass"].get<bool>());
}

TEST_F(CompareCommand, ThresholdsGiveExitOne) {
  CompareCliOptions o = opts("out");
  o.minIou = 0.99;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 1);
  o.minIou.reset();
  o.maxDensityL1 = 0.01;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b" / "snap_31.h5", o), 1);
  std::ifstream in(o.out / "compare.json");
  EXPECT_FALSE(nlohmann::json::parse(in)["thresholds"]["pass"].get<bool>());
}

TEST_F(CompareCommand, SnapshotAtAGivenTime) {
  CompareCliOptions o = opts("out");
  o.time = 0.0;
  o.minIou = 1.0;
  o.maxDensityL1 = 0.0;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 0);
  o.time = 0.5;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
}

TEST_F(CompareCommand, BadInputGivesExitTwo) {
  CompareCliOptions o = opts("out");
  EXPECT_EQ(runCompareCommand(root_ / "missing", root_ / "b", o), 2);
  fs::create_directories(root_ / "empty");
  EXPECT_EQ(runCompareCommand(root_ / "empty", root_ / "b", o), 2);
  std::ofstream(root_ / "junk.h5") << "not hdf5";
  EXPECT_EQ(runCompareCommand(root_ / "junk.h5", root_ / "b", o), 2);
  o.spacing = -1.0;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
}

TEST_F(CompareCommand, SphAgainstTvdWithFeaturesFromTheStoredScene) {
  // Both snapshots carry the resolved variant-1 scene: bodies "striker" and "shield", shield band
  // z in [8, 8.155]. A plate with a hole of radius 0.35 cm: particles (0.01 cm) against a grid
  // (0.015 cm); the common grid is the coarser, and the hole radius is found within one cell.
  std::ifstream in(fs::path(HVI_SOURCE_DIR) / "cases" / "scenes" / "variant1_tvd_coarse.toml");
  const std::string toml{std::istreambuf_iterator<char>(in), {}};
  ASSERT_FALSE(toml.empty());
  test::Scene2 plate{[](Vec2 p) {
    return p.z >= 8.0 && p.z <= 8.155 && p.x >= 0.35 && p.x <= 2.0 ? 0 : -1;
  }};
  plate.object = [](Vec2) { return 1; };
  Snapshot sph = test::lattice(plate, 0.0, 2.0, 7.9, 8.3, 0.01, 1.0, Geometry::Axisymmetric);
  Snapshot tvd = test::gridOf(plate, GridSpec{140, 40, 0.0, 7.7, 0.015, 0.015},
                              Geometry::Axisymmetric);
  io::writeHdf5(root_ / "sph.h5", sph, toml);
  io::writeHdf5(root_ / "tvd.h5", tvd, toml);
  CompareCliOptions o = opts("out");
  ASSERT_EQ(runCompareCommand(root_ / "sph.h5", root_ / "tvd.h5", o), 0);
  std::ifstream js(o.out / "compare.json");
  const nlohmann::json j = nlohmann::json::parse(js);
  EXPECT_EQ(j["a"]["features_config"]["shield"], "shield");
  EXPECT_EQ(j["a"]["features_config"]["shield_z_min"].get<double>(), 8.0);
  for (const char* side : {"a", "b"}) {
    EXPECT_NEAR(j[side]["features"]["hole_radius"].get<double>(), 0.35, 0.015) << side;
    EXPECT_TRUE(j[side]["features"]["cloud_leading_edge_z"].is_null()) << side;
  }
  EXPECT_NEAR(j["grid"]["dx"].get<double>(), 0.015, 1e-12);
}

TEST_F(CompareCommand, SparseSprayAgainstItsCloudUnderBothReadings) {
  // A spray of fragments (h = 0.01 cm, 3 h apart, each keeping the solid density 2.79) against
  // the grid of the cloud it stands for (density 2.79 / 9). Adaptive (the default): every
  // particle stands for its (3 h)^2, so the cloud is read as one body of the cloud's density;
  // constant (the study's): a fragment's kernel sum peaks at 1/pi < 1/2, so nothing is material.
  test::Scene2 cloud{test::box(0.0, 0.6, 0.0, 0.6)};
  cloud.object = [](Vec2) { return 0; };
  cloud.density = [](Vec2) { return 2.79 / 9.0; };
  Snapshot sph = test::lattice(cloud, 0.0, 0.6, 0.0, 0.6, 0.03, 1.0 / 3.0);
  for (double& rho : sph.fields[0].data) rho *= 9.0;
  io::writeHdf5(root_ / "spray.h5", sph, "");
  write(root_ / "cloud.h5", cloud, GridSpec{80, 80, -0.1, -0.1, 0.01, 0.01}, 0.0, 0);
  auto read = [&](const fs::path& out) {
    std::ifstream js(out / "compare.json");
    return nlohmann::json::parse(js);
  };
  CompareCliOptions o = opts("adaptive");
  ASSERT_EQ(runCompareCommand(root_ / "spray.h5", root_ / "cloud.h5", o), 0);
  const nlohmann::json a = read(o.out);
  EXPECT_EQ(a["sph_reconstruction"], "adaptive");
  // The cloud's edge: the spray's outer particles sit 1.5 h inside the box and its reading
  // ends within a spacing of them, so the IoU lies within a 3 h band on a 0.6 cm square.
  EXPECT_GT(a["objects"]["min_iou"].get<double>(), 1.0 - 4.0 * 0.03 / 0.6);
  EXPECT_LT(a["density"]["material"]["rel_l1"].get<double>(), 4.0 * 0.03 / 0.6);
  o = opts("constant");
  o.sphReconstruction = SphReconstruction::Constant;
  ASSERT_EQ(runCompareCommand(root_ / "spray.h5", root_ / "cloud.h5", o), 0);
  const nlohmann::json c = read(o.out);
  EXPECT_EQ(c["sph_reconstruction"], "constant");
  EXPECT_EQ(c["materials"]["per_class"][1]["cells_a"].get<long>(), 0);
}

// An .h5 the run's record does not list (an older run's, a copy) is never read, even when its
// step number is the largest.
TEST_F(CompareCommand, RunFolderReadsOnlyTheSnapshotsItsRecordLists) {
  const GridSpec g{80, 80, -0.4, -0.4, 0.01, 0.01};
  write(root_ / "a" / "snap_99.h5", disk(0.2), g, 1.0, 99);  // stale, not in a's record
  CompareCliOptions o = opts("out");
  ASSERT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 0);
  std::ifstream in(o.out / "compare.json");
  EXPECT_NE(nlohmann::json::parse(in)["a"]["file"].get<std::string>().find("snap_20.h5"),
            std::string::npos);
  // A folder without a record is not a run folder; a listed file that is gone is named.
  fs::remove(root_ / "a" / "timeseries.json");
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
  record(root_ / "a", {{0.0, "snap_0"}, {1.0, "snap_21"}});
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
  record(root_ / "a", {{0.0, "../b/snap_0"}});
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
}

TEST_F(CompareCommand, ThresholdsThatMeanNothingAreRefused) {
  for (const auto& [l1, iou] : std::vector<std::pair<std::optional<double>, std::optional<double>>>{
           {std::nan(""), std::nullopt}, {-0.1, std::nullopt}, {std::nullopt, 1.5},
           {std::nullopt, -0.5}, {std::nullopt, std::nan("")}, {HUGE_VAL, std::nullopt}}) {
    CompareCliOptions o = opts("out");
    o.maxDensityL1 = l1;
    o.minIou = iou;
    EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 2);
  }
  CompareCliOptions o = opts("out");
  o.minIou = 0.0;
  o.maxDensityL1 = 1e9;
  EXPECT_EQ(runCompareCommand(root_ / "a", root_ / "b", o), 0);  // the bounds themselves are fine
}

// Sod's tube against an impact: unrelated problems, refused even with --force (their domains
// barely overlap). Two scenes of one geometry whose domains overlap: refused unless --force.
TEST_F(CompareCommand, UnrelatedProblemsAreRefusedUnlessForcedAndSharingADomain) {
  const GridSpec g{80, 80, -0.4, -0.4, 0.01, 0.01};
  Snapshot s = test::gridOf(disk(0.0), g);
  io::writeHdf5(root_ / "sod.h5", s, sceneText("sod_x.toml"));
  io::writeHdf5(root_ / "sod_b.h5", s, sceneText("sod_x.toml"));
  io::writeHdf5(root_ / "impact.h5", s, sceneText("default.toml"));
  std::string other = sceneText("sod_x.toml");
  const auto at = other.find("\"0.125 g/cm^3\"");
  ASSERT_NE(at, std::string::npos);
  other.replace(at, 14, "\"0.2 g/cm^3\"");  // another right state: another problem, same domain
  io::writeHdf5(root_ / "sod_moved.h5", s, other);
  CompareCliOptions o = opts("out");
  EXPECT_EQ(runCompareCommand(root_ / "sod.h5", root_ / "sod_b.h5", o), 0);
  EXPECT_EQ(runCompareCommand(root_ / "sod.h5", root_ / "impact.h5", o), 2);
  EXPECT_EQ(runCompareCommand(root_ / "sod.h5", root_ / "sod_moved.h5", o), 2);
  o.force = true;
  EXPECT_EQ(runCompareCommand(root_ / "sod.h5", root_ / "sod_moved.h5", o), 0);
  EXPECT_EQ(runCompareCommand(root_ / "sod.h5", root_ / "impact.h5", o), 2);
}

}  // namespace
}  // namespace hvi::compare
