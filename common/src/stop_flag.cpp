//! @file Signal-driven stop request.
#include "hvi/common/stop_flag.hpp"

#include <csignal>

namespace hvi {
namespace {
// The one piece of process-wide state: a signal handler can reach nothing else.
volatile std::sig_atomic_t gStop = 0;
extern "C" void onStopSignal(int) { gStop = 1; }
}  // namespace

void installStopHandlers() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
}
bool stopRequested() { return gStop != 0; }
void requestStop() { gStop = 1; }
void clearStop() { gStop = 0; }

void throwIfStopRequested(const std::string& stage) {
  if (gStop != 0) throw StopDuringSetUp("stopped during " + stage);
}

}  // namespace hvi
