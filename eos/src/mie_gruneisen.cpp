//! @file Linear Us-up Mie-Gruneisen EOS.
#include <algorithm>
#include <cmath>

#include "hvi/eos/mie_gruneisen.hpp"

namespace hvi::eos {

EosState MieGruneisen::state(double rho, double e) const {
  double eta = 1.0 - rho0 / rho;
  const double detaDRho = rho0 / (rho * rho);
  const double etaMax = 0.95 / s;
  bool clamped = false;
  if (eta > etaMax) {
    eta = etaMax;
    clamped = true;
  }
  double pH, dpH;
  if (eta >= 0.0) {
    const double d = 1.0 - s * eta;
    pH = rho0 * c0 * c0 * eta / (d * d);
    dpH = rho0 * c0 * c0 * (1.0 + s * eta) / (d * d * d);
  } else {
    pH = rho0 * c0 * c0 * eta;
    dpH = rho0 * c0 * c0;
  }
  const double eH = pH * eta / (2.0 * rho0);
  const double deH = (dpH * eta + pH) / (2.0 * rho0);
  EosState st;
  st.pressure = pH + gamma0 * rho0 * (e - eH);
  st.dPdE = gamma0 * rho0;
  st.dPdRho = clamped ? 0.0 : (dpH - gamma0 * rho0 * deH) * detaDRho;
  if (tensionCutoff && st.pressure < 0.0) {
    st = EosState{};
  }
  const double c2 = st.dPdRho + st.pressure / (rho * rho) * st.dPdE;
  st.soundSpeed = std::max(std::sqrt(std::max(c2, 0.0)), soundSpeedFloorFraction * c0);
  return st;
}

}  // namespace hvi::eos
