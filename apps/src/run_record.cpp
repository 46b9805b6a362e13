//! @file summary.json, timeseries.json and the energy budget of a run.
#include "hvi/apps/run_record.hpp"

#include <algorithm>
#include <cmath>

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
  return {{"mass", t.mass}, {"momentum_x", t.momentumX}, {"momentum_z", t.momentumZ},
          {"kinetic", t.kinetic}, {"internal", t.internal}, {"energy", t.energy()}};
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
  budget_.push_back({solver.time(), t.kinetic, t.internal, t.energy(), dt});
}

void RunRecord::snapshot(const Snapshot& snap, const Totals& totals, const std::string& stem) {
  json e = {{"time", snap.time}, {"step", snap.step}, {"file", stem},
            {"totals", totalsJson(totals)},
            {"peak_density", peak(snap, "density")}, {"peak_pressure", peak(snap, "pressure")}};
  if (scene_.has(cases::Effect::Features)) e["features"] = measureFeaturesJson(snap, scene_);
  history_.push_back(std::move(e));
  writeTimeseries();
  if (!budget_.empty()) writeEnergyBudget();
}

void RunRecord::writeTimeseries() const {
  writeTextAtomically(out_ / "timeseries.json",
                      json{{"units", "cm-g-us"}, {"snapshots", history_}}.dump(1));
}

void RunRecord::writeEnergyBudget() const {
  std::string csv = "time_us,kinetic,internal,total,dt_us\n";
  for (const auto& r : budget_)
    csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", r[0], r[1], r[2], r[3], r[4]);
  writeTextAtomically(out_ / "energy_budget.csv", csv);
}

void RunRecord::finish(const Solver& solver, double wallSeconds, long stepsThisRun, int threads,
                       const std::string& status, const std::string& error) {
  const Totals now = solver.totals();
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
       {{"initial", totalsJson(initial_)},
        {"final", totalsJson(now)},
        {"mass_rel_error", relative(now.mass, initial_.mass, initial_.mass)},
        {"energy_rel_error", relative(now.energy(), initial_.energy(), initial_.energy())},
        {"momentum_x_rel_error", relative(now.momentumX, initial_.momentumX, pScale)},
        {"momentum_z_rel_error", relative(now.momentumZ, initial_.momentumZ, pScale)}}},
      {"snapshots", history_.size()},
  };
  writeTextAtomically(out_ / "summary.json", s.dump(2));
}

json RunRecord::checkpointHeader() const {
  json b = json::array();
  for (const auto& r : budget_) b.push_back(r);
  return {{"scene", sceneToml_}, {"initial", totalsJson(initial_)}, {"history", history_},
          {"budget", b}};
}

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
  budget_.clear();
  for (const auto& r : h.at("budget"))
    if (r[0].get<double>() <= time) budget_.push_back(r.get<std::array<double, 5>>());
}

}  // namespace hvi::app
