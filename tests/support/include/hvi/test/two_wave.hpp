//! @file The two-wave structure of a planar impact into an elastic-plastic solid, read off a
//! stress profile along the impact (docs/strength.md: the elastic precursor at sigma_HEL and the
//! plastic wave behind it). Shared by the SPH and TVD strength tests, which measure the same
//! flyer-plate scene.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace hvi::test {

struct TwoWave {
  double plateau = 0.0;   //!< the precursor's stress where the profile is flattest near the HEL
  double zPlateau = 0.0;  //!< where that is
  double peak = 0.0;      //!< the largest stress (the plastic wave)
  double zElastic = 0.0;  //!< the precursor's front: first z (deep end first) at half the HEL
  double zPlastic = 0.0;  //!< the plastic front: first z at half-way from the HEL to the peak
};

//! `z` ascending from the deep end of the target, `stress` the longitudinal compression there.
//! The plateau is the flattest point (smallest 4-spacing difference) among the stresses within
//! [0.5, 1.5] x the HEL.
inline TwoWave twoWave(const std::vector<double>& z, const std::vector<double>& stress,
                       double hel) {
  TwoWave w;
  double flattest = 1e300;
  for (std::size_t r = 2; r + 2 < z.size(); ++r) {
    w.peak = std::max(w.peak, stress[r]);
    if (stress[r] < 0.5 * hel || stress[r] > 1.5 * hel) continue;
    const double slope = std::abs(stress[r + 2] - stress[r - 2]);
    if (slope < flattest) {
      flattest = slope;
      w.plateau = stress[r];
      w.zPlateau = z[r];
    }
  }
  auto firstAbove = [&](double level) {
    for (std::size_t r = 0; r < z.size(); ++r)
      if (stress[r] >= level) return z[r];
    return 0.0;
  };
  w.zElastic = firstAbove(0.5 * hel);
  w.zPlastic = firstAbove(0.5 * (hel + w.peak));
  return w;
}

}  // namespace hvi::test
