//! @file Property test over the whole path of `hvi run`: randomly damaged scenes are parsed,
//! validated, and where they are accepted the solver is built (fill, mass iteration, markers) and
//! stepped. Every scene must end in an InputError (bad input, before anything runs), a
//! SimulationError (the run went wrong and says where), or steps; nothing else may escape, crash
//! or hang. The parser alone gets many more mutations in tests/unit/cases/test_fuzz.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"
#include "hvi/test/scene_mutate.hpp"

namespace hvi::app {
namespace {

TEST(SceneFuzz, DamagedScenesRunOrGiveAClearError) {
  // One mutation each, so that most scenes stay valid enough to reach the solvers. Scenes whose
  // resolution was damaged into millions of items are accepted by the parser (under its memory
  // caps) but only built when small (kMaxItems), to keep this test to seconds.
  constexpr int kTrials = 600;
  constexpr double kMaxItems = 4e4;
  constexpr int kSteps = 3;
  const auto shipped = cases::test::tomlFiles(cases::test::shippedDir());
  ASSERT_FALSE(shipped.empty());
  std::mt19937 rng(20261201);  // fixed: a failure must reproduce
  int rejected = 0, tooLarge = 0, built = 0, stepped = 0, failedRuns = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int trial = 0; trial < kTrials; ++trial) {
    const auto& file = shipped[static_cast<std::size_t>(trial) % shipped.size()];
    const std::string text = cases::test::mutate(cases::test::readText(file), rng);
    cases::Scene scene;
    try {
      scene = cases::parseScene(text, "fuzz.toml");
    } catch (const InputError&) {
      ++rejected;
      continue;
    }
    if (cases::estimatedWorkItems(scene) > kMaxItems) {
      ++tooLarge;
      continue;
    }
    try {
      auto solver = createSolver(scene);
      ++built;
      for (int k = 0; k < kSteps && solver->time() < scene.tEnd; ++k) solver->advance(scene.tEnd);
      ++stepped;
    } catch (const InputError& e) {
      ++rejected;  // refused before it ran: the message names the scene
      EXPECT_NE(std::string(e.what()).find("fuzz.toml"), std::string::npos)
          << "trial " << trial << " (" << file.filename() << "): " << e.what();
    } catch (const SimulationError&) {
      ++failedRuns;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "trial " << trial << " (" << file.filename()
                    << ") threw neither InputError nor SimulationError: " << e.what()
                    << "\n--- input ---\n"
                    << text;
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "[ fuzz ] %d damaged scenes: %d rejected with InputError, %d too large to build "
      "here, %d built, %d stepped %d times, %d stopped with SimulationError, %.1f s\n",
      kTrials, rejected, tooLarge, built, stepped, kSteps, failedRuns, s);
  RecordProperty("tried", kTrials);
  EXPECT_GT(stepped, kTrials / 10);  // the test does reach the solvers
}

}  // namespace
}  // namespace hvi::app
