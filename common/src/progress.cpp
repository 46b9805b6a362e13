//! @file Progress line for long runs.
#include "hvi/common/progress.hpp"

#include <unistd.h>

#include <fmt/format.h>

namespace hvi {

Progress::Progress(double tStart, double tEnd, std::FILE* out)
    : tStart_(tStart), tEnd_(tEnd), out_(out), tty_(::isatty(::fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()), last_(start_),
      intervalSeconds_(tty_ ? 0.5 : 10.0) {}

double Progress::wallSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double Progress::eta(double tFrom, double tEnd, double t, double wall) {
  const double frac = tEnd > tFrom ? (t - tFrom) / (tEnd - tFrom) : 1.0;
  return frac > 1e-9 ? wall * (1.0 - frac) / frac : 0.0;
}

void Progress::update(double t, long step, double dt, bool force) {
  auto now = std::chrono::steady_clock::now();
  if (!force && std::chrono::duration<double>(now - last_).count() < intervalSeconds_) return;
  last_ = now;
  double wall = wallSeconds();
  std::string line = fmt::format("t = {:.4g} / {:.4g} us  step {}  dt = {:.3e} us  wall {:.1f} s  ETA {:.1f} s",
                                 t, tEnd_, step, dt, wall, eta(tStart_, tEnd_, t, wall));
  if (tty_)
    fmt::print(out_, "\r{:<100}", line);
  else
    fmt::print(out_, "{}\n", line);
  if (force && tty_) fmt::print(out_, "\n");
  std::fflush(out_);
}

}  // namespace hvi
