//! @file Exceptions that carry a user-facing diagnostic.
#pragma once
#include <stdexcept>
#include <string>

namespace hvi {

//! Bad input: the run must not start. The message names file, line, key and what is allowed.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A run that went wrong (NaN, negative density, time-step collapse). The message names the
//! particle or cell, its state and the step; the driver writes a last snapshot for inspection.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! An output file could not be written (disk full, quota, read-only file system, ...). The
//! message names the file and the operating system's reason; the file's previous content is
//! intact (every write goes through writeAtomically). The driver stops the run with exit 4.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hvi
