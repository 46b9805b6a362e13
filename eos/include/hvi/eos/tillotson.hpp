//! @file Tillotson equation of state (spec section 2, docs/method.md), four regions, tension
//! cut-off.
#pragma once
#include "hvi/eos/state.hpp"

namespace hvi::eos {

//! Tillotson EOS in cm-g-us units (pressures in Mbar, energies in cm^2/us^2).
//!
//! Regions: compressed or cold (rho >= rho0, or rho < rho0 with e <= e1) use Pc; expanded hot
//! (rho < rho0, e >= e2) use PH; in between, P blends Pc and PH linearly in e.
//! With `tensionCutoff`, a negative formula pressure means spall: P = 0 and both derivatives 0.
//! The sound speed is floored at `soundSpeedFloorFraction * sqrt(A / rho0)` (the cold bulk sound
//! speed), because expanded states and the cut-off give c^2 <= 0, which no solver can step.
struct Tillotson {
  double rho0 = 2.79;
  double a = 0.5, b = 1.63;
  double A = 0.75, B = 0.65;  //!< Mbar
  double e0 = 0.05;           //!< cm^2/us^2
  double alpha = 5.0, beta = 5.0;
  double e1 = 0.03, e2 = 0.15;  //!< incipient / full vaporisation energy, cm^2/us^2
  bool tensionCutoff = true;  //!< solvers: the scene's effect (cases::resolveMaterials)
  double soundSpeedFloorFraction = 0.05;

  enum class Region { Compressed, ColdExpanded, Blend, HotExpanded };

  [[nodiscard]] Region region(double rho, double e) const;
  [[nodiscard]] double pressure(double rho, double e) const { return state(rho, e).pressure; }
  [[nodiscard]] EosState state(double rho, double e) const;
  //! The formula pressure before the cut-off, with its derivatives (for tests and diagnostics).
  [[nodiscard]] EosState formulaState(double rho, double e) const;
  [[nodiscard]] double referenceDensity() const { return rho0; }
  [[nodiscard]] double soundSpeedFloor() const;
  [[nodiscard]] Phase phase(double e) const {
    return e <= e1 ? Phase::Solid : (e >= e2 ? Phase::Vapour : Phase::PartlyVaporised);
  }
};

}  // namespace hvi::eos
