//! @file The exact Riemann solution dressed as a Solver, for verification scenes.
#pragma once
#include <memory>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"

namespace hvi::app {

//! solver = "riemann": bodies[0] is the left state, bodies[1] the right state, meeting at
//! x = riemann.interface; the solution is sampled on riemann.cells cells across the domain.
std::unique_ptr<Solver> createRiemannSolver(const cases::Scene& scene);

}  // namespace hvi::app
