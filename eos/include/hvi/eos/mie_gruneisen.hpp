//! @file Linear Us-up Mie-Gruneisen EOS with Gamma rho = Gamma0 rho0.
#pragma once
#include "hvi/eos/state.hpp"

namespace hvi::eos {

//! Reference curve: the principal Hugoniot of Us = c0 + s up, i.e. with eta = 1 - rho0/rho,
//! P_H = rho0 c0^2 eta / (1 - s eta)^2 and e_H = P_H eta / (2 rho0) in compression; in
//! expansion P_H = rho0 c0^2 eta (the linear acoustic limit). Off the reference curve,
//! P = P_H + Gamma0 rho0 (e - e_H). Compression beyond eta = 0.95/s (the Hugoniot's asymptote)
//! is clamped there. Optional tension cut-off as for Tillotson.
struct MieGruneisen {
  double rho0 = 8.93;   //!< g/cm^3 (copper by default)
  double c0 = 0.394;    //!< cm/us
  double s = 1.49;
  double gamma0 = 2.0;
  bool tensionCutoff = false;  //!< solvers: the scene's effect (cases::resolveMaterials)
  double soundSpeedFloorFraction = 0.05;

  [[nodiscard]] double pressure(double rho, double e) const { return state(rho, e).pressure; }
  [[nodiscard]] EosState state(double rho, double e) const;
  [[nodiscard]] double referenceDensity() const { return rho0; }
};

}  // namespace hvi::eos
