//! @file The SPH time integrator: predictor (continuity density), corrector (summation density).
#pragma once
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"
#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/particles.hpp"
#include "hvi/sph/viscosity.hpp"
#include "hvi/strength/strength.hpp"

namespace hvi::sph {

struct StepperConfig {
  Geometry geometry = Geometry::Planar;
  cases::Kernel kernel = cases::Kernel::Gaussian;
  bool viscosity = true;                                     //!< effect artificial_viscosity
  MonaghanViscosity visc;                                    //!< alpha_Pi, beta_Pi
  cases::EnergyForm energy = cases::EnergyForm::Compatible;  //!< docs/sph.md, "Energy"
  //! docs/sph-rz.md; Symmetric selects that form, anything else the ring form
  cases::RzForm rzForm = cases::RzForm::Ring;
  double rzViscousHoop = 0.0;  //!< symmetric r-z form: kappa of the viscous hoop (sph-rz.md)
  //! symmetric r-z form: corrected axial gradient within this many h of the axis, 0 off
  double rzAxisCorrection = 0.0;
  double cfl = 0.3;
  cases::Domain domain;  //!< walls / axis are mirrors, outflow sides remove particles
  double time = 0.0;     //!< us, time of the initial state
  std::vector<std::string> objectNames;  //!< for diagnostics
  //! Effect strength (docs/strength.md, "SPH"): per material its strength (nullopt: a fluid,
  //! which carries no deviator) and its reference density. Empty: no strength (bit for bit the
  //! hydrodynamic scheme, nothing allocated).
  std::vector<std::optional<strength::Material>> strength;
  std::vector<double> strengthRho0;
  bool fracture = false;  //!< effect fracture (with strength): spall strength and damage
  double hFactor = 1.0;   //!< h / dp: W(dp) of the artificial stress
  //! Monaghan's (2000) artificial stress with strength: epsilon and the exponent n of
  //! f_ab^n (Gray, Monaghan and Swift 2001: 0.3 and 4); epsilon = 0 switches it off.
  double artificialStress = 0.3;
  int artificialStressPower = 4;
  //! Morris and Monaghan's (1997) viscosity switch (with strength and viscosity only;
  //! docs/strength.md, "Viscosity switch"): per-particle alpha_i in [alphaMin, visc.alpha],
  //! the pair's alpha the mean, beta scaled alike; decay time h / (switchDecay c). The force
  //! passes then run inviscid and the strength pass adds the switched viscosity.
  bool viscositySwitch = false;
  double alphaMin = 0.1;
  double switchDecay = 0.2;
  //! The yield law's strain rate: the last step's plastic strain rate (true) instead of the
  //! velocity gradient's total equivalent rate (docs/strength.md, "SPH viscosity switch").
  bool plasticStrainRate = false;
};

//! The strength state of the real particles (empty vectors without the effect).
struct StrengthFields {
  std::vector<double> sxx, szz, sxz, stt;  //!< deviatoric stress, Mbar (stt = -(sxx + szz))
  std::vector<double> plasticStrain;       //!< equivalent plastic strain
  std::vector<double> damage;              //!< D in [0, 1]
  std::vector<double> temperature;         //!< K (docs/strength.md, Temperature); 0 for fluids
  std::vector<double> viscosityAlpha;      //!< alpha_i of the viscosity switch (empty without)
  std::vector<double> plasticStrainRate;   //!< last step's, 1/us (yield_strain_rate "plastic")
};

//! Advances a particle system with the scheme of docs/sph.md:
//!   state n (list built at x^n, summation rho^n, P^n) -> rates a^n, de^n, drho^n (cached W)
//!   dt = CFL limit (uses c, |v|, viscosity and |a|)
//!   half state:  x, v, e, rho += dt/2 * rates^n;  P, c from the EOS
//!   rates at the half state (same list, W recomputed)
//!   x^{n+1} = x^n + dt v^{n+1/2},  v^{n+1} = v^n + dt a^{n+1/2},  e^{n+1} = e^n + dt de^{n+1/2}
//!   corrector: list rebuilt at x^{n+1}, rho^{n+1} by summation, P and c from the EOS.
//! The list radius (kernel support + cfl) h_ij covers every pair that can come within the
//! support during the half step, because the CFL limit bounds each particle's motion.
//! The summation density (5) and the continuity rate (7) of particle i sum over i's own object
//! (body), which the per-object mass iteration makes exact at t = 0, also where bodies touch;
//! momentum and energy sum over every pair (docs/sph.md).
class Stepper {
 public:
  //! Takes masses as given (traditional, or from adjustMasses) and runs the corrector once to
  //! set rho, P, c at t = config.time. `materials` is indexed by ps.material.
  Stepper(const ParticleSystem& ps, std::vector<eos::Eos> materials, StepperConfig config);
  //! The same taking ps's arrays over (no copy of them at the peak of a run's set-up).
  Stepper(ParticleSystem&& ps, std::vector<eos::Eos> materials, StepperConfig config);
  ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  //! One step, never past tStop; returns dt (0 if time() >= tStop). Throws SimulationError on
  //! a non-finite or non-positive state, naming the particle, its state and the step.
  double step(double tStop);

  //! Frees the work space that is dead between steps (step arrays, cell grid, scratch), so that
  //! an output's copies do not add to it; the next step allocates it again. No result changes.
  void releaseWork();

  [[nodiscard]] double time() const;
  [[nodiscard]] long stepCount() const;
  [[nodiscard]] std::size_t size() const;  //!< real particles
  [[nodiscard]] std::size_t ghostCount() const;
  [[nodiscard]] ParticleSystem particles() const;       //!< copy of the real particles' state
  [[nodiscard]] StrengthFields strengthFields() const;  //!< empty without strength
  //! The step's list: half rows (NeighbourList::half: each real pair once, in the row of its
  //! lower index) in planar Gaussian runs without strength on AVX2 / AVX-512, else full rows.
  [[nodiscard]] const NeighbourList& neighbours() const;
  [[nodiscard]] const StepperConfig& config() const;
  //! Integrals over the particles in the domain plus what left through outflow sides, so that
  //! drift measures the scheme, not the boundary.
  [[nodiscard]] Totals totals() const;
  [[nodiscard]] Totals outflow() const;  //!< what left through outflow sides

  //! Exact binary state; readState then continues bit for bit (same materials and config).
  void writeState(std::ostream& out) const;
  void readState(std::istream& in);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hvi::sph
