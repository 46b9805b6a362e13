//! @file Exact Riemann solver for any EOS of the library, vacuum generation included.
#pragma once
#include <memory>

#include "hvi/eos/eos.hpp"

namespace hvi::verify {

namespace detail {
class Isentrope;
}

//! Initial state of one side: density g/cm^3, normal velocity cm/us, specific energy cm^2/us^2.
struct RiemannState {
  double rho = 0.0;
  double u = 0.0;
  double e = 0.0;
};

//! The exact solution at one similarity coordinate xi = (x - x0) / t.
struct RiemannSample {
  double rho = 0.0, u = 0.0, p = 0.0, e = 0.0;
  int material = 0;  //!< -1: left material, +1: right material, 0: vacuum
};

//! One of the two nonlinear waves.
struct RiemannWave {
  bool shock = false;
  double headSpeed = 0.0;  //!< shock speed, or the rarefaction head speed (cm/us)
  double tailSpeed = 0.0;  //!< equals headSpeed for a shock
};

//! Exact self-similar solution of the 1-D Riemann problem between two materials with general
//! EOS: shocks by the Rankine-Hugoniot relations (energy jump e* - e = (p* + p)(1/rho - 1/rho*)/2),
//! rarefactions by integrating the isentrope de = P/rho^2 drho with the Riemann invariant
//! u +- integral c/rho drho; vacuum generation when the two rarefactions cannot meet.
//!
//! p* is the root of f_L(p) + f_R(p) + u_R - u_L (Brent, to a few ulp of p*). Sound speeds are
//! the physical ones from the EOS formula (not the solvers' floor). With a tension cut-off a
//! rarefaction ends at the spall point, where the formula pressure first reaches 0 at finite
//! density: there the material is a free surface moving at u_K +- (escape velocity), preceded
//! by a constant state at the spall density between the fan's tail (u -+ c) and the surface.
//! An ideal gas expands to zero density instead. When u_R - u_L exceeds the two escape
//! velocities, the region between the two free surfaces is vacuum (sample().material = 0),
//! starPressure() is 0 and starVelocity() is the mean of the two surface velocities.
//! Assumes genuinely nonlinear waves (no composite waves); throws hvi::SimulationError when an
//! isentrope leaves the hyperbolic region (c^2 <= 0) or a state is outside the EOS's domain.
class ExactRiemann {
 public:
  ExactRiemann(const eos::Eos& leftEos, RiemannState left, const eos::Eos& rightEos,
               RiemannState right);

  [[nodiscard]] RiemannSample sample(double xi) const;

  [[nodiscard]] double starPressure() const { return pStar_; }
  [[nodiscard]] double starVelocity() const { return uStar_; }
  [[nodiscard]] double starDensityLeft() const { return rhoStarL_; }
  [[nodiscard]] double starDensityRight() const { return rhoStarR_; }
  [[nodiscard]] bool vacuumGenerated() const { return vacuum_; }
  [[nodiscard]] const RiemannWave& leftWave() const { return waveL_; }
  [[nodiscard]] const RiemannWave& rightWave() const { return waveR_; }
  [[nodiscard]] double starEnergyLeft() const { return eStarL_; }
  [[nodiscard]] double starEnergyRight() const { return eStarR_; }
  //! Free-surface speeds bounding the vacuum region (only meaningful if vacuumGenerated()).
  [[nodiscard]] double vacuumFrontLeft() const { return vacuumFrontL_; }
  [[nodiscard]] double vacuumFrontRight() const { return vacuumFrontR_; }

 private:
  eos::Eos eosL_, eosR_;
  RiemannState L_, R_;
  double pStar_ = 0.0, uStar_ = 0.0, rhoStarL_ = 0.0, rhoStarR_ = 0.0;
  double eStarL_ = 0.0, eStarR_ = 0.0;
  bool vacuum_ = false;
  double vacuumFrontL_ = 0.0, vacuumFrontR_ = 0.0;  //!< edge speeds of the vacuum region
  RiemannWave waveL_, waveR_;
  double pL_ = 0.0, pR_ = 0.0;
  // Release isentropes of both sides (shared so the solution stays cheap to copy).
  std::shared_ptr<const detail::Isentrope> isL_, isR_;
};

}  // namespace hvi::verify
