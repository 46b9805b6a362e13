//! @file `hvi compare A B`: resolve inputs, compare, print, write compare.json and the diff.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hvi/cases/load.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/command.hpp"
#include "hvi/compare/compare.hpp"
#include "hvi/io/output.hpp"

namespace hvi::compare {
namespace fs = std::filesystem;

namespace {
//! The snapshots a run folder's record lists, in order: (time, file). timeseries.json is
//! rewritten with every snapshot and cut back on restart, so it names exactly this run's files.
std::vector<std::pair<double, fs::path>> recordedSnapshots(const fs::path& dir) {
  const fs::path record = dir / "timeseries.json";
  std::error_code ec;
  if (!fs::is_regular_file(record, ec))
    throw InputError(fmt::format("compare: '{}' is not an hvi run folder (it has no "
                                 "timeseries.json); give a snapshot file (.h5) or a folder "
                                 "written by hvi run", dir.string()));
  std::ifstream in(record);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("snapshots") ||
      !j["snapshots"].is_array())
    throw InputError(fmt::format("compare: {} is not a run record (no \"snapshots\" list)",
                                 record.string()));
  std::vector<std::pair<double, fs::path>> v;
  for (const auto& e : j["snapshots"]) {
    if (!e.is_object() || !e.contains("file") || !e["file"].is_string() || !e.contains("time") ||
        !e["time"].is_number())
      throw InputError(fmt::format("compare: {}: a snapshot entry lacks \"file\" or \"time\"",
                                   record.string()));
    const std::string stem = e["file"].get<std::string>();
    // Only a plain name inside the folder: the record cannot send the reader elsewhere.
    if (stem.empty() || stem.find('/') != std::string::npos || stem[0] == '.')
      throw InputError(fmt::format("compare: {}: snapshot name '{}' is not a file of the folder",
                                   record.string(), stem));
    v.emplace_back(e["time"].get<double>(), dir / (stem + ".h5"));
  }
  if (v.empty())
    throw InputError(fmt::format("compare: run folder '{}' has no snapshot yet ({} lists none)",
                                 dir.string(), record.string()));
  return v;
}

Snapshot readRecorded(const fs::path& file, const fs::path& dir, std::string* sceneToml) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError(fmt::format("compare: {} lists {}, which is missing (the run wrote no HDF5 "
                                 "snapshots, output.hdf5 = false, or the file was removed)",
                                 (dir / "timeseries.json").string(), file.string()));
  return io::readHdf5(file, sceneToml);
}
}  // namespace

Snapshot loadSnapshot(const fs::path& path, std::optional<double> time, double tolerance,
                      std::string* sceneToml, fs::path* chosen) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw InputError(fmt::format("compare: '{}' does not exist; give an HDF5 snapshot (.h5) or a "
                                 "run folder written by hvi run", path.string()));
  if (!fs::is_directory(path, ec)) {
    if (chosen) *chosen = path;
    return io::readHdf5(path, sceneToml);
  }
  const auto files = recordedSnapshots(path);
  if (!time) {
    if (chosen) *chosen = files.back().second;
    return readRecorded(files.back().second, path, sceneToml);
  }
  std::vector<double> times;
  for (const auto& [t, file] : files) {
    times.push_back(t);
    if (std::abs(t - *time) <= tolerance) {
      if (chosen) *chosen = file;
      return readRecorded(file, path, sceneToml);
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

//! The physical problem of a scene: geometry, domain, materials and bodies as the resolved
//! TOML writes them, with what only says how it is solved (solver, its resolution and
//! parameters, times, outputs, effects, title) reset. SPH and TVD runs of one problem agree.
std::string problemKey(cases::Scene s) {
  const cases::Scene defaults;
  s.path.clear();
  s.title.clear();
  s.solver = defaults.solver;
  s.sph = defaults.sph;
  s.tvd = defaults.tvd;
  s.riemann = defaults.riemann;
  s.tStart = defaults.tStart;
  s.tEnd = defaults.tEnd;
  s.output = defaults.output;
  s.effects.clear();
  return cases::toToml(s);
}

//! Refuses two snapshots of unrelated problems (a Sod tube against an impact): their numbers
//! would mean nothing. `force` admits different scenes whose domains overlap.
void checkSameProblem(const std::string& tomlA, const std::string& tomlB, const fs::path& fileA,
                      const fs::path& fileB, bool force) {
  std::optional<cases::Scene> sa, sb;
  try {
    if (!tomlA.empty()) sa = cases::parseScene(tomlA, fileA.string());
    if (!tomlB.empty()) sb = cases::parseScene(tomlB, fileB.string());
  } catch (const InputError&) {
  }
  if (!sa || !sb) {
    fmt::print(stderr, "hvi compare: note: {} stores no readable scene; cannot check that A and B "
                       "are the same problem\n", (!sa ? fileA : fileB).string());
    return;
  }
  if (problemKey(*sa) == problemKey(*sb)) return;
  // "Sharing a domain": the overlap covers at least half of each domain, so that a coarse and a
  // fine variant of one set-up qualify and a Sod tube inside an impact's domain does not.
  const auto& da = sa->domain;
  const auto& db = sb->domain;
  const double ox = std::min(da.xmax, db.xmax) - std::max(da.xmin, db.xmin);
  const double oz = std::min(da.zmax, db.zmax) - std::max(da.zmin, db.zmin);
  const double overlapArea = ox > 0.0 && oz > 0.0 ? ox * oz : 0.0;
  const double areaA = (da.xmax - da.xmin) * (da.zmax - da.zmin);
  const double areaB = (db.xmax - db.xmin) * (db.zmax - db.zmin);
  const bool overlap = overlapArea >= 0.5 * std::max(areaA, areaB);
  const std::string what = fmt::format(
      "A ({}, \"{}\") and B ({}, \"{}\") are snapshots of different scenes (their geometry, "
      "domain, materials or bodies differ)", fileA.string(), sa->title, fileB.string(), sb->title);
  if (sa->geometry != sb->geometry)
    throw InputError(fmt::format("compare: {}; their geometries differ ({} and {}): nothing to "
                                 "compare, even with --force", what, toString(sa->geometry),
                                 toString(sb->geometry)));
  if (!overlap)
    throw InputError(fmt::format(
        "compare: {}; their domains x [{}, {}] z [{}, {}] and x [{}, {}] z [{}, {}] cm overlap in "
        "less than half of each: nothing to compare, even with --force",
        what, da.xmin, da.xmax, da.zmin, da.zmax, db.xmin, db.xmax, db.zmin, db.zmax));
  if (!force)
    throw InputError(fmt::format("compare: {}; give --force to compare them anyway", what));
  fmt::print(stderr, "hvi compare: --force: {}\n", what);
}

void checkThresholds(const CompareCliOptions& opt) {
  if (opt.maxDensityL1 && !(std::isfinite(*opt.maxDensityL1) && *opt.maxDensityL1 >= 0.0))
    throw InputError(fmt::format("compare: --max-density-l1 {} must be a number >= 0 (a relative "
                                 "L1 difference)", *opt.maxDensityL1));
  if (opt.minIou && !(*opt.minIou >= 0.0 && *opt.minIou <= 1.0))
    throw InputError(fmt::format("compare: --min-iou {} must lie in [0, 1] (an IoU is a fraction)",
                                 *opt.minIou));
  if (opt.time && !std::isfinite(*opt.time))
    throw InputError(fmt::format("compare: --time {} must be a finite time in us", *opt.time));
}

int compareImpl(const fs::path& a, const fs::path& b, const CompareCliOptions& opt) {
  if (opt.spacing && !(*opt.spacing > 0.0 && std::isfinite(*opt.spacing)))
    throw InputError(fmt::format("compare: --spacing {} must be a positive length in cm",
                                 *opt.spacing));
  if (!(opt.timeTolerance >= 0.0))
    throw InputError("compare: --time-tolerance must be >= 0");
  checkThresholds(opt);
  std::string tomlA, tomlB;
  fs::path fileA, fileB;
  const Snapshot sa = loadSnapshot(a, opt.time, opt.timeTolerance, &tomlA, &fileA);
  const Snapshot sb = loadSnapshot(b, opt.time, opt.timeTolerance, &tomlB, &fileB);
  checkSameProblem(tomlA, tomlB, fileA, fileB, opt.force);
  if (std::abs(sa.time - sb.time) > opt.timeTolerance)
    fmt::print(stderr, "hvi compare: warning: A is at t = {} us and B at t = {} us\n", sa.time,
               sb.time);

  CompareOptions co;
  co.spacing = opt.spacing.value_or(0.0);
  co.resample.sphReconstruction = opt.sphReconstruction;
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
  j["sph_reconstruction"] = toString(opt.sphReconstruction);
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
  } catch (const OutputError& e) {
    // As for hvi run: 4 is "an output file could not be written".
    report(e.what());
    return 4;
  }
}

}  // namespace hvi::compare
