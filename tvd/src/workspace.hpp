//! @file The per-thread workspace of TvdSolver (sweep buffers) and the per-line ledger record.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cut_line.hpp"
#include "line_batch.hpp"
#include "line_work.hpp"
#include "strength_step.hpp"

namespace hvi::tvd {

struct TvdSolver::Workspace {
  explicit Workspace(int lineCells) : line(lineCells) {}
  detail::LineWork line;
  std::unique_ptr<detail::CutLineWork> cut;  // cut-cell mode only
  std::unique_ptr<detail::BatchWork> batch;  // single material (no markers) only
  std::unique_ptr<detail::StrengthLineWork> strength;  // effect strength only
  long redone = 0;  // batch lanes redone by LineSolver (positivity fallback)
  bool failed = false;
  int failedLine = 0;  // the lowest failed line this thread saw: the report does not depend on
                       // the schedule
  std::string message;
  //! Keeps the report of the lowest failed line.
  void fail(int line, std::string what) {
    if (failed && failedLine < line) return;
    failed = true;
    failedLine = line;
    message = std::move(what);
  }
};

struct TvdSolver::LineRecord {
  Budget boundary, interfaces, floors, outflow;
  std::array<double, 2> edgeMass{};  // mass in through the low and high domain edge
  std::array<int, 2> edgeMaterial{-1, -1};
  long relaxed = 0, mixed = 0, pooled = 0;  // cut-cell mode diagnostics (LineBudget)

  //! What a line that reaches the domain's edges moved through them (line budget `lb`, scaled
  //! to the solver's units): through an outflow side it is what left, as totals() adds it back;
  //! through a wall or the axis only the pressure's impulse.
  void bookEdges(const detail::LineBudget& lb, const detail::LineSetup& setup, detail::Side low,
                 detail::Side high, double scale) {
    const bool edge[2] = {setup.leftEdge, setup.rightEdge};
    const bool open[2] = {low == detail::Side::Outflow, high == detail::Side::Outflow};
    for (int e = 0; e < 2; ++e) {
      if (!edge[e]) continue;
      if (open[e])
        outflow += lb.edge[e].scaled(-scale);
      else
        boundary += lb.edge[e].scaled(scale);
    }
  }
};

}  // namespace hvi::tvd
