//! @file The Taylor anvil scene (cases/scenes/taylor_copper_sph.toml) run by the SPH solver and
//! its final shape, shared by the default test and the convergence study (tests/study).
#pragma once
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "hvi/cases/load.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/test/scene_files.hpp"
#include "hvi/test/taylor_data.hpp"

namespace hvi::sph::test {

using hvi::test::kTaylorFinalLength;
using hvi::test::kTaylorFootDiameter;


struct TaylorShape {
  double length = 0.0;        //!< cm
  double footDiameter = 0.0;  //!< cm
  double kineticLeft = 0.0;   //!< kinetic energy at the end / at impact
  double energyDrift = 0.0;   //!< total energy at the end / at impact - 1
  std::size_t particles = 0;
  std::vector<double> profileRadius, profilePlasticStrain;  //!< per twelfth of the final length
};

//! Runs the shipped scene at `spacing` (cm) to its end (80 us, the rod at rest) and measures the
//! rod: the length is the particles' axial extent plus one spacing (each end particle stands for
//! half a spacing of material beyond its centre), the foot diameter twice the largest radius
//! plus one spacing likewise (the outer particles are the least compressed: the undeformed
//! spacing is their size to within the strain, a few %).
//! `overrides`: further `key=value` settings of the scene (as `hvi run --set`), e.g. the
//! viscosity switch.
inline TaylorShape taylorAnvil(double spacing, std::vector<std::string> overrides = {}) {
  overrides.insert(overrides.begin(), "sph.spacing=" + std::to_string(spacing) + " cm");
  const cases::Scene s =
      cases::loadScene(cases::test::shippedDir() / "taylor_copper_sph.toml", overrides);
  SphSolver solver(s);
  const Totals t0 = solver.totals();
  while (solver.time() < s.tEnd) solver.advance(s.tEnd);
  const ParticleSystem ps = solver.stepper().particles();
  const StrengthFields f = solver.stepper().strengthFields();
  TaylorShape r;
  double zmin = 1e300, zmax = -1e300, rmax = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    zmin = std::min(zmin, ps.z[i]);
    zmax = std::max(zmax, ps.z[i]);
    rmax = std::max(rmax, ps.x[i]);
  }
  r.length = zmax - zmin + spacing;
  r.footDiameter = 2.0 * rmax + spacing;
  r.particles = ps.size();
  const std::size_t bins = 12;
  std::vector<double> count(bins, 0.0);
  r.profileRadius.assign(bins, 0.0);
  r.profilePlasticStrain.assign(bins, 0.0);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const auto b = std::min(bins - 1, static_cast<std::size_t>((ps.z[i] - zmin) / r.length * bins));
    r.profileRadius[b] = std::max(r.profileRadius[b], ps.x[i] + 0.5 * spacing);
    r.profilePlasticStrain[b] += f.plasticStrain[i];
    count[b] += 1.0;
  }
  for (std::size_t b = 0; b < bins; ++b)
    if (count[b] > 0.0) r.profilePlasticStrain[b] /= count[b];
  r.kineticLeft = solver.totals().kinetic / t0.kinetic;
  r.energyDrift = solver.totals().energy() / t0.energy() - 1.0;
  return r;
}

inline void printTaylor(double spacing, const TaylorShape& t) {
  std::printf(
      "Taylor anvil, dx = %.4f cm (%zu particles): L = %.4f cm (%+.1f %% of %.4f), D = %.4f cm "
      "(%+.1f %% of %.4f), kinetic energy left %.1e, dE/E %.1e\n",
      spacing, t.particles, t.length, 100.0 * (t.length / kTaylorFinalLength - 1.0),
      kTaylorFinalLength, t.footDiameter, 100.0 * (t.footDiameter / kTaylorFootDiameter - 1.0),
      kTaylorFootDiameter, t.kineticLeft, t.energyDrift);
  for (std::size_t b = 0; b < t.profileRadius.size(); ++b)
    std::printf("  z / L in [%.2f, %.2f]: outer radius %.4f cm, mean eps_p %.3f\n",
                static_cast<double>(b) / t.profileRadius.size(),
                static_cast<double>(b + 1) / t.profileRadius.size(), t.profileRadius[b],
                t.profilePlasticStrain[b]);
}

}  // namespace hvi::sph::test
