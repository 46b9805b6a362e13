//! @file Impacts with marker lines: the ledger closes, the conservation error stays bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

struct Drift {
  double mass = 0.0, energy = 0.0;            // largest |relative change| of the totals
  double massBound = 0.0, energyBound = 0.0;  // the same for the bounds below
};

// Content of the boundary layer: mass and energy of the owned cells that have a face
// neighbour in vacuum or in an object of another material. Filling or emptying such a cell
// is off by at most the part of it that crossed its face since the marker line passed its
// centre, half a cell's content, so at any moment the booked changes are bounded by half this
// layer's content (errors of successive cells cancel in part, so the drift sits well below).
void boundaryLayer(const TvdSolver& s, double& mass, double& energy) {
  const int nx = s.grid().nx, nz = s.grid().nz;
  const auto& own = s.owner();
  const auto& mat = s.objectMaterial();
  const auto& U = s.conserved();
  mass = energy = 0.0;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const long c = static_cast<long>(k) * nx + i;
      const int o = own[static_cast<std::size_t>(c)];
      if (o < 0) continue;
      bool edge = false;
      const int di[4] = {-1, 1, 0, 0}, dk[4] = {0, 0, -1, 1};
      for (int q = 0; q < 4; ++q) {
        const int ii = i + di[q], kk = k + dk[q];
        if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
        const int n = own[static_cast<std::size_t>(static_cast<long>(kk) * nx + ii)];
        edge |= n < 0 || mat[static_cast<std::size_t>(n)] != mat[static_cast<std::size_t>(o)];
      }
      if (!edge) continue;
      mass += U.rho[static_cast<std::size_t>(c)] * s.cellVolume(c);
      energy += U.E[static_cast<std::size_t>(c)] * s.cellVolume(c);
    }
}

// Runs to t, checking at every report time that the totals change exactly as booked and
// that the drift stays below half the boundary layer's content.
Drift runAndCheck(const cases::Scene& s, double tEnd, const char* what) {
  TvdSolver solver(s);
  const Totals t0 = solver.totals();
  Drift d;
  for (int r = 1; r <= 8; ++r) {
    runTo(solver, tEnd * r / 8);
    const Totals tt = solver.totals();
    const Budget b = solver.ledger().sum();
    EXPECT_NEAR(tt.mass - t0.mass, b.mass, 1e-11 * t0.mass) << what;
    EXPECT_NEAR(tt.energy() - t0.energy(), b.energy, 1e-11 * t0.energy()) << what;
    double layerMass, layerEnergy;
    boundaryLayer(solver, layerMass, layerEnergy);
    EXPECT_LE(std::abs(tt.mass - t0.mass), 0.5 * layerMass) << what << " t=" << solver.time();
    EXPECT_LE(std::abs(tt.energy() - t0.energy()), 0.5 * layerEnergy) << what;
    d.mass = std::max(d.mass, std::abs(tt.mass / t0.mass - 1));
    d.energy = std::max(d.energy, std::abs(tt.energy() / t0.energy() - 1));
    d.massBound = std::max(d.massBound, 0.5 * layerMass / t0.mass);
    d.energyBound = std::max(d.energyBound, 0.5 * layerEnergy / t0.energy());
  }
  const Ledger& L = solver.ledger();
  std::printf(
      "%s: max |relative drift| mass %.2e (bound %.2e), energy %.2e (bound %.2e) over "
      "%ld steps; booked: owner changes %.2e of the mass, interfaces %.2e\n",
      what, d.mass, d.massBound, d.energy, d.energyBound, solver.step(),
      L.ownerChanges.mass / t0.mass, L.interfaces.mass / t0.mass);
  return d;
}

cases::Scene impactScene(Geometry g, bool copperStriker, double h) {
  const bool rz = g == Geometry::Axisymmetric;
  cases::Scene s = baseScene(rz ? 0.0 : -2.0, 2.0, -2.0, 1.2, h, g);
  if (rz) s.domain.boundary[0] = cases::Boundary::Axis;
  s.materials.push_back(material("aluminium", eos::aluminiumStudy()));
  s.materials.push_back(material("copper", eos::MieGruneisen{}));
  // The study's aluminium (a Scene built in code gets the cut-off only by naming it).
  s.effects.insert(cases::Effect::TensionCutoff);
  s.bodies.push_back(
      body("shield", 0, cases::Rect{rz ? 0.0 : -1.6, 1.6, -0.3, 0.0}, {2.79, {}, 0.0}));
  s.bodies.push_back(body("striker", copperStriker ? 1 : 0, cases::Disk{{0.0, 0.4}, 0.4},
                          {copperStriker ? 8.93 : 2.79, {0, -0.67}, 0.0}));
  s.effects.insert(cases::Effect::MaterialInterfaces);
  return s;
}

// Aluminium on aluminium (the study's pairing): one medium, so only the free surfaces move
// mass by emptying and filling cells.
TEST(TvdMarkerImpact, AluminiumOnAluminiumPlanar) {
  runAndCheck(impactScene(Geometry::Planar, false, 0.04), 2.0, "Al->Al planar");
}

TEST(TvdMarkerImpact, AluminiumOnAluminiumRz) {
  runAndCheck(impactScene(Geometry::Axisymmetric, false, 0.04), 2.0, "Al->Al r-z");
}

// Copper on aluminium: two materials, so the contact has its own two-sided flux and moving it
// re-initialises cells from the new owner's neighbours (not conservative, booked).
TEST(TvdMarkerImpact, CopperOnAluminiumPlanar) {
  runAndCheck(impactScene(Geometry::Planar, true, 0.04), 1.5, "Cu->Al planar");
}

}  // namespace
}  // namespace hvi::tvd
