//! @file Particle rows buckling behind the Noh shocks (issue 14, item 3; docs/sph.md "Rows
//! behind a strong shock"): the study's strip (8 rows between walls) with a seeded transverse
//! velocity, and the growth of that seed in the shocked gas.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hvi/cases/load.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/sph/sph.hpp"

namespace hvi::sph {
namespace {

//! rms of v_z over the shocked gas well inside the shock (x or r in [0.3, 0.65] of the shock
//! position u0 t / 3: off the wall or axis heating and off the shock layer) at t = 0.6 us, for
//! the study's Noh strip (tools/study_plan.py: 8 rows, walls in z, modified SPH) with spacing
//! dx, each particle's v_z seeded uniformly in [-seed, seed] (fixed generator: reproducible).
double shockedVzRms(const std::string& scene, double dx, double seed,
                    const std::vector<std::string>& extra) {
  std::vector<std::string> ov = {fmt::format("domain.z=[\"0 cm\", \"{} cm\"]", 8 * dx),
                                 fmt::format("bodies[0].z=[\"0 cm\", \"{} cm\"]", 8 * dx),
                                 fmt::format("sph.spacing=\"{} cm\"", dx), "solver=sph",
                                 "effects=[\"artificial_viscosity\", \"mass_adjustment\"]"};
  ov.insert(ov.end(), extra.begin(), extra.end());
  const cases::Scene s =
      cases::loadScene(std::string(HVI_SOURCE_DIR) + "/cases/scenes/study/" + scene + ".toml", ov);
  ParticleSystem ps = fillBodies(s);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& v : ps.vz) v += seed * u(rng);
  SphSolver solver(s, ps);
  const double t = 0.6;
  while (solver.time() < t) solver.advance(t);
  const ParticleSystem p = solver.stepper().particles();
  const double shock = t / 3.0;  // both Noh problems, gamma 5/3, u0 = 1 cm/us: D = u0 / 3
  double sum = 0.0;
  long n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i] > 0.3 * shock && p.x[i] < 0.65 * shock) sum += p.vz[i] * p.vz[i], ++n;
  const double rms = std::sqrt(sum / std::max(n, 1L));
  std::printf("%s dx = %g, seed %g, %s: shocked-gas vz rms %.3e (%ld particles)\n", scene.c_str(),
              dx, seed, extra.empty() ? "h = dx, alpha 1" : extra.front().c_str(), rms, n);
  return rms;
}

#ifndef HVI_LONG_TESTS
// Noh has no length scale: the state at time t and spacing dx is the state at t / 2 and dx / 2.
// A mode that grows at a rate ~ c / dx therefore goes through twice the e-folds at half the
// spacing by the same time. Seeded at 1e-6 (rms 5.8e-7), 0.005 cm shows in seconds what
// round-off (1e-16) reaches at 0.00125 cm. Measured at 0.6 us, planar / cylindrical: h = dx,
// alpha 1 (the study's): 1.9e-3 / 1.4e-4; h = 1.5 dx: 4.0e-7 / 2.8e-7 (the seed decays).
constexpr double kSeed = 1e-6, kSeedRms = kSeed / 1.7320508075688772;  // uniform: seed / sqrt(3)

TEST(RowBuckling, TransverseModeGrowsBehindTheShockAtOneSpacingPerH) {
  // The cause, shown: 100x is far above any transient of a stable scheme (the seed is a
  // velocity perturbation; a stable shocked state keeps or damps it, as h = 1.5 dx does).
  EXPECT_GT(shockedVzRms("noh_planar", 0.005, kSeed, {}), 100.0 * kSeedRms);
  EXPECT_GT(shockedVzRms("noh_cylindrical_rz", 0.005, kSeed, {}), 100.0 * kSeedRms);
}

TEST(RowBuckling, WiderKernelAcrossTheRowsKeepsTheSeedDown) {
  // The remedy: h = 1.5 dx (sph.h_factor), the kernel reaching 1.5 rows across. The seed must
  // not grow (its rms at 0.6 us at most the initial one).
  for (const char* scene : {"noh_planar", "noh_cylindrical_rz"})
    EXPECT_LE(shockedVzRms(scene, 0.005, kSeed, {"sph.h_factor=1.5"}), kSeedRms) << scene;
}
#else
// The resolution, from round-off (no seed): 2 000 to 6 000 steps per run, minutes each;
// `ctest -L long` in a build configured with -DHVI_LONG_TESTS=ON.
TEST(RowBucklingFine, RowsStayStraightAtTheFinestStudySpacingWithEitherRemedy) {
  // Round-off seeds vz at ~1e-16 cm/us; without the instability it stays near there (planar,
  // measured: 3.3e-16 with h = 1.5 dx, 8.5e-15 with beta 4). 1e-10 is 5 orders above that and
  // 7 below the buckled rows' 2.1e-3 (h = dx, alpha 1, beta 2).
  for (const char* scene : {"noh_planar", "noh_cylindrical_rz"})
    for (const char* remedy : {"sph.h_factor=1.5", "sph.beta=4"})
      EXPECT_LE(shockedVzRms(scene, 0.00125, 0.0, {remedy}), 1e-10) << scene << " " << remedy;
}
#endif

}  // namespace
}  // namespace hvi::sph
