//! @file Marker lines driven by the solver: advection and return of a disk, the ledger,
//! slip at a two-material contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

void expectLedgerCloses(const TvdSolver& s, const Totals& t0, const char* what) {
  const Totals t = s.totals();
  const Budget b = s.ledger().sum();
  // Every change of the totals is booked: round-off only (1e-12 of the totals).
  EXPECT_NEAR(t.mass - t0.mass, b.mass, 1e-12 * t0.mass) << what;
  EXPECT_NEAR(t.energy() - t0.energy(), b.energy, 1e-12 * t0.energy()) << what;
  EXPECT_NEAR(t.momentumZ - t0.momentumZ, b.momentumZ, 1e-12 * t0.mass) << what;
}

// Marker spacing after redistribution, in cells: every segment within the bounds the marker
// set keeps (minSpacingCells, maxSpacingCells).
void expectSpacing(const TvdSolver& s) {
  const MarkerSet& m = s.markers();
  const double h = s.grid().dx;
  double lo = 1e300, hi = 0.0;
  for (const auto& l : m.lines())
    for (std::size_t j = 0; j < l.points.size(); ++j) {
      const double d = norm(l.points[(j + 1) % l.points.size()] - l.points[j]) / h;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  std::printf("  marker spacing %.3f .. %.3f cells (bounds %.3f .. %.3f)\n", lo, hi,
              m.minSpacingCells(), m.maxSpacingCells());
  EXPECT_GE(lo, m.minSpacingCells() * (1 - 1e-9));
  EXPECT_LE(hi, m.maxSpacingCells() * (1 + 1e-9));
}

// An aluminium disk at P = 0 carried through vacuum at 45 degrees to the grid, then sent back
// (velocity reversed) for the same time: it returns to its start. The interpolated velocity
// is uniform, so the marker area changes only by redistribution (markers are inserted on
// segments and removed where lines shorten: second order in the spacing); the cells it
// leaves and enters are emptied and filled by the configuration changes.
TEST(TvdMarkerFlow, DiskCarriedThroughVacuumReturns) {
  cases::Scene s = baseScene(-1.0, 1.0, -1.0, 1.0, 0.025);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  // The study's aluminium (a Scene built in code gets the cut-off only by naming it).
  s.effects.insert(cases::Effect::TensionCutoff);
  const double R = 0.25;
  s.bodies.push_back(body("disk", 0, cases::Disk{{-0.3, -0.3}, R}, {2.79, {0.3, 0.3}, 0.0}));
  s.effects.insert(cases::Effect::MaterialInterfaces);
  s.tvd.interfaces = cases::InterfaceMode::WholeCell;  // the study's mode (cut cells: test_cut_cells.cpp)
  TvdSolver solver(s);
  const Totals t0 = solver.totals();
  const double a0 = solver.markers().area(0);
  runTo(solver, 2.0);  // 0.6 cm along each axis = 24 cells
  const double aMid = solver.markers().area(0);
  expectLedgerCloses(solver, t0, "outbound");
  // Uniform motion: the state must stay uniform (no pressure, exactly the body's velocity).
  double vErr = 0.0;
  const auto& U = solver.conserved();
  for (std::size_t c = 0; c < U.rho.size(); ++c)
    if (solver.owner()[c] == 0)
      vErr = std::max({vErr, std::abs(U.mx[c] / U.rho[c] - 0.3), std::abs(U.rho[c] - 2.79)});
  EXPECT_LT(vErr, 1e-12);
  // Reverse (outside the solver: the ledger restarts from the reversed totals).
  Conserved& W = solver.conservedForTesting();
  for (std::size_t c = 0; c < W.rho.size(); ++c) {
    W.mx[c] = -W.mx[c];
    W.mz[c] = -W.mz[c];
  }
  const Totals tRev = solver.totals();
  const Ledger lRev = solver.ledger();
  runTo(solver, 4.0);
  const double a1 = solver.markers().area(0);
  double cx = 0.0, cz = 0.0, m = 0.0;
  for (std::size_t c = 0; c < U.rho.size(); ++c) {
    const double x = s.domain.xmin + (static_cast<double>(c % solver.grid().nx) + 0.5) * 0.025;
    const double z = s.domain.zmin + (static_cast<double>(c / solver.grid().nx) + 0.5) * 0.025;
    cx += U.rho[c] * x;
    cz += U.rho[c] * z;
    m += U.rho[c];
  }
  cx /= m;
  cz /= m;
  const Totals t1 = solver.totals();
  std::printf(
      "disk out and back: area %.3e -> %.3e -> %.3e (rel. change %.2e), mass change "
      "%.2e, centroid (%.5f, %.5f), %ld owner changes\n",
      a0, aMid, a1, a1 / a0 - 1, t1.mass / t0.mass - 1, cx, cz, solver.ownerChanges());
  // Area: the redistribution inserts markers on the chords (no change) and removes markers
  // whose neighbours are closer than 0.25 cells (chord error ~ spacing^2 curvature per removal,
  // ~1e-5 of the area each): 1e-3 allows ~100 removals.
  EXPECT_NEAR(a1 / a0, 1.0, 1e-3);
  EXPECT_NEAR(cx, -0.3, 0.25 * 0.025);  // back to its start within a quarter cell
  EXPECT_NEAR(cz, -0.3, 0.25 * 0.025);
  // Mass: emptying and filling whole cells balance on average; what remains is the mass of
  // the cells in flight at the end, bounded by half a ring of surface cells,
  // pi R / h * rho h^2 / 2 of pi R^2 rho: h / (2 R) = 5%.
  EXPECT_LT(std::abs(t1.mass / t0.mass - 1), 0.025 / (2 * R));
  EXPECT_GT(solver.ownerChanges(), 100);
  const Budget b1 = solver.ledger().sum(), b0 = lRev.sum();
  EXPECT_NEAR(t1.mass - tRev.mass, b1.mass - b0.mass, 1e-12 * t0.mass);
  EXPECT_NEAR(t1.energy() - tRev.energy(), b1.energy - b0.energy, 1e-12 * t0.energy());
  EXPECT_NEAR(t1.momentumZ - tRev.momentumZ, b1.momentumZ - b0.momentumZ, 1e-12 * t0.mass);
  expectSpacing(solver);
}

// CASES.md two-material slip: an aluminium block slides at 0.5 cm/us over a copper block at
// rest, both at P = 0, along an interface at 45 degrees to the grid (the cells see a
// staircase). Across the contact the solver exchanges only the pressure of a Riemann problem
// along the marker normal (here zero), and each side advects with its own tangential
// velocity, so nothing mixes: near the contact the states stay exact. The same blocks made of
// one material are one medium (no contact treatment): the staircase and the TVD flux's
// numerical viscosity smear the shear there and raise spurious pressure.
double slipError(bool twoMaterials) {
  const double h = 0.02, v = 0.5 / std::sqrt(2.0);
  cases::Scene s = baseScene(-1.6, 1.6, -1.6, 1.6, h);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.materials.push_back(material("copper", eos::MieGruneisen{}));
  s.effects.insert(cases::Effect::TensionCutoff);
  const double rhoB = twoMaterials ? 8.93 : 2.79;
  s.bodies.push_back(body("slider", 0,
                          cases::Polygon{{{-0.7, -0.7}, {0.7, 0.7}, {0, 1.4}, {-1.4, 0}}},
                          {2.79, {v, v}, 0.0}));
  s.bodies.push_back(body("base", twoMaterials ? 1 : 0,
                          cases::Polygon{{{-0.7, -0.7}, {0, -1.4}, {1.4, 0}, {0.7, 0.7}}},
                          {rhoB, {}, 0.0}));
  s.effects.insert(cases::Effect::MaterialInterfaces);
  s.tvd.interfaces = cases::InterfaceMode::WholeCell;  // the study's mode (cut cells: test_cut_cells.cpp)
  TvdSolver solver(s);
  runTo(solver, 0.4);
  // Cells within 0.3 cm of the centre of the contact (0.5 cm from the block corners, which
  // the release waves from the ends reach only after 0.4 us x 0.52 cm/us = 0.2 cm).
  double err = 0.0;
  const int nx = solver.grid().nx;
  const auto& U = solver.conserved();
  for (std::size_t c = 0; c < U.rho.size(); ++c) {
    const double x = -1.6 + (static_cast<double>(c % nx) + 0.5) * h;
    const double z = -1.6 + (static_cast<double>(c / nx) + 0.5) * h;
    if (std::hypot(x, z) > 0.3) continue;
    const bool slider = solver.owner()[c] == 0;
    const double rho0 = slider ? 2.79 : rhoB, vx = slider ? v : 0.0;
    err = std::max({err, std::abs(U.rho[c] / rho0 - 1), std::abs(U.mx[c] / U.rho[c] - vx),
                    std::abs(U.mz[c] / U.rho[c] - vx)});
  }
  return err;
}

TEST(TvdMarkerFlow, TwoMaterialContactSlips) {
  const double two = slipError(true), one = slipError(false);
  std::printf(
      "slip at 45 degrees: max state error near the contact %.2e (Al on Cu, contact "
      "flux), %.2e (one material, no contact treatment)\n",
      two, one);
  // Any mixing across the contact is >= 1e-3. Without the tension cut-off on copper the states
  // are exact up to round-off (the star state rebuilds the velocity from its normal and
  // tangential parts every step: a few 1e-11 after 100 steps); the cut-off, which a scene
  // switches for every material at once, zeroes copper's pressure derivatives wherever
  // round-off makes its P < 0 and leaves 4.8e-7. (Before cases::resolveMaterials this test ran
  // Al cut and Cu uncut, which no scene file can give. With the cut-off on neither material the
  // error is 7.4e-3: aluminium carrying tension at the contact is not exact; measured, open.)
  EXPECT_LT(two, 1e-6);
  EXPECT_GT(one, 1e-2);
}

}  // namespace
}  // namespace hvi::tvd
