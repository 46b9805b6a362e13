//! @file `hvi sweep` and `hvi ballistic-limit`: shield cases run as child `hvi run` processes,
//! several at once, resumable, Ctrl-C safe (docs/shield.md).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hvi/cases/scene.hpp"

namespace hvi::app {

//! One case of a sweep: the shield with these values in place of the declared ones.
struct ShieldCase {
  cases::SolverKind solver = cases::SolverKind::Tvd;
  double speed = 0.0;                                //!< km/s
  double diameter = 0.0;                             //!< cm
  std::optional<double> standoff, rearWall, bumper;  //!< cm
};

//! What the runner needs from the command line.
struct SweepOptions {
  std::filesystem::path shield;  //!< shield declaration
  std::filesystem::path out = "sweep";
  int jobs = 1;                        //!< runs at once (the command line: the cores)
  std::vector<std::string> overrides;  //!< --set, passed to every `hvi run`
  std::string hvi;                     //!< executable run for each case (default: this one)
  bool quiet = false;
};

//! The outcome of a case, read from its run folder's summary.json.
struct CaseOutcome {
  ShieldCase c;
  std::string id;
  std::string status;              //!< completed, failed (simulation), interrupted, error
  std::optional<bool> perforated;  //!< the rear-wall verdict (absent: no verdict)
  nlohmann::json verdict;
  double wallSeconds = 0.0;
  bool reused = false;  //!< finished by an earlier invocation: not rerun
};

//! The folder name of a case, e.g. "tvd_v7.44_d0.634" (+ "_S10.16", "_tw0.406", "_tb0.127").
std::string caseId(const ShieldCase& c);

//! `hvi sweep`: every combination of the given values (empty: the declaration's). Writes
//! <out>/sweep.json and sweep.csv. Returns an ExitCode.
struct SweepGrid {
  std::vector<cases::SolverKind> solvers;
  std::vector<double> speeds, diameters, standoffs, rearWalls, bumpers;
};
int runSweep(const SweepOptions& opt, const SweepGrid& grid);

//! `hvi ballistic-limit`: at each speed the critical diameter by bisection to a relative
//! `tolerance`, from [dMin, dMax] (default: 0.5 and 2 times the BLE's d_c). Writes
//! <out>/ballistic_limit.json, .csv and (with /usr/bin/python3) .png.
struct BallisticLimitOptions {
  std::optional<cases::SolverKind> solver;  //!< absent: the declaration's `solver`
  std::vector<double> speeds;  //!< km/s
  double tolerance = 0.05;
  std::optional<double> dMin, dMax;  //!< cm
  std::string plotScript;            //!< tools/plot_ballistic_limit.py (empty: no plot)
};
int runBallisticLimit(const SweepOptions& opt, const BallisticLimitOptions& bl);

}  // namespace hvi::app
