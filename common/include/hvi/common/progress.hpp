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
  //! A restarted run measures its rate from the checkpoint's time: the simulated time before it
  //! cost no wall time in this process.
  void resumeAt(double t) { tStart_ = t; }
  //! Seconds left at simulated time t after `wall` seconds spent since simulated time tFrom,
  //! at the mean rate so far (0 before any progress).
  [[nodiscard]] static double eta(double tFrom, double tEnd, double t, double wall);

 private:
  double tStart_, tEnd_;
  std::FILE* out_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_;
  double intervalSeconds_;
};

}  // namespace hvi
