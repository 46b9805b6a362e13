//! @file The single-material sweep's line batches give the one-line-at-a-time result bit for bit.
//!
//! Without markers the sweeps advance detail::kBatch lines together (line_batch.hpp, issue 17):
//! the same operations as LineSolver in the same order, lane by lane, with the lines that need
//! the positivity fallback redone by LineSolver. Any difference in an operation's order would
//! show as a difference in the last bit of some cell, so the check is exact: the checkpoints
//! (conserved state and every ledger entry) of a run with batches and one without are equal.
#include <gtest/gtest.h>

#include <sstream>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

struct Runs {
  std::string batched, single;
  long redone = 0;
};

Runs runBoth(const cases::Scene& s, int steps) {
  Runs r;
  for (bool batches : {true, false}) {
    Options o;
    o.threads = 1;
    o.lineBatches = batches;
    TvdSolver solver(s, o);
    for (int k = 0; k < steps; ++k) solver.advance(1e9);
    std::ostringstream out;
    solver.writeCheckpoint(out);
    (batches ? r.batched : r.single) = out.str();
    if (batches) r.redone = solver.linesRedone();
  }
  return r;
}

// Ideal gas between walls, 61 x 43 cells (neither a multiple of the batch: the remainder lines
// go one at a time), a hot spot and a moving blob: shocks on every wall, all three limiters.
TEST(TvdBatches, IdealGasBoxIsBitForBit) {
  for (auto lim : {cases::Limiter::Minmod, cases::Limiter::VanLeer, cases::Limiter::Superbee}) {
    cases::Scene s = baseScene(0.0, 1.0, 0.0, 43.0 / 61.0, 1.0 / 61.0);
    s.tvd.limiter = lim;
    s.domain.boundary = {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall,
                         cases::Boundary::Outflow};
    s.materials.push_back(material("gas", eos::IdealGas{1.4, 1.0}));
    s.bodies.push_back(body("gas", 0, cases::Rect{0, 1, 0, 1}, {1.0, {0.2, -0.1}, 2.5}));
    s.bodies.push_back(body("hot", 0, cases::Disk{{0.3, 0.4}, 0.12}, {1.0, {}, 20.0}));
    s.bodies.push_back(body("blob", 0, cases::Disk{{0.7, 0.3}, 0.15}, {3.0, {-0.8, 1.1}, 1.0}));
    const Runs r = runBoth(s, 40);
    ASSERT_EQ(r.batched.size(), r.single.size());
    EXPECT_TRUE(r.batched == r.single) << "limiter " << static_cast<int>(lim);
  }
}

// Tillotson aluminium striking a plate in vacuum (no markers): thin cells at the free surfaces
// are put at rest (floors in the ledger) and the positivity fallback is needed, so batch lanes
// are redone one at a time; r-z too (its axial lines are batched, its radial lines are not).
TEST(TvdBatches, ImpactInVacuumIsBitForBit) {
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const bool rz = g == Geometry::Axisymmetric;
    cases::Scene s = baseScene(rz ? 0.0 : -1.0, 1.0, -0.8, 0.8, 0.03, g);
    if (rz) s.domain.boundary[0] = cases::Boundary::Axis;
    s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
    s.effects.insert(cases::Effect::TensionCutoff);
    s.bodies.push_back(body("shield", 0, cases::Rect{-0.9, 0.9, -0.2, 0.0}, {2.79, {}, 0.0}));
    s.bodies.push_back(body("striker", 0, cases::Disk{{0.1, 0.25}, 0.25}, {2.79, {0, -0.67}, 0.0}));
    const Runs r = runBoth(s, 60);
    ASSERT_EQ(r.batched.size(), r.single.size());
    EXPECT_TRUE(r.batched == r.single) << (rz ? "r-z" : "planar");
    if (!rz) {
      EXPECT_GT(r.redone, 0) << "the fallback path of the batches was not exercised";
    }
  }
}

}  // namespace
}  // namespace hvi::tvd
