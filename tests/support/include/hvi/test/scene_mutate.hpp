//! @file Random damage to scene files, shared by the parser fuzz test (tests/unit/cases) and the
//! one that also builds and steps the solvers (tests/unit/app).
#pragma once
#include <array>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace hvi::cases::test {

inline constexpr std::array<const char*, 32> kTokens{"\"\"",
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
inline constexpr std::string_view kChars = "[]\"'={}.,#\n\\ 0-e";

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

inline std::string joinLines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& l : v) s += l + "\n";
  return s;
}

//! One random mutation: delete, duplicate or damage a line, swap or flip characters, truncate.
inline std::string mutate(std::string text, std::mt19937& rng) {
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

}  // namespace hvi::cases::test
