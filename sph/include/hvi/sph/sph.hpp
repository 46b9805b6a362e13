//! @file The SPH solver behind the hvi::Solver interface (modified or traditional SPH).
#pragma once
#include <memory>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"
#include "hvi/sph/mass_adjust.hpp"
#include "hvi/sph/stepper.hpp"

namespace hvi::sph {

//! Builds the solver for a scene: fills the bodies (fill.hpp), runs the mass iteration when the
//! scene names mass_adjustment (modified SPH; otherwise traditional equal masses), sets each
//! Tillotson / Mie-Gruneisen material's tension cut-off from the tension_cutoff effect, and
//! takes the artificial viscosity from artificial_viscosity. Throws InputError for a scene SPH
//! cannot run (r-z without the axis at x = 0, a body without particles, bad parameters).
std::unique_ptr<Solver> createSolver(const cases::Scene& scene);

//! The construction steps of SphSolver, each usable alone; the solver is exactly these.
//! The materials' EOS with the tension cut-off switched as the scene's effects say.
std::vector<eos::Eos> sceneMaterials(const cases::Scene& scene);
//! The stepper settings of the scene's sph table and effects.
StepperConfig stepperConfig(const cases::Scene& scene);
//! The mass iteration settings of the scene's sph table.
MassAdjustOptions massAdjustOptions(const cases::Scene& scene);

//! The concrete solver, for callers that want more than the Solver interface.
class SphSolver final : public Solver {
 public:
  //! The scene's bodies filled (fillBodies) and run.
  explicit SphSolver(const cases::Scene& scene);
  //! Given particles (a state a scene cannot express, e.g. fillBodies(scene) with one body
  //! moved) run with the scene's settings; with mass_adjustment their masses are iterated first,
  //! as for a filled scene.
  SphSolver(const cases::Scene& scene, ParticleSystem particles);

  [[nodiscard]] std::string name() const override { return "sph"; }
  [[nodiscard]] double time() const override { return stepper_->time(); }
  [[nodiscard]] long step() const override { return stepper_->stepCount(); }
  [[nodiscard]] long workItems() const override { return static_cast<long>(stepper_->size()); }
  double advance(double tStop) override { return stepper_->step(tStop); }
  //! Particles; fields density, pressure, velocity (2), specific_energy, sound_speed, mass,
  //! material, object, smoothing_length, id; with phase_bookkeeping also vapour_fraction and
  //! phase (eos::phaseState: 0 solid, 1 partly vaporised, 2 vapour).
  [[nodiscard]] Snapshot snapshot() const override;
  [[nodiscard]] Totals totals() const override { return stepper_->totals(); }
  [[nodiscard]] Totals outflow() const override { return stepper_->outflow(); }
  void writeCheckpoint(std::ostream& out) const override { stepper_->writeState(out); }
  void readCheckpoint(std::istream& in) override { stepper_->readState(in); }

  [[nodiscard]] const Stepper& stepper() const { return *stepper_; }
  [[nodiscard]] const MassAdjustReport& massAdjustment() const { return massReport_; }

 private:
  cases::Scene scene_;
  std::vector<eos::Eos> materials_;
  MassAdjustReport massReport_;
  std::unique_ptr<Stepper> stepper_;
};

}  // namespace hvi::sph
