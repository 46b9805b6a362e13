//! @file Uniform motion in the conservative cut-cell mode (issue 13, "Slip"; docs/tvd.md,
//! "Uniform motion"): a body of uniform state moving uniformly must keep its state to round-off.
//! Every face then carries the same flux per unit aperture, every phase cell's working part
//! moves with the same velocity, and whatever the sweeps' swept volumes miss of the marker
//! geometry the settle moves at the donor's own state, so nothing can make two cells of the
//! body differ: any difference beyond round-off is a defect, not a truncation error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// Largest relative error of every phase's state (density against rho0[p], velocity against v)
// over every cell the phase occupies, cut cells included.
double stateError(const TvdSolver& solver, const std::vector<double>& rho0, Vec2 v) {
  const Phases& ph = solver.phases();
  const double speed = std::hypot(v.x, v.z);
  double err = 0.0;
  for (int p = 0; p < ph.count; ++p) {
    const Conserved& q = ph.q[static_cast<std::size_t>(p)];
    const auto& a = ph.alpha[static_cast<std::size_t>(p)];
    for (std::size_t c = 0; c < q.rho.size(); ++c) {
      if (!(a[c] >= kPhaseAbsent)) continue;
      err = std::max({err, std::abs(q.rho[c] / a[c] / rho0[static_cast<std::size_t>(p)] - 1),
                      std::abs(q.mx[c] / q.rho[c] - v.x) / speed,
                      std::abs(q.mz[c] / q.rho[c] - v.z) / speed});
    }
  }
  return err;
}

// Round-off of ~100 steps of fluxes, fractions and settles (each ~1e-16 relative): 1e-12, as
// TvdCutCells.BlockCarriedExactly.
constexpr double kRoundOff = 1e-12;

// A block offset from the grid carried through vacuum along x, along z and diagonally (the
// diagonal case reached 3.8e-3 within 12 steps before the settle could route a mismatch across
// the body: the split sweeps' swept volumes miss the marker geometry at the block's corners with
// opposite signs on opposite edges, docs/tvd.md "Uniform motion").
TEST(TvdCutMotion, BlockKeepsItsStateInAnyDirection) {
  const double h = 0.05;
  for (const Vec2 v : {Vec2{0.5, 0.0}, Vec2{0.0, 0.5}, Vec2{0.4, 0.3}, Vec2{-0.3, 0.4}}) {
    cases::Scene s = cutScene(-0.8, 0.8, -0.8, 0.8, h);
    s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
    s.bodies.push_back(body("block", 0, cases::Rect{-0.413, 0.037, -0.387, 0.063}, {2.79, v, 0.0}));
    TvdSolver solver(s);
    const auto m0 = phaseMasses(solver);
    runTo(solver, 0.7);  // 0.35 cm: 7 cells, every edge crosses several faces
    const double err = stateError(solver, {2.79}, v);
    std::printf("  v = (%.1f, %.1f): %ld steps, state error %.3e, mass change %.3e\n", v.x, v.z,
                solver.step(), err, phaseMasses(solver)[0] / m0[0] - 1.0);
    EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
    EXPECT_LT(err, kRoundOff);
  }
}

// The same block inside a plate of another material (Mie-Gruneisen copper), both at rest
// density and P = 0, moving together diagonally: the block's lines are an interface the exchange
// sees on both sides at the same pressure and velocity, so it must pass nothing.
TEST(TvdCutMotion, BlockInsideAnotherMaterialKeepsItsState) {
  const double h = 0.05;
  const Vec2 v{0.4, 0.3};
  cases::Scene s = cutScene(-1.0, 1.0, -1.0, 1.0, h);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.materials.push_back(material("copper", eos::MieGruneisen{}));
  s.bodies.push_back(body("block", 0, cases::Rect{-0.413, 0.037, -0.387, 0.063}, {2.79, v, 0.0}));
  // The plate wraps the block: a C open to the right, closed by a second copper body.
  s.bodies.push_back(body("plate", 1,
                          cases::Polygon{{{-0.713, -0.687},
                                          {0.337, -0.687},
                                          {0.337, -0.387},
                                          {-0.413, -0.387},
                                          {-0.413, 0.063},
                                          {0.337, 0.063},
                                          {0.337, 0.363},
                                          {-0.713, 0.363}}},
                          {8.93, v, 0.0}));
  s.bodies.push_back(body("plug", 1, cases::Rect{0.037, 0.337, -0.387, 0.063}, {8.93, v, 0.0}));
  TvdSolver solver(s);
  const auto m0 = phaseMasses(solver);
  runTo(solver, 0.5);
  const double err = stateError(solver, {2.79, 8.93, 8.93}, v);
  const auto m1 = phaseMasses(solver);
  std::printf("  %ld steps: state error %.3e, mass change %.3e / %.3e\n", solver.step(), err,
              m1[0] / m0[0] - 1.0, m1[1] / m0[1] - 1.0);
  for (int p = 0; p < 3; ++p) EXPECT_NEAR(m1[p], m0[p], 1e-12 * m0[p]);
  EXPECT_LT(err, kRoundOff);
}

// r-z: a cylinder on the axis carried along it (its radial faces see no radial velocity, its
// axial faces carry r-weighted fluxes; the settle moves volumes weighted by the cell volumes).
TEST(TvdCutMotion, CylinderOnTheAxisKeepsItsState) {
  const double h = 0.05;
  const Vec2 v{0.0, 0.5};
  cases::Scene s = cutScene(0.0, 0.8, -0.8, 0.8, h, Geometry::Axisymmetric);
  s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.bodies.push_back(body("cylinder", 0, cases::Rect{0.0, 0.237, -0.387, 0.063}, {2.79, v, 0.0}));
  TvdSolver solver(s);
  const auto m0 = phaseMasses(solver);
  runTo(solver, 0.7);
  const double err = stateError(solver, {2.79}, v);
  std::printf("  r-z: %ld steps, state error %.3e, mass change %.3e\n", solver.step(), err,
              phaseMasses(solver)[0] / m0[0] - 1.0);
  EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
  EXPECT_LT(err, kRoundOff);
}

// A disk carried diagonally through vacuum (the 20 diameters along x are
// TvdCutCells.DiskCarriedTwentyDiameters): 4 diameters at (0.4, 0.3) cm/us, every part of its
// outline sliding along x and z faces at once.
TEST(TvdCutMotion, DiskCarriedDiagonally) {
  const double h = 0.05, R = 0.25;
  const Vec2 v{0.4, 0.3};
  cases::Scene s = cutScene(-0.4, 2.0, -0.4, 1.6, h);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.bodies.push_back(body("disk", 0, cases::Disk{{0.013, 0.021}, R}, {2.79, v, 0.0}));
  TvdSolver solver(s);
  const auto m0 = phaseMasses(solver);
  runTo(solver, 4.0);  // 2 cm: 4 diameters
  const double err = stateError(solver, {2.79}, v);
  std::printf("  %ld steps: state error %.3e, mass change %.3e\n", solver.step(), err,
              phaseMasses(solver)[0] / m0[0] - 1.0);
  EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
  EXPECT_LT(err, kRoundOff);
}

// r-z: a sphere on the axis carried along it (the disk's r-z counterpart: curved outline, cell
// volumes growing with r).
TEST(TvdCutMotion, SphereOnTheAxisKeepsItsState) {
  const double h = 0.05, R = 0.25;
  const Vec2 v{0.0, 0.5};
  cases::Scene s = cutScene(0.0, 0.6, -0.4, 1.6, h, Geometry::Axisymmetric);
  s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.bodies.push_back(body("sphere", 0, cases::Disk{{0.0, 0.021}, R}, {2.79, v, 0.0}));
  TvdSolver solver(s);
  const auto m0 = phaseMasses(solver);
  runTo(solver, 2.0);  // 1 cm: 2 diameters
  const double err = stateError(solver, {2.79}, v);
  std::printf("  r-z sphere: %ld steps, state error %.3e, mass change %.3e\n", solver.step(), err,
              phaseMasses(solver)[0] / m0[0] - 1.0);
  EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
  EXPECT_LT(err, kRoundOff);
}

}  // namespace
}  // namespace hvi::tvd

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

// A block whose outline lies exactly on grid faces (as the shield generator's plates do: their
// thickness and position are whole cells), carried through vacuum along x, along z and
// diagonally. Every edge starts on a face the phase wets from one side only: the first step must
// move the phase into the empty cells beyond its leading faces (and out of the cells behind its
// trailing faces) as it does when the edge lies inside a cell (docs/tvd.md, "Interfaces on cell
// faces"). Cells of 1/16 cm on a domain of +-1 cm: every face and edge exactly representable.
// Before the kernel opened such faces: state errors 6.4e-2 (along x), 6.1e-2 (along z) and
// 1.6e-1 (diagonally) after 0.7 us; the same block off the faces is exact (the test above).
TEST(TvdCutMotion, BlockOnGridFacesKeepsItsState) {
  const double h = 0.0625;
  for (const Vec2 v : {Vec2{0.5, 0.0}, Vec2{0.0, 0.5}, Vec2{0.4, 0.3}, Vec2{-0.3, 0.4}}) {
    cases::Scene s = cutScene(-1.0, 1.0, -1.0, 1.0, h);
    s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
    s.bodies.push_back(body("block", 0, cases::Rect{-0.5, 0.0625, -0.4375, 0.125}, {2.79, v, 0.0}));
    TvdSolver solver(s);
    const auto m0 = phaseMasses(solver);
    runTo(solver, 0.7);
    const double err = stateError(solver, {2.79}, v);
    std::printf("  on faces, v = (%.1f, %.1f): %ld steps, state error %.3e, mass change %.3e\n",
                v.x, v.z, solver.step(), err, phaseMasses(solver)[0] / m0[0] - 1.0);
    EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
    EXPECT_LT(err, kRoundOff);
  }
  // r-z: a cylinder on the axis, its radius and both ends on faces, carried along the axis
  // (the radial lines see its side on a face at rest; the axial lines open the cells ahead).
  cases::Scene s = cutScene(0.0, 1.0, -1.0, 1.0, h, Geometry::Axisymmetric);
  s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.bodies.push_back(
      body("cylinder", 0, cases::Rect{0.0, 0.25, -0.4375, 0.125}, {2.79, {0.0, 0.5}, 0.0}));
  TvdSolver solver(s);
  const auto m0 = phaseMasses(solver);
  runTo(solver, 0.7);
  const double err = stateError(solver, {2.79}, {0.0, 0.5});
  std::printf("  on faces, r-z cylinder: %ld steps, state error %.3e, mass change %.3e\n",
              solver.step(), err, phaseMasses(solver)[0] / m0[0] - 1.0);
  EXPECT_NEAR(phaseMasses(solver)[0], m0[0], 1e-12 * m0[0]);
  EXPECT_LT(err, kRoundOff);
}

}  // namespace
}  // namespace hvi::tvd
