//! @file A Solver over an SPH Stepper built from hand-placed particles (states a scene cannot
//! express, such as particles of two bodies almost on top of each other).
#pragma once
#include <memory>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"
#include "hvi/sph/particles.hpp"
#include "hvi/sph/stepper.hpp"

namespace hvi::hard {

//! Runs `ps` with the scene's SPH settings exactly as sph::SphSolver would (same StepperConfig,
//! same materials); the masses in `ps` are used as given.
class StepperSolver final : public Solver {
 public:
  StepperSolver(const cases::Scene& scene, const sph::ParticleSystem& ps);

  [[nodiscard]] std::string name() const override { return "sph"; }
  [[nodiscard]] double time() const override { return stepper_->time(); }
  [[nodiscard]] long step() const override { return stepper_->stepCount(); }
  [[nodiscard]] long workItems() const override { return static_cast<long>(stepper_->size()); }
  double advance(double tStop) override { return stepper_->step(tStop); }
  [[nodiscard]] Snapshot snapshot() const override;
  [[nodiscard]] Totals totals() const override { return stepper_->totals(); }
  void writeCheckpoint(std::ostream& out) const override { stepper_->writeState(out); }
  void readCheckpoint(std::istream& in) override { stepper_->readState(in); }

  [[nodiscard]] const sph::Stepper& stepper() const { return *stepper_; }

 private:
  cases::Scene scene_;
  std::unique_ptr<sph::Stepper> stepper_;
};

}  // namespace hvi::hard
