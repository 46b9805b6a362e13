//! @file Exact Noh implosion for an ideal gas, planar (n = 0), cylindrical (1), spherical (2).
#pragma once

namespace hvi::verify {

struct NohSample {
  double rho = 0.0, u = 0.0, p = 0.0, e = 0.0;  //!< u is the radial velocity (negative inflow)
};

//! Cold gas of density rho0 flowing to the origin at speed u0 > 0; a shock moves out at
//! speed u0 (gamma - 1) / 2 and leaves gas at rest with density rho0 ((g+1)/(g-1))^(n+1).
struct NohSolution {
  double gamma = 5.0 / 3.0;
  double rho0 = 1.0;
  double u0 = 1.0;
  int n = 1;  //!< 0 planar, 1 cylindrical, 2 spherical

  [[nodiscard]] double shockRadius(double t) const;
  [[nodiscard]] NohSample sample(double r, double t) const;
};

}  // namespace hvi::verify
