//! @file The run driver behind `hvi run`: steps a solver to the end time, writes outputs.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
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
  bool quiet = false;                   //!< no progress line
  long stopAfterSteps = -1;             //!< testing aid: request a stop after this many steps
};

//! Exit statuses of `hvi`: documented in README.md.
enum ExitCode : int {
  kOk = 0,
  kThresholdFailed = 1,
  kBadInput = 2,
  kSimulationFailed = 3,
  kInterrupted = 130,
};

//! Builds the solver a scene names. Throws InputError if that solver is not available.
std::unique_ptr<Solver> createSolver(const cases::Scene& scene);

//! Runs a scene; returns an ExitCode. Diagnostics go to stderr.
int runScene(const RunOptions& opts);

//! Same, with the solver built by `factory` instead of createSolver (tests use it to wrap a
//! solver).
using SolverFactory = std::function<std::unique_ptr<Solver>(const cases::Scene&)>;
int runScene(const RunOptions& opts, const SolverFactory& factory);

}  // namespace hvi::app
