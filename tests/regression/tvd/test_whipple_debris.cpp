//! @file The conservative cut-cell mode in a Whipple shield's debris cloud (docs/tvd.md,
//! "Robustness"): the coarse smoke-run scene of docs/shield.md stopped at step 421 (t = 19.8 us,
//! "phase density not positive ... after the positivity fallback"): a small-cell merge pooled a
//! cell whose working volume had gone below zero, and the deficit it made was out of the
//! positivity limiter's reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hvi/cases/load.hpp"
#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

TEST(TvdWhippleDebris, ConservativeModePassesTheFirstFailure) {
  // To 21 us: 446 steps, past the step that failed (421, t = 19.8 us).
  const cases::Scene s =
      cases::loadScene(HVI_SOURCE_DIR "/tests/regression/tvd/whipple_coarse_d04.toml");
  TvdSolver solver(s);
  ASSERT_TRUE(solver.phases().count > 1);  // the conservative mode, one phase per body
  const Totals t0 = solver.totals();
  // Stopping at the scene's report times as `hvi run` does (each one ends a step), so that this
  // is the run that failed.
  EXPECT_NO_THROW({
    for (double t : s.output.times)
      if (t < 21.0) runTo(solver, t);
    runTo(solver, 21.0);
  });
  EXPECT_GT(solver.step(), 430L);  // measured: 446
  // The ledger closes (mass and energy through the outflow sides and the floors).
  const Totals t1 = solver.totals();
  const Budget b = solver.ledger().sum();
  EXPECT_NEAR(t1.mass - t0.mass, b.mass, 1e-11 * t0.mass);
  EXPECT_NEAR(t1.energy() - t0.energy(), b.energy, 1e-11 * t0.energy());
  std::printf("whipple coarse d=0.4: t = %.3f us, step %ld, mass change %.3g (booked %.3g)\n",
              solver.time(), static_cast<long>(solver.step()), t1.mass / t0.mass - 1,
              b.mass / t0.mass);
}

}  // namespace
}  // namespace hvi::tvd
