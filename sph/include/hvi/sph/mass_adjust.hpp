//! @file The mass iteration of modified SPH (spec section 3, docs/method.md).
#pragma once
#include <cstddef>

#include "hvi/cases/scene.hpp"
#include "hvi/sph/particles.hpp"

namespace hvi::sph {

struct MassAdjustOptions {
  Geometry geometry = Geometry::Planar;
  cases::Kernel kernel = cases::Kernel::Gaussian;
  cases::RzForm rzForm = cases::RzForm::Ring;  //!< r-z: the density's weights (sph-rz.md)
  cases::Domain domain;         //!< walls and the axis are mirrors, as in the run
  double tolerance = 1e-9;      //!< stop when |rho0_i / rho_i - 1| < tolerance for every i
  double deleteFraction = 1e-4; //!< delete i when m_i^(s+1) / max_k m_k^(s+1) < deleteFraction
  int maxIterations = 10000;
};

struct MassAdjustReport {
  int iterations = 0;          //!< mass updates made
  std::size_t deleted = 0;     //!< particles removed as badly placed
  double maxResidual = 0.0;    //!< max |rho0 / rho - 1| with the final masses
};

//! Per object, from m = 1, iterates m_i <- m_i rho0_i / rho_i with rho_i = sum_j m_j W_ij over
//! the particles (and mirror ghosts) of the same object, deleting the badly placed particles
//! after each update, until |rho0_i / rho_i - 1| < tolerance for every particle. rho0_i is
//! ps.rhoRef. In r-z the unknown is the planar weight mu = m / (2 pi r) (docs/sph-rz.md), and
//! the deletion test compares weights, not ring masses (which shrink towards the axis anyway).
//! Sets ps.m, removes the deleted particles; positions are untouched. Throws SimulationError
//! if maxIterations pass without convergence.
MassAdjustReport adjustMasses(ParticleSystem& ps, const MassAdjustOptions& options);

}  // namespace hvi::sph
