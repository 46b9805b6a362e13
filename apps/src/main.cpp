//! @file The `hvi` command line: run, check, compare.
#if __has_include(<malloc.h>)
#include <malloc.h>  // mallopt (glibc)
#endif
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "hvi/apps/driver.hpp"
#include "hvi/apps/sweep.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/command.hpp"

namespace {

//! The options of `hvi compare` (CLI11 stays in this file: the libraries take plain options).
void addCompareOptions(CLI::App& cmd, hvi::compare::CompareCliOptions& opt) {
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
  cmd.add_option_function<std::string>(
         "--sph-reconstruction",
         [&opt](const std::string& v) {
           opt.sphReconstruction = hvi::compare::parseSphReconstruction(v);
         },
         "How SPH particles are read onto the grid: adaptive (a particle stands for its share of "
         "the space its neighbours leave it, so a sparse spray reads as a cloud) or constant "
         "(each particle's own h and volume, the study's reading)")
      ->check(CLI::IsMember({"adaptive", "constant"}))
      ->default_str("adaptive");
  cmd.add_flag("--quiet,-q", opt.quiet, "Do not print the table");
  cmd.add_flag("--force", opt.force,
               "Compare snapshots of different scenes (bodies, materials or domain differ) whose "
               "domains overlap");
}

//! Options shared by `hvi sweep` and `hvi ballistic-limit`.
void addSweepOptions(CLI::App& cmd, hvi::app::SweepOptions& opt) {
  opt.jobs = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  cmd.add_option("shield", opt.shield, "Shield declaration (TOML, docs/shield.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd.add_option("--out,-o", opt.out, "Folder for the cases' scenes, runs and results")
      ->capture_default_str();
  cmd.add_option("--jobs,-j", opt.jobs,
                 "Runs at once (each a child `hvi run`, one thread each; default: the cores)")
      ->capture_default_str();
  cmd.add_option("--set,-s", opt.overrides, "Passed to every `hvi run`, e.g. --set tvd.cfl=0.3");
  cmd.add_option("--hvi", opt.hvi, "Executable run for each case (default: this hvi)");
  cmd.add_flag("--quiet,-q", opt.quiet, "No progress lines");
}

//! "sph,tvd" into solver kinds; false on an unknown name.
bool parseSolvers(const std::vector<std::string>& names, std::vector<hvi::cases::SolverKind>& out) {
  for (const auto& n : names) {
    if (n == "sph")
      out.push_back(hvi::cases::SolverKind::Sph);
    else if (n == "tvd")
      out.push_back(hvi::cases::SolverKind::Tvd);
    else {
      fmt::print(stderr, "hvi: --solver {}: allowed: sph, tvd\n", n);
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef M_MMAP_THRESHOLD
  // glibc raises its mmap threshold to the size of each large block freed (up to 32 MiB); the
  // solvers' large arrays then come from the heap and fragment it as they are rebuilt: +120 B
  // per SPH particle by step 50 of variant 2 (docs/performance.md, "SPH memory"). A fixed
  // threshold keeps large arrays mapped and returned when freed; the heap's smaller blocks are
  // kept (not trimmed and faulted in again at every step).
  mallopt(M_MMAP_THRESHOLD, 256 * 1024);
  mallopt(M_TRIM_THRESHOLD, 64 * 1024 * 1024);
#endif
  CLI::App app{"hvi: hypervelocity impact with modified SPH and Eulerian TVD, and their comparison",
               "hvi"};
  app.set_version_flag("--version", std::string("hvi ") + HVI_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 compare thresholds exceeded, 2 bad input (scene, options, output\n"
      "folder), 3 simulation failed (diagnostic printed, last state written), 4 an output file\n"
      "could not be written (disk full, ...; the last checkpoint is intact), 130 interrupted\n"
      "(checkpoint written; continue with --restart). Units are cm-g-us (see docs/scenes.md).");

  hvi::app::RunOptions run;
  auto* runCmd = app.add_subcommand("run", "Run a scene: snapshots (HDF5, VTK), summary.json");
  runCmd->add_option("scene", run.scene, "Scene file (TOML)")->required()->check(CLI::ExistingFile);
  runCmd->add_option("--out,-o", run.out, "Output folder")->capture_default_str();
  runCmd->add_option("--set,-s", run.overrides,
                     "Override a scene value, e.g. --set sph.alpha=1.5 --set 'time.end=2 us'");
  runCmd->add_flag("--restart", run.restart, "Continue from <out>/checkpoint.bin");
  runCmd->add_flag(
      "--overwrite", run.overwrite,
      "Remove the results of an earlier run in --out first (only files hvi run writes)");
  runCmd->add_flag("--quiet,-q", run.quiet, "No progress line");
  runCmd->add_option(
      "--stop-after", run.stopAfterSteps,
      "Stop (with a checkpoint, exit 130) after this many steps, as Ctrl-C would; 0: "
      "before the first step");
  run.program = argc > 0 ? argv[0] : "hvi";

  std::string checkScene;
  std::vector<std::string> checkOverrides;
  auto* checkCmd = app.add_subcommand("check", "Validate a scene and print it resolved");
  checkCmd->add_option("scene", checkScene, "Scene file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  checkCmd->add_option("--set,-s", checkOverrides, "Override a scene value");

  hvi::compare::CompareCliOptions cmp;
  std::string cmpA, cmpB;
  auto* cmpCmd = app.add_subcommand(
      "compare",
      "Compare two results (SPH vs TVD, or two runs) on one grid: density, material, features");
  cmpCmd->add_option("a", cmpA, "Snapshot (.h5) or run folder")->required();
  cmpCmd->add_option("b", cmpB, "Snapshot (.h5) or run folder")->required();
  addCompareOptions(*cmpCmd, cmp);

  hvi::app::SweepOptions sweepOpt;
  hvi::app::SweepGrid grid;
  std::vector<std::string> sweepSolvers;
  auto* sweepCmd = app.add_subcommand(
      "sweep", "Run a shield over parameters (every combination), several at once, resumable");
  addSweepOptions(*sweepCmd, sweepOpt);
  sweepCmd->add_option("--solver", sweepSolvers, "Solvers: sph, tvd")->delimiter(',');
  sweepCmd->add_option("--speed", grid.speeds, "Impact speeds, km/s (e.g. 3,5,7)")->delimiter(',');
  sweepCmd->add_option("--diameter", grid.diameters, "Projectile diameters, cm")->delimiter(',');
  sweepCmd
      ->add_option("--standoff", grid.standoffs, "Standoffs (bumper rear face to rear wall), cm")
      ->delimiter(',');
  sweepCmd->add_option("--rear-wall", grid.rearWalls, "Rear-wall thicknesses, cm")->delimiter(',');
  sweepCmd->add_option("--bumper", grid.bumpers, "Bumper thicknesses, cm")->delimiter(',');

  hvi::app::SweepOptions blOpt;
  blOpt.out = "ballistic_limit";
  hvi::app::BallisticLimitOptions bl;
  std::string blSolver;  // empty: the declaration's solver
  auto* blCmd = app.add_subcommand(
      "ballistic-limit",
      "Critical projectile diameter at each speed by bisection on rear-wall failure");
  addSweepOptions(*blCmd, blOpt);
  blCmd->add_option("--solver", blSolver, "sph or tvd (default: the declaration's solver)");
  blCmd->add_option("--speed", bl.speeds, "Impact speeds, km/s (e.g. 2,3,5,7,9,12)")
      ->delimiter(',')
      ->required();
  blCmd
      ->add_option("--tolerance", bl.tolerance,
                   "Stop when (failed - survived) <= tolerance * midpoint")
      ->capture_default_str();
  blCmd->add_option("--d-min", bl.dMin, "Start bracket, cm (default: 0.5 x the BLE's d_c)");
  blCmd->add_option("--d-max", bl.dMax, "Start bracket, cm (default: 2 x the BLE's d_c)");
  bl.plotScript = HVI_TOOLS_DIR "/plot_ballistic_limit.py";
  blCmd->add_option("--plot-script", bl.plotScript, "Python script drawing the PNG ('' for none)")
      ->capture_default_str();

  // CLI11 reports a mistyped command as an unexpected argument; name it and the commands instead.
  const auto isCommand = [&](const std::string& name) {
    for (const auto* sub : app.get_subcommands([](CLI::App*) { return true; }))
      if (sub->get_name() == name) return true;
    return false;
  };
  if (argc > 1 && argv[1][0] != '-' && !isCommand(argv[1])) {
    fmt::print(stderr,
               "hvi: unknown command '{}'; the commands are run, check, compare, sweep and "
               "ballistic-limit (see "
               "hvi --help)\n",
               argv[1]);
    return hvi::app::kBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0; every real one is bad input.
    return app.exit(e) == 0 ? hvi::app::kOk : hvi::app::kBadInput;
  }

  // Each command turns its own errors into exit codes; this is the last line of defence, so
  // that nothing ends in std::terminate (exit 134) with a message the user cannot act on.
  try {
    if (*runCmd) {
      const int rc = hvi::app::runScene(run);
      if (rc == hvi::app::kOutputFailed || rc == hvi::app::kSimulationFailed) {
        // After a failed H5Fclose (disk full) HDF5 1.10 keeps a half-closed file in its ID table
        // and its atexit handler then segfaults (exit 139 instead of 4). Every file hvi wrote is
        // closed and renamed or removed by now, so skipping the exit handlers loses nothing.
        std::fflush(nullptr);
        std::_Exit(rc);
      }
      return rc;
    }
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
    if (*sweepCmd) {
      if (!parseSolvers(sweepSolvers, grid.solvers)) return hvi::app::kBadInput;
      return hvi::app::runSweep(sweepOpt, grid);
    }
    if (*blCmd) {
      if (!blSolver.empty()) {
        std::vector<hvi::cases::SolverKind> k;
        if (!parseSolvers({blSolver}, k)) return hvi::app::kBadInput;
        bl.solver = k.front();
      }
      return hvi::app::runBallisticLimit(blOpt, bl);
    }
  } catch (const hvi::OutputError& e) {
    fmt::print(stderr, "hvi: output could not be written: {}\n", e.what());
    return hvi::app::kOutputFailed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "hvi: internal error: {}\n", e.what());
    return hvi::app::kSimulationFailed;
  }
  return hvi::app::kBadInput;
}
