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
class SedovSolution {
 public:
  SedovSolution(double gamma, double rho0, double energy, int n);
  [[nodiscard]] double shockRadius(double t) const;
  [[nodiscard]] SedovSample sample(double r, double t) const;
  [[nodiscard]] double alpha() const { return alpha_; }  //!< E = alpha rho0 R^(n+3) / t^2

 private:
  double gamma_, rho0_, energy_;
  int n_;
  double alpha_ = 0.0;
  // Profiles on the similarity coordinate lambda = r / R(t) in [0, 1].
  std::vector<double> lambda_, rhoRatio_, uRatio_, pRatio_;
};

}  // namespace hvi::verify
