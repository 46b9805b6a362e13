//! @file `hvi run` on a hostile machine and with careless use: unusable output folders, a full
//! disk, two runs into one folder, an earlier run's results, time that stops advancing, the
//! restart hint, --stop-after edge cases, an unknown command.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hvi/apps/driver.hpp"
#include "hvi/apps/output_folder.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/progress.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/io/checkpoint.hpp"
#include "hvi/io/output.hpp"
#include "hvi/test/run_files.hpp"

namespace fs = std::filesystem;
using namespace hvi;
using nlohmann::json;

namespace {

fs::path freshDir(const std::string& name) { return test::freshDir("app_rel", name); }
using test::readJson;
using test::scene;
std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
std::vector<std::string> names(const fs::path& dir) {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(dir)) v.push_back(e.path().filename().string());
  std::sort(v.begin(), v.end());
  return v;
}

// The exact Sod solution: two steps, milliseconds.
app::RunOptions sod(const fs::path& out) {
  app::RunOptions o;
  o.scene = scene("sod_x");
  o.out = out;
  o.quiet = true;
  return o;
}

// A small TVD impact (as in test_driver.cpp): about a hundred steps, well under a second.
app::RunOptions smallTvd(const fs::path& out) {
  app::RunOptions o;
  o.scene = scene("default");
  o.out = out;
  o.quiet = true;
  o.overrides = {"solver=tvd", R"(effects=["tension_cutoff", "material_interfaces"])",
                 "tvd.cell_size=0.1 cm", "time.end=0.6 us",
                 "output.times=[\"0.2 us\", \"0.4 us\"]"};
  return o;
}

//! runScene with stderr captured.
std::pair<int, std::string> runCaptured(const app::RunOptions& o,
                                        const app::SolverFactory& f = app::createSolver) {
  ::testing::internal::CaptureStderr();
  const int rc = app::runScene(o, f);
  return {rc, ::testing::internal::GetCapturedStderr()};
}

//! The hvi binary through the shell; returns the exit status, stderr in `err`.
int shell(const std::string& cmd, std::string* err = nullptr) {
  // One file per test: ctest -j runs the tests of this binary side by side.
  const fs::path errFile = fs::path(HVI_BINARY_DIR) / "test_out" / "app_rel" /
                           (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                            ".stderr");
  fs::create_directories(errFile.parent_path());
  const int st = std::system(fmt::format("OMP_WAIT_POLICY=passive {} 2> {}", cmd,
                                         app::shellQuote(errFile.string())).c_str());
  if (err) *err = readText(errFile);
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}
const std::string hviExe = app::shellQuote(HVI_EXE);

//! Wraps a real solver to inject faults by step or by checkpoint count.
class FaultySolver final : public Solver {
 public:
  struct Faults {
    long freezeTimeFrom = -1;         //!< from this step on, steps do not advance time
    int fillDiskAtCheckpoint = -1;   //!< before this checkpoint (1, 2, ...) the disk is "full"
  };
  FaultySolver(std::unique_ptr<Solver> inner, Faults f) : inner_(std::move(inner)), f_(f) {}
  std::string name() const override { return inner_->name(); }
  double time() const override { return inner_->time(); }
  long step() const override { return inner_->step() + frozenSteps_; }
  long workItems() const override { return inner_->workItems(); }
  double advance(double tStop) override {
    if (f_.freezeTimeFrom >= 0 && step() >= f_.freezeTimeFrom) {
      ++frozenSteps_;  // as t + dt == t at t = 1e20 us: a step is taken, time stays
      return 1e-3;
    }
    return inner_->advance(tStop);
  }
  Snapshot snapshot() const override {
    Snapshot s = inner_->snapshot();
    s.step = step();
    return s;
  }
  Totals totals() const override { return inner_->totals(); }
  void writeCheckpoint(std::ostream& o) const override {
    // RLIMIT_FSIZE: every write past 16 KiB fails with EFBIG from here on, as ENOSPC would on a
    // full disk. The test restores the limit.
    if (++checkpoints_ == f_.fillDiskAtCheckpoint) {
      std::signal(SIGXFSZ, SIG_IGN);
      rlimit l{};
      ::getrlimit(RLIMIT_FSIZE, &l);
      l.rlim_cur = 16 * 1024;
      ::setrlimit(RLIMIT_FSIZE, &l);
    }
    inner_->writeCheckpoint(o);
  }
  void readCheckpoint(std::istream& i) override { inner_->readCheckpoint(i); }

 private:
  std::unique_ptr<Solver> inner_;
  Faults f_;
  long frozenSteps_ = 0;
  mutable int checkpoints_ = 0;
};

app::SolverFactory faulty(FaultySolver::Faults f) {
  return [f](const cases::Scene& s) { return std::make_unique<FaultySolver>(app::createSolver(s), f); };
}

}  // namespace

// Item 3: each unusable --out is exit 2 with the folder and the cause, before anything runs.
TEST(OutputFolder, UnusableFoldersAreRefusedNamingFolderAndCause) {
  const fs::path root = freshDir("unusable");
  std::ofstream(root / "afile") << "x";
  const struct {
    fs::path out;
    std::string cause;
  } cases[] = {
      {root / "afile", "is a file"},
      {root / "afile" / "below", std::strerror(ENOTDIR)},
      {"/dev/null", "is a character device"},
      {"", "--out is empty"},
      {"/proc/hvi_no_such/x", ""},             // cannot be created (ENOENT on Linux)
      {"/proc/self/fdinfo", "not writable"},   // a folder nobody may write into, root included
  };
  for (const auto& c : cases) {
    auto o = sod(c.out);
    const auto [rc, err] = runCaptured(o);
    EXPECT_EQ(rc, app::kBadInput) << c.out << ": " << err;
    EXPECT_NE(err.find(c.out.string()), std::string::npos) << err;
    EXPECT_NE(err.find(c.cause), std::string::npos) << err;
  }
  EXPECT_EQ(readText(root / "afile"), "x");
  // Through the binary as well: an exit code, never an abort.
  std::string err;
  EXPECT_EQ(shell(fmt::format("{} run {} --out /dev/null -q", hviExe, app::shellQuote(scene("sod_x"))),
                  &err),
            app::kBadInput) << err;
}

// Item 4: a full disk at a checkpoint stops the run with exit 4 and the cause; the previous
// checkpoint stays intact and the run continues from it once there is room.
TEST(OutputFolder, FullDiskStopsWithTheCauseAndKeepsTheCheckpoint) {
  const fs::path out = freshDir("disk_full");
  rlimit saved{};
  ::getrlimit(RLIMIT_FSIZE, &saved);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  const auto [rc, err] = runCaptured(smallTvd(out), faulty({.fillDiskAtCheckpoint = 2}));
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_EQ(rc, app::kOutputFailed) << err;
  EXPECT_NE(err.find("checkpoint.bin"), std::string::npos) << err;
  EXPECT_NE(err.find(std::strerror(EFBIG)), std::string::npos) << err;
  EXPECT_NE(err.find("--restart"), std::string::npos) << err;
  for (const auto& n : names(out)) EXPECT_FALSE(temporaryOwner(n)) << "temporary left: " << n;
  // The first checkpoint (t = 0.2 us) is complete, and the run goes on from it.
  EXPECT_NO_THROW(io::readCheckpointFile(out / "checkpoint.bin", nullptr));
  auto again = smallTvd(out);
  again.restart = true;
  const auto [rc2, err2] = runCaptured(again);
  ASSERT_EQ(rc2, app::kOk) << err2;
  EXPECT_NE(err2.find("t = 0.2 us"), std::string::npos) << err2;
  EXPECT_EQ(readJson(out / "timeseries.json")["snapshots"].size(), 4u);  // 0, 0.2, 0.4, 0.6 us
  EXPECT_EQ(readJson(out / "summary.json")["status"], "completed");
}

// Item 8: steps that do not move the time end the run after kMaxStalledSteps as a failure,
// with the state written like any other.
TEST(OutputFolder, TimeThatStopsAdvancingEndsTheRun) {
  const fs::path out = freshDir("stalled");
  const auto [rc, err] = runCaptured(smallTvd(out), faulty({.freezeTimeFrom = 5}));
  EXPECT_EQ(rc, app::kSimulationFailed) << err;
  EXPECT_NE(err.find("stopped advancing"), std::string::npos) << err;
  const json s = readJson(out / "summary.json");
  EXPECT_EQ(s["status"], "failed");
  EXPECT_EQ(s["steps"].get<long>(), 5 + app::kMaxStalledSteps);
  EXPECT_TRUE(fs::exists(out / fmt::format("failed_{:08d}.h5", 5 + app::kMaxStalledSteps)));
}

// Item 9: a locked folder is refused naming the holder; the kernel frees the lock of a
// SIGKILLed holder; only dead processes' temporaries are removed.
TEST(OutputFolder, SecondRunIntoALockedFolderIsRefusedAndAKilledHolderFreesIt) {
  const fs::path out = freshDir("locked");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t holder = ::fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {
    ::close(ready[0]);
    try {
      app::FolderLock lock(out);
      (void)!::write(ready[1], "x", 1);
      for (;;) ::pause();
    } catch (...) {
      ::_exit(3);
    }
  }
  ::close(ready[1]);
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  ::close(ready[0]);

  // Another process's temporary beside a dead one's: the dead one's may go, the other stays.
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const fs::path live = temporaryPath(out / "compare.json", holder);
  const fs::path stale = temporaryPath(out / "snap_00000007.h5", dead);
  std::ofstream(live) << "live";
  std::ofstream(stale) << "stale";

  const auto [rc, err] = runCaptured(sod(out));
  EXPECT_EQ(rc, app::kBadInput);
  EXPECT_NE(err.find(out.string()), std::string::npos) << err;
  EXPECT_NE(err.find(fmt::format("pid {}", holder)), std::string::npos) << err;
  EXPECT_TRUE(fs::exists(live) && fs::exists(stale)) << "the refused run touched the folder";
  EXPECT_FALSE(fs::exists(out / "scene.toml"));

  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);
  const auto [rc2, err2] = runCaptured(sod(out));
  EXPECT_EQ(rc2, app::kOk) << err2;
  EXPECT_FALSE(fs::exists(stale));
  // The holder is dead now too, so its temporary could have gone; what matters is that a
  // live one was kept while its owner lived (above).
}

// Item 10: an earlier run's results are refused; --overwrite removes exactly hvi's files.
TEST(OutputFolder, EarlierResultsAreRefusedUnlessOverwriteWhichKeepsUserFiles) {
  const fs::path out = freshDir("stale");
  ASSERT_EQ(runCaptured(smallTvd(out)).first, app::kOk);
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(out / "my_data.h5") << "mine";
  const auto before = names(out);

  auto second = smallTvd(out);
  second.overrides.back() = "output.times=[\"0.3 us\"]";
  const auto [rc, err] = runCaptured(second);
  EXPECT_EQ(rc, app::kBadInput);
  EXPECT_NE(err.find("--overwrite"), std::string::npos) << err;
  EXPECT_EQ(names(out), before) << "a refused run changed the folder";

  second.overwrite = true;
  const auto [rc2, err2] = runCaptured(second);
  ASSERT_EQ(rc2, app::kOk) << err2;
  EXPECT_EQ(readText(out / "notes.txt"), "mine");
  EXPECT_EQ(readText(out / "my_data.h5"), "mine");
  // Every snapshot file is one the new run lists: none of the first run's survive.
  std::set<std::string> listed;
  const json record = readJson(out / "timeseries.json");
  for (const auto& e : record["snapshots"])
    listed.insert(e["file"].get<std::string>());
  EXPECT_EQ(listed.size(), 3u);  // 0, 0.3, 0.6 us
  for (const auto& n : names(out))
    if (n.rfind("snap_", 0) == 0) {
      EXPECT_TRUE(listed.count(n.substr(0, 13))) << n;  // snap_<8 digits>
    }

  // --restart and --overwrite contradict each other.
  second.restart = true;
  EXPECT_EQ(runCaptured(second).first, app::kBadInput);
}

TEST(OutputFolder, RunFilesAreOnlyWhatHviRunWrites) {
  for (const char* n : {"scene.toml", "summary.json", "timeseries.json", "energy_budget.csv",
                        "checkpoint.bin", "hvi.pvd", "snap_00000012.h5", "snap_00000012.vti",
                        "snap_00000012.vtu", "snap_00000012_markers.vtp", "failed_00000099.h5"})
    EXPECT_TRUE(app::isRunFile(n)) << n;
  for (const char* n : {"notes.txt", "my.h5", "snap_final.h5", "compare.json", ".hvi.lock",
                        "density.png", "snap_00000012.h5.bak", "scene.toml~"})
    EXPECT_FALSE(app::isRunFile(n)) << n;
}

// Item 11: the printed restart command, run as printed, continues the run (overrides with
// spaces and quotes included).
TEST(OutputFolder, PrintedRestartCommandWorks) {
  const fs::path out = freshDir("hint dir");  // a space in the folder name too
  std::string err;
  const std::string cmd = fmt::format(
      "{} run {} --out {} -q --stop-after 3 --set solver=tvd --set 'tvd.cell_size=0.1 cm' "
      "--set 'effects=[\"tension_cutoff\", \"material_interfaces\"]' --set 'time.end=0.4 us' "
      "--set 'output.times=[\"0.2 us\"]'",
      hviExe, app::shellQuote(scene("default")), app::shellQuote(out.string()));
  ASSERT_EQ(shell(cmd, &err), app::kInterrupted) << err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(err, m, std::regex("continue with `([^`]*)`"))) << err;
  const std::string hint = m[1].str();
  EXPECT_NE(hint.find("tvd.cell_size=0.1 cm"), std::string::npos) << hint;
  ASSERT_EQ(shell(hint + " -q", &err), app::kOk) << hint << "\n" << err;
  EXPECT_EQ(readJson(out / "summary.json")["status"], "completed");
}

TEST(OutputFolder, ShellQuoting) {
  EXPECT_EQ(app::shellQuote("out/a-1.toml"), "out/a-1.toml");
  EXPECT_EQ(app::shellQuote("time.end=2 us"), "'time.end=2 us'");
  EXPECT_EQ(app::shellQuote("it's"), "'it'\\''s'");
  EXPECT_EQ(app::shellQuote(""), "''");
  EXPECT_EQ(app::shellQuote("a$b"), "'a$b'");
}

// --stop-after: negative refused before anything is made; 0 takes no step but checkpoints,
// and the run continues from there.
TEST(OutputFolder, StopAfterZeroTakesNoStepAndNegativeIsRefused) {
  const fs::path root = freshDir("stop_after");
  auto neg = smallTvd(root / "neg");
  neg.stopAfterSteps = -1;
  EXPECT_EQ(runCaptured(neg).first, app::kBadInput);
  EXPECT_FALSE(fs::exists(root / "neg"));

  auto zero = smallTvd(root / "zero");
  zero.stopAfterSteps = 0;
  EXPECT_EQ(runCaptured(zero).first, app::kInterrupted);
  clearStop();
  const json s = readJson(root / "zero" / "summary.json");
  EXPECT_EQ(s["steps"].get<long>(), 0);
  EXPECT_EQ(s["status"], "interrupted");
  auto cont = smallTvd(root / "zero");
  cont.restart = true;
  EXPECT_EQ(runCaptured(cont).first, app::kOk);
}

TEST(OutputFolder, RestartIntoAMissingFolderCreatesNothing) {
  const fs::path root = freshDir("restart_missing");
  auto o = sod(root / "missing");
  o.restart = true;
  const auto [rc, err] = runCaptured(o);
  EXPECT_EQ(rc, app::kBadInput);
  EXPECT_NE(err.find("missing"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(root / "missing"));
}

// The closing progress line shows the last step, not 0.
TEST(OutputFolder, FinalProgressLineShowsTheLastStep) {
  auto o = smallTvd(freshDir("progress"));
  o.quiet = false;
  const auto [rc, err] = runCaptured(o);
  ASSERT_EQ(rc, app::kOk);
  const auto last = err.rfind("dt = ");
  ASSERT_NE(last, std::string::npos) << err;
  EXPECT_NE(err.substr(last, 17), "dt = 0.000e+00 us") << err;
}

// A run restarted at 32.5 us of 37 us that took 100 s for its first 0.5 us has 800 s left at
// that rate; measured from t = 0 the same line said 12.5 s (the ETA of the restarted shield run).
TEST(Progress, EtaAfterARestartUsesTheRateSinceTheRestart) {
  EXPECT_DOUBLE_EQ(Progress::eta(32.5, 37.0, 33.0, 100.0), 800.0);
  EXPECT_NEAR(Progress::eta(0.0, 37.0, 33.0, 100.0), 12.12, 0.01);
  EXPECT_EQ(Progress::eta(32.5, 37.0, 32.5, 5.0), 0.0);  // no progress yet: no estimate
}

TEST(OutputFolder, UnknownCommandIsNamed) {
  std::string err;
  EXPECT_EQ(shell(hviExe + " frobnicate", &err), app::kBadInput);
  EXPECT_NE(err.find("'frobnicate'"), std::string::npos) << err;
}
