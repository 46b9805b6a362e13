//! @file Very coarse variant-2 runs (rod on plate, planar) for the compare regression tests.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/compare/command.hpp"
#include "hvi/compare/compare.hpp"

namespace hvi::compare::regression {

namespace fs = std::filesystem;

//! Cell size of every run here (cm): 16 cells across the 1 cm striker, 6.4 across the 0.4 cm
//! plate. Coarse enough that a TVD run to 2 us takes ~2 s of CPU, fine enough that the hole, the
//! striker remnant and the start of the debris cloud are several cells across.
inline constexpr double kCell = 0.0625;
//! Time compared (us): the striker has gone through the plate (hole open, cloud 0.9 cm beyond the
//! rear face) but the cloud is still compact, so its front is a feature both methods resolve.
inline constexpr double kTime = 2.0;

//! The shipped coarse scenes with the resolution above, the end time above and z cut to
//! [-2.5, 1.5] cm (the cloud's front is at z ~ -1.3 cm at 2 us; backsplash leaves through zmax,
//! as it does in the full domain). Only the final state is written (HDF5).
inline std::vector<std::string> coarseOverrides() {
  return {"sph.spacing=0.0625 cm", "tvd.cell_size=0.0625 cm", "time.end=2 us",
          "output.times=[]",       "output.vtk=false",        R"(domain.z=["-2.5 cm", "1.5 cm"])"};
}

inline fs::path scenePath(const std::string& name) {
  return fs::path(HVI_SOURCE_DIR) / "cases" / "scenes" / (name + ".toml");
}

//! A fresh folder for the current test (tests may run in parallel under ctest -j).
inline fs::path testRoot() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path root = fs::path(HVI_BINARY_DIR) / "test_tmp" / "compare_regression" /
                        (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(root);
  fs::create_directories(root);
  return root;
}

//! Runs `hvi run <scene> --out <out> --set ...` in-process; returns the driver's exit status.
inline int runVariant2(const std::string& scene, const fs::path& out,
                       const std::vector<std::string>& extra = {}) {
  app::RunOptions o;
  o.scene = scenePath(scene);
  o.out = out;
  o.overrides = coarseOverrides();
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  o.quiet = true;
  return app::runScene(o);
}

//! The snapshot of a run folder at kTime and the feature configuration of its stored scene.
struct Loaded {
  Snapshot snapshot;
  FeatureConfig features;
};

inline Loaded loadRun(const fs::path& dir) {
  std::string toml;
  Loaded l;
  l.snapshot = loadSnapshot(dir, kTime, 1e-6, &toml);
  l.features = featureConfigFromScene(cases::parseScene(toml, (dir / "scene").string()));
  return l;
}

//! `hvi compare A B --time 2 --quiet --out OUT [--min-iou] [--max-density-l1]`; the exit status
//! and compare.json.
struct CommandResult {
  int status = -1;
  nlohmann::json json;
};

//! `force`: B is a deliberately altered scene (hvi compare refuses different scenes without it).
inline CommandResult compareCommand(const fs::path& a, const fs::path& b, const fs::path& out,
                                    std::optional<double> minIou,
                                    std::optional<double> maxDensityL1, bool force = false) {
  CompareCliOptions o;
  o.force = force;
  o.time = kTime;
  o.out = out;
  o.quiet = true;
  o.minIou = minIou;
  o.maxDensityL1 = maxDensityL1;
  CommandResult r;
  r.status = runCompareCommand(a, b, o);
  std::ifstream in(out / "compare.json");
  if (in) r.json = nlohmann::json::parse(in);
  return r;
}

}  // namespace hvi::compare::regression
