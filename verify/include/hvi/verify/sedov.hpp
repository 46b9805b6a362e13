//! @file Sedov-Taylor point blast in an ideal gas, planar (n = 0), cylindrical (1), spherical (2).
#pragma once
#include <vector>

namespace hvi::verify {

struct SedovSample {
  double rho = 0.0, u = 0.0, p = 0.0;
};

//! Self-similar blast of energy E (per unit area for planar, per unit length for cylindrical)
//! released at t = 0 in gas of density rho0 at zero pressure. Built once by integrating the
//! similarity ODEs (or Kamm & Timmes' closed form), then sampled.
//!
//! Built from Sedov's closed form in the standard case (Kamm & Timmes, LA-UR-07-2849, eqs.
//! 38-47, uniform density): every quantity is an explicit function of the similarity velocity
//! V, so sample() inverts lambda(V) by a bracketed root find and is exact to round-off; alpha
//! comes from the energy integral by Gauss-Legendre quadrature (relative error below 1e-12).
//! Planar convention (Kamm & Timmes'): E is the energy in the half-space x >= 0, i.e. the
//! blast against a reflecting wall at x = 0 (alpha = 0.5387 for gamma = 1.4); a blast free on
//! both sides with total energy E_tot per unit area is this solution with E = E_tot / 2.
//! Requires the standard (non-vacuum) case: 1 < gamma < 7 (spherical), any gamma > 1 planar
//! and cylindrical below the singular value 2/((gamma-1)(n+1)+2) = 4/((n+3)(gamma+1)).
class SedovSolution {
 public:
  SedovSolution(double gamma, double rho0, double energy, int n);
  [[nodiscard]] double shockRadius(double t) const;
  //! The state at distance |r| from the centre (or the plane) at time t > 0.
  [[nodiscard]] SedovSample sample(double r, double t) const;
  [[nodiscard]] double alpha() const { return alpha_; }  //!< E = alpha rho0 R^(n+3) / t^2

 private:
  // The Sedov functions at s = ln x2 (x2 -> 0 at the centre, s = 0 at the shock):
  // lambda = r / R, rho / rho0, u / (dR/dt), p / (rho0 (dR/dt)^2).
  struct Profile {
    double lambda, rho, u, p;
  };
  [[nodiscard]] Profile profile(double s) const;

  double gamma_, rho0_, energy_;
  int n_;
  double alpha_ = 0.0;
  // Closed-form constants (Kamm & Timmes' notation).
  double a0_ = 0, a1_ = 0, a2_ = 0, a3_ = 0, a4_ = 0, a5_ = 0;
  double av_ = 0, bv_ = 0, cv_ = 0, dv_ = 0, ev_ = 0;
  // Profiles on the similarity coordinate lambda = r / R(t) in (0, 1], ascending, at the
  // nodes s_ (a bracket for the root find in sample()).
  std::vector<double> s_, lambda_, rhoRatio_, uRatio_, pRatio_;
};

}  // namespace hvi::verify
