//! @file Gamma-law ideal gas, P = (gamma - 1) rho e.
#pragma once
#include <cmath>

#include "hvi/eos/state.hpp"

namespace hvi::eos {

struct IdealGas {
  double gamma = 1.4;
  double rho0 = 1.0;  //!< reference density, only used to fill bodies (g/cm^3)

  [[nodiscard]] double pressure(double rho, double e) const { return (gamma - 1.0) * rho * e; }
  [[nodiscard]] EosState state(double rho, double e) const {
    EosState s;
    s.pressure = pressure(rho, e);
    s.dPdRho = (gamma - 1.0) * e;
    s.dPdE = (gamma - 1.0) * rho;
    s.soundSpeed = std::sqrt(std::max(gamma * (gamma - 1.0) * e, 0.0));
    return s;
  }
  [[nodiscard]] double referenceDensity() const { return rho0; }
  //! e from (rho, P): used to set up initial states given a pressure.
  [[nodiscard]] double energyFromPressure(double rho, double p) const {
    return p / ((gamma - 1.0) * rho);
  }
};

}  // namespace hvi::eos
