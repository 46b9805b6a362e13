//! @file The effects a scene may name, in one table (name, meaning), the effects each solver
//! implements, and the one resolution of a scene's materials that every solver runs with.
#pragma once
#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hvi/cases/scene.hpp"

namespace hvi::cases {

//! One effect: how scene files name it and what it does. docs/scenes.md's effect table is this
//! table with supportedEffects (tests/unit/cases/test_docs_tables.cpp checks it).
struct EffectInfo {
  Effect effect;
  std::string_view name;
  std::string_view meaning;
};
std::span<const EffectInfo> effectTable();  //!< in enum order

//! The effects solver `s` implements (the parser refuses any other; listed in this order).
//! Validation needs it before any solver is built, and cases sits below the solver libraries,
//! so the declaration lives here, one list per solver, rather than in each solver's library.
std::span<const Effect> supportedEffects(SolverKind s);
bool supports(SolverKind s, Effect e);

//! The scene's materials as every solver runs them: the tension cut-off of each Tillotson and
//! Mie-Gruneisen EOS switched on exactly when the scene names `tension_cutoff` (the cut-off is
//! the scene's effect, not a material property). The parser stores this in Scene::materials;
//! the solvers resolve again, so that a Scene built in code runs alike in all of them.
//! With a strength table, the temperature model's bulk sound speed is filled from the EOS
//! (bulkSoundSpeed) where the scene leaves it 0.
std::vector<Material> resolveMaterials(const Scene& scene);

//! The reference bulk sound speed of an EOS: sqrt(A / rho0) (Tillotson), c0 (Mie-Gruneisen),
//! 0 for the ideal gas.
double bulkSoundSpeed(const eos::Eos& e);

}  // namespace hvi::cases
