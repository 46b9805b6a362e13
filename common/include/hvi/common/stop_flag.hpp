//! @file SIGINT/SIGTERM turn into a polite stop request that the run loop honours between steps.
#pragma once
#include <stdexcept>
#include <string>

namespace hvi {

//! Installs handlers for SIGINT and SIGTERM that set the stop flag (async-signal-safe).
void installStopHandlers();
[[nodiscard]] bool stopRequested();
void requestStop();   //!< for tests
void clearStop();

//! A stop request honoured while a run is being set up (particle fill, mass iteration, marker
//! lines, the exact Riemann solution): nothing has been computed that a checkpoint could keep,
//! so the driver reports it and exits 130 (kInterrupted) without one. The message says which
//! set-up stage was interrupted.
class StopDuringSetUp : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Throws StopDuringSetUp naming `stage` if a stop was requested. For the long set-up loops;
//! cheap (one flag read), but call it every few thousand items, not in the innermost loop.
void throwIfStopRequested(const std::string& stage);

}  // namespace hvi
