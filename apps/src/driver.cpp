//! @file `hvi run`: steps a solver through the output times with snapshots and checkpoints.
#include "hvi/apps/driver.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hvi/apps/output_folder.hpp"
#include "hvi/apps/run_record.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/progress.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/io/checkpoint.hpp"
#include "hvi/io/output.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/tvd/tvd.hpp"
#include "hvi/verify/riemann_solver.hpp"

namespace hvi::app {
namespace fs = std::filesystem;
using nlohmann::json;

std::unique_ptr<Solver> createSolver(const cases::Scene& scene) {
  switch (scene.solver) {
    case cases::SolverKind::Sph: return sph::createSolver(scene);
    case cases::SolverKind::Tvd: return tvd::createSolver(scene);
    case cases::SolverKind::Riemann: return verify::createRiemannSolver(scene);
  }
  throw InputError(scene.path + ": unknown solver");
}

namespace {

int threadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

//! Runs an output step (snapshot, checkpoint, record). Every failure becomes an OutputError:
//! hvi's own writers already name the file and the system's reason; a library writer (HDF5,
//! VTK) names the file and its own operation, and errno, when it is a storage error, adds why.
template <class F>
void writeOutput(F&& write) {
  errno = 0;
  try {
    write();
  } catch (const OutputError&) {
    throw;
  } catch (const std::exception& e) {
    const int err = errno;
    const bool storage = err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO ||
                         err == EROFS || err == EACCES || err == EPERM;
    const std::string why = errnoText(err);
    if (storage && std::string(e.what()).find(why) == std::string::npos)
      throw OutputError(fmt::format("{}: {}", e.what(), why));
    throw OutputError(e.what());
  }
}

class Run {
 public:
  Run(const RunOptions& opts, cases::Scene scene, SolverFactory factory)
      : factory_(std::move(factory)), opts_(opts), scene_(std::move(scene)), sceneToml_(cases::toToml(scene_)),
        record_(opts.out, scene_, sceneToml_), pvd_(opts.out / "hvi.pvd"),
        ckpt_(opts.out / "checkpoint.bin") {}

  int execute() {
    solver_ = factory_(scene_);
    Progress progress(scene_.tStart, scene_.tEnd);
    long stepsThisRun = 0;
    double lastDt = 0.0;
    try {
      if (opts_.restart) {
        const std::string header = io::readCheckpointFile(ckpt_, [&](std::istream& in) {
          solver_->readCheckpoint(in);
        });
        record_.restore(json::parse(header), solver_->time());
        checkpointTime_ = solver_->time();
        checkpointStep_ = solver_->step();
        pvd_.resumeFrom(solver_->time());
        progress.resumeAt(solver_->time());
        // Written only now: a refused restart (another scene) must not replace the folder's
        // scene.toml.
        writeOutput([&] { writeTextAtomically(opts_.out / "scene.toml", sceneToml_); });
        fmt::print(stderr, "hvi: restarted from {} at t = {} us, step {}\n", ckpt_.string(),
                   solver_->time(), solver_->step());
      } else {
        writeOutput([&] { writeTextAtomically(opts_.out / "scene.toml", sceneToml_); });
        record_.begin(solver_->totals());
        writeSnapshot("snap");
      }
      if (opts_.stopAfterSteps == 0 && solver_->time() < scene_.tEnd)
        return stop(progress, stepsThisRun, lastDt);

      auto lastCheckpoint = std::chrono::steady_clock::now();
      const auto outputs = scene_.output.times;
      int stalled = 0;
      double stalledMoved = 0.0;
      try {
        while (solver_->time() < scene_.tEnd) {
          const double tNext = nextOutputTime(outputs, solver_->time());
          const double tBefore = solver_->time();
          const double dt = advance(tNext);
          ++stepsThisRun;
          lastDt = dt;
          // A step that round-off swallows (t + dt == t at a large t) or a solver that returns a
          // zero step would spin for ever with an ETA of 0; a few in a row end the run.
          const double moved = solver_->time() - tBefore;
          if (moved > 0.5 * dt && dt > 0.0) {
            stalled = 0;
            stalledMoved = 0.0;
          } else {
            ++stalled;
            stalledMoved += moved;
          }
          if (stalled >= kMaxStalledSteps) {
            throw SimulationError(fmt::format(
                "simulated time stopped advancing at t = {:.17g} us (step {}): the last {} steps "
                "of dt = {:.3e} us moved t by {:.3e} us in all (the step is lost to round-off at "
                "this t, or the solver returns no step)",
                solver_->time(), solver_->step(), stalled, dt, stalledMoved));
          }
          record_.afterStep(*solver_, dt);
          if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), dt);
          if (solver_->time() >= tNext) {
            writeSnapshot("snap");
            writeCheckpoint();
            lastCheckpoint = std::chrono::steady_clock::now();
          } else if (scene_.output.checkpointEvery > 0.0 &&
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - lastCheckpoint)
                             .count() > scene_.output.checkpointEvery) {
            writeCheckpoint();
            lastCheckpoint = std::chrono::steady_clock::now();
          }
          if (opts_.stopAfterSteps && stepsThisRun >= *opts_.stopAfterSteps) requestStop();
          if (stopRequested() && solver_->time() < scene_.tEnd)
            return stop(progress, stepsThisRun, lastDt);
        }
      } catch (const SimulationError& e) {
        fmt::print(stderr, "\nhvi: simulation failed: {}\n", e.what());
        // The failed state is written under its own name for inspection; earlier snapshots and
        // the last checkpoint stay as they were.
        try {
          writeOutput([&] { writeSnapshot("failed", false); });
          fmt::print(stderr, "hvi: state at failure written to {}\n",
                     (opts_.out / fmt::format("failed_{:08d}.h5", solver_->step())).string());
        } catch (const std::exception& w) {
          fmt::print(stderr, "hvi: could not write the failed state: {}\n", w.what());
        }
        try {
          record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "failed",
                         e.what());
        } catch (const std::exception& w) {
          fmt::print(stderr, "hvi: could not write summary.json: {}\n", w.what());
        }
        return kSimulationFailed;
      }
      if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), lastDt, true);
      writeOutput([&] {
        record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "completed", "");
      });
    } catch (const OutputError& e) {
      return outputFailed(e, progress, stepsThisRun);
    }
    fmt::print(stderr, "hvi: done, {} steps in {:.1f} s; results in {}\n", solver_->step(),
               progress.wallSeconds(), opts_.out.string());
    return kOk;
  }

 private:
  //! One solver step. Anything but a SimulationError escaping a solver (std::length_error,
  //! bad_alloc, ...) is a bug or an exhausted machine, not bad output: it is reported as a failed
  //! run, with the state written, instead of aborting the process.
  double advance(double tNext) {
    try {
      return solver_->advance(tNext);
    } catch (const SimulationError&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw SimulationError(fmt::format("out of memory in step {} at t = {} us", solver_->step() + 1,
                                        solver_->time()));
    } catch (const std::exception& e) {
      throw SimulationError(fmt::format("internal error in step {} at t = {} us: {}",
                                        solver_->step() + 1, solver_->time(), e.what()));
    }
  }

  //! Stop requested (signal, --stop-after): checkpoint, hint, summary, exit 130.
  int stop(Progress& progress, long stepsThisRun, double lastDt) {
    writeCheckpoint();
    if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), lastDt, true);
    fmt::print(stderr, "hvi: stopped at t = {} us, step {}; checkpoint {}; continue with `{}`\n",
               solver_->time(), solver_->step(), ckpt_.string(), restartCommand(opts_));
    writeOutput([&] {
      record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "interrupted", "");
    });
    return kInterrupted;
  }

  //! A write failed: stop at once (the next writes would fail the same way), say which file and
  //! why, and point at the last checkpoint, which writeAtomically left intact.
  int outputFailed(const OutputError& e, const Progress& progress, long stepsThisRun) {
    fmt::print(stderr, "\nhvi: output could not be written: {}\n", e.what());
    if (checkpointTime_)
      fmt::print(stderr, "hvi: the last checkpoint {} (t = {} us, step {}) is intact; make room, "
                         "then continue with `{}`\n",
                 ckpt_.string(), *checkpointTime_, checkpointStep_, restartCommand(opts_));
    else
      fmt::print(stderr, "hvi: no checkpoint was written yet; make room and run again{}\n",
                 runFiles(opts_.out).empty() ? "" : " with --overwrite");
    // Best effort: summary.json says what happened when there is room for it.
    try {
      if (solver_)
        record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(),
                       "output_failed", e.what());
    } catch (const std::exception&) {
    }
    return kOutputFailed;
  }

  double nextOutputTime(const std::vector<double>& times, double t) const {
    for (double o : times)
      if (o > t) return std::min(o, scene_.tEnd);
    return scene_.tEnd;
  }

  void writeSnapshot(const char* prefix, bool addToSeries = true) {
    writeOutput([&] {
      const Snapshot snap = solver_->snapshot();
      const std::string stem = fmt::format("{}_{:08d}", prefix, snap.step);
      std::vector<fs::path> files;
      if (scene_.output.hdf5 || !addToSeries) io::writeHdf5(opts_.out / (stem + ".h5"), snap, sceneToml_);
      if (scene_.output.vtk) files = io::writeVtk(opts_.out / stem, snap);
      if (!addToSeries) return;
      if (!files.empty()) {
        for (auto& f : files) f = f.filename();
        pvd_.add(snap.time, files);
      }
      record_.snapshot(snap, solver_->totals(), stem);
    });
  }

  void writeCheckpoint() {
    writeOutput([&] {
      io::writeCheckpointFile(ckpt_, record_.checkpointHeader().dump(),
                              [&](std::ostream& out) { solver_->writeCheckpoint(out); });
    });
    checkpointTime_ = solver_->time();
    checkpointStep_ = solver_->step();
  }

  SolverFactory factory_;
  RunOptions opts_;
  cases::Scene scene_;
  std::string sceneToml_;
  RunRecord record_;
  io::PvdSeries pvd_;
  fs::path ckpt_;
  std::unique_ptr<Solver> solver_;
  std::optional<double> checkpointTime_;  //!< time of the last checkpoint on disk, if any
  long checkpointStep_ = 0;
};

//! Refuses what would mix two runs' results or lose the user's files, before anything is
//! written.
void checkFolderContents(const RunOptions& opts) {
  std::error_code ec;
  const fs::path sceneOut = opts.out / "scene.toml";
  if (!opts.restart && fs::exists(sceneOut, ec) && fs::equivalent(opts.scene, sceneOut, ec))
    throw InputError(fmt::format("the scene file {} is where the run writes its resolved scene; "
                                 "copy it out of the output folder first", opts.scene.string()));
  if (opts.restart) return;
  const auto old = runFiles(opts.out);
  if (old.empty()) return;
  if (!opts.overwrite) {
    std::string names;
    for (std::size_t i = 0; i < old.size() && i < 4; ++i)
      names += (i ? ", " : "") + old[i].filename().string();
    if (old.size() > 4) names += fmt::format(", ... ({} files)", old.size());
    throw InputError(fmt::format(
        "output folder {} holds the results of an earlier run ({}); give --overwrite to replace "
        "them, --restart to continue that run, or another --out",
        opts.out.string(), names));
  }
  const int n = removeRunFiles(opts.out);
  fmt::print(stderr, "hvi: --overwrite: removed {} files of the earlier run in {}\n", n,
             opts.out.string());
}

}  // namespace

std::string restartCommand(const RunOptions& opts) {
  std::string cmd = fmt::format("{} run {} --out {}", shellQuote(opts.program),
                                shellQuote(opts.scene.string()), shellQuote(opts.out.string()));
  for (const auto& o : opts.overrides) cmd += " --set " + shellQuote(o);
  return cmd + " --restart";
}

int runScene(const RunOptions& opts) { return runScene(opts, createSolver); }

int runScene(const RunOptions& opts, const SolverFactory& factory) {
  cases::Scene scene;
  std::optional<FolderLock> lock;
  try {
    // Options first, then the scene, then the folder: nothing is created for bad input.
    if (opts.stopAfterSteps && *opts.stopAfterSteps < 0)
      throw InputError(fmt::format("--stop-after {}: must be a number of steps >= 0",
                                   *opts.stopAfterSteps));
    if (opts.restart && opts.overwrite)
      throw InputError("--restart continues the run in --out and --overwrite replaces it; give one");
    scene = cases::loadScene(opts.scene, opts.overrides);
    if (opts.restart) {
      std::error_code ec;
      if (!opts.out.empty() && !fs::exists(opts.out, ec))
        throw InputError(fmt::format("--restart: output folder {} does not exist; there is no run "
                                     "to continue", opts.out.string()));
      prepareOutputFolder(opts.out, false);
      if (!fs::is_regular_file(opts.out / "checkpoint.bin", ec))
        throw InputError(fmt::format("{}: --restart given but no checkpoint there",
                                     (opts.out / "checkpoint.bin").string()));
    } else {
      prepareOutputFolder(opts.out, true);
    }
    lock.emplace(opts.out);
    // Only with the lock held: no other run can be writing here now.
    removeStaleTemporaries(opts.out);
    checkFolderContents(opts);
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi: {}\n", e.what());
    return kBadInput;
  } catch (const OutputError& e) {
    fmt::print(stderr, "hvi: {}\n", e.what());
    return kOutputFailed;
  }
  try {
    installStopHandlers();
    Run run(opts, std::move(scene), factory);
    return run.execute();
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi: {}\n", e.what());
    return kBadInput;
  } catch (const StopDuringSetUp& e) {
    fmt::print(stderr, "hvi: {} (SIGINT/SIGTERM); nothing to checkpoint yet, no --restart\n", e.what());
    return kInterrupted;
  } catch (const SimulationError& e) {
    // Raised while the solver is built (e.g. an exact solution that does not exist for these
    // states): nothing has run, so there is no state to write.
    fmt::print(stderr, "hvi: cannot start: {}\n", e.what());
    return kSimulationFailed;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "hvi: cannot start: out of memory while building the solver\n");
    return kSimulationFailed;
  } catch (const std::exception& e) {
    fmt::print(stderr, "hvi: cannot start: internal error: {}\n", e.what());
    return kSimulationFailed;
  }
}

}  // namespace hvi::app
