//! @file Shared helpers of the scene tests: where the scenes are, reading them, comparing Scenes.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hvi/cases/load.hpp"

namespace hvi::cases::test {

inline std::filesystem::path shippedDir() {
  return std::filesystem::path(HVI_SOURCE_DIR) / "cases" / "scenes";
}
inline std::filesystem::path badDir() {
  return std::filesystem::path(HVI_SOURCE_DIR) / "tests" / "scenes" / "bad";
}

//! The *.toml files under a folder (subfolders too: cases/scenes/hard, ...), sorted so failures
//! are reproducible.
inline std::vector<std::filesystem::path> tomlFiles(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

//! Field-by-field equality, exact: the round trip writes shortest round-trip decimals, so every
//! double must come back bit for bit. Scene::path is not part of the scene's content.
void expectSameScene(const Scene& a, const Scene& b);

//! Minimal scene text for targeted tests; `extra` is appended (TOML allows later tables).
std::string plateScene(const std::string& bodies,
                       const std::string& header = "geometry = \"planar\"");

}  // namespace hvi::cases::test
