//! @file summary.json, timeseries.json and the energy budget of a run.
#include "hvi/apps/run_record.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "hvi/apps/features_hook.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"

#ifndef HVI_VERSION
#define HVI_VERSION "unknown"
#endif

namespace hvi::app {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
json totalsJson(const Totals& t) {
  return {{"mass", t.mass},       {"momentum_x", t.momentumX}, {"momentum_z", t.momentumZ},
          {"kinetic", t.kinetic}, {"internal", t.internal},    {"energy", t.energy()}};
}
Totals minus(const Totals& a, const Totals& b) {
  Totals t;
  t.mass = a.mass - b.mass;
  t.momentumX = a.momentumX - b.momentumX;
  t.momentumZ = a.momentumZ - b.momentumZ;
  t.kinetic = a.kinetic - b.kinetic;
  t.internal = a.internal - b.internal;
  return t;
}
Totals totalsFromJson(const json& j) {
  Totals t;
  t.mass = j.at("mass");
  t.momentumX = j.at("momentum_x");
  t.momentumZ = j.at("momentum_z");
  t.kinetic = j.at("kinetic");
  t.internal = j.at("internal");
  return t;
}
double relative(double now, double ref, double scale) {
  return scale > 0.0 ? (now - ref) / scale : 0.0;
}
double peak(const Snapshot& s, const char* name) {
  const Field* f = s.find(name);
  if (!f || f->data.empty()) return 0.0;
  return *std::max_element(f->data.begin(), f->data.end());
}
}  // namespace

RunRecord::RunRecord(fs::path out, const cases::Scene& scene, std::string sceneToml)
    : out_(std::move(out)), scene_(scene), sceneToml_(std::move(sceneToml)) {}

void RunRecord::begin(const Totals& initial) { initial_ = initial; }

void RunRecord::afterStep(const Solver& solver, double dt) {
  if (!scene_.has(cases::Effect::EnergyBudget)) return;
  const Totals t = solver.totals();
  pending_.push_back({solver.time(), t.kinetic, t.internal, t.energy(), dt});
}

void RunRecord::snapshot(const Snapshot& snap, const Totals& totals, const std::string& stem) {
  json e = {{"time", snap.time},
            {"step", snap.step},
            {"file", stem},
            {"totals", totalsJson(totals)},
            {"peak_density", peak(snap, "density")},
            {"peak_pressure", peak(snap, "pressure")}};
  if (scene_.has(cases::Effect::Features)) {
    e["features"] = measureFeaturesJson(snap, scene_);
    if (auto rw = measureRearWallJson(snap, scene_); !rw.is_null()) e["rear_wall"] = std::move(rw);
    if (auto p = measurePlatesJson(snap, scene_); !p.is_null()) e["plates"] = std::move(p);
  }
  history_.push_back(std::move(e));
  writeTimeseries();
  appendEnergyBudget();
}

void RunRecord::writeTimeseries() const {
  writeTextAtomically(out_ / "timeseries.json",
                      json{{"units", "cm-g-us"}, {"snapshots", history_}}.dump(1));
}

// Appending costs the new rows only (rewriting the whole file at every snapshot grew with the
// run). A run killed while appending may leave part of a row; a restart trims the file to the
// rows its checkpoint counts.
void RunRecord::appendEnergyBudget() {
  if (pending_.empty()) return;
  const fs::path file = out_ / "energy_budget.csv";
  std::string csv = budgetRows_ == 0 ? "time_us,kinetic,internal,total,dt_us\n" : "";
  for (const auto& r : pending_)
    csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", r[0], r[1], r[2], r[3], r[4]);
  errno = 0;
  std::ofstream f(file, std::ios::binary | (budgetRows_ == 0 ? std::ios::trunc : std::ios::app));
  f.write(csv.data(), static_cast<std::streamsize>(csv.size()));
  f.flush();
  if (!f)
    throw OutputError(fmt::format("{}: cannot write: {}", file.string(),
                                  errno != 0 ? errnoText(errno) : "write failed"));
  budgetRows_ += static_cast<long>(pending_.size());
  pending_.clear();
}

void RunRecord::finish(const Solver& solver, double wallSeconds, long stepsThisRun, int threads,
                       const std::string& status, const std::string& error) {
  const Totals now = solver.totals(), out = solver.outflow();
  // Momentum drift is scaled by the momentum scale sqrt(2 M E) since the net momentum of a
  // symmetric impact may be zero.
  const double pScale = std::sqrt(2.0 * initial_.mass * std::max(initial_.energy(), 1e-300));
  const double updates = static_cast<double>(solver.workItems()) * stepsThisRun;
  json s = {
      {"hvi_version", HVI_VERSION},
      {"scene", scene_.path},
      {"title", scene_.title},
      {"solver", solver.name()},
      {"status", status},
      {"error", error},
      {"final_time_us", solver.time()},
      {"end_time_us", scene_.tEnd},
      {"steps", solver.step()},
      {"steps_this_run", stepsThisRun},
      {"wall_seconds", wallSeconds},
      {"threads", threads},
      {"work_items", solver.workItems()},
      {"updates_per_second", wallSeconds > 0 ? updates / wallSeconds : 0.0},
      {"updates_per_second_per_core", wallSeconds > 0 ? updates / wallSeconds / threads : 0.0},
      {"conservation",
       {{"definition", "in the domain plus what left through outflow sides"},
        {"initial", totalsJson(initial_)},
        {"final", totalsJson(now)},
        {"in_domain", totalsJson(minus(now, out))},
        {"outflow", totalsJson(out)},
        {"mass_rel_error", relative(now.mass, initial_.mass, initial_.mass)},
        {"energy_rel_error", relative(now.energy(), initial_.energy(), initial_.energy())},
        {"momentum_x_rel_error", relative(now.momentumX, initial_.momentumX, pScale)},
        {"momentum_z_rel_error", relative(now.momentumZ, initial_.momentumZ, pScale)}}},
      {"snapshots", history_.size()},
  };
  if (auto verdict = rearWallVerdictJson(history_); !verdict.is_null())
    s["rear_wall_failure"] = std::move(verdict);
  if (auto plates = platesSummaryJson(history_); !plates.is_null()) s["plates"] = std::move(plates);
  writeTextAtomically(out_ / "summary.json", s.dump(2));
}

json RunRecord::checkpointHeader() {
  appendEnergyBudget();
  return {{"version", kHeaderVersion},
          {"scene", sceneToml_},
          {"initial", totalsJson(initial_)},
          {"history", history_},
          {"budget_rows", budgetRows_}};
}

namespace {
// Cuts `file` after its header line and `rows` rows; false if it holds fewer.
bool trimCsv(const fs::path& file, long rows) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return rows == 0;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t end = 0;
  for (long line = 0; line <= rows; ++line) {
    const std::size_t nl = text.find('\n', end);
    if (nl == std::string::npos) return false;
    end = nl + 1;
  }
  in.close();
  if (end < text.size()) fs::resize_file(file, end);
  return true;
}
}  // namespace

void RunRecord::restore(const json& h, double time) {
  if (h.at("scene").get<std::string>() != sceneToml_)
    throw InputError(fmt::format(
        "{}: the checkpoint in {} was written by a different scene (or other --set values); "
        "restart with the same scene and settings, or run into a new --out folder",
        scene_.path, out_.string()));
  initial_ = totalsFromJson(h.at("initial"));
  history_ = json::array();
  for (const auto& e : h.at("history"))
    if (e.at("time").get<double>() <= time) history_.push_back(e);
  pending_.clear();
  budgetRows_ = 0;
  if (!h.contains("version")) {  // version 1: the whole budget in the header, the file rewritten
    for (const auto& r : h.at("budget"))
      if (r[0].get<double>() <= time) pending_.push_back(r.get<BudgetRow>());
    return;
  }
  const long rows = h.at("budget_rows").get<long>();
  const fs::path file = out_ / "energy_budget.csv";
  if (!trimCsv(file, rows))
    throw InputError(fmt::format(
        "{}: the checkpoint counts {} energy budget rows, the file holds fewer (or is missing); "
        "run into a new --out folder",
        file.string(), rows));
  budgetRows_ = rows;
}

}  // namespace hvi::app
