//! @file The shipped coarse variant-1 scenes (sphere on plate, r-z) run to 7.2 us with both solvers
//! and `hvi compare` measures them. Regression: the SPH run used to stop at 6.26 us with a
//! time-step collapse (a particle at e < 0 hit Tillotson's pole at w = 0; docs/eos.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "variant2_runs.hpp"

namespace hvi::compare::regression {
namespace {

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  return nlohmann::json::parse(in);
}

int runShipped(const std::string& scene, const fs::path& out) {
  app::RunOptions o;
  o.scene = scenePath(scene);
  o.out = out;
  o.overrides = {"output.vtk=false"};
  o.quiet = true;
  return app::runScene(o);
}

TEST(Variant1Coarse, BothSolversReachTheEndAndCompare) {
  const fs::path root = testRoot();
  ASSERT_EQ(runShipped("variant1_sph_coarse", root / "sph"), 0);
  ASSERT_EQ(runShipped("variant1_tvd_coarse", root / "tvd"), 0);
  const auto sph = readJson(root / "sph" / "summary.json");
  EXPECT_EQ(sph["status"], "completed");
  EXPECT_DOUBLE_EQ(sph["final_time_us"].get<double>(), 7.2);
  // SPH: masses are fixed per particle (bitwise); ~0.5% of the mass leaves through the outflow
  // sides, and the total is the in-domain sum plus the outflow sum, so it is exact up to the
  // order of the additions (measured 0 and -1.2e-16; the hard cases allow 1e-12). The compatible
  // energy (the default, docs/sph.md) conserves total energy to round-off (measured 1.8e-15;
  // the study's symmetric form drifts by O(dt^2), 4.7e-6 here, within the hard-case bound 5e-3).
  // A particle thrown by a singular EOS state shows up here first.
  EXPECT_LE(std::abs(sph["conservation"]["mass_rel_error"].get<double>()), 1e-14);
  EXPECT_LE(std::abs(sph["conservation"]["energy_rel_error"].get<double>()), 1e-12);

  CompareCliOptions o;
  o.time = 7.2;
  o.out = root / "cmp";
  o.quiet = true;
  // The default (adaptive) reading: the centroid weighs the striker's own partial density
  // (docs/compare.md), so the spray's reading no longer pulls it ahead (4.452 cm before, 4.512
  // now, against 4.579 for the particles' own mass centroid and 4.565 for TVD).
  ASSERT_EQ(runCompareCommand(root / "sph", root / "tvd", o), 0);
  const auto j = readJson(root / "cmp" / "compare.json");
  const double cell = j["grid"]["dx"].get<double>();
  const auto& d = j["features_diff"];
  for (const char* key : {"hole_radius", "cloud_leading_edge_z", "striker_centroid_z"})
    std::printf("%-22s SPH %.4f TVD %.4f  TVD - SPH %+.2f cells\n", key,
                j["a"]["features"][key].get<double>(), j["b"]["features"][key].get<double>(),
                d[key].get<double>() / cell);
  // The striker's centroid moves with the striker's momentum, which both methods exchange with
  // the shield through the same contact pressure; each side reads it to a cell on the common
  // grid, and the rest is the methods' discretisation at this spacing. Measured: 0.4 cells, 1.5
  // since the conservative TVD's thin-phase relaxation, 2.4 (0.073 cm) since the r-z interface
  // area of full cells was corrected (docs/tvd.md, "The r-z interface area"; TVD 4.565 -> 4.585
  // cm). The gap closes with resolution: TVD at 0.015 cm 4.508 cm against SPH at 0.01 cm 4.460
  // (0.048 cm). Bound 3 cells: the coarse gap and half a cell of reading. Hole and cloud front
  // are printed, not bounded: they are where the methods differ (docs/figures.md).
  EXPECT_LE(std::abs(d["striker_centroid_z"].get<double>()), 3.0 * cell + 1e-9);
}

}  // namespace
}  // namespace hvi::compare::regression
