//! @file Child `hvi run` processes for shield cases; the scheduler with progress and ETA.
#include "case_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"

namespace hvi::app {
namespace fs = std::filesystem;
using nlohmann::json;

std::string caseId(const ShieldCase& c) {
  std::string id =
      fmt::format("{}_v{:.5g}_d{:.5g}", cases::toString(c.solver), c.speed, c.diameter);
  if (c.standoff) id += fmt::format("_S{:.5g}", *c.standoff);
  if (c.rearWall) id += fmt::format("_tw{:.5g}", *c.rearWall);
  if (c.bumper) id += fmt::format("_tb{:.5g}", *c.bumper);
  return id;
}

namespace detail {
namespace {

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

json readSummary(const fs::path& dir) {
  try {
    return json::parse(readText(dir / "summary.json"));
  } catch (const std::exception&) {
    return nullptr;
  }
}

std::string duration(double s) {
  if (!(s >= 0) || !std::isfinite(s)) return "?";
  const long t = std::lround(s);
  if (t >= 3600) return fmt::format("{}h{:02}m", t / 3600, (t % 3600) / 60);
  if (t >= 60) return fmt::format("{}m{:02}s", t / 60, t % 60);
  return fmt::format("{}s", t);
}

std::string selfExe() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "hvi" : p.string();
}

}  // namespace

shield::ShieldSpec applyCase(shield::ShieldSpec s, const ShieldCase& c) {
  s.solver = c.solver;
  s.projectile.speed = c.speed;
  s.projectile.diameter = c.diameter;
  if (c.rearWall) s.walls.back().thickness = *c.rearWall;
  if (c.bumper) s.walls.front().thickness = *c.bumper;
  if (c.standoff) shield::setStandoff(s, *c.standoff);
  return s;
}

CaseRunner::CaseRunner(shield::ShieldSpec base, SweepOptions opt)
    : base_(std::move(base)), opt_(std::move(opt)) {
  if (opt_.jobs < 1) throw InputError(fmt::format("--jobs {}: allowed: 1 or more", opt_.jobs));
  if (opt_.hvi.empty()) opt_.hvi = selfExe();
  fs::create_directories(opt_.out / "scenes");
  fs::create_directories(opt_.out / "runs");
}

CaseRunner::~CaseRunner() {
  // Never leave children behind (an exception in the caller): stop them as Ctrl-C would.
  if (!running_.empty()) (void)stopAll();
}

std::string CaseRunner::sceneText(const ShieldCase& c) const {
  std::string text = shield::sceneToml(applyCase(base_, c));
  // The --set values are part of what a finished run was run with.
  for (const auto& o : opt_.overrides) text = "# hvi run --set " + o + "\n" + text;
  return text;
}

bool CaseRunner::isRunning(const std::string& id) const {
  for (const auto& [pid, ch] : running_)
    if (ch.id == id) return true;
  return false;
}

std::optional<CaseOutcome> CaseRunner::earlier(const ShieldCase& c) const {
  const std::string id = caseId(c);
  if (readText(opt_.out / "scenes" / (id + ".toml")) != sceneText(c)) return std::nullopt;
  const json s = readSummary(opt_.out / "runs" / id);
  if (s.is_null()) return std::nullopt;
  const std::string status = s.value("status", "");
  if (status != "completed" && status != "failed") return std::nullopt;
  CaseOutcome o = collect({c, id, {}}, 0);
  o.reused = true;
  return o;
}

void CaseRunner::start(const ShieldCase& c) {
  const std::string id = caseId(c);
  const fs::path scene = opt_.out / "scenes" / (id + ".toml");
  const fs::path dir = opt_.out / "runs" / id;
  const std::string text = sceneText(c);
  const bool sameScene = readText(scene) == text;
  const json summary = readSummary(dir);
  std::vector<std::string> args{opt_.hvi, "run", scene.string(), "--out", dir.string(), "--quiet"};
  if (sameScene && fs::exists(dir / "checkpoint.bin") &&
      summary.value("status", "") == "interrupted")
    args.emplace_back("--restart");
  else
    args.emplace_back("--overwrite");
  for (const auto& o : opt_.overrides) {
    args.emplace_back("--set");
    args.push_back(o);
  }
  // The scene file is written first: a case whose scene is on disk and whose summary says
  // completed is finished, whatever happened to the sweep afterwards.
  if (!sameScene) writeTextAtomically(scene, text);
  fs::create_directories(dir);
  const std::string log = (dir / "hvi_run.log").string();
  // One thread per child unless the user says otherwise: the children share the cores.
  const bool setThreads = std::getenv("OMP_NUM_THREADS") == nullptr;
  const pid_t pid = fork();
  if (pid < 0)
    throw OutputError(fmt::format("{}: cannot start a process: {}", id, errnoText(errno)));
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    if (setThreads) ::setenv("OMP_NUM_THREADS", "1", 1);
    if (std::getenv("OMP_WAIT_POLICY") == nullptr) ::setenv("OMP_WAIT_POLICY", "passive", 1);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    std::fprintf(stderr, "hvi sweep: cannot run %s\n", argv[0]);
    ::_exit(127);
  }
  running_[pid] = {c, id, std::chrono::steady_clock::now()};
}

CaseOutcome CaseRunner::collect(const Child& ch, int exitStatus) const {
  CaseOutcome o;
  o.c = ch.c;
  o.id = ch.id;
  const json s = readSummary(opt_.out / "runs" / ch.id);
  o.status = s.is_null() ? "error" : s.value("status", "error");
  if (exitStatus == kInterrupted) o.status = "interrupted";
  if (!s.is_null()) {
    o.wallSeconds = s.value("wall_seconds", 0.0);
    if (s.contains("rear_wall_failure") && !s.at("rear_wall_failure").is_null()) {
      const json& v = s.at("rear_wall_failure");
      // A completed run's verdict stands; a run the solver could not finish (exit 3) counts
      // when it had already shown the perforation in an earlier snapshot, and is no result
      // otherwise (its wall might have failed later).
      if (o.status == "completed" || (o.status == "failed" && v.value("perforated", false))) {
        o.verdict = v;
        o.perforated = v.value("perforated", false);
      }
    }
  }
  if (o.status == "completed" && !o.perforated) o.status = "error";  // no rear-wall verdict
  return o;
}

std::optional<CaseOutcome> CaseRunner::waitOne() {
  while (!running_.empty()) {
    int st = 0;
    const pid_t pid = ::waitpid(-1, &st, WNOHANG);
    if (pid > 0 && running_.count(pid)) {
      const Child ch = running_.at(pid);
      running_.erase(pid);
      CaseOutcome o = collect(ch, WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st));
      if (o.wallSeconds == 0.0)
        o.wallSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - ch.started).count();
      return o;
    }
    if (stopRequested()) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return std::nullopt;
}

std::vector<CaseOutcome> CaseRunner::stopAll() {
  // Each child checkpoints and exits 130 on SIGINT; a terminal's Ctrl-C has already reached
  // them (one process group), a second SIGINT is harmless.
  for (const auto& [pid, ch] : running_) ::kill(pid, SIGINT);
  std::vector<CaseOutcome> out;
  while (!running_.empty()) {
    int st = 0;
    const pid_t pid = ::waitpid(-1, &st, 0);
    if (pid < 0) break;
    if (!running_.count(pid)) continue;
    const Child ch = running_.at(pid);
    running_.erase(pid);
    out.push_back(collect(ch, WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st)));
  }
  running_.clear();
  return out;
}

int driveCases(CaseRunner& runner, const std::function<std::vector<ShieldCase>()>& wanted,
               const std::function<void(const CaseOutcome&)>& record,
               const std::function<int()>& toGo, const std::string& label) {
  const auto t0 = std::chrono::steady_clock::now();
  std::set<std::string> started;  // in this invocation: never twice
  int finished = 0, reused = 0;
  double runSeconds = 0.0;
  int runsTimed = 0;
  const bool quiet = runner.options().quiet;
  const auto progress = [&] {
    if (quiet) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const int jobs = runner.options().jobs;
    const int left = toGo();
    std::string eta = "?";
    if (runsTimed > 0)
      eta = duration(runSeconds / runsTimed * std::ceil(static_cast<double>(left) / jobs));
    fmt::print(stderr,
               "[{}] {} runs done ({} from earlier), {} running, ~{} to go; elapsed {}, ETA {}\n",
               label, finished, reused, runner.running(), left, duration(elapsed), eta);
  };
  for (;;) {
    if (stopRequested()) break;
    // Take finished cases of earlier invocations until none is left, then start new ones.
    bool changed = true;
    while (changed) {
      changed = false;
      for (const auto& c : wanted()) {
        const std::string id = caseId(c);
        if (started.count(id) || runner.isRunning(id)) continue;
        if (auto o = runner.earlier(c)) {
          started.insert(id);
          record(*o);
          ++finished;
          ++reused;
          changed = true;
        } else if (runner.canStart()) {
          started.insert(id);
          runner.start(c);
        }
      }
    }
    if (runner.running() == 0) {
      progress();
      return kOk;
    }
    progress();
    if (auto o = runner.waitOne()) {
      if (o->status != "interrupted") {
        runSeconds += o->wallSeconds;
        ++runsTimed;
      }
      ++finished;
      record(*o);
    }
  }
  for (const auto& o : runner.stopAll()) record(o);
  fmt::print(stderr,
             "[{}] interrupted: running cases were checkpointed; run the same command to "
             "resume (finished cases are not rerun)\n",
             label);
  return kInterrupted;
}

}  // namespace detail
}  // namespace hvi::app
