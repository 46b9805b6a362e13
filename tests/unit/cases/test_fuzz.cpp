//! @file Property test: randomly damaged scenes either parse (and then round-trip through toToml)
//! or give an InputError; never another exception, a crash or a hang.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <iostream>
#include <random>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "scene_files.hpp"
#include "scene_mutate.hpp"

namespace hvi::cases {
namespace {

TEST(SceneFuzz, DamagedScenesParseOrGiveInputError) {
  // 2600 mutations of the shipped scenes, then 1000 of the broken ones (which may get repaired).
  const auto shipped = test::tomlFiles(test::shippedDir());
  const auto broken = test::tomlFiles(test::badDir());
  ASSERT_FALSE(shipped.empty());
  ASSERT_FALSE(broken.empty());
  constexpr int kShippedTrials = 2600, kTrials = kShippedTrials + 1000;
  std::mt19937 rng(20240611);  // fixed: a failure must reproduce
  int parsed = 0, rejected = 0, parsedShipped = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int trial = 0; trial < kTrials; ++trial) {
    const bool fromShipped = trial < kShippedTrials;
    const auto& pool = fromShipped ? shipped : broken;
    const auto& file = pool[static_cast<std::size_t>(trial) % pool.size()];
    std::string text = test::readText(file);
    const int n = 1 + static_cast<int>(rng() % 3);  // one to three mutations
    for (int m = 0; m < n; ++m) text = test::mutate(text, rng);
    try {
      const Scene scene = parseScene(text, "fuzz.toml");
      ++parsed;
      if (fromShipped) ++parsedShipped;
      // Whatever parses also round-trips: odd names, titles and values included.
      try {
        test::expectSameScene(scene, parseScene(toToml(scene), "resolved.toml"));
      } catch (const InputError& e) {
        ADD_FAILURE() << "the resolved scene does not read back: " << e.what() << "\n"
                      << toToml(scene);
      }
    } catch (const InputError& e) {
      ++rejected;
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.toml", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "trial " << trial << " (" << file.filename()
                    << ") threw a non-InputError: " << e.what() << "\n--- input ---\n"
                    << text;
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "[ fuzz ] " << kTrials << " damaged scenes (" << kShippedTrials
            << " from shipped ones): " << parsed << " parsed (" << parsedShipped
            << " of the shipped), " << rejected << " rejected with InputError, " << s << " s\n";
  RecordProperty("tried", kTrials);
  RecordProperty("parsed", parsed);
  EXPECT_EQ(parsed + rejected, kTrials);
  EXPECT_GT(rejected, kTrials / 4);  // the mutations do break most scenes
  EXPECT_LT(s, 20.0);
}

}  // namespace
}  // namespace hvi::cases
