//! @file Initial state of a body with a radial velocity field (the Noh problems).
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/common/stop_flag.hpp"

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

cases::Body radialDisk(double speed, bool markers, cases::Scene& s) {
  cases::Body b = body("gas", 0, cases::Disk{{0.0, 0.0}, 0.5}, {1.0, {}, 0.0});
  b.radial = true;
  b.radialSpeed = speed;
  if (markers) s.effects.insert(cases::Effect::MaterialInterfaces);
  return b;
}

// Cold gas converging on the centre of a disk (planar: cylindrical Noh in x-z). Momentum is 0
// by symmetry. Without markers a cell averages 4 x 4 samples: the kinetic energy of the mean
// velocity falls short of M u0^2 / 2 by var(angle) = 0.078 (h/r)^2 in a cell at radius r, over
// the disk 0.156 (h/R)^2 ln(2R/h) = 1.4e-3 (2e-3 allowed for the centre cells, where the
// small-angle estimate fails); the cells' velocity spread must not become heat, so the internal
// energy is only that of the edge cells' mix with the vacuum gas (rho 5e-7, at rest): at most
// 15 x 5e-7 of a cell's kinetic energy (a cell with 1 of 16 samples in the disk). With markers
// each cell takes the velocity at its centre: kinetic energy exact.
TEST(TvdRadialInit, ConvergingDiskHasNoNetMomentumAndNoHeat) {
  for (bool markers : {false, true}) {
    SCOPED_TRACE(markers ? "markers" : "no markers");
    cases::Scene s = baseScene(-1.0, 1.0, -1.0, 1.0, 0.025);
    s.materials.push_back(material("gas", eos::IdealGas{5.0 / 3.0, 1.0}));
    s.bodies.push_back(radialDisk(-1.0, markers, s));
    const TvdSolver solver(s);
    const Totals t = solver.totals();
    std::printf("radial disk (%s): M %.6f, P (%.2e, %.2e), KE / (M u0^2/2) - 1 = %.3e, IE %.2e\n",
                markers ? "markers" : "no markers", t.mass, t.momentumX, t.momentumZ,
                t.kinetic / (0.5 * t.mass) - 1, t.internal);
    EXPECT_LT(std::abs(t.momentumX), 1e-13 * t.mass);
    EXPECT_LT(std::abs(t.momentumZ), 1e-13 * t.mass);
    EXPECT_LT(std::abs(t.internal), 15 * 5e-7 * t.kinetic);
    EXPECT_LT(t.kinetic, 0.5 * t.mass * (1 + 1e-14));
    EXPECT_GT(t.kinetic, 0.5 * t.mass * (1 - (markers ? 1e-14 : 2e-3)));
  }
}

// r-z: v = (u0, 0) off the axis, so every cell (all its samples have r > 0) moves at exactly u0.
TEST(TvdRadialInit, StreamOntoTheAxisIsUniformOffIt) {
  cases::Scene s = baseScene(0.0, 1.0, 0.0, 0.1, 0.025, Geometry::Axisymmetric);
  s.domain.boundary = {cases::Boundary::Axis, cases::Boundary::Outflow, cases::Boundary::Wall,
                       cases::Boundary::Wall};
  s.materials.push_back(material("gas", eos::IdealGas{5.0 / 3.0, 1.0}));
  cases::Body b = body("gas", 0, cases::Rect{0.0, 1.0, 0.0, 0.1}, {1.0, {}, 0.0});
  b.radial = true;
  b.radialSpeed = -1.0;
  s.bodies.push_back(b);
  const TvdSolver solver(s);
  const auto& U = solver.conserved();
  for (std::size_t c = 0; c < U.rho.size(); ++c) {
    EXPECT_EQ(U.rho[c], 1.0);
    EXPECT_EQ(U.mx[c], -1.0);
    EXPECT_EQ(U.mz[c], 0.0);
  }
}

// SIGINT/SIGTERM while the grid is filled (up to 5e7 cells): set-up ends with StopDuringSetUp,
// which `hvi run` reports as exit 130 with nothing to checkpoint (issue 11, item 7).
TEST(TvdRadialInit, StopRequestEndsTheSetUp) {
  for (bool markers : {false, true}) {
    SCOPED_TRACE(markers ? "markers" : "no markers");
    cases::Scene s = baseScene(-1.0, 1.0, -1.0, 1.0, 0.05);
    s.materials.push_back(material("gas", eos::IdealGas{5.0 / 3.0, 1.0}));
    s.bodies.push_back(radialDisk(-1.0, markers, s));
    requestStop();
    EXPECT_THROW(TvdSolver{s}, StopDuringSetUp);
    clearStop();
    EXPECT_NO_THROW(TvdSolver{s});
  }
}

}  // namespace
}  // namespace hvi::tvd
