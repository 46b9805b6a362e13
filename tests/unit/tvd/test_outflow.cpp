//! @file What leaves through outflow sides: counted in totals() (as SPH counts the particles
//! that left), booked once, the walls' impulse kept apart; version-2 checkpoints still read.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// A block moving at 0.6 cm/us towards the x = 1 outflow side of a box whose z sides are walls;
// by 1.2 us about half of it has left. In-domain content plus outflow is the initial total to
// the ledger (without markers: mass to round-off, energy by the floors only), the walls book
// only normal momentum, and the marker run's renormalisation targets follow the outflow.
void checkBlockLeaves(bool markers) {
  cases::Scene s = baseScene(-1.0, 1.0, -0.5, 0.5, 0.025);
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(body("block", 0, cases::Rect{-0.1, 0.6, -0.3, 0.3}, {2.79, {0.6, 0.0}, 0.0}));
  if (markers) s.effects.insert(cases::Effect::MaterialInterfaces);
  TvdSolver solver(s);
  const Totals t0 = solver.totals();
  EXPECT_EQ(solver.outflow().mass, 0.0);
  runTo(solver, 1.2);
  const Totals t = solver.totals(), out = solver.outflow();
  const Ledger& L = solver.ledger();
  double inDomain = 0.0;
  for (std::size_t c = 0; c < solver.conserved().rho.size(); ++c)
    inDomain += solver.conserved().rho[c] * solver.cellVolume(static_cast<long>(c));
  std::printf("%s: outflow %.3f of the mass, %.3f of the energy; drift mass %.2e energy %.2e\n",
              markers ? "markers" : "no markers", out.mass / t0.mass, out.energy() / t0.energy(),
              t.mass / t0.mass - 1, t.energy() / t0.energy() - 1);
  EXPECT_GT(out.mass, 0.3 * t0.mass);
  EXPECT_LT(out.mass, 0.7 * t0.mass);
  EXPECT_EQ(out.kinetic, 0.0);  // TVD books the energy that left as internal
  EXPECT_EQ(out.mass, L.outflow.mass);
  EXPECT_NEAR(t.mass, inDomain + out.mass, 1e-13 * t0.mass);
  // The ledger: what changed the totals; the outflow is not among the changes.
  EXPECT_NEAR(t.mass - t0.mass, L.sum().mass, 1e-11 * t0.mass);
  EXPECT_NEAR(t.energy() - t0.energy(), L.sum().energy, 1e-11 * t0.energy());
  EXPECT_NEAR(t.momentumX - t0.momentumX, L.sum().momentumX, 1e-11 * t0.mass);
  EXPECT_NEAR(t.momentumZ - t0.momentumZ, L.sum().momentumZ, 1e-11 * t0.mass);
  EXPECT_EQ(L.boundary.mass, 0.0);  // walls pass no mass and no energy
  EXPECT_EQ(L.boundary.energy, 0.0);
  // Without markers only the floors change the mass (none here) and the energy (the vacuum
  // resets at the free surfaces, 1e-6): the total with the outflow is the initial one.
  if (!markers) {
    EXPECT_NEAR(t.mass / t0.mass, 1.0, 1e-12);
    EXPECT_NEAR(t.energy() - t0.energy(), L.floors.energy, 1e-11 * t0.energy());
  }
}

// Checkpoint version 2 had no outflow budget: its boundary budget held the outflow sides and
// the walls together. Read now, that budget counts as outflow (mass and energy exact: walls
// carry none) and the state continues as written.
TEST(TvdOutflow, CheckpointVersion2IsReadWithItsBoundaryAsOutflow) {
  cases::Scene s = baseScene(-1.0, 1.0, -0.5, 0.5, 0.05);
  s.domain.boundary[2] = s.domain.boundary[3] = cases::Boundary::Wall;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(body("block", 0, cases::Rect{0.2, 0.9, -0.3, 0.3}, {2.79, {0.6, 0.0}, 0.0}));
  TvdSolver a(s);
  runTo(a, 0.6);
  std::stringstream v4;
  a.writeCheckpoint(v4);
  std::string bytes = v4.str();
  // Layout (docs/tvd.md): magic u64, version u32, 4 x i32, the interface-mode i32 (version 4),
  // 2 x f64, 2 x i64, then the budgets; version 2 has no mode flag and no outflow budget.
  constexpr std::size_t kVersionAt = 8, kModeAt = 28, kBudget = 4 * sizeof(double);
  bytes.erase(kModeAt, sizeof(std::int32_t));
  constexpr std::size_t kBudgetsAt = 60;
  const std::uint32_t two = 2;
  std::memcpy(bytes.data() + kVersionAt, &two, sizeof two);
  double boundary[4], outflow[4];
  std::memcpy(boundary, bytes.data() + kBudgetsAt, kBudget);
  std::memcpy(outflow, bytes.data() + kBudgetsAt + 4 * kBudget, kBudget);
  for (int k = 0; k < 4; ++k) boundary[k] -= outflow[k];  // version 2: inflow positive, walls too
  std::memcpy(bytes.data() + kBudgetsAt, boundary, kBudget);
  bytes.erase(kBudgetsAt + 4 * kBudget, kBudget);
  TvdSolver b(s);
  std::stringstream v2(bytes);
  b.readCheckpoint(v2);
  EXPECT_EQ(b.conserved().rho, a.conserved().rho);
  EXPECT_EQ(b.ledger().outflow.mass, -boundary[0]);
  EXPECT_EQ(b.ledger().outflow.energy, -boundary[3]);
  EXPECT_EQ(b.ledger().boundary.momentumZ, 0.0);
  EXPECT_GT(b.outflow().mass, 0.0);
  EXPECT_NEAR(b.totals().mass, a.totals().mass, 1e-15 * a.totals().mass);
  EXPECT_NEAR(b.totals().energy(), a.totals().energy(), 1e-14 * a.totals().energy());
  b.advance(1e9);
  a.advance(1e9);
  EXPECT_EQ(b.conserved().E, a.conserved().E);
}

TEST(TvdOutflow, TotalsCountWhatLeft) { checkBlockLeaves(false); }
TEST(TvdOutflow, TotalsCountWhatLeftWithMarkers) { checkBlockLeaves(true); }

}  // namespace
}  // namespace hvi::tvd
