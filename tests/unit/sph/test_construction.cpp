//! @file SphSolver from given particles: the same solver as from the scene, every particle
//! array carried through the stepper, snapshot units and phase fields.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "hvi/sph/fill.hpp"
#include "hvi/sph/sph.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

cases::Scene plateScene(Geometry g, std::set<Effect> effects) {
  cases::Scene s;
  s.path = "test";
  s.geometry = g;
  s.domain = {g == Geometry::Planar ? -0.3 : 0.0, 0.3, -0.2, 0.3, {}};
  if (g == Geometry::Axisymmetric) s.domain.boundary[0] = cases::Boundary::Axis;
  s.sph.spacing = 0.02;
  s.effects = std::move(effects);
  s.materials = {{"aluminium", eos::aluminiumStudy()}};
  cases::Body plate;
  plate.name = "plate";
  plate.material = 0;
  plate.shape = cases::Rect{g == Geometry::Planar ? -0.2 : 0.0, 0.2, -0.06, 0.0};
  plate.velocity = {0.0, -0.3};
  plate.density = 2.79;
  s.bodies = {plate};
  s.tEnd = 1.0;
  return s;
}

std::string checkpointAfter(Solver& solver, int steps) {
  for (int k = 0; k < steps; ++k) solver.advance(1e9);
  std::stringstream out;
  solver.writeCheckpoint(out);
  return out.str();
}

// The scene constructor is the particle constructor given fillBodies(scene): one solver.
TEST(Construction, FromTheFilledParticlesIsTheSolverOfTheScene) {
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const auto s = plateScene(g, {Effect::ArtificialViscosity, Effect::MassAdjustment});
    SphSolver fromScene(s);
    SphSolver fromParticles(s, fillBodies(s));
    EXPECT_EQ(fromScene.massAdjustment().iterations, fromParticles.massAdjustment().iterations);
    EXPECT_GT(fromParticles.massAdjustment().iterations, 0);
    EXPECT_EQ(checkpointAfter(fromScene, 5), checkpointAfter(fromParticles, 5));
  }
}

// Every ParticleSystem array goes in and comes out (stepper_impl.hpp's field lists).
TEST(Construction, EveryParticleArrayIsCarried) {
  const auto s = plateScene(Geometry::Planar, {});
  ParticleSystem ps;
  for (int i = 0; i < 3; ++i)
    ps.push(0.1 * i, 0.01 * i, 0.001 * i, -0.002 * i, 2.7 + 0.01 * i, 1e-4 * (i + 1),
            1e-3 * (i + 1), 0.03 + 0.001 * i, 2.79 - 0.001 * i, 0, 0, 10 + i);
  const SphSolver solver(s, ps);
  const ParticleSystem out = solver.stepper().particles();
  const auto same = [&](auto member) { EXPECT_EQ(out.*member, ps.*member); };
  using P = ParticleSystem;
  same(&P::x), same(&P::z), same(&P::vx), same(&P::vz), same(&P::e), same(&P::m), same(&P::h);
  same(&P::rhoRef), same(&P::material), same(&P::object), same(&P::id);
  ASSERT_EQ(out.rho.size(), 3u);  // derived by the corrector: summation density, EOS
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_GT(out.rho[i], 0.0);
    EXPECT_DOUBLE_EQ(out.p[i], eos::pressure(sceneMaterials(s)[0], out.rho[i], out.e[i]));
    EXPECT_GT(out.c[i], 0.0);
  }
}

// Particles below e1, halfway between e1 and e2 and above e2: phases 0, 1, 2 and fractions
// 0, 0.5, 1 (eos::phaseState, as in TVD); the mass is a ring's in r-z, per cm in planar.
TEST(Construction, SnapshotPhaseFieldsAndMassUnit) {
  const eos::Tillotson al = eos::aluminiumStudy();
  const double es[3] = {0.5 * al.e1, 0.5 * (al.e1 + al.e2), 2.0 * al.e2};
  for (Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const auto s = plateScene(g, {Effect::PhaseBookkeeping});
    ParticleSystem ps;
    for (int i = 0; i < 3; ++i)
      ps.push(0.05 + 0.1 * i, 0.0, 0.0, 0.0, 2.79, es[i], 1e-3, 0.03, 2.79, 0, 0, i);
    const Snapshot snap = SphSolver(s, ps).snapshot();
    const Field* frac = snap.find("vapour_fraction");
    const Field* phase = snap.find("phase");
    ASSERT_NE(frac, nullptr);
    ASSERT_NE(phase, nullptr);
    ASSERT_EQ(frac->data.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(frac->data[i], 0.5 * static_cast<double>(i));
      EXPECT_EQ(phase->data[i], static_cast<double>(i));
    }
    ASSERT_NE(snap.find("mass"), nullptr);
    EXPECT_EQ(snap.find("mass")->unit, g == Geometry::Axisymmetric ? "g" : "g/cm");
  }
}

}  // namespace
}  // namespace hvi::sph
