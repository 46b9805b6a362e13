//! @file Particles from a scene: bodies filled on a global lattice.
#pragma once
#include "hvi/cases/scene.hpp"
#include "hvi/sph/particles.hpp"

namespace hvi::sph {

//! Area per particle of the lattice (cm^2): spacing^2 for both lattices (the hexagonal one is
//! stretched so that it has the same particle density as the square one, docs/sph.md).
double latticeCellArea(const cases::SphParams& params);

//! Fills every body of `scene` with particles at the sites of one global lattice anchored at
//! the domain's lower-left corner (sites at (xmin + (i + 1/2) dx, zmin + (k + 1/2) dz); the
//! hexagonal lattice shifts odd rows by half a spacing). Bodies that touch therefore share no
//! site; a site inside several bodies goes to the first in scene order. Sites outside the
//! domain are not filled. Each particle gets its body's velocity, density (Body::density),
//! specific energy, material, object (body index) and h = hFactor * spacing; its mass is the
//! traditional one, rhoRef * cell area (times 2 pi r in r-z). p and c are left 0.
ParticleSystem fillBodies(const cases::Scene& scene);

}  // namespace hvi::sph
