//! @file The per-thread workspace of TvdSolver (sweep buffers and ledger accumulators).
#pragma once
#include <string>
#include <vector>

#include "hvi/tvd/tvd.hpp"
#include "line_work.hpp"

namespace hvi::tvd {

struct TvdSolver::Workspace {
  explicit Workspace(int lineCells) : line(lineCells) {}
  detail::LineWork line;
  Budget boundary, interfaces, floors;
  std::vector<double> boundaryMass;  // per material: mass in through the domain boundary
  bool failed = false;
  std::string message;
};

}  // namespace hvi::tvd
