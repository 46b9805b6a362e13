//! @file Shield cases as child `hvi run` processes: scene files, run folders, resumption.
#pragma once
#include <sys/types.h>

#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hvi/apps/sweep.hpp"
#include "hvi/shield/shield.hpp"

namespace hvi::app::detail {

//! The declaration with the case's values in place.
shield::ShieldSpec applyCase(shield::ShieldSpec s, const ShieldCase& c);

class CaseRunner {
 public:
  CaseRunner(shield::ShieldSpec base, SweepOptions opt);
  ~CaseRunner();
  CaseRunner(const CaseRunner&) = delete;
  CaseRunner& operator=(const CaseRunner&) = delete;

  //! The outcome of an earlier invocation when the case finished then with the same scene.
  [[nodiscard]] std::optional<CaseOutcome> earlier(const ShieldCase& c) const;
  [[nodiscard]] bool canStart() const { return static_cast<int>(running_.size()) < opt_.jobs; }
  [[nodiscard]] bool isRunning(const std::string& id) const;
  [[nodiscard]] int running() const { return static_cast<int>(running_.size()); }
  //! Writes the case's scene and starts `hvi run` on it (--restart after an interruption).
  void start(const ShieldCase& c);
  //! Waits (polling every 0.1 s) until a child ends or a stop is requested (then nullopt).
  std::optional<CaseOutcome> waitOne();
  //! Passes SIGINT to every child and collects their outcomes (interrupted, or finished).
  std::vector<CaseOutcome> stopAll();
  [[nodiscard]] const SweepOptions& options() const { return opt_; }

 private:
  struct Child {
    ShieldCase c;
    std::string id;
    std::chrono::steady_clock::time_point started;
  };
  [[nodiscard]] std::string sceneText(const ShieldCase& c) const;
  CaseOutcome collect(const Child& ch, int exitStatus) const;

  shield::ShieldSpec base_;
  SweepOptions opt_;
  std::map<pid_t, Child> running_;
};

//! Drives a set of cases: `wanted` lists those whose results are needed now; finished ones of
//! an earlier invocation are taken as they are; `record` receives every outcome; `toGo` counts
//! runs still expected (for the ETA). Returns kOk or kInterrupted.
int driveCases(CaseRunner& runner, const std::function<std::vector<ShieldCase>()>& wanted,
               const std::function<void(const CaseOutcome&)>& record,
               const std::function<int()>& toGo, const std::string& label);

}  // namespace hvi::app::detail
