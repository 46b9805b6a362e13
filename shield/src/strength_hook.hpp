//! @file The one place where a shield scene switches material strength and fracture on for its
//! plates and projectile (issue 15; docs/shield.md, "Strength").
#pragma once
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/shield/shield.hpp"

namespace hvi::shield::detail {

//! The effects `strength` and `fracture`, each when the effect table knows it and `solver`
//! supports it (both solvers have both; TVD in its conservative interface mode).
std::vector<std::string> strengthEffects(cases::SolverKind solver);

//! Lines added to [materials.<name>] of `m` when strength is on: the material's strength and
//! fracture parameters in the keys issue 15 defines (the spall strength is read by fracture only).
std::string strengthMaterialKeys(const ShieldMaterial& m, bool strengthOn);

}  // namespace hvi::shield::detail
