//! @file The exact Riemann solution dressed as a Solver, for verification scenes (solver =
//! "riemann"). Its own target, hvi::verify_solver: it reads a Scene, and hvi::cases itself links
//! hvi::verify (validation builds the exact solution), so it cannot live in hvi::verify.
#pragma once
#include <memory>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"

namespace hvi::verify {

//! solver = "riemann": the body further left (smaller x) is the left state, the other the right
//! state, in either order in the scene, meeting at x = riemann.interface; the solution is sampled
//! on riemann.cells cells across the domain.
std::unique_ptr<Solver> createRiemannSolver(const cases::Scene& scene);

}  // namespace hvi::verify
