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

//! Keeps the run's history (one entry per snapshot, one per step for the energy budget). The
//! JSON files are written atomically, so a killed run leaves consistent files; the energy
//! budget is appended (its rows are never rewritten). The history and the budget's row count
//! travel in the checkpoint header, so a restarted run continues the same history.
class RunRecord {
 public:
  RunRecord(std::filesystem::path out, const cases::Scene& scene, std::string sceneToml);

  void begin(const Totals& initial);
  //! Per step; records the energy budget only when the scene names that effect.
  void afterStep(const Solver& solver, double dt);
  //! Per snapshot: totals, peak density and pressure, debris-cloud features; rewrites
  //! timeseries.json and appends the budget's new rows to energy_budget.csv.
  void snapshot(const Snapshot& snap, const Totals& totals, const std::string& stem);
  //! Writes summary.json.
  void finish(const Solver& solver, double wallSeconds, long stepsThisRun, int threads,
              const std::string& status, const std::string& error);

  //! The header of a checkpoint of the state now. Appends the budget rows not yet in
  //! energy_budget.csv first: the header records how many rows the file holds.
  [[nodiscard]] nlohmann::json checkpointHeader();
  //! Restores from a checkpoint header (and trims energy_budget.csv to the rows it counts, so
  //! rows written after the checkpoint, or half a row of a killed run, go); refuses a
  //! checkpoint of another scene, or a budget file with fewer rows than the checkpoint counts.
  //! Reads the headers of earlier versions (the whole budget stored in the header).
  void restore(const nlohmann::json& header, double time);

  //! Version of the checkpoint header this build writes (docs/output.md).
  static constexpr int kHeaderVersion = 2;

 private:
  void writeTimeseries() const;
  void appendEnergyBudget();

  std::filesystem::path out_;
  const cases::Scene& scene_;
  std::string sceneToml_;
  Totals initial_;
  nlohmann::json history_ = nlohmann::json::array();
  using BudgetRow = std::array<double, 5>;  // t, kinetic, internal, total, dt
  std::vector<BudgetRow> pending_;          // budget rows not yet in energy_budget.csv
  long budgetRows_ = 0;                     // rows in energy_budget.csv
};

}  // namespace hvi::app
