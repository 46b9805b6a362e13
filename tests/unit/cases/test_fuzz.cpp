//! @file Property test: randomly damaged scenes either parse (and then round-trip through toToml)
//! or give an InputError; never another exception, a crash or a hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <random>
#include <regex>
#include <string>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"
#include "hvi/test/scene_mutate.hpp"

namespace hvi::cases {
namespace {

// What an InputError from parseScene(text, "fuzz.toml") must look like: the file, the line
// where there is one (within the text), then either a TOML syntax error with its column, or the
// key the problem is about and the problem. Empty string if it does; else what is wrong.
std::string badMessage(const std::string& msg, const std::string& text) {
  static const std::regex kSyntax(R"(^fuzz\.toml:([0-9]+): syntax error: [\s\S]+ \(column [0-9]+\)$)");
  static const std::regex kKeyed(R"(^fuzz\.toml(?::([0-9]+))?: ([^\s:][^\n]*?): \S[\s\S]*$)");
  std::smatch m;
  if (!std::regex_match(msg, m, kSyntax) && !std::regex_match(msg, m, kKeyed))
    return "neither \"fuzz.toml:LINE: syntax error: ... (column C)\" nor "
           "\"fuzz.toml[:LINE]: KEY: PROBLEM\"";
  if (m[1].matched) {
    const long line = std::stol(m[1].str());
    const long lines = 1 + static_cast<long>(std::count(text.begin(), text.end(), '\n'));
    if (line < 1 || line > lines)
      return "line " + m[1].str() + " is not in the text (" + std::to_string(lines) + " lines)";
  }
  return {};
}

TEST(SceneFuzz, DamagedScenesParseOrGiveInputError) {
  // 2600 mutations of the shipped scenes, then 1000 of the broken ones (which may get repaired).
  // The work is bounded by the trial count, not by time (no wall-clock bound on shared cores).
  const auto shipped = test::tomlFiles(test::shippedDir());
  const auto broken = test::tomlFiles(test::badDir());
  ASSERT_FALSE(shipped.empty());
  ASSERT_FALSE(broken.empty());
  constexpr int kShippedTrials = 2600, kTrials = kShippedTrials + 1000;
  std::mt19937 rng(20240611);  // fixed: a failure must reproduce
  int parsedShipped = 0, parsedBroken = 0, syntaxErrors = 0, keyedErrors = 0, rejectedBroken = 0;
  int badMessages = 0, otherExceptions = 0;
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
      ++(fromShipped ? parsedShipped : parsedBroken);
      // Whatever parses also round-trips: odd names, titles and values included.
      try {
        test::expectSameScene(scene, parseScene(toToml(scene), "resolved.toml"));
      } catch (const InputError& e) {
        ADD_FAILURE() << "the resolved scene does not read back: " << e.what() << "\n"
                      << toToml(scene);
      }
    } catch (const InputError& e) {
      const std::string msg = e.what();
      if (!fromShipped) ++rejectedBroken;
      ++(msg.find(": syntax error: ") != std::string::npos ? syntaxErrors : keyedErrors);
      if (const std::string why = badMessage(msg, text); !why.empty()) {
        ++badMessages;
        ADD_FAILURE() << "trial " << trial << " (" << file.filename() << "): " << why << ": "
                      << msg;
      }
    } catch (const std::exception& e) {
      ++otherExceptions;
      ADD_FAILURE() << "trial " << trial << " (" << file.filename()
                    << ") threw a non-InputError: " << e.what() << "\n--- input ---\n"
                    << text;
    }
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int parsed = parsedShipped + parsedBroken, rejected = syntaxErrors + keyedErrors;
  std::cout << "[ fuzz ] " << kTrials << " damaged scenes (" << kShippedTrials
            << " from shipped ones): " << parsed << " parsed (" << parsedShipped
            << " of the shipped), " << rejected << " rejected with InputError (" << syntaxErrors
            << " syntax, " << keyedErrors << " naming a key), " << otherExceptions
            << " other exceptions, " << s << " s (measured, not asserted)\n";
  RecordProperty("tried", kTrials);
  RecordProperty("parsed", parsed);
  EXPECT_EQ(otherExceptions, 0);
  EXPECT_EQ(badMessages, 0);
  // Both outcomes occur, and rejections come from both the TOML reader and the validator: a
  // mutator that only broke the syntax (or never did) would not test what it claims. Measured
  // 52% syntax and 35% keyed; 5% each is far below either, so only a broken mutator fails it.
  EXPECT_GT(parsedShipped, 0);
  EXPECT_GT(rejectedBroken, 0);
  EXPECT_GT(rejected, kTrials / 4);  // the mutations do break most scenes
  EXPECT_GT(syntaxErrors, kTrials / 20);
  EXPECT_GT(keyedErrors, kTrials / 20);
}

}  // namespace
}  // namespace hvi::cases
