//! @file The `hvi` command line: run, check, compare.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hvi: hypervelocity impact with modified SPH and Eulerian TVD, and their comparison",
               "hvi"};
  app.set_version_flag("--version", std::string("hvi ") + HVI_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 compare thresholds exceeded, 2 bad input (scene, options),\n"
      "3 simulation failed (diagnostic printed, last state written), 130 interrupted (checkpoint\n"
      "written; continue with --restart). Units are cm-g-us (see docs/scenes.md).");

  hvi::app::RunOptions run;
  auto* runCmd = app.add_subcommand("run", "Run a scene: snapshots (HDF5, VTK), summary.json");
  runCmd->add_option("scene", run.scene, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
  runCmd->add_option("--out,-o", run.out, "Output folder")->capture_default_str();
  runCmd->add_option("--set,-s", run.overrides,
                     "Override a scene value, e.g. --set sph.alpha=1.5 --set 'time.end=2 us'");
  runCmd->add_flag("--restart", run.restart, "Continue from <out>/checkpoint.bin");
  runCmd->add_flag("--quiet,-q", run.quiet, "No progress line");
  runCmd->add_option("--stop-after", run.stopAfterSteps,
                     "Stop (with a checkpoint) after this many steps, as Ctrl-C would");

  std::string checkScene;
  std::vector<std::string> checkOverrides;
  auto* checkCmd = app.add_subcommand("check", "Validate a scene and print it resolved");
  checkCmd->add_option("scene", checkScene, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
  checkCmd->add_option("--set,-s", checkOverrides, "Override a scene value");

  hvi::compare::CompareCliOptions cmp;
  std::string cmpA, cmpB;
  auto* cmpCmd = app.add_subcommand(
      "compare", "Compare two results (SPH vs TVD, or two runs) on one grid: density, material, features");
  cmpCmd->add_option("a", cmpA, "Snapshot (.h5) or run folder")->required();
  cmpCmd->add_option("b", cmpB, "Snapshot (.h5) or run folder")->required();
  hvi::compare::addCliOptions(*cmpCmd, cmp);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0; every real one is bad input.
    return app.exit(e) == 0 ? hvi::app::kOk : hvi::app::kBadInput;
  }

  if (*runCmd) return hvi::app::runScene(run);
  if (*checkCmd) {
    try {
      const auto scene = hvi::cases::loadScene(checkScene, checkOverrides);
      std::cout << hvi::cases::toToml(scene);
      fmt::print(stderr, "hvi: {} is valid\n", checkScene);
      return hvi::app::kOk;
    } catch (const hvi::InputError& e) {
      fmt::print(stderr, "hvi: {}\n", e.what());
      return hvi::app::kBadInput;
    }
  }
  if (*cmpCmd) return hvi::compare::runCompareCommand(cmpA, cmpB, cmp);
  return hvi::app::kBadInput;
}
