//! @file Progress line for long runs: simulated time, step, dt, wall time, ETA.
#pragma once
#include <chrono>
#include <cstdio>

namespace hvi {

class Progress {
 public:
  Progress(double tStart, double tEnd, std::FILE* out = stderr);
  //! Prints at most every `intervalSeconds` of wall time (always when `force`).
  void update(double t, long step, double dt, bool force = false);
  [[nodiscard]] double wallSeconds() const;

 private:
  double tStart_, tEnd_;
  std::FILE* out_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_;
  double intervalSeconds_;
};

}  // namespace hvi
