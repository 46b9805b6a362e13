//! @file The hard-case runner: step loop, state checks, conservation and time-step measures.
#include "harness.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/io/output.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/tvd/tvd.hpp"

namespace hvi::hard {
namespace fs = std::filesystem;

namespace {

fs::path scenePath(const std::string& name) {
  return fs::path(HVI_SOURCE_DIR) / "cases" / "scenes" / "hard" / (name + ".toml");
}

fs::path outDir() {
  fs::path d = fs::path(HVI_BINARY_DIR) / "test_out" / "hard";
  fs::create_directories(d);
  return d;
}

// The scene files are written for SPH; TVD gets its own effects (the parser rejects effects a
// solver does not support, so they are replaced, not added).
std::vector<std::string> solverOverrides(const std::string& solver) {
  if (solver == "tvd")  // the study's whole-cell interfaces unless a variant overrides them
    return {"solver=tvd", R"(effects=["tension_cutoff", "material_interfaces"])",
            R"(tvd.interfaces="whole_cell")"};
  return {"solver=" + solver};
}

const sph::Stepper* sphStepper(const Solver& s) {
  if (const auto* p = dynamic_cast<const sph::SphSolver*>(&s)) return &p->stepper();
  return nullptr;
}

// Finite fields everywhere, positive density wherever there is material. Updates the extrema.
std::optional<std::string> checkSnapshot(const Snapshot& snap, RunResult& r) {
  const Field* rho = snap.find("density");
  const Field* p = snap.find("pressure");
  const Field* v = snap.find("velocity");
  const Field* e = snap.find("specific_energy");
  const Field* mat = snap.find("material");
  if (!rho || !p || !v || !e || !mat)
    return "snapshot lacks density, pressure, velocity, specific_energy or material";
  const long n = snap.count();
  const bool particles = snap.kind == Snapshot::Kind::Particles;
  long material = 0;
  for (long i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double vx = v->data[2 * k], vz = v->data[2 * k + 1];
    const bool finite =
        std::isfinite(rho->data[k]) && std::isfinite(p->data[k]) && std::isfinite(vx) &&
        std::isfinite(vz) && std::isfinite(e->data[k]) &&
        (!particles || (std::isfinite(snap.positions[k].x) && std::isfinite(snap.positions[k].z)));
    auto where = [&] {
      if (particles)
        return fmt::format("particle {} at ({:.4g}, {:.4g}) cm", i, snap.positions[k].x,
                           snap.positions[k].z);
      return fmt::format("cell (i={}, k={}) at ({:.4g}, {:.4g}) cm", i % snap.grid.nx,
                         i / snap.grid.nx, snap.grid.x0 + (i % snap.grid.nx + 0.5) * snap.grid.dx,
                         snap.grid.z0 + (i / snap.grid.nx + 0.5) * snap.grid.dz);
    };
    const auto state = [&] {
      return fmt::format("rho = {:.6g}, P = {:.6g}, v = ({:.6g}, {:.6g}), e = {:.6g}", rho->data[k],
                         p->data[k], vx, vz, e->data[k]);
    };
    if (!finite)
      return fmt::format("step {}, t = {:.6g} us: non-finite state at {}: {}", snap.step, snap.time,
                         where(), state());
    if (!particles && mat->data[k] < 0.0) continue;  // vacuum cell
    ++material;
    if (!(rho->data[k] > 0.0))
      return fmt::format("step {}, t = {:.6g} us: non-positive density in material at {}: {}",
                         snap.step, snap.time, where(), state());
    r.maxSpeed = std::max(r.maxSpeed, std::hypot(vx, vz));
    r.minDensity = std::min(r.minDensity, rho->data[k]);
    r.maxPressure = std::max(r.maxPressure, p->data[k]);
    if (e->data[k] < r.minEnergy) {
      r.minEnergy = e->data[k];
      const Field* obj = snap.find("object");
      const auto name = [](const std::vector<std::string>& names, double v) {
        const auto j = static_cast<std::size_t>(v);
        return v >= 0.0 && j < names.size() ? names[j] : std::string("?");
      };
      r.minEnergyWhere =
          fmt::format("{} ({}) at {}, t = {:.3g} us", name(snap.materialNames, mat->data[k]),
                      obj ? name(snap.objectNames, obj->data[k]) : "?", where(), snap.time);
    }
  }
  r.itemsEnd = material;
  return std::nullopt;
}

// The raw TVD state of every cell, vacuum included: finite, and no negative density.
std::optional<std::string> checkTvdConserved(const tvd::TvdSolver& s) {
  const auto& U = s.conserved();
  const int nx = s.grid().nx;
  for (std::size_t c = 0; c < U.rho.size(); ++c) {
    if (std::isfinite(U.rho[c]) && U.rho[c] >= 0.0 && std::isfinite(U.mx[c]) &&
        std::isfinite(U.mz[c]) && std::isfinite(U.E[c]))
      continue;
    return fmt::format(
        "step {}: raw state of cell (i={}, k={}) (owner {}): rho = {:.6g}, "
        "m = ({:.6g}, {:.6g}), E = {:.6g}",
        s.step(), c % static_cast<std::size_t>(nx), c / static_cast<std::size_t>(nx),
        s.owner().empty() ? -2 : s.owner()[c], U.rho[c], U.mx[c], U.mz[c], U.E[c]);
  }
  return std::nullopt;
}

class Run {
 public:
  Run(const RunSetup& setup, RunResult& r) : setup_(setup), r_(r) {}

  void execute() {
    auto overrides = solverOverrides(setup_.solver);
    overrides.insert(overrides.end(), setup_.overrides.begin(), setup_.overrides.end());
    scene_ = cases::loadScene(scenePath(setup_.caseName), overrides);
    r_.tEnd = scene_.tEnd;
    solver_ = setup_.make ? setup_.make(scene_) : app::createSolver(scene_);
    r_.items = solver_->workItems();
    t0_ = solver_->totals();
    r_.minDensity = std::numeric_limits<double>::infinity();
    r_.minEnergy = std::numeric_limits<double>::infinity();
    if (const auto* st = sphStepper(*solver_)) {
      const sph::ParticleSystem ps = st->particles();
      for (std::size_t i = 0; i < ps.size(); ++i) mass0_[ps.id[i]] = ps.m[i];
    }
    if (!check()) return;
    while (solver_->time() < scene_.tEnd) {
      const double dt = solver_->advance(scene_.tEnd);
      const bool cut = solver_->time() >= scene_.tEnd;  // the last step lands on time.end
      ++r_.steps;
      if (r_.steps == 1 && !cut) r_.dt0 = dt;
      if (r_.steps > kSettleSteps && !cut && r_.dt0 > 0.0 && dt / r_.dt0 < r_.minDtRatio) {
        r_.minDtRatio = dt / r_.dt0;
        r_.minDtStep = solver_->step();
      }
      r_.tReached = solver_->time();
      if ((r_.steps % setup_.checkEvery == 0 || cut) && !check()) return;
    }
    r_.completed = true;
  }

  void writeFailedState() const {
    if (!solver_) return;
    try {
      io::writeHdf5(outDir() / (stem() + "_failed.h5"), solver_->snapshot(), cases::toToml(scene_));
    } catch (const std::exception&) {
      // The state at failure is a diagnostic aid; the failure itself is already recorded.
    }
  }

  [[nodiscard]] std::string stem() const {
    return setup_.caseName + "_" + setup_.solver + setup_.variant;
  }

 private:
  // Full state check and conservation measures; false (with r_.failure) if the state is bad.
  bool check() {
    const Snapshot snap = solver_->snapshot();
    if (auto bad = checkSnapshot(snap, r_)) return fail(*bad);
    const Totals t = solver_->totals();
    const double m0 = t0_.mass, e0 = t0_.energy();
    if (const auto* st = sphStepper(*solver_)) {
      // totals() adds what left through outflow sides: the sum is the initial one to round-off.
      r_.massDriftEnd = (t.mass - m0) / m0;
      r_.energyDriftEnd = (t.energy() - e0) / e0;
      r_.massError = std::max(r_.massError, std::abs(r_.massDriftEnd));
      r_.energyError = std::max(r_.energyError, std::abs(r_.energyDriftEnd));
      r_.outflowMass = st->outflow().mass / m0;
      r_.energyOutflow = st->outflow().energy() / e0;
      // By id, each id at most once: a duplicated particle would pass a per-particle mass check.
      const sph::ParticleSystem ps = st->particles();
      std::unordered_set<std::int64_t> seen;
      seen.reserve(ps.size());
      for (std::size_t i = 0; i < ps.size(); ++i) {
        const auto it = mass0_.find(ps.id[i]);
        const bool twice = !seen.insert(ps.id[i]).second;
        if (twice || it == mass0_.end() || it->second != ps.m[i]) {
          r_.massesBitwise = false;
          return fail(fmt::format(
              "step {}: particle id {} {} mass {:.17g}, initially {}", solver_->step(), ps.id[i],
              twice ? "appears twice; has" : "has", ps.m[i],
              it == mass0_.end() ? std::string("absent") : fmt::format("{:.17g}", it->second)));
        }
      }
      r_.massesBitwise = true;
    } else if (const auto* tv = dynamic_cast<const tvd::TvdSolver*>(solver_.get())) {
      if (auto bad = checkTvdConserved(*tv)) return fail(*bad);
      const tvd::Ledger& L = tv->ledger();
      const tvd::Budget all = L.sum();
      r_.massDriftEnd = (t.mass - m0 - L.boundary.mass) / m0;
      r_.energyDriftEnd = (t.energy() - e0 - L.boundary.energy) / e0;
      r_.massError = std::max(r_.massError, std::abs(r_.massDriftEnd));
      const auto worst = [](const std::optional<double>& a, double b) {
        return std::max(a.value_or(0.0), b);
      };
      r_.massClosure = worst(r_.massClosure, std::abs(t.mass - m0 - all.mass) / m0);
      r_.energyError = std::max(r_.energyError, std::abs(r_.energyDriftEnd));
      r_.energyClosure = worst(r_.energyClosure, std::abs(t.energy() - e0 - all.energy) / e0);
      // Momentum starts at any value (zero for a body at rest): relative to sqrt(2 M0 E0), the
      // momentum scale summary.json uses.
      const double p0 = std::sqrt(2.0 * m0 * e0);
      double pErr = std::abs(t.momentumZ - t0_.momentumZ - all.momentumZ) / p0;
      if (scene_.geometry != Geometry::Axisymmetric)
        pErr = std::max(pErr, std::abs(t.momentumX - t0_.momentumX - all.momentumX) / p0);
      r_.momentumClosure = worst(r_.momentumClosure, pErr);
      r_.outflowMass = tv->outflow().mass / m0;  // Ledger::boundary holds only the walls
      r_.energyOutflow = tv->outflow().energy() / e0;
      r_.massInterfaces = L.interfaces.mass / m0;
      r_.massOwnerChanges = L.ownerChanges.mass / m0;
      r_.massFloors = L.floors.mass / m0;
      r_.energyInterfaces = L.interfaces.energy / e0;
      r_.energyOwnerChanges = L.ownerChanges.energy / e0;
      r_.energyFloors = L.floors.energy / e0;
    }
    return true;
  }

  bool fail(const std::string& why) {
    r_.failure = why;
    return false;
  }

  const RunSetup& setup_;
  RunResult& r_;
  cases::Scene scene_;
  std::unique_ptr<Solver> solver_;
  Totals t0_;
  std::unordered_map<std::int64_t, double> mass0_;
};

// A measure the solver does not have is null in the JSON, not a value that looks like a pass.
template <class T>
nlohmann::json opt(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

void writeJson(const RunResult& r, const fs::path& file) {
  const nlohmann::json j = {{"case", r.caseName},
                            {"solver", r.solver},
                            {"completed", r.completed},
                            {"failure", r.failure},
                            {"steps", r.steps},
                            {"items", r.items},
                            {"items_end", r.itemsEnd},
                            {"t_end", r.tEnd},
                            {"t_reached", r.tReached},
                            {"dt0", r.dt0},
                            {"min_dt_ratio", r.minDtRatio},
                            {"min_dt_step", r.minDtStep},
                            {"mass_error", r.massError},
                            {"mass_closure", opt(r.massClosure)},
                            {"mass_drift_end", r.massDriftEnd},
                            {"energy_drift_end", r.energyDriftEnd},
                            {"energy_error", r.energyError},
                            {"energy_closure", opt(r.energyClosure)},
                            {"momentum_closure", opt(r.momentumClosure)},
                            {"outflow_mass", r.outflowMass},
                            {"masses_bitwise", opt(r.massesBitwise)},
                            {"max_speed", r.maxSpeed},
                            {"min_density", r.minDensity},
                            {"max_pressure", r.maxPressure},
                            {"min_specific_energy", r.minEnergy},
                            {"min_specific_energy_where", r.minEnergyWhere},
                            {"wall_seconds", r.wallSeconds},
                            {"energy_outflow", r.energyOutflow},
                            {"ledger_mass",
                             {{"interfaces", r.massInterfaces},
                              {"owner_changes", r.massOwnerChanges},
                              {"floors", r.massFloors}}},
                            {"ledger_energy",
                             {{"interfaces", r.energyInterfaces},
                              {"owner_changes", r.energyOwnerChanges},
                              {"floors", r.energyFloors}}}};
  std::ofstream(file) << j.dump(2) << "\n";
}

}  // namespace

std::unique_ptr<Solver> makeShiftedSph(const cases::Scene& scene, int object, double dz) {
  sph::ParticleSystem ps = sph::fillBodies(scene);
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (ps.object[i] == object) ps.z[i] += dz;
  // The mass iteration is per object: a rigid shift of one object leaves its masses as they are
  // without the shift.
  return std::make_unique<sph::SphSolver>(scene, std::move(ps));
}

RunResult runHardCase(const RunSetup& setup) {
  const auto fmtOpt = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.2e}", *v) : std::string("n/a");
  };
  RunResult r;
  r.caseName = setup.caseName;
  r.solver = setup.solver + setup.variant;
  const auto start = std::chrono::steady_clock::now();
  Run run(setup, r);
  try {
    run.execute();
  } catch (const SimulationError& e) {
    r.failure = std::string("SimulationError: ") + e.what();
  }
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.completed) run.writeFailedState();
  writeJson(r, outDir() / (run.stem() + ".json"));
  std::printf(
      "[hard] %-15s %-8s %s steps=%ld items=%ld t=%.3g/%.3g dt0=%.3e min_dt/dt0=%.3g "
      "mass_err=%.2e (closure %s) energy_err=%.2e (closure %s) %s outflow=%.3g "
      "vmax=%.3g rho_min=%.3g Pmax=%.3g e_min=%.3g wall=%.2fs%s%s\n",
      r.caseName.c_str(), r.solver.c_str(), r.completed ? "ok  " : "FAIL", r.steps, r.items,
      r.tReached, r.tEnd, r.dt0, r.minDtRatio, r.massError, fmtOpt(r.massClosure).c_str(),
      r.energyError, fmtOpt(r.energyClosure).c_str(),
      r.massesBitwise ? (*r.massesBitwise ? "masses bitwise" : "MASSES CHANGED")
                      : fmt::format("momentum closure {}", fmtOpt(r.momentumClosure)).c_str(),
      r.outflowMass, r.maxSpeed, r.minDensity, r.maxPressure, r.minEnergy,
      r.wallSeconds, r.failure.empty() ? "" : "\n[hard]   ", r.failure.c_str());
  std::printf("[hard]   at the end: mass drift %+.3e, energy drift %+.3e; e_min at %s\n",
              r.massDriftEnd, r.energyDriftEnd, r.minEnergyWhere.c_str());
  if (setup.solver == "tvd")
    std::printf(
        "[hard]   tvd ledger / M0: interfaces %+.3e, owner changes %+.3e, floors %+.3e; "
        "/ E0: interfaces %+.3e, owner changes %+.3e, floors %+.3e, outflow %.3e\n",
        r.massInterfaces, r.massOwnerChanges, r.massFloors, r.energyInterfaces,
        r.energyOwnerChanges, r.energyFloors, r.energyOutflow);
  std::fflush(stdout);
  return r;
}

}  // namespace hvi::hard
