//! @file The run driver behind `hvi run`: steps a solver to the end time, writes outputs.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"

namespace hvi::app {

struct RunOptions {
  std::filesystem::path scene;
  std::filesystem::path out = "out";
  std::vector<std::string> overrides;   //!< --set key=value
  bool restart = false;                 //!< continue from <out>/checkpoint.bin
  bool overwrite = false;               //!< remove an earlier run's files from <out> first
  bool quiet = false;                   //!< no progress line
  //! Request a stop (checkpoint, exit 130) after this many steps; 0 stops before the first.
  std::optional<long> stopAfterSteps;
  std::string program = "hvi";          //!< how the restart hint names the executable
};

//! Exit statuses of `hvi`: documented in README.md.
enum ExitCode : int {
  kOk = 0,
  kThresholdFailed = 1,
  kBadInput = 2,
  kSimulationFailed = 3,
  kOutputFailed = 4,  //!< an output file could not be written (disk full, ...); checkpoint kept
  kInterrupted = 130,
};

//! Builds the solver a scene names. Throws InputError if that solver is not available.
std::unique_ptr<Solver> createSolver(const cases::Scene& scene);

//! Simulated time that moved by less than half the step this many steps in a row (round-off
//! at a large t swallows the step) stops the run as a failure: it could never reach the end.
inline constexpr int kMaxStalledSteps = 10;

//! The command that continues a stopped run: program, scene, --out, every --set (shell-quoted)
//! and --restart.
std::string restartCommand(const RunOptions& opts);

//! Runs a scene; returns an ExitCode. Diagnostics go to stderr.
int runScene(const RunOptions& opts);

//! Same, with the solver built by `factory` instead of createSolver (tests use it to wrap a
//! solver).
using SolverFactory = std::function<std::unique_ptr<Solver>(const cases::Scene&)>;
int runScene(const RunOptions& opts, const SolverFactory& factory);

}  // namespace hvi::app
