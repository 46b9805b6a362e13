//! @file Conservative cut-cell interfaces (docs/tvd.md, "Conservative interfaces"): mass of
//! every material to round-off, rest, slip, uniform motion, restart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

std::vector<double> phaseMasses(const TvdSolver& s) {
  const Phases& ph = s.phases();
  std::vector<double> m(static_cast<std::size_t>(ph.count), 0.0);
  for (int p = 0; p < ph.count; ++p)
    for (long c = 0; c < s.grid().cells(); ++c)
      m[static_cast<std::size_t>(p)] +=
          ph.q[static_cast<std::size_t>(p)].rho[static_cast<std::size_t>(c)] * s.cellVolume(c);
  return m;
}

double maxSpeed(const TvdSolver& s) {
  const Phases& ph = s.phases();
  double v = 0.0;
  for (int p = 0; p < ph.count; ++p) {
    const Conserved& q = ph.q[static_cast<std::size_t>(p)];
    for (std::size_t c = 0; c < q.rho.size(); ++c)
      if (q.rho[c] > 0.0) v = std::max(v, std::hypot(q.mx[c], q.mz[c]) / q.rho[c]);
  }
  return v;
}

cases::Scene cutScene(double xmin, double xmax, double zmin, double zmax, double h,
                      Geometry g = Geometry::Planar) {
  cases::Scene s = baseScene(xmin, xmax, zmin, zmax, h, g);
  s.effects.insert(cases::Effect::MaterialInterfaces);
  s.effects.insert(cases::Effect::TensionCutoff);
  s.tvd.interfaces = cases::InterfaceMode::Conservative;
  return s;
}

TEST(TvdCutCells, FreePlateStaysAtRest) {
  cases::Scene s = cutScene(-1.0, 1.0, -1.0, 1.0, 0.05);
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.bodies.push_back(
      body("plate", 0, cases::Rect{-0.513, 0.488, -0.217, 0.131}, {2.79, {0.0, 0.0}, 0.0}));
  TvdSolver solver(s);
  ASSERT_TRUE(solver.cutCells());
  const auto m0 = phaseMasses(solver);
  for (int n = 0; n < 200; ++n) solver.advance(1e9);
  const auto m1 = phaseMasses(solver);
  std::printf("  mass change %.3e, max speed %.3e\n", m1[0] / m0[0] - 1.0, maxSpeed(solver));
  EXPECT_NEAR(m1[0], m0[0], 1e-12 * m0[0]);
  EXPECT_LT(maxSpeed(solver), 1e-10 * 0.5);
}

TEST(TvdCutCells, ImpactConservesEveryMaterial) {
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const bool rz = g == Geometry::Axisymmetric;
    cases::Scene s = cutScene(rz ? 0.0 : -1.2, 1.2, -1.0, 1.0, 0.04, g);
    // Walls all round: nothing leaves, so every material's mass is a constant of the run.
    for (auto& b : s.domain.boundary) b = cases::Boundary::Wall;
    if (rz) s.domain.boundary[0] = cases::Boundary::Axis;
    s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
    s.materials.push_back(material("copper", eos::aluminiumStudy()));
    s.bodies.push_back(
        body("plate", 0, cases::Rect{-1.0, 1.0, -0.31, 0.013}, {2.79, {0.0, 0.0}, 0.0}));
    s.bodies.push_back(
        body("disk", 1, cases::Disk{{0.0, 0.263}, 0.25}, {2.79, {0.0, -0.5}, 0.0}));
    TvdSolver solver(s);
    const auto m0 = phaseMasses(solver);
    const Totals t0 = solver.totals();
    while (solver.time() < 3.0) solver.advance(3.0);
    const auto m1 = phaseMasses(solver);
    const Totals t1 = solver.totals();
    std::printf("  %s: steps %ld, mass change %.3e / %.3e, energy %.3e\n", rz ? "r-z" : "planar",
                solver.step(), m1[0] / m0[0] - 1.0, m1[1] / m0[1] - 1.0,
                t1.energy() / t0.energy() - 1.0);
    EXPECT_NEAR(m1[0], m0[0], 1e-12 * m0[0]);
    EXPECT_NEAR(m1[1], m0[1], 1e-12 * m0[1]);
  }
}

}  // namespace
}  // namespace hvi::tvd
