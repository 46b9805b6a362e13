//! @file Conservation in closed boxes, the ledger, the free body at rest, mirror symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "hvi/common/error.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// Ideal gas in a box with reflecting walls: an off-centre hot spot and a moving blob, so that
// shocks hit every wall and the flow is fully 2-D.
cases::Scene closedBox(Geometry g, int n) {
  const double h = 1.0 / n;
  cases::Scene s = baseScene(0.0, 1.0, 0.0, 1.0, h, g);
  s.domain.boundary = {g == Geometry::Axisymmetric ? cases::Boundary::Axis : cases::Boundary::Wall,
                       cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall};
  s.materials.push_back(material("gas", eos::IdealGas{1.4, 1.0}));
  s.bodies.push_back(body("hot", 0, cases::Disk{{0.3, 0.6}, 0.12}, {1.0, {}, 20.0}));
  s.bodies.push_back(body("blob", 0, cases::Disk{{0.7, 0.3}, 0.15}, {3.0, {-0.8, 1.1}, 1.0}));
  s.bodies.push_back(body("gas", 0, cases::Rect{0, 1, 0, 1}, {1.0, {0.2, -0.1}, 2.5}));
  return s;
}

// Mass and total energy are conserved to round-off: every face flux is added to one cell and
// subtracted from the other, walls pass only pressure. Momentum changes only by the wall
// impulse, which the ledger books from the same fluxes. Round-off: ~1e-16 per operation,
// accumulated over ~1e4 cells x 100 steps at random sign: 1e-12 relative is generous but a
// single lost flux (1e-4 relative or more) fails it.
void checkClosedBox(Geometry g) {
  TvdSolver solver(closedBox(g, 64));
  const Totals t0 = solver.totals();
  for (int i = 0; i < 100; ++i) solver.advance(1e9);
  const Totals t1 = solver.totals();
  const Budget& wall = solver.ledger().boundary;
  std::printf(
      "%s closed box, 100 steps: mass %.2e, energy %.2e, momentum z %.2e (after wall "
      "impulse %.2e)\n",
      toString(g).data(), t1.mass / t0.mass - 1, t1.energy() / t0.energy() - 1,
      (t1.momentumZ - t0.momentumZ) / t0.mass,
      (t1.momentumZ - t0.momentumZ - wall.momentumZ) / t0.mass);
  EXPECT_NEAR(t1.mass / t0.mass, 1.0, 1e-12);
  EXPECT_NEAR(t1.energy() / t0.energy(), 1.0, 1e-12);
  EXPECT_EQ(wall.mass, 0.0);
  EXPECT_EQ(wall.energy, 0.0);
  // Momentum scale: mass times the largest velocity (~1 cm/us).
  EXPECT_NEAR(t1.momentumZ - t0.momentumZ, wall.momentumZ, 1e-12 * t0.mass);
  if (g == Geometry::Planar) {
    EXPECT_NEAR(t1.momentumX - t0.momentumX, wall.momentumX, 1e-12 * t0.mass);
  }
  EXPECT_NE(wall.momentumZ, 0.0);  // the walls did push
}

TEST(TvdConservation, ClosedBoxPlanar) { checkClosedBox(Geometry::Planar); }
TEST(TvdConservation, ClosedBoxRz) { checkClosedBox(Geometry::Axisymmetric); }

// A free aluminium block at rest in vacuum (CASES.md): nothing may move, with or without
// marker lines. Exact: the faces to vacuum carry the block's own flux at zero velocity and
// P = 0, and the characteristic jump across a contact at rest has no acoustic part.
void checkFreeBlock(bool markers) {
  cases::Scene s = baseScene(-1.0, 1.0, -1.0, 1.0, 0.05);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  // The study's aluminium (a Scene built in code gets the cut-off only by naming it).
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(body("block", 0, cases::Rect{-0.52, 0.37, -0.31, 0.44}, {2.79, {}, 0.0}));
  s.bodies.push_back(body("disk", 0, cases::Disk{{0.5, -0.6}, 0.23}, {2.79, {}, 0.0}));
  if (markers) s.effects.insert(cases::Effect::MaterialInterfaces);
  s.tvd.interfaces = cases::InterfaceMode::WholeCell;  // the study's mode (cut cells: test_cut_cells.cpp)
  TvdSolver solver(s);
  const Conserved before = solver.conserved();
  for (int i = 0; i < 50; ++i) solver.advance(1e9);
  const Conserved& after = solver.conserved();
  EXPECT_EQ(before.rho, after.rho);
  EXPECT_EQ(before.E, after.E);
  for (std::size_t c = 0; c < after.mx.size(); ++c) {
    ASSERT_EQ(after.mx[c], 0.0) << c;
    ASSERT_EQ(after.mz[c], 0.0) << c;
  }
  if (markers) {
    EXPECT_EQ(solver.ownerChanges(), 0);
  }
}

TEST(TvdConservation, FreeBlockAtRestStaysAtRest) { checkFreeBlock(false); }
TEST(TvdConservation, FreeBlockAtRestStaysAtRestWithMarkers) { checkFreeBlock(true); }

// Normal impact of a disk on a plate in x-z, the domain symmetric about x = 0: without markers
// the state stays mirror-symmetric bit for bit (the fluxes, limiters and sums are written so
// that a mirrored face gives the mirrored flux exactly).
TEST(TvdSymmetry, NormalImpactStaysMirrorSymmetric) {
  cases::Scene s = baseScene(-1.0, 1.0, -0.8, 0.8, 0.02);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(body("shield", 0, cases::Rect{-0.9, 0.9, -0.2, 0.0}, {2.79, {}, 0.0}));
  s.bodies.push_back(body("striker", 0, cases::Disk{{0.0, 0.25}, 0.25}, {2.79, {0, -0.67}, 0.0}));
  TvdSolver solver(s);
  runTo(solver, 0.6);
  const auto& U = solver.conserved();
  const int nx = solver.grid().nx, nz = solver.grid().nz;
  double vmax = 0.0;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx / 2; ++i) {
      const auto a = static_cast<std::size_t>(k) * nx + i;
      const auto b = static_cast<std::size_t>(k) * nx + (nx - 1 - i);
      ASSERT_EQ(U.rho[a], U.rho[b]) << i << " " << k;
      ASSERT_EQ(U.E[a], U.E[b]);
      ASSERT_EQ(U.mz[a], U.mz[b]);
      ASSERT_EQ(U.mx[a], -U.mx[b]);
      vmax = std::max(vmax, std::abs(U.mx[a]) / U.rho[a]);
    }
  EXPECT_GT(vmax, 0.1);  // the impact did spread material sideways
}

// Restart: a checkpoint written after 30 steps and read into a fresh solver continues bit for
// bit (state, markers, configuration, step parity of the splitting).
void checkRestart(bool markers) {
  cases::Scene s = baseScene(-1.0, 1.0, -0.8, 0.8, 0.04);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(body("shield", 0, cases::Rect{-0.7, 0.7, -0.2, 0.0}, {2.79, {}, 0.0}));
  s.bodies.push_back(body("striker", 0, cases::Disk{{0.1, 0.25}, 0.25}, {2.79, {0.1, -0.67}, 0.0}));
  if (markers) s.effects.insert(cases::Effect::MaterialInterfaces);
  TvdSolver a(s);
  for (int i = 0; i < 31; ++i) a.advance(1e9);  // odd: the next step starts with the z sweep
  std::stringstream cp;
  a.writeCheckpoint(cp);
  for (int i = 0; i < 20; ++i) a.advance(1e9);
  TvdSolver b(s);
  b.readCheckpoint(cp);
  EXPECT_EQ(b.step(), 31);
  for (int i = 0; i < 20; ++i) b.advance(1e9);
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.conserved().rho, b.conserved().rho);
  EXPECT_EQ(a.conserved().mx, b.conserved().mx);
  EXPECT_EQ(a.conserved().mz, b.conserved().mz);
  EXPECT_EQ(a.conserved().E, b.conserved().E);
  if (markers) {
    EXPECT_EQ(a.owner(), b.owner());
    ASSERT_EQ(a.markers().lines().size(), b.markers().lines().size());
    for (std::size_t l = 0; l < a.markers().lines().size(); ++l)
      EXPECT_EQ(a.markers().lines()[l].points, b.markers().lines()[l].points);
  }
}

TEST(TvdCheckpoint, RestartIsBitForBit) { checkRestart(false); }
TEST(TvdCheckpoint, RestartIsBitForBitWithMarkers) { checkRestart(true); }

TEST(TvdCheckpoint, RejectsAnotherGrid) {
  cases::Scene s = baseScene(0.0, 1.0, 0.0, 1.0, 0.1);
  s.materials.push_back(material("gas", eos::IdealGas{}));
  s.bodies.push_back(body("gas", 0, cases::Rect{0, 1, 0, 1}, {1.0, {}, 1.0}));
  TvdSolver a(s);
  std::stringstream cp;
  a.writeCheckpoint(cp);
  s.tvd.cellSize = 0.05;
  TvdSolver b(s);
  EXPECT_THROW(b.readCheckpoint(cp), InputError);
  std::stringstream junk("not a checkpoint at all, not at all");
  EXPECT_THROW(a.readCheckpoint(junk), InputError);
}

}  // namespace
}  // namespace hvi::tvd
