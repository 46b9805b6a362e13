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

namespace hvi::cases {
namespace {

constexpr std::array<const char*, 32> kTokens{"\"\"",
                                              "\"abc\"",
                                              "-1",
                                              "0",
                                              "1e308",
                                              "-1e308",
                                              "nan",
                                              "inf",
                                              "-inf",
                                              "true",
                                              "[]",
                                              "[1, 2]",
                                              "{}",
                                              "\"1 cm\"",
                                              "\"-5 km/s\"",
                                              "\"1e400 cm\"",
                                              "\"0 us\"",
                                              "\"axis\"",
                                              "[[1]]",
                                              "9223372036854775807",
                                              "\"disk\"",
                                              "\"polygon\"",
                                              "1979-05-27",
                                              "'''x'''",
                                              "[\"0 cm\"]",
                                              "[\"1 cm\", \"-1 cm\"]",
                                              "\"1e-300 cm\"",
                                              "{ a = 1 }",
                                              "\"nan cm\"",
                                              "[\"1 km/s\", true]",
                                              "0.0",
                                              "\"sph\""};
constexpr std::string_view kChars = "[]\"'={}.,#\n\\ 0-e";

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::string joinLines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& l : v) s += l + "\n";
  return s;
}

std::string mutate(std::string text, std::mt19937& rng) {
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  if (text.empty()) return text;
  switch (pick(7)) {
    case 0: {  // delete a line
      auto v = lines(text);
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(pick(v.size())));
      return joinLines(v);
    }
    case 1: {  // duplicate a line
      auto v = lines(text);
      const std::size_t i = pick(v.size());
      v.insert(v.begin() + static_cast<std::ptrdiff_t>(i), v[i]);
      return joinLines(v);
    }
    case 2: {  // swap two neighbouring characters
      if (text.size() < 2) return text;
      const std::size_t i = pick(text.size() - 1);
      std::swap(text[i], text[i + 1]);
      return text;
    }
    case 3: {  // replace a value by a random token
      auto v = lines(text);
      std::vector<std::size_t> withValue;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (v[i].find('=') != std::string::npos) withValue.push_back(i);
      if (withValue.empty()) return text;
      auto& l = v[withValue[pick(withValue.size())]];
      l = l.substr(0, l.find('=') + 1) + " " + kTokens[pick(kTokens.size())];
      return joinLines(v);
    }
    case 4:  // truncate
      return text.substr(0, pick(text.size()));
    case 5:  // insert a syntax character
      text.insert(pick(text.size()), 1, kChars[pick(kChars.size())]);
      return text;
    default:  // flip a byte to anything, invalid UTF-8 included
      text[pick(text.size())] = static_cast<char>(pick(256));
      return text;
  }
}

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
    for (int m = 0; m < n; ++m) text = mutate(text, rng);
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
