//! @file End-to-end tests of `hvi run`: outputs, bad input, stop and restart, signals, failures.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hvi/apps/driver.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/io/output.hpp"
#include "hvi/test/run_files.hpp"

namespace fs = std::filesystem;
using namespace hvi;
using nlohmann::json;

namespace {

fs::path freshDir(const std::string& name) { return test::freshDir("app", name); }
using test::readJson;
using test::scene;
std::vector<fs::path> snapshots(const fs::path& dir, const std::string& prefix = "snap_") {
  std::vector<fs::path> v;
  for (auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".h5" && e.path().filename().string().rfind(prefix, 0) == 0)
      v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

// A quiet run of a shipped scene into `out`.
app::RunOptions quietRun(const std::string& name, const fs::path& out) {
  app::RunOptions o;
  o.scene = scene(name);
  o.out = out;
  o.quiet = true;
  return o;
}

// A few-second impact: the default scene (coarse variant 2), coarser still and shorter.
app::RunOptions smallImpact(const std::string& solver, const fs::path& out) {
  app::RunOptions o = quietRun("default", out);
  // Each solver with the effects it supports (an unsupported effect is an input error).
  const std::string effects = solver == "sph"
      ? R"(effects=["artificial_viscosity", "tension_cutoff", "mass_adjustment", "features"])"
      : R"(effects=["tension_cutoff", "material_interfaces", "features"])";
  o.overrides = {"solver=" + solver, effects, "sph.spacing=0.1 cm", "tvd.cell_size=0.1 cm",
                 "time.end=0.6 us", "output.times=[\"0.3 us\", \"0.6 us\"]"};
  return o;
}

}  // namespace

TEST(Driver, RiemannSceneWritesEveryOutput) {
  const fs::path out = freshDir("riemann");
  ASSERT_EQ(app::runScene(quietRun("sod_x", out)), app::kOk);
  for (const char* f : {"scene.toml", "hvi.pvd", "summary.json", "timeseries.json", "checkpoint.bin"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const auto snaps = snapshots(out);
  ASSERT_EQ(snaps.size(), 3u);  // t = 0, 0.1, 0.2 us
  const json s = readJson(out / "summary.json");
  EXPECT_EQ(s["status"], "completed");
  EXPECT_DOUBLE_EQ(s["final_time_us"].get<double>(), 0.2);
  for (const char* k : {"wall_seconds", "steps", "updates_per_second_per_core", "conservation",
                        "threads", "work_items"})
    EXPECT_TRUE(s.contains(k)) << k;
  EXPECT_EQ(readJson(out / "timeseries.json")["snapshots"].size(), 3u);

  const Snapshot last = io::readHdf5(snaps.back());
  EXPECT_DOUBLE_EQ(last.time, 0.2);
  const Field* rho = last.find("density");
  ASSERT_NE(rho, nullptr);
  ASSERT_EQ(rho->data.size(), 400u);
  // Far from the diaphragm the gas is undisturbed at t = 0.2 us: the rarefaction head moves at
  // c_L = 1.18 cm/us (to x = 0.26 cm) and the shock at 1.75 cm/us (to x = 0.85 cm).
  EXPECT_DOUBLE_EQ(rho->data[10], 1.0);
  EXPECT_DOUBLE_EQ(rho->data[395], 0.125);
}

// The shipped Tillotson tube runs with its own (exact) solver: its aluminium has no tension
// cut-off (the riemann solver takes no effects), and the solution is two shocks whose star
// state must not depend on the release isentrope, which Tillotson without the cut-off ends at
// rho / rho0 = 0.57 (c^2 <= 0). Star state: docs/verification.md, p* = 0.9882128 Mbar.
TEST(Driver, ShippedTillotsonTubeRunsWithTheExactSolver) {
  const fs::path out = freshDir("al_tube_riemann");
  ASSERT_EQ(app::runScene(quietRun("al_impact_tube", out)), app::kOk);
  const Snapshot last = io::readHdf5(snapshots(out).back());
  const Field* p = last.find("pressure");
  ASSERT_NE(p, nullptr);
  const std::size_t mid = p->data.size() / 2;  // x = 1 cm, inside the shocked region
  EXPECT_NEAR(p->data[mid], 0.9882128, 1e-6);
}

TEST(Driver, BadSceneIsRejectedBeforeAnythingRuns) {
  const fs::path out = freshDir("bad");
  const fs::path bad = out / "bad.toml";
  std::ifstream in(scene("default"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto pos = text.find("radius = \"0.5 cm\"");
  ASSERT_NE(pos, std::string::npos);
  text.replace(pos, 17, "radius = \"-0.5 cm\"");
  std::ofstream(bad) << text;
  app::RunOptions o;
  o.scene = bad;
  o.out = out / "run";
  o.quiet = true;
  EXPECT_EQ(app::runScene(o), app::kBadInput);
  EXPECT_FALSE(fs::exists(o.out / "summary.json"));
  EXPECT_FALSE(fs::exists(o.out)) << "nothing may be written for a scene that does not validate";
}

class RestartTest : public ::testing::TestWithParam<std::string> {};

// A run stopped after a few steps and restarted from its checkpoint must end in exactly the
// state of an uninterrupted run: the checkpoint holds the whole state bit for bit, and the
// solvers are deterministic for a fixed thread count (no order-dependent reductions in the
// dynamics).
TEST_P(RestartTest, StopAndRestartIsBitForBit) {
  const std::string solver = GetParam();
  const fs::path whole = freshDir("restart_whole_" + solver);
  const fs::path split = freshDir("restart_split_" + solver);
  ASSERT_EQ(app::runScene(smallImpact(solver, whole)), app::kOk);

  auto first = smallImpact(solver, split);
  first.stopAfterSteps = 7;
  ASSERT_EQ(app::runScene(first), app::kInterrupted);
  clearStop();
  EXPECT_EQ(readJson(split / "summary.json")["status"], "interrupted");
  auto second = smallImpact(solver, split);
  second.restart = true;
  ASSERT_EQ(app::runScene(second), app::kOk);

  const auto a = snapshots(whole), b = snapshots(split);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), 3u);
  const Snapshot sa = io::readHdf5(a.back()), sb = io::readHdf5(b.back());
  EXPECT_EQ(sa.step, sb.step);
  EXPECT_EQ(sa.time, sb.time);
  ASSERT_EQ(sa.fields.size(), sb.fields.size());
  for (std::size_t f = 0; f < sa.fields.size(); ++f) {
    ASSERT_EQ(sa.fields[f].name, sb.fields[f].name);
    ASSERT_EQ(sa.fields[f].data.size(), sb.fields[f].data.size());
    for (std::size_t i = 0; i < sa.fields[f].data.size(); ++i)
      ASSERT_EQ(sa.fields[f].data[i], sb.fields[f].data[i]) << sa.fields[f].name << "[" << i << "]";
  }
  EXPECT_EQ(sa.positions.size(), sb.positions.size());
  for (std::size_t i = 0; i < sa.positions.size(); ++i) ASSERT_EQ(sa.positions[i], sb.positions[i]);
  EXPECT_EQ(readJson(whole / "timeseries.json")["snapshots"].size(),
            readJson(split / "timeseries.json")["snapshots"].size());
}
INSTANTIATE_TEST_SUITE_P(BothSolvers, RestartTest, ::testing::Values("sph", "tvd"));

// energy_budget.csv is appended, never rewritten; the checkpoint counts its rows. Rows written
// after the checkpoint (and half a row, as a killed run leaves) are cut on restart, so the file
// ends as an uninterrupted run's; a file with fewer rows than counted refuses the restart.
TEST(Driver, EnergyBudgetIsAppendedAndARestartTrimsIt) {
  auto readText = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  auto withBudget = [](const fs::path& out) {
    auto o = smallImpact("tvd", out);
    o.overrides[1] = R"(effects=["tension_cutoff", "material_interfaces", "energy_budget"])";
    return o;
  };
  const fs::path whole = freshDir("budget_whole"), split = freshDir("budget_split");
  ASSERT_EQ(app::runScene(withBudget(whole)), app::kOk);
  auto first = withBudget(split);
  first.stopAfterSteps = 5;
  ASSERT_EQ(app::runScene(first), app::kInterrupted);
  clearStop();
  const fs::path csv = split / "energy_budget.csv";
  const std::string atStop = readText(csv);
  EXPECT_EQ(std::count(atStop.begin(), atStop.end(), '\n'), 6) << "header and 5 rows";
  std::ofstream(csv, std::ios::app) << "9,9,9,9,9\n1,2,";
  auto second = withBudget(split);
  second.restart = true;
  ASSERT_EQ(app::runScene(second), app::kOk);
  EXPECT_EQ(readText(csv), readText(whole / "energy_budget.csv"));

  // A budget file shorter than the checkpoint counts: the restart is refused.
  first.out = freshDir("budget_short");
  ASSERT_EQ(app::runScene(first), app::kInterrupted);
  clearStop();
  std::ofstream(first.out / "energy_budget.csv") << "time_us,kinetic,internal,total,dt_us\n";
  second.out = first.out;
  EXPECT_EQ(app::runScene(second), app::kBadInput);
}

TEST(Driver, RestartRefusesAnotherScene) {
  const fs::path out = freshDir("restart_other");
  auto first = smallImpact("tvd", out);
  first.stopAfterSteps = 2;
  ASSERT_EQ(app::runScene(first), app::kInterrupted);
  clearStop();
  const auto sceneText = [&] {
    std::ifstream in(out / "scene.toml");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const std::string before = sceneText();
  auto second = smallImpact("tvd", out);
  second.restart = true;
  second.overrides.push_back("tvd.cfl=0.2");
  EXPECT_EQ(app::runScene(second), app::kBadInput);
  EXPECT_EQ(sceneText(), before) << "a refused restart replaced the run's scene.toml";
}

// SIGINT through the real binary: the run stops between steps, writes a checkpoint, exits 130.
TEST(Driver, SigintWritesCheckpointAndExits130) {
  const fs::path out = freshDir("sigint");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string sc = scene("default").string(), o = out.string();
    ::freopen("/dev/null", "w", stderr);
    execl(HVI_EXE, HVI_EXE, "run", sc.c_str(), "--out", o.c_str(), "--quiet",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait until the first snapshot exists, so the signal arrives while it is stepping.
  for (int i = 0; i < 600 && snapshots(out).empty(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_TRUE(fs::exists(out / "checkpoint.bin"));
  EXPECT_EQ(readJson(out / "summary.json")["status"], "interrupted");
}

namespace {
// A real solver that is made to fail at a chosen step, as a NaN or negative density would make
// it fail: the driver must stop, report, write the failed state and keep what came before.
class FailingSolver final : public Solver {
 public:
  FailingSolver(std::unique_ptr<Solver> inner, long failAt) : inner_(std::move(inner)), failAt_(failAt) {}
  std::string name() const override { return inner_->name(); }
  double time() const override { return inner_->time(); }
  long step() const override { return inner_->step(); }
  long workItems() const override { return inner_->workItems(); }
  double advance(double tStop) override {
    const double dt = inner_->advance(tStop);
    if (inner_->step() == failAt_)
      throw SimulationError("cell 7 (i = 7, k = 0): density -1 g/cm^3 at step " +
                            std::to_string(failAt_));
    return dt;
  }
  Snapshot snapshot() const override { return inner_->snapshot(); }
  Totals totals() const override { return inner_->totals(); }
  void writeCheckpoint(std::ostream& o) const override { inner_->writeCheckpoint(o); }
  void readCheckpoint(std::istream& i) override { inner_->readCheckpoint(i); }

 private:
  std::unique_ptr<Solver> inner_;
  long failAt_;
};
}  // namespace

TEST(Driver, FailedRunStopsWithDiagnosticAndKeepsEarlierSnapshots) {
  const fs::path out = freshDir("failing");
  auto o = smallImpact("tvd", out);
  const int rc = app::runScene(o, [&](const cases::Scene& s) {
    return std::make_unique<FailingSolver>(app::createSolver(s), 12);
  });
  EXPECT_EQ(rc, app::kSimulationFailed);
  const auto snaps = snapshots(out);
  ASSERT_GE(snaps.size(), 1u);  // the t = 0 snapshot (and any written before step 12)
  for (const auto& f : snaps) {
    const Snapshot s = io::readHdf5(f);  // complete and readable
    EXPECT_LT(s.step, 12);
  }
  const auto failed = snapshots(out, "failed_");
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(io::readHdf5(failed[0]).step, 12);
  const json sum = readJson(out / "summary.json");
  EXPECT_EQ(sum["status"], "failed");
  EXPECT_NE(sum["error"].get<std::string>().find("cell 7"), std::string::npos);
}

// SIGKILL gives the run no chance to clean up: every snapshot under its final name must still be
// complete, because each was written under a temporary name and renamed.
TEST(Driver, SigkillLeavesEverySnapshotReadable) {
  const fs::path out = freshDir("sigkill");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string sc = scene("default").string(), o = out.string();
    ::freopen("/dev/null", "w", stderr);
    // Frequent outputs make it likely that the kill lands inside a write.
    execl(HVI_EXE, HVI_EXE, "run", sc.c_str(), "--out", o.c_str(), "--quiet", "--set",
          "output.times=[\"0.1 us\",\"0.2 us\",\"0.3 us\",\"0.4 us\",\"0.5 us\",\"0.6 us\",\"0.7 us\",\"0.8 us\"]",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 600 && snapshots(out).size() < 3; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const auto snaps = snapshots(out);
  ASSERT_GE(snaps.size(), 3u);
  for (const auto& f : snaps) EXPECT_NO_THROW(io::readHdf5(f)) << f;
  EXPECT_NO_THROW((void)readJson(out / "timeseries.json"));
}
