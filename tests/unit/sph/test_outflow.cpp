//! @file Material that leaves through outflow boundaries: the run continues to its end time.
//!
//! Once every particle has left, nothing is left to evolve, so the solution at any later time is
//! the empty domain; the solver must reach its end time (and snapshot, checkpoint and restart)
//! instead of building a neighbour grid over no points (which threw std::length_error).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

// An aluminium block at zero pressure (rho0, e = 0) drifting out of a small, all-outflow
// domain: it is gone after about 0.3 cm / 0.5 cm/us = 0.6 us of the 3 us run.
cases::Scene driftingBlock() {
  auto s = test::baseScene(Geometry::Planar, -0.2, 0.2, -0.2, 0.2, 0.02,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment,
                            Effect::TensionCutoff});
  s.materials = {test::aluminium()};
  s.bodies = {test::rectBody("block", 0, -0.06, 0.06, -0.05, 0.05, {0.3, -0.4})};
  s.tEnd = 3.0;
  test::resolveDensities(s);
  return s;
}

TEST(Neighbours, EmptyPointSetGivesAnEmptyGrid) {
  CellGrid grid;
  NeighbourList list;
  buildNeighbourList(nullptr, nullptr, nullptr, 0, 0, 3.0, grid, list);
  EXPECT_EQ(grid.nx(), 1);
  EXPECT_EQ(grid.nz(), 1);
  EXPECT_EQ(grid.begin(0), 0);
  EXPECT_EQ(grid.begin(1), 0);
  EXPECT_TRUE(list.count.empty());
}

TEST(Outflow, RunReachesItsEndAfterAllMaterialHasLeft) {
  const cases::Scene s = driftingBlock();
  SphSolver solver(s);
  const Totals initial = solver.totals();
  ASSERT_GT(solver.stepper().size(), 0u);
  // Bounded work: the block leaves within ~100 steps at this spacing.
  int steps = 0;
  std::stringstream emptyCheckpoint;
  while (solver.time() < s.tEnd && steps < 2000) {
    const double dt = solver.advance(s.tEnd);
    ASSERT_GT(dt, 0.0) << "time stopped advancing at t = " << solver.time();
    ++steps;
    if (solver.stepper().size() == 0 && emptyCheckpoint.str().empty() && solver.time() < s.tEnd)
      solver.writeCheckpoint(emptyCheckpoint);
  }
  EXPECT_EQ(solver.time(), s.tEnd);
  EXPECT_EQ(solver.stepper().size(), 0u);
  // Everything left through the boundary and is booked there: mass, momentum and energy of
  // a uniformly drifting block at zero pressure are conserved (round-off over ~100 steps).
  const Totals final = solver.totals();
  EXPECT_NEAR(final.mass, initial.mass, 1e-13 * initial.mass);
  EXPECT_NEAR(final.momentumX, initial.momentumX, 1e-12 * std::abs(initial.momentumX));
  EXPECT_NEAR(final.momentumZ, initial.momentumZ, 1e-12 * std::abs(initial.momentumZ));
  EXPECT_NEAR(final.energy(), initial.energy(), 1e-10 * initial.energy());
  const Snapshot snap = solver.snapshot();
  ASSERT_NE(snap.find("density"), nullptr);
  EXPECT_TRUE(snap.find("density")->data.empty());

  // The empty state restarts and reaches the same end.
  ASSERT_FALSE(emptyCheckpoint.str().empty()) << "the block never left before the end time";
  SphSolver restarted(s);
  restarted.readCheckpoint(emptyCheckpoint);
  EXPECT_EQ(restarted.stepper().size(), 0u);
  EXPECT_GT(restarted.advance(s.tEnd), 0.0);
  EXPECT_EQ(restarted.time(), s.tEnd);
  EXPECT_EQ(restarted.totals().mass, final.mass);
}

}  // namespace
}  // namespace hvi::sph
