//! @file `hvi compare A B`: resolve inputs, compare, print, write compare.json and the diff.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <regex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hvi/cases/load.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/cli.hpp"
#include "hvi/compare/compare.hpp"
#include "hvi/io/output.hpp"

namespace hvi::compare {
namespace fs = std::filesystem;

void addCliOptions(CLI::App& cmd, CompareCliOptions& opt) {
  cmd.add_option("--time,-t", opt.time,
                 "Time (us) of the snapshot to take from a run folder (default: the last one)");
  cmd.add_option("--time-tolerance", opt.timeTolerance,
                 "How close (us) a snapshot's time must be to --time")
      ->capture_default_str();
  cmd.add_option("--spacing", opt.spacing,
                 "Cell size (cm) of the common grid (default: the coarser native spacing)");
  cmd.add_option("--out,-o", opt.out, "Folder for compare.json and compare_diff.vti")
      ->capture_default_str();
  cmd.add_option("--max-density-l1", opt.maxDensityL1,
                 "Fail (exit 1) if the relative L1 density difference over the material region "
                 "exceeds this");
  cmd.add_option("--min-iou", opt.minIou,
                 "Fail (exit 1) if the smallest object (or material) IoU is below this");
  cmd.add_flag("--quiet,-q", opt.quiet, "Do not print the table");
}

Snapshot loadSnapshot(const fs::path& path, std::optional<double> time, double tolerance,
                      std::string* sceneToml, fs::path* chosen) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw InputError(fmt::format("compare: '{}' does not exist; give an HDF5 snapshot (.h5) or a "
                                 "run folder holding snap_*.h5", path.string()));
  if (!fs::is_directory(path, ec)) {
    if (chosen) *chosen = path;
    return io::readHdf5(path, sceneToml);
  }
  // Run folder: the driver writes snap_<step>.h5; the largest step is the last snapshot.
  static const std::regex pattern(R"(snap_(\d+)\.h5)");
  std::vector<std::pair<long long, fs::path>> files;
  for (const auto& e : fs::directory_iterator(path)) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && std::regex_match(name, m, pattern))
      files.emplace_back(std::stoll(m[1].str()), e.path());
  }
  if (files.empty())
    throw InputError(fmt::format("compare: run folder '{}' holds no snap_<step>.h5 snapshot",
                                 path.string()));
  std::sort(files.begin(), files.end());
  if (!time) {
    if (chosen) *chosen = files.back().second;
    return io::readHdf5(files.back().second, sceneToml);
  }
  std::vector<double> times;
  for (const auto& [step, file] : files) {
    std::string toml;
    Snapshot s = io::readHdf5(file, &toml);
    times.push_back(s.time);
    if (std::abs(s.time - *time) <= tolerance) {
      if (sceneToml) *sceneToml = std::move(toml);
      if (chosen) *chosen = file;
      return s;
    }
  }
  throw InputError(fmt::format("compare: run folder '{}' has no snapshot within {} us of t = {} "
                               "us; its snapshots are at t = {} us",
                               path.string(), tolerance, *time, fmt::join(times, ", ")));
}

namespace {

//! Feature config from the scene stored in a snapshot; empty (with a note) if there is none.
std::optional<FeatureConfig> configFrom(const std::string& toml, const fs::path& file) {
  if (toml.empty()) return std::nullopt;
  try {
    return featureConfigFromScene(cases::parseScene(toml, file.string()));
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi compare: no debris features for {}: {}\n", file.string(), e.what());
    return std::nullopt;
  }
}

int compareImpl(const fs::path& a, const fs::path& b, const CompareCliOptions& opt) {
  if (opt.spacing && !(*opt.spacing > 0.0))
    throw InputError(fmt::format("compare: --spacing {} must be a positive length in cm",
                                 *opt.spacing));
  if (!(opt.timeTolerance >= 0.0))
    throw InputError("compare: --time-tolerance must be >= 0");
  std::string tomlA, tomlB;
  fs::path fileA, fileB;
  const Snapshot sa = loadSnapshot(a, opt.time, opt.timeTolerance, &tomlA, &fileA);
  const Snapshot sb = loadSnapshot(b, opt.time, opt.timeTolerance, &tomlB, &fileB);
  if (std::abs(sa.time - sb.time) > opt.timeTolerance)
    fmt::print(stderr, "hvi compare: warning: A is at t = {} us and B at t = {} us\n", sa.time,
               sb.time);

  CompareOptions co;
  co.spacing = opt.spacing.value_or(0.0);
  co.features = configFrom(tomlA, fileA);
  co.featuresB = configFrom(tomlB, fileB);
  if (!co.features) co.features = co.featuresB;
  if (co.features && !co.featuresB) co.featuresB = co.features;
  const double d = co.spacing > 0.0 ? co.spacing : std::max(nativeSpacing(sa), nativeSpacing(sb));
  const GridSpec grid = coveringGrid(sa, sb, d);
  const Resampled ra = resample(sa, grid, co.resample), rb = resample(sb, grid, co.resample);
  Report report;
  try {
    report = compareResampled(ra, rb, co);
  } catch (const InputError& e) {
    if (!co.features) throw;
    // Features are a bonus: a part the scene names but a snapshot lacks must not stop the compare.
    fmt::print(stderr, "hvi compare: no debris features: {}\n", e.what());
    co.features.reset();
    co.featuresB.reset();
    report = compareResampled(ra, rb, co);
  }

  const Thresholds th{opt.maxDensityL1, opt.minIou};
  std::string why;
  const bool ok = passes(report, th, &why);
  nlohmann::json j = toJson(report);
  j["a"]["file"] = fileA.string();
  j["b"]["file"] = fileB.string();
  j["a"]["features_config"] = co.features ? toJson(*co.features) : nlohmann::json(nullptr);
  j["b"]["features_config"] = co.featuresB ? toJson(*co.featuresB) : nlohmann::json(nullptr);
  j["thresholds"] = {{"max_density_l1", opt.maxDensityL1 ? nlohmann::json(*opt.maxDensityL1)
                                                         : nlohmann::json(nullptr)},
                     {"min_iou",
                      opt.minIou ? nlohmann::json(*opt.minIou) : nlohmann::json(nullptr)},
                     {"pass", ok},
                     {"why", why}};
  fs::create_directories(opt.out);
  writeTextAtomically(opt.out / "compare.json", j.dump(2) + "\n");
  io::writeVtk(opt.out / "compare_diff", report.difference);

  if (!opt.quiet) {
    std::cout << fmt::format("A: {}\nB: {}\n", fileA.string(), fileB.string())
              << formatTable(report);
    std::cout << fmt::format("wrote {}, {}\n", (opt.out / "compare.json").string(),
                             (opt.out / "compare_diff.vti").string());
  }
  if (!ok) {
    fmt::print(stderr, "hvi compare: FAILED: {}\n", why);
    return 1;
  }
  return 0;
}

}  // namespace

namespace {
void report(const std::string& message) {
  // Library messages already start with "compare: "; others (io, file system) get it added.
  fmt::print(stderr, "hvi {}{}\n", message.rfind("compare: ", 0) == 0 ? "" : "compare: ", message);
}
}  // namespace

int runCompareCommand(const fs::path& a, const fs::path& b, const CompareCliOptions& opt) {
  try {
    return compareImpl(a, b, opt);
  } catch (const InputError& e) {
    report(e.what());
    return 2;
  } catch (const fs::filesystem_error& e) {
    report(e.what());
    return 2;
  }
}

}  // namespace hvi::compare
