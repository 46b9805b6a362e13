//! @file What an equation of state returns at one (rho, e): pressure and its derivatives.
#pragma once
#include <concepts>

namespace hvi::eos {

//! Thermodynamic response at density rho (g/cm^3) and specific internal energy e (cm^2/us^2).
struct EosState {
  double pressure = 0.0;  //!< P, Mbar
  double dPdRho = 0.0;    //!< dP/drho at constant e, Mbar cm^3/g
  double dPdE = 0.0;      //!< dP/de at constant rho, g/cm^3
  double soundSpeed = 0.0;//!< c = sqrt(dP/drho + P/rho^2 dP/de), floored, cm/us
};

//! Phase bookkeeping from e against the incipient (e1) and full (e2) vaporisation energies.
enum class Phase { Solid, PartlyVaporised, Vapour };

//! Every EOS is a small value type with these members; solvers dispatch once per material.
template <class E>
concept EquationOfState = requires(const E& eos, double rho, double e) {
  { eos.pressure(rho, e) } -> std::same_as<double>;
  { eos.state(rho, e) } -> std::same_as<EosState>;
  { eos.referenceDensity() } -> std::same_as<double>;
};

}  // namespace hvi::eos
