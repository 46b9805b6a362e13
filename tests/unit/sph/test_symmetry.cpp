//! @file A normal impact symmetric about x = 0 stays mirror-symmetric to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "hvi/sph/sph.hpp"
#include "hvi/test/sph_test_scenes.hpp"

namespace hvi::sph {
namespace {

using cases::Effect;

TEST(Symmetry, DiskOntoPlateStaysMirrorSymmetric) {
  // Domain symmetric about x = 0 with an even number of lattice columns: the lattice, and
  // hence the initial state, is its own mirror image.
  // No tension cut-off: with it, Tillotson's sound speed drops from 0.52 cm/us to its 5% floor
  // as soon as P < 0, i.e. it is discontinuous at rho0 (e = 0), exactly where the mass
  // iteration leaves every particle (to 1e-9). Mirror partners whose densities differ by
  // round-off then land on different sides and get viscosities 20x apart: the symmetry breaks
  // at 1e-6 after one step, a property of that EOS model rather than of the scheme.
  auto s = test::baseScene(Geometry::Planar, -0.6, 0.6, -0.3, 0.5, 0.01,
                           {Effect::ArtificialViscosity, Effect::MassAdjustment});
  s.materials = {test::aluminium()};
  s.bodies = {test::diskBody("striker", 0, {0.0, 0.12}, 0.12, {0.0, -0.5}),
              test::rectBody("plate", 0, -0.4, 0.4, -0.06, 0.0)};
  test::resolveDensities(s);
  SphSolver solver(s);
  // Mirror partners by initial position.
  const ParticleSystem p0 = solver.stepper().particles();
  std::map<std::pair<long, long>, std::int64_t> site;
  for (std::size_t i = 0; i < p0.size(); ++i)
    site[{std::lround(p0.x[i] * 1e4), std::lround(p0.z[i] * 1e4)}] = p0.id[i];
  std::map<std::int64_t, std::int64_t> partner;
  for (std::size_t i = 0; i < p0.size(); ++i) {
    auto it = site.find({std::lround(-p0.x[i] * 1e4), std::lround(p0.z[i] * 1e4)});
    ASSERT_NE(it, site.end()) << "no mirror site for particle " << p0.id[i];
    partner[p0.id[i]] = it->second;
  }
  for (int k = 0; k < 120; ++k) solver.advance(1e9);
  const ParticleSystem p = solver.stepper().particles();
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i < p.size(); ++i) index[p.id[i]] = i;
  double dx = 0.0, dz = 0.0, dv = 0.0, drho = 0.0, vmax = 0.0, pmax = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = index.at(partner.at(p.id[i]));
    dx = std::max(dx, std::abs(p.x[i] + p.x[j]));
    dz = std::max(dz, std::abs(p.z[i] - p.z[j]));
    dv = std::max(dv, std::hypot(p.vx[i] + p.vx[j], p.vz[i] - p.vz[j]));
    drho = std::max(drho, std::abs(p.rho[i] - p.rho[j]) / p.rho[i]);
    vmax = std::max(vmax, std::hypot(p.vx[i], p.vz[i]));
    pmax = std::max(pmax, p.p[i]);
  }
  std::printf("t = %.3f us (120 steps), peak P %.3f Mbar: mirror error |x+x'| %.2e cm, "
              "|z-z'| %.2e cm, |v-v'| %.2e cm/us, |rho-rho'|/rho %.2e\n",
              solver.time(), pmax, dx, dz, dv, drho);
  // A particle and its partner sum the same terms in mirrored order, so they differ by
  // round-off (1e-16 relative per operation; the masses by 5e-14 after ~540 multiplicative
  // mass iterations), which 120 steps of shock amplify only mildly: 1e-12 of the scales
  // (0.6 cm, 0.5 cm/us, rho) is a round-off bound with room. (Measured ~1e-15.)
  EXPECT_LT(dx, 1e-12 * 0.6);
  EXPECT_LT(dz, 1e-12 * 0.6);
  EXPECT_LT(dv, 1e-12 * 0.5);
  EXPECT_LT(drho, 1e-12);
}

}  // namespace
}  // namespace hvi::sph
