//! @file createSolver: scene checks, effects wiring, snapshot contents.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hvi/common/error.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

cases::Scene smallImpact(Geometry g, std::initializer_list<Effect> effects) {
  auto s = test::baseScene(g, g == Geometry::Planar ? -0.3 : 0.0, 0.3, -0.2, 0.3, 0.02, effects);
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.1}, 0.1, {0.0, -0.67}),
              test::rectBody("shield", 0, g == Geometry::Planar ? -0.24 : 0.0, 0.24, -0.06, 0.0)};
  test::resolveDensities(s);
  return s;
}

TEST(Solver, RzNeedsTheAxisAtXZero) {
  auto s = smallImpact(Geometry::Axisymmetric, {});
  s.domain.boundary[0] = cases::Boundary::Wall;
  EXPECT_THROW(createSolver(s), InputError);
  s = smallImpact(Geometry::Planar, {});
  s.domain.boundary[3] = cases::Boundary::Axis;
  EXPECT_THROW(createSolver(s), InputError);
}

// docs/sph-rz.md, "Which form": auto is the symmetric form, the ring form with strength (whose
// stress terms exist for the ring form only); asking for symmetric with strength names the key.
TEST(Solver, RzFormAutoAndItsStrengthLimit) {
  auto s = smallImpact(Geometry::Axisymmetric, {});
  EXPECT_EQ(stepperConfig(s).rzForm, cases::RzForm::Symmetric);
  EXPECT_EQ(massAdjustOptions(s).rzForm, cases::RzForm::Symmetric);
  s.effects.insert(Effect::Strength);
  EXPECT_EQ(stepperConfig(s).rzForm, cases::RzForm::Ring);
  EXPECT_EQ(massAdjustOptions(s).rzForm, cases::RzForm::Ring);
  s.sph.rzForm = cases::RzForm::Symmetric;
  try {
    (void)createSolver(s);
    ADD_FAILURE() << "symmetric with strength was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sph.rz_form"), std::string::npos) << e.what();
  }
}

// sph.rz_viscous_hoop (docs/sph-rz.md, "The viscous hoop") exists in the symmetric r-z form
// only: with the ring form (or auto with strength) the scene is refused naming the key.
TEST(Solver, RzViscousHoopNeedsTheSymmetricForm) {
  auto s = smallImpact(Geometry::Axisymmetric, {});
  s.sph.rzViscousHoop = 0.25;
  EXPECT_EQ(stepperConfig(s).rzViscousHoop, 0.25);
  EXPECT_NO_THROW((void)createSolver(s));
  s.sph.rzForm = cases::RzForm::Ring;
  try {
    (void)createSolver(s);
    ADD_FAILURE() << "the viscous hoop with the ring form was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sph.rz_viscous_hoop"), std::string::npos) << e.what();
  }
}

TEST(Solver, TensionCutoffFollowsTheEffect) {
  auto s = smallImpact(Geometry::Planar, {});
  EXPECT_FALSE(std::get<eos::Tillotson>(sceneMaterials(s)[0]).tensionCutoff);
  s.effects.insert(Effect::TensionCutoff);
  EXPECT_TRUE(std::get<eos::Tillotson>(sceneMaterials(s)[0]).tensionCutoff);
}

// docs/performance.md, "SPH memory": the compatible energy's remainder recomputes each pair's
// w_ij a_ij at the half state instead of reading them stored by the half-state pass. The same
// code on the same state, so the same bits: planar and r-z, viscous, over steps with contact.
// (Stored pair data need full rows: the planar run keeps them here, HVI_SPH_HALF=0, so that
// both runs add the same terms in the same order.)
TEST(Solver, RecomputedPairDataGiveTheStoredBits) {
  ASSERT_EQ(setenv("HVI_SPH_HALF", "0", 1), 0);
  for (const Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const auto s = smallImpact(g, {Effect::ArtificialViscosity, Effect::TensionCutoff});
    ASSERT_EQ(s.sph.energy, cases::EnergyForm::Compatible);
    Snapshot snap[2];
    for (int store = 0; store < 2; ++store) {
      // Read by the stepper's constructor (HVI_SPH_STORE_PAIRS=1 stores them).
      ASSERT_EQ(setenv("HVI_SPH_STORE_PAIRS", store ? "1" : "0", 1), 0);
      auto solver = createSolver(s);
      for (int k = 0; k < 8; ++k) solver->advance(1.0);
      snap[store] = solver->snapshot();
    }
    unsetenv("HVI_SPH_STORE_PAIRS");
    ASSERT_EQ(snap[0].count(), snap[1].count());
    for (const char* name : {"density", "pressure", "specific_energy", "velocity"})
      EXPECT_EQ(snap[0].find(name)->data, snap[1].find(name)->data) << name;
    for (long i = 0; i < snap[0].count(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_EQ(snap[0].positions[k].x, snap[1].positions[k].x);
      EXPECT_EQ(snap[0].positions[k].z, snap[1].positions[k].z);
    }
    // The remainder is not trivially zero here: the run changed the internal energy.
    double emax = 0.0;
    for (const double e : snap[0].find("specific_energy")->data) emax = std::max(emax, e);
    EXPECT_GT(emax, 1e-4);
  }
  unsetenv("HVI_SPH_HALF");
}

// Half rows (docs/performance.md, "SPH pair loops: half rows"): the planar step evaluates each
// pair once and adds both ends' terms in another order than the full rows' gather, so a run
// differs from the full rows' (HVI_SPH_HALF=0) by round-off grown through the steps, and must
// conserve as well. Contact at 6.7 km/s, 8 steps (the stored-pairs test's run).
TEST(Solver, HalfRowsAgreeWithFullRows) {
  const auto s = smallImpact(Geometry::Planar, {Effect::ArtificialViscosity, Effect::TensionCutoff});
  Snapshot snap[2];
  double drift[2];
  for (int half = 0; half < 2; ++half) {
    ASSERT_EQ(setenv("HVI_SPH_HALF", half ? "1" : "0", 1), 0);
    SphSolver solver(s);
    const double e0 = solver.totals().energy();
    for (int k = 0; k < 8; ++k) solver.advance(1.0);
    drift[half] = solver.totals().energy() / e0 - 1.0;
    snap[half] = solver.snapshot();
  }
  unsetenv("HVI_SPH_HALF");
  ASSERT_EQ(snap[0].count(), snap[1].count());
  // Round-off only: the same state to ~1e-13 relative after 8 steps (measured: TODO); a pair
  // lost or counted twice would change the velocities at the percent level.
  double dmax = 0.0, vmax = 0.0;
  const auto& v0 = snap[0].find("velocity")->data;
  const auto& v1 = snap[1].find("velocity")->data;
  for (std::size_t k = 0; k < v0.size(); ++k) {
    dmax = std::max(dmax, std::abs(v0[k] - v1[k]));
    vmax = std::max(vmax, std::abs(v0[k]));
  }
  std::printf("half vs full rows: max |dv| / max |v| = %.2e\n", dmax / vmax);
  EXPECT_LT(dmax, 1e-12 * vmax);
  EXPECT_GT(dmax, 0.0);  // the orders differ: the tolerance is exercised
  // The compatible energy's exactness does not depend on the order.
  EXPECT_LT(std::abs(drift[0]), 1e-13);
  EXPECT_LT(std::abs(drift[1]), 1e-13);
}

TEST(Solver, SnapshotHasTheFieldsOutputNeeds) {
  const auto s = smallImpact(Geometry::Axisymmetric,
                             {Effect::ArtificialViscosity, Effect::MassAdjustment,
                              Effect::TensionCutoff, Effect::PhaseBookkeeping});
  auto solver = createSolver(s);
  for (int k = 0; k < 5; ++k) solver->advance(1.0);
  const Snapshot snap = solver->snapshot();
  EXPECT_EQ(snap.kind, Snapshot::Kind::Particles);
  EXPECT_EQ(snap.geometry, Geometry::Axisymmetric);
  EXPECT_EQ(snap.step, 5);
  const long n = snap.count();
  EXPECT_EQ(n, solver->workItems());
  for (const char* name : {"density", "pressure", "specific_energy", "mass", "material", "object",
                           "smoothing_length", "vapour_fraction", "phase"}) {
    const Field* f = snap.find(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_EQ(static_cast<long>(f->data.size()), n) << name;
  }
  ASSERT_NE(snap.find("velocity"), nullptr);
  EXPECT_EQ(snap.find("velocity")->components, 2);
  EXPECT_EQ(snap.objectNames, (std::vector<std::string>{"striker", "shield"}));
  EXPECT_EQ(snap.materialNames, (std::vector<std::string>{"aluminium"}));
  // Traditional ring masses 2 pi r rho0 dx^2 add up to the bodies' masses (plate
  // pi r^2 t rho0, sphere 4/3 pi R^3 rho0) up to the sphere's staircase surface (a few %).
  const double expect = 2.79 * (M_PI * 0.24 * 0.24 * 0.06 + 4.0 / 3.0 * M_PI * 1e-3);
  const double traditional = createSolver(smallImpact(Geometry::Axisymmetric, {}))->totals().mass;
  EXPECT_NEAR(traditional, expect, 0.03 * expect);
  // Modified masses exceed them: summation density rho0 *at* the surface particles needs
  // mass spread beyond them (surface layers 1.45, 0.83, 1.06 x the interior mass), about a
  // third of a layer per free surface, here a lot for a plate 3 particles thick.
  const double modified = solver->totals().mass;
  std::printf("r-z masses: analytic %.5f g, traditional %.5f g, modified %.5f g\n", expect,
              traditional, modified);
  EXPECT_GT(modified, traditional);
  EXPECT_EQ(solver->totals().momentumX, 0.0);  // r-z: zero by symmetry
  // Without phase_bookkeeping the phase fields cost nothing and are absent.
  auto plain = createSolver(smallImpact(Geometry::Planar, {}));
  EXPECT_EQ(plain->snapshot().find("vapour_fraction"), nullptr);
}

}  // namespace
}  // namespace hvi::sph
