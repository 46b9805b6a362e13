//! @file SPH with strength (effect `strength`, docs/strength.md "SPH"): the deviatoric stress
//! of every particle, its Jaumann update with radial return, and the stress pair pass that adds
//! the stress force and power to a force pass's rates. Exists only when the effect is named, so
//! a scene without it allocates and computes nothing of this (bit for bit).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "detail/arrays.hpp"
#include "detail/boundary.hpp"
#include "detail/passes.hpp"
#include "hvi/cases/scene.hpp"
#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/viscosity.hpp"
#include "hvi/strength/strength.hpp"

namespace hvi::sph::detail {

//! What a stress pass reads of every point (reals, then ghosts mirrored as tensors).
struct StressPoints {
  std::vector<double> txx, tzz, txz;  //!< rw s / rho^2 (rw = r in r-z, 1 planar)
  std::vector<double> rxx, rzz, rxz;  //!< rw times Monaghan's artificial stress R (/ rho^2)
  std::vector<double> htt;            //!< r-z hoop: -rw s_tt / rho^2 (the pressure's q part)
  std::vector<double> alpha;          //!< viscosity switch only: alpha_i (ghosts as parents)
  std::vector<double> vol;            //!< mu / rho of every point (the gradient's volume)
  //! The lane kernels' copy, one 64-byte record a point: txx, tzz, txz, rxx, rzz, rxz, vol, mu
  //! (stress_lanes_impl.hpp loads whole records instead of gathering 8 columns).
  std::vector<double> rec;
};

//! Velocity gradient and the deviator's rate of the real particles, written by a stress pass.
struct StressRates {
  double* dsxx;
  double* dszz;
  double* dsxz;
  double* strainRate;  //!< equivalent strain rate (yield laws), 1/us
};

class StrengthModel {
 public:
  //! `solids[k]`: material k's strength (nullopt: a fluid, its deviator stays 0); `rho0[k]` its
  //! reference density (compression eta = rho / rho0 for temperature and melt).
  //! `hFactor` = h / dp sets W(dp) of the artificial stress; `epsilon`, `power` its constants.
  //! `fracture`: the effect fracture (docs/strength.md, "Damage and spall").
  StrengthModel(std::vector<std::optional<strength::Material>> solids, std::vector<double> rho0,
                cases::Kernel kernel, double hFactor, double epsilon, int power, bool fracture);

  // State of the real particles (checkpointed; StrengthModel::forEachState's order).
  std::vector<double> sxx, szz, sxz, epsP;
  std::vector<double> damage;  //!< D in [0, 1] (0 without fracture)
  template <class Self, class F>
  static void forEachState(Self& s, F&& f) {
    f(s.sxx);
    f(s.szz);
    f(s.sxz);
    f(s.epsP);
    f(s.damage);
  }

  //! New real particles start unstressed (construction); the state keeps its values.
  void resize(std::size_t n);
  //! Removes the particles whose keep flag is 0, as the stepper's outflow removal does.
  void compact(const std::vector<unsigned char>& keep, std::size_t n0, std::size_t n);
  //! Stores the deviator of the start of the step (the predictor's and corrector's base).
  void beginStep(std::size_t n);
  //! s = s0 + dt ds/dt (the last stress pass's rate), then radial return to the yield surface
  //! of the material at (rho, P, e); `accumulate`: the step's end, where eps_p grows.
  void advance(double dt, std::size_t n, const PairArrays& a, const double* e, const int* mat,
               bool accumulate);
  //! Effect fracture, right after the EOS of a state: a solid's tension is limited to its spall
  //! strength and scaled by 1 - D (`strength::effectivePressure`). `atStepEnd` (the corrector's
  //! state): a solid whose EOS tension exceeds its spall strength fails, D = 1 (the hydrocodes'
  //! pressure-cut-off spall). No-op without fracture.
  void limitTension(PairArrays& a, std::size_t n, const int* mat, bool atStepEnd);
  //! After the EOS of a state: shear modulus, longitudinal sound speed, s / rho^2 and the
  //! artificial stress of the reals, then of the ghosts (mirrored).
  void refreshPoints(const PairArrays& a, std::size_t n, const double* e, const int* mat,
                     const Boundaries& bounds);
  //! Adds the stress force and stress power of every pair to `out` (ax, az, de and, when
  //! `out.pairWx` is set, the compatible energy's pair data with the even share 1/2), and
  //! writes the deviator's Jaumann rate.
  //! `axis`: the r-z axis correction of the hoop term (null in planar geometry).
  void pass(const PairArrays& a, std::size_t n, const NeighbourList& list, bool cached,
            const AxisCorrection* axis, const Rates& out);

  //! Whether passWithForces runs here: the Gaussian kernel in lanes of 4 or more (the stress
  //! lane kernels).
  [[nodiscard]] bool fusable() const;
  //! The force pass over full rows (the lane kernel of selectForcePass(Gaussian, rz, viscous,
  //! compatible, cached): ax, az, de and its drho, phi, pair data and hoop acceleration written)
  //! and then this pass's terms added, in one sweep over the rows: per row the force kernel,
  //! whose pair geometry (dx, dv, h_j, W, grad W) the stress kernel reads instead of computing
  //! it again. The same bits as the force pass over all rows followed by pass() (rows are
  //! independent in both). Not with the r-z symmetric form or the axis matrix (the ring form's
  //! `axis` only). With the viscosity switch `viscous` is false (the switched viscosity is
  //! this pass's).
  void passWithForces(const PairArrays& a, std::size_t n, const NeighbourList& list, bool cached,
                      const AxisCorrection* axis, bool viscous, bool compatible,
                      const MonaghanViscosity& visc, const Rates& out);

  //! Morris and Monaghan's (1997) viscosity switch (docs/strength.md, "Viscosity switch"): the
  //! pass then adds the Monaghan viscosity with the pair's alpha_ij = (alpha_i + alpha_j) / 2
  //! and beta_ij = beta alpha_ij / alpha (the force passes must run inviscid), and the step's
  //! end advances d alpha_i / dt = -(alpha_i - alphaMin) l c_i / h_i
  //! + max(-div v_i, 0) (alpha - alpha_i). alpha_i starts at `visc.alpha` (its maximum).
  void enableViscositySwitch(const MonaghanViscosity& visc, double alphaMin, double decay,
                             std::size_t n);
  [[nodiscard]] bool viscositySwitch() const { return switch_; }
  std::vector<double> alpha;  //!< alpha_i of the reals (checkpointed with the switch only)

  //! The yield law's strain rate becomes each particle's equivalent plastic strain rate of its
  //! last step, d eps_p / dt (0 at the start; checkpointed), instead of the velocity
  //! gradient's total equivalent rate (docs/strength.md, "SPH viscosity switch").
  void enablePlasticStrainRate(std::size_t n);
  [[nodiscard]] bool plasticStrainRate() const { return plasticRateOn_; }
  std::vector<double> plasticRate;  //!< 1/us, of the reals

  //! Temperature of real particle i (snapshots), K.
  [[nodiscard]] double temperature(const PairArrays& a, const double* e, int mat,
                                   std::size_t i) const;

  std::vector<double> cL;  //!< longitudinal sound speed of the reals, cm/us (time step)

 private:
  std::vector<std::optional<strength::Material>> solids_;
  std::vector<double> rho0_;
  cases::Kernel kernel_;
  double hFactor_, epsilon_;
  int power_;
  bool fracture_;
  std::vector<double> g_;  // shear modulus of the reals at the last refresh, Mbar
  // The terms of one eta and one eps_p per real particle, kept between the calls that share
  // them (docs/strength.md, "Cost of strength in SPH"): the half state's advance, refresh and
  // the step's end read one eta and (before the end counts it) one eps_p. Recomputed where the
  // key differs, so a value read is the one the call would compute (the same bits); NaN keys
  // (resize, compact) recompute.
  struct EtaTerms {
    double eta, cold, cbrt;  // key, cold energy, cbrt(eta) (SG)
    double meltEta, melt;    // SG's T_m(eta), computed where a yield reads it (its own key)
  };
  struct HardTerms {
    double epsP, hard;  // key, SG's hardening
  };
  std::vector<EtaTerms> etaTerms_;
  std::vector<HardTerms> hardTerms_;
  EtaTerms& etaTerms(std::size_t i, std::size_t k, double eta);
  std::vector<double> sxx0_, szz0_, sxz0_, dsxx_, dszz_, dsxz_, rate_;
  StressPoints pts_;
  bool switch_ = false;
  MonaghanViscosity visc_;      // alpha, beta: the switch's maximum
  double alphaMin_ = 0.0, decay_ = 0.0;
  std::vector<double> divv_;    // div v of the reals from the last pass (the switch's source)
  bool plasticRateOn_ = false;
};

}  // namespace hvi::sph::detail
