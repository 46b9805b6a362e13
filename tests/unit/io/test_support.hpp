//! @file Shared fixtures of the io tests: scratch folders, sample snapshots, bitwise comparison.
#pragma once
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hvi/common/snapshot.hpp"

namespace hvi::io::test {

//! A fresh folder per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  //! Names of all entries, sorted (to prove no temporary file is left behind).
  [[nodiscard]] std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

//! Particles with a scalar, a 2-vector and a 4-component field; the density holds the awkward
//! doubles (-0, NaN with payload, +-inf, the smallest subnormal, the largest finite).
Snapshot particleSnapshot(long n, double time = 0.3, long step = 17);
//! A grid whose "density" encodes the cell index (1000 k + i), plus marker lines (closed,
//! open, empty).
Snapshot gridSnapshot(int nx, int nz, double time = 1.25, long step = 301);
//! A scene text with non-ASCII characters, quotes and newlines.
std::string sampleScene();

//! Field-by-field, bit-for-bit equality (NaN payloads and signed zeros included).
void expectBitEqual(const Snapshot& a, const Snapshot& b);
bool sameBits(double a, double b);

}  // namespace hvi::io::test
