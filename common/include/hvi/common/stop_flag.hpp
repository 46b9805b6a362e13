//! @file SIGINT/SIGTERM turn into a polite stop request that the run loop honours between steps.
#pragma once

namespace hvi {

//! Installs handlers for SIGINT and SIGTERM that set the stop flag (async-signal-safe).
void installStopHandlers();
[[nodiscard]] bool stopRequested();
void requestStop();   //!< for tests
void clearStop();

}  // namespace hvi
