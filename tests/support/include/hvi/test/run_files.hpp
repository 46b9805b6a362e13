//! @file Files of the tests that run hvi end to end: scratch folders, shipped scenes, JSON.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace hvi::test {

//! An empty folder <build>/test_out/<group>/<name> (HVI_BINARY_DIR: hvi_add_test defines it).
inline std::filesystem::path freshDir(const std::string& group, const std::string& name) {
  auto d = std::filesystem::path(HVI_BINARY_DIR) / "test_out" / group / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

//! cases/scenes/<name>.toml of the source tree.
inline std::filesystem::path scene(const std::string& name) {
  return std::filesystem::path(HVI_SOURCE_DIR) / "cases" / "scenes" / (name + ".toml");
}

inline nlohmann::json readJson(const std::filesystem::path& p) {
  std::ifstream f(p);
  return nlohmann::json::parse(f);
}

}  // namespace hvi::test
