//! @file Hard cases (cases/scenes/hard/) stay numerically stable with both solvers.
//! Bounds and their reasons: docs/hard_cases.md. Each test prints one "[hard]" line of results.
#include <gtest/gtest.h>

#include "harness.hpp"

namespace hvi::hard {
namespace {

//! Smallest allowed dt / (first CFL step) after kSettleSteps. dt = CFL h / (c + |v| + ...) and
//! the signal speed of the hottest state these cases reach (c of the ~5 Mbar shocked or the
//! released vapour state plus the flow speed, <= ~4 cm/us) is at most ~5x that of the first
//! step (1-3 cm/us), so physically dt/dt0 stays above ~0.2 (measured: >= 0.29). A runaway
//! particle or cell (what this check is for) drives dt down by orders of magnitude within a few
//! steps; 1e-2 leaves a margin of 20 over the physical bound.
constexpr double kMinDtRatio = 1e-2;

//! SPH masses never change: each particle keeps its mass bit for bit (checked by id), and the
//! total in the domain plus what left through outflow sides equals the initial one up to the
//! summation order: <= N eps with N ~ 1e4 particles.
constexpr double kSphMassRoundOff = 1e-12;

//! TVD ledger closure: M - M0 equals the sum of the ledger's entries (boundary, interfaces,
//! owner changes, floors) to round-off accumulated over ~1e3 steps of ~1e4 cells. The same for
//! energy and for the momentum components the ledger closes (relative to sqrt(2 M0 E0)).
constexpr double kTvdClosure = 1e-10;

struct Bounds {
  double energy;  //!< relative total-energy error (see RunResult::energyError)
  double mass;    //!< relative mass error (SPH: round-off; TVD: made by the vacuum treatment)
};

//! SPH: the pair sums exchange energy antisymmetrically, so total energy (with what left through
//! outflow sides) changes only by the error of the second-order (midpoint) time integration,
//! largest where shocks steepen over a few steps; measured 1.5e-5 to 6e-4 in these cases. 5e-3 is
//! ~10x the largest; a missing or one-sided term (viscous heating, the energy of removed
//! particles) costs 1e-2 to 1e-1 of the impact energy and fails it.
constexpr Bounds kSph{.energy = 5e-3, .mass = kSphMassRoundOff};

//! TVD with marker lines: the scheme is conservative to round-off except at faces next to
//! another object or to vacuum (ghost-fluid fluxes) and in cells that change owner (re-set from
//! their neighbours' mean), which by design balance each other only on average, to first order
//! in dx: a block translating through vacuum is exact; the hot release converges as dx
//! (1-D slab: -2.8%, -1.5%, -0.75% of the mass at dx = 0.05, 0.025, 0.0125 cm). What does not
//! balance (drift) is removed by the per-material renormalisation, which leaves each material's
//! mass within half a layer of its interface cells of its target (docs/tvd.md). At dx =
//! 0.025-0.05 cm on bodies 0.25-1 cm across half a layer is dx / (2 L) = 2.5-10% of the mass;
//! the energy error is about twice the mass error (the outermost layer is the fastest). Bounds:
//! 10% of the mass, 20% of the energy. (Without markers the same scheme conserves
//! vapour_release to 1e-13 in mass and 1.4e-5 in energy.) An error that does not shrink with dx
//! is a defect whatever its size: docs/hard_cases.md.
constexpr Bounds kTvd{.energy = 2e-1, .mass = 1e-1};

// What both solvers promise: the run completes and dt does not collapse.
void expectCompletedWithSteadyDt(const RunResult& r) {
  EXPECT_TRUE(r.completed) << r.caseName << " / " << r.solver << " failed at t = " << r.tReached
                           << " us: " << r.failure;
  if (!r.completed) return;
  EXPECT_GT(r.dt0, 0.0);
  EXPECT_GE(r.minDtRatio, kMinDtRatio) << "at step " << r.minDtStep;
}

// SPH: particle masses bit for bit (the harness fails the run at the first changed, missing or
// duplicated particle, so a completed run has massesBitwise == true; checked here so that a run
// that never compared masses does not pass), the total with the outflow at round-off.
void expectStableSph(const RunResult& r) {
  const Bounds& b = kSph;
  expectCompletedWithSteadyDt(r);
  if (!r.completed) return;
  ASSERT_TRUE(r.massesBitwise.has_value()) << "particle masses were never compared";
  EXPECT_TRUE(*r.massesBitwise);
  EXPECT_FALSE(r.massClosure.has_value()) << "an SPH run measured as TVD";
  EXPECT_LE(r.massError, b.mass);
  EXPECT_LE(r.energyError, b.energy);
}

// TVD: the ledger closes at round-off for mass, energy and momentum; what the vacuum treatment
// makes or loses (mass and energy errors net of the boundary flux) stays within the band.
void expectStableTvd(const RunResult& r) {
  const Bounds& b = kTvd;
  expectCompletedWithSteadyDt(r);
  if (!r.completed) return;
  ASSERT_TRUE(r.massClosure && r.energyClosure && r.momentumClosure)
      << "the ledger closure was never measured";
  EXPECT_FALSE(r.massesBitwise.has_value()) << "a TVD run measured as SPH";
  EXPECT_LE(*r.massClosure, kTvdClosure);
  EXPECT_LE(*r.energyClosure, kTvdClosure);
  EXPECT_LE(*r.momentumClosure, kTvdClosure);
  EXPECT_LE(r.massError, b.mass);
  EXPECT_LE(r.energyError, b.energy);
}

RunResult run(const std::string& name, const std::string& solver) {
  RunSetup s;
  s.caseName = name;
  s.solver = solver;
  return runHardCase(s);
}

TEST(HardImpact15, Sph) { expectStableSph(run("impact_15kms", "sph")); }
TEST(HardImpact15, Tvd) { expectStableTvd(run("impact_15kms", "tvd")); }
TEST(HardImpact20, Sph) { expectStableSph(run("impact_20kms", "sph")); }
TEST(HardImpact20, Tvd) { expectStableTvd(run("impact_20kms", "tvd")); }
TEST(HardThinPlate, Sph) { expectStableSph(run("thin_plate", "sph")); }
TEST(HardThinPlate, Tvd) { expectStableTvd(run("thin_plate", "tvd")); }
TEST(HardOblique45, Sph) { expectStableSph(run("oblique_45", "sph")); }
TEST(HardOblique45, Tvd) { expectStableTvd(run("oblique_45", "tvd")); }
TEST(HardDenseStriker, Sph) { expectStableSph(run("dense_striker", "sph")); }
// Tungsten on aluminium (density ratio 7): the tungsten marker outruns its material, and before
// the per-material renormalisation (docs/tvd.md) every Al -> W owner change created
// (rho_W - rho_Al) V, +12.7 % of the mass by 2 us. Now held within the band of kTvd.
//
// The error must also shrink with dx: it is first order (half a layer of interface cells), and
// an error that does not shrink is a defect whatever its size. The same case at dx = 0.05 cm
// (twice the scene's 0.025) must complete and make at least 1.25 times the mass error (order >=
// 0.3): a first-order error halves once the interface length has converged, but the rod's lip and
// the aluminium sheet along it are only resolved from 0.025 cm on. kTvd's mass bound is 10% at
// 0.05 cm, where the rod is 10 cells across, so that run is not held to it. At dx = 0.0125 cm
// the run stops at 0.52 us (a near-vacuum cell of the aluminium lip goes negative after the
// positivity fallback): open, docs/tvd.md.
TEST(HardDenseStriker, Tvd) {
  const RunResult scene = run("dense_striker", "tvd");
  expectStableTvd(scene);
  RunSetup coarse;
  coarse.caseName = "dense_striker";
  coarse.solver = "tvd";
  coarse.variant = "_dx0.05";
  coarse.overrides = {R"(tvd.cell_size="0.05 cm")"};
  const RunResult c = runHardCase(coarse);
  EXPECT_TRUE(c.completed) << c.failure;
  EXPECT_GE(c.massError, 1.25 * scene.massError)
      << "dx halved: " << c.massError << " -> " << scene.massError;
}
TEST(HardVapourRelease, Sph) { expectStableSph(run("vapour_release", "sph")); }
TEST(HardVapourRelease, Tvd) { expectStableTvd(run("vapour_release", "tvd")); }
TEST(HardNearContact, Sph) { expectStableSph(run("near_contact", "sph")); }
TEST(HardNearContact, Tvd) { expectStableTvd(run("near_contact", "tvd")); }
TEST(HardThinShell, Sph) { expectStableSph(run("thin_shell", "sph")); }
TEST(HardThinShell, Tvd) { expectStableTvd(run("thin_shell", "tvd")); }

// TVD with conservative cut-cell interfaces (docs/tvd.md): every material's mass is moved only
// by fluxes between its own cells, so the total is the initial one to the summation's round-off
// (~1e3 steps of ~1e4 cells: 1e-12; measured <= 2.2e-14). The exchange, merges and repair move
// energy between cells and phases; what changes the total is only the booked floors (negative
// internal energies of thin cells raised to zero), measured <= 1.9e-4 in these cases; 1e-3
// leaves a margin of 5, while an exchange that is not equal and opposite costs >= 1e-2. The
// ledger closes as in the whole-cell mode.
void expectConservativeTvd(const std::string& name) {
  RunSetup s;
  s.caseName = name;
  s.solver = "tvd";
  s.variant = "_conservative";
  s.overrides = {R"(tvd.interfaces="conservative")"};
  const RunResult r = runHardCase(s);
  expectCompletedWithSteadyDt(r);
  if (!r.completed) return;
  ASSERT_TRUE(r.massClosure && r.energyClosure && r.momentumClosure);
  EXPECT_LE(*r.massClosure, kTvdClosure);
  EXPECT_LE(*r.energyClosure, kTvdClosure);
  EXPECT_LE(*r.momentumClosure, kTvdClosure);
  EXPECT_LE(r.massError, 1e-12);
  EXPECT_LE(r.energyError, 1e-3);
}
TEST(HardImpact15, TvdConservative) { expectConservativeTvd("impact_15kms"); }
TEST(HardImpact20, TvdConservative) { expectConservativeTvd("impact_20kms"); }
TEST(HardThinPlate, TvdConservative) { expectConservativeTvd("thin_plate"); }
TEST(HardOblique45, TvdConservative) { expectConservativeTvd("oblique_45"); }
TEST(HardDenseStriker, TvdConservative) { expectConservativeTvd("dense_striker"); }
TEST(HardVapourRelease, TvdConservative) { expectConservativeTvd("vapour_release"); }
TEST(HardNearContact, TvdConservative) { expectConservativeTvd("near_contact"); }
TEST(HardThinShell, TvdConservative) { expectConservativeTvd("thin_shell"); }

// near_contact with the upper block's particles moved down by 0.99 spacing: its lowest row sits
// 0.01 spacing above the lower block's top row, so pairs of particles of the two bodies start
// 0.01 spacing apart (r -> 0 in the kernel gradient and the viscosity's phi).
TEST(HardNearContact, SphCoincidentPairs) {
  RunSetup s;
  s.caseName = "near_contact";
  s.solver = "sph";
  s.variant = "_pairs";
  s.make = [](const cases::Scene& scene) {
    return makeShiftedSph(scene, 1, -0.99 * scene.sph.spacing);
  };
  expectStableSph(runHardCase(s));
}

}  // namespace
}  // namespace hvi::hard
