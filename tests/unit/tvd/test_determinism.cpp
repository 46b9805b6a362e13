//! @file The TVD state and its ledger do not depend on the thread count.
//!
//! The sweeps hand lines to threads dynamically. The ledger (and the material target masses the
//! renormalisation scales to) used to be summed per thread, so its round-off depended on which
//! thread ran which line: two identical runs wrote different checkpoints, and a restart with
//! another thread count could drift. Each line's bookings are now summed in line order.
#include <gtest/gtest.h>

#include <sstream>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// Over 16384 cells, so the sweeps really run in parallel; material leaves through xmax (boundary
// bookings per material) and slides over a plate (interface bookings).
cases::Scene outflowScene() {
  auto s = baseScene(-1.5, 1.5, -1.5, 1.5, 0.02);
  s.effects = {cases::Effect::MaterialInterfaces, cases::Effect::TensionCutoff};
  s.materials = {material("aluminium", eos::aluminiumStudy())};
  s.bodies = {body("striker", 0, cases::Disk{{1.3, 0.2}, 0.3}, {2.7, {0.5, -0.3}, 0.0}),
              body("plate", 0, cases::Rect{-1.5, 1.5, -0.4, 0.0}, {2.7, {}, 0.0})};
  return s;
}

std::string checkpointAfter(int threads, int steps) {
  Options o;
  o.threads = threads;
  TvdSolver solver(outflowScene(), o);
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  std::ostringstream out;
  solver.writeCheckpoint(out);
  return out.str();
}

TEST(TvdDeterminism, CheckpointIsTheSameForOneAndThreeThreads) {
  const std::string one = checkpointAfter(1, 25), three = checkpointAfter(3, 25);
  ASSERT_EQ(one.size(), three.size());
  EXPECT_TRUE(one == three) << "the state or the ledger depends on the thread count";
  EXPECT_TRUE(checkpointAfter(3, 25) == three) << "two identical runs differ";
}

}  // namespace
}  // namespace hvi::tvd
