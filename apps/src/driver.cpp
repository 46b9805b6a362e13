//! @file `hvi run`: steps a solver through the output times with snapshots and checkpoints.
#include "hvi/apps/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "hvi/apps/riemann_solver.hpp"
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

namespace hvi::app {
namespace fs = std::filesystem;
using nlohmann::json;

std::unique_ptr<Solver> createSolver(const cases::Scene& scene) {
  switch (scene.solver) {
    case cases::SolverKind::Sph: return sph::createSolver(scene);
    case cases::SolverKind::Tvd: return tvd::createSolver(scene);
    case cases::SolverKind::Riemann: return createRiemannSolver(scene);
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

class Run {
 public:
  Run(const RunOptions& opts, cases::Scene scene, SolverFactory factory)
      : factory_(std::move(factory)), opts_(opts), scene_(std::move(scene)), sceneToml_(cases::toToml(scene_)),
        record_(opts.out, scene_, sceneToml_), pvd_(opts.out / "hvi.pvd") {}

  int execute() {
    solver_ = factory_(scene_);
    const fs::path ckpt = opts_.out / "checkpoint.bin";
    if (opts_.restart) {
      if (!fs::exists(ckpt))
        throw InputError(fmt::format("{}: --restart given but no checkpoint there", ckpt.string()));
      const std::string header = io::readCheckpointFile(ckpt, [&](std::istream& in) {
        solver_->readCheckpoint(in);
      });
      record_.restore(json::parse(header), solver_->time());
      pvd_.resumeFrom(solver_->time());
      fmt::print(stderr, "hvi: restarted from {} at t = {} us, step {}\n", ckpt.string(),
                 solver_->time(), solver_->step());
    } else {
      record_.begin(solver_->totals());
      writeSnapshot("snap");
    }

    Progress progress(scene_.tStart, scene_.tEnd);
    auto lastCheckpoint = std::chrono::steady_clock::now();
    long stepsThisRun = 0;
    const auto outputs = scene_.output.times;
    try {
      while (solver_->time() < scene_.tEnd) {
        const double tNext = nextOutputTime(outputs, solver_->time());
        const double dt = solver_->advance(tNext);
        ++stepsThisRun;
        record_.afterStep(*solver_, dt);
        if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), dt);
        if (solver_->time() >= tNext) {
          writeSnapshot("snap");
          writeCheckpoint(ckpt);
          lastCheckpoint = std::chrono::steady_clock::now();
        } else if (scene_.output.checkpointEvery > 0.0 &&
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - lastCheckpoint)
                           .count() > scene_.output.checkpointEvery) {
          writeCheckpoint(ckpt);
          lastCheckpoint = std::chrono::steady_clock::now();
        }
        if (opts_.stopAfterSteps >= 0 && stepsThisRun >= opts_.stopAfterSteps) requestStop();
        if (stopRequested() && solver_->time() < scene_.tEnd) {
          writeCheckpoint(ckpt);
          if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), dt, true);
          fmt::print(stderr, "hvi: stopped at t = {} us, step {}; checkpoint {}; continue with "
                             "`hvi run {} --out {} --restart`\n",
                     solver_->time(), solver_->step(), ckpt.string(), opts_.scene.string(),
                     opts_.out.string());
          record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "interrupted", "");
          return kInterrupted;
        }
      }
    } catch (const SimulationError& e) {
      fmt::print(stderr, "\nhvi: simulation failed: {}\n", e.what());
      // The failed state is written under its own name for inspection; earlier snapshots and the
      // last checkpoint stay as they were.
      try {
        writeSnapshot("failed", false);
        fmt::print(stderr, "hvi: state at failure written to {}\n",
                   (opts_.out / fmt::format("failed_{:08d}.h5", solver_->step())).string());
      } catch (const std::exception& w) {
        fmt::print(stderr, "hvi: could not write the failed state: {}\n", w.what());
      }
      record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "failed", e.what());
      return kSimulationFailed;
    }
    if (!opts_.quiet) progress.update(solver_->time(), solver_->step(), 0.0, true);
    record_.finish(*solver_, progress.wallSeconds(), stepsThisRun, threadCount(), "completed", "");
    fmt::print(stderr, "hvi: done, {} steps in {:.1f} s; results in {}\n", solver_->step(),
               progress.wallSeconds(), opts_.out.string());
    return kOk;
  }

 private:
  double nextOutputTime(const std::vector<double>& times, double t) const {
    for (double o : times)
      if (o > t) return std::min(o, scene_.tEnd);
    return scene_.tEnd;
  }

  void writeSnapshot(const char* prefix, bool addToSeries = true) {
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
  }

  void writeCheckpoint(const fs::path& ckpt) {
    io::writeCheckpointFile(ckpt, record_.checkpointHeader().dump(),
                            [&](std::ostream& out) { solver_->writeCheckpoint(out); });
  }

  SolverFactory factory_;
  RunOptions opts_;
  cases::Scene scene_;
  std::string sceneToml_;
  RunRecord record_;
  io::PvdSeries pvd_;
  std::unique_ptr<Solver> solver_;
};

//! A run killed while writing leaves its temporary file (".name.tmp<pid>.ext", see
//! common/atomic_file.cpp); the final names are intact, so the leftovers are only clutter.
void removeStaleTemporaries(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 1 && n[0] == '.' && n.find(".tmp") != std::string::npos) fs::remove(e.path(), ec);
  }
}

}  // namespace

int runScene(const RunOptions& opts) { return runScene(opts, createSolver); }

int runScene(const RunOptions& opts, const SolverFactory& factory) {
  cases::Scene scene;
  try {
    scene = cases::loadScene(opts.scene, opts.overrides);
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi: {}\n", e.what());
    return kBadInput;
  }
  try {
    fs::create_directories(opts.out);
    removeStaleTemporaries(opts.out);
    writeTextAtomically(opts.out / "scene.toml", cases::toToml(scene));
    installStopHandlers();
    Run run(opts, std::move(scene), factory);
    return run.execute();
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi: {}\n", e.what());
    return kBadInput;
  } catch (const SimulationError& e) {
    // Raised while the solver is built (e.g. an exact solution that does not exist for these
    // states): nothing has run, so there is no state to write.
    fmt::print(stderr, "hvi: cannot start: {}\n", e.what());
    return kSimulationFailed;
  }
}

}  // namespace hvi::app
