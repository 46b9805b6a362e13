//! @file The time step's scan: the largest signal speed over a set of cells, threaded.
#pragma once
#include <algorithm>
#include <cmath>

#include "hvi/tvd/characteristics.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd::detail {

//! The largest signal speed max(|u|, |w|) + c, its cell, and the lowest unphysical cell.
struct SpeedScan {
  double smax = 0.0;
  long worst = -1, bad = -1;
};

//! Adds cells 0..cells-1 to `scan`: state(c, s) returns 0 to skip the cell, -1 if it is
//! unphysical, 1 with its state in s. The reduction keeps the fastest cell and, on ties and for
//! the unphysical one, the lowest index, so the result does not depend on the thread count.
//! Returns true if this call found the lowest unphysical cell so far.
template <class State>
bool scanSignalSpeed(long cells, int threads, SpeedScan& scan, State state) {
  return scanSignalSpeed(0, cells, threads, scan, state);
}
//! Same over cells lo..hi-1 (the others hold nothing).
template <class State>
bool scanSignalSpeed(long lo, long hi, int threads, SpeedScan& scan, State state) {
  bool foundBad = false;
#pragma omp parallel num_threads(threads) if (hi - lo >= kParallelCells)
  {
    double sLocal = 0.0;
    long wLocal = -1, bLocal = -1;
#pragma omp for schedule(static)
    for (long c = lo; c < hi; ++c) {
      CellState s;
      const int kind = state(c, s);
      if (kind == 0) continue;
      const double v = kind > 0 ? std::max(std::abs(s.u), std::abs(s.w)) + s.c : 0.0;
      if (kind < 0 || !std::isfinite(v)) {
        if (bLocal < 0) bLocal = c;
        continue;
      }
      if (v > sLocal) {
        sLocal = v;
        wLocal = c;
      }
    }
#pragma omp critical(hvi_tvd_signal)
    {
      if (sLocal > scan.smax || (sLocal == scan.smax && wLocal >= 0 && wLocal < scan.worst)) {
        scan.smax = sLocal;
        scan.worst = wLocal;
      }
      if (bLocal >= 0 && (scan.bad < 0 || bLocal < scan.bad)) {
        scan.bad = bLocal;
        foundBad = true;
      }
    }
  }
  return foundBad;
}

}  // namespace hvi::tvd::detail
