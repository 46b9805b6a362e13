//! @file `hvi compare A B`: the whole command (inputs, table, compare.json, compare_diff.vti).
#pragma once
#include <filesystem>
#include <optional>

#include "hvi/common/snapshot.hpp"
#include "hvi/compare/resample.hpp"

namespace hvi::compare {

//! The options of `hvi compare`; the command line itself is parsed in apps/src/main.cpp.
struct CompareCliOptions {
  std::optional<double> time;        //!< us: pick the snapshot at this time in a run folder
  double timeTolerance = 1e-3;       //!< us: how close a snapshot's time must be to `time`
  std::optional<double> spacing;     //!< cm: common grid spacing (default: coarser native one)
  std::filesystem::path out = ".";   //!< folder for compare.json and compare_diff.vti
  std::optional<double> maxDensityL1;  //!< bound on the material-region relative L1
  std::optional<double> minIou;        //!< bound on the smallest object (or material) IoU
  bool quiet = false;                  //!< no table on stdout
  //! Compare snapshots of different scenes (bodies, materials, domain differ) whose domains
  //! overlap; without it they are refused as unrelated problems.
  bool force = false;
  //! How SPH particles are read onto the grid (docs/compare.md, "Sparse particles"); Constant is
  //! the study's reading.
  SphReconstruction sphReconstruction = SphReconstruction::Adaptive;
};

//! A snapshot file, or the snapshot of a run folder at `time` (within `tolerance`) or the last
//! one. A run folder's snapshots are those its own record (timeseries.json) lists, never other
//! .h5 files lying there (an older run's, a copy). `sceneToml` receives the resolved scene
//! stored in the file. Throws InputError naming the path and, for a time with no snapshot, the
//! times available.
Snapshot loadSnapshot(const std::filesystem::path& path, std::optional<double> time,
                      double tolerance, std::string* sceneToml = nullptr,
                      std::filesystem::path* chosen = nullptr);

//! Runs `hvi compare A B`: prints the table, writes <out>/compare.json and
//! <out>/compare_diff.vti. Returns 0 (compared, thresholds met), 1 (a threshold failed) or 2
//! (bad input: missing file, no snapshot at the time, incompatible snapshots, snapshots of
//! different problems without `force`, thresholds that are NaN, negative or an IoU above 1)
//! or 4 (compare.json or the difference file could not be written).
int runCompareCommand(const std::filesystem::path& a, const std::filesystem::path& b,
                      const CompareCliOptions& opt);

}  // namespace hvi::compare
