//! @file What a run records beside its snapshots: summary.json, timeseries.json, energy budget.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"

namespace hvi::app {

//! Keeps the run's history (one entry per snapshot, one per step for the energy budget) and
//! writes it atomically, so a killed run leaves consistent files. Its state travels in the
//! checkpoint header, so a restarted run continues the same history.
class RunRecord {
 public:
  RunRecord(std::filesystem::path out, const cases::Scene& scene, std::string sceneToml);

  void begin(const Totals& initial);
  //! Per step; records the energy budget only when the scene names that effect.
  void afterStep(const Solver& solver, double dt);
  //! Per snapshot: totals, peak density and pressure, debris-cloud features; rewrites
  //! timeseries.json.
  void snapshot(const Snapshot& snap, const Totals& totals, const std::string& stem);
  //! Writes summary.json.
  void finish(const Solver& solver, double wallSeconds, long stepsThisRun, int threads,
              const std::string& status, const std::string& error);

  [[nodiscard]] nlohmann::json checkpointHeader() const;
  //! Restores from a checkpoint header; refuses a checkpoint of another scene.
  void restore(const nlohmann::json& header, double time);

 private:
  void writeTimeseries() const;
  void writeEnergyBudget() const;

  std::filesystem::path out_;
  const cases::Scene& scene_;
  std::string sceneToml_;
  Totals initial_;
  nlohmann::json history_ = nlohmann::json::array();
  std::vector<std::array<double, 5>> budget_;  // t, kinetic, internal, total, dt
};

}  // namespace hvi::app
