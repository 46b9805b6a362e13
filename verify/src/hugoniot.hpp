//! @file Shock state on the Hugoniot of a general EOS (internal).
#pragma once
#include "hvi/eos/eos.hpp"

namespace hvi::verify::detail {

struct ShockState {
  double rho = 0.0, e = 0.0;
  double massFlux = 0.0;  //!< m = rhoK |uK - S| = rho |u - S|, g/(cm^2 us)
  double du = 0.0;        //!< velocity jump |u - uK| = (p - pK) / m, cm/us
};

//! The state behind a shock that raises the pressure from pK to p > pK in material at
//! (rhoK, eK): the root in rho > rhoK of P(rho, eK + (p + pK)(1/rhoK - 1/rho)/2) = p, i.e. the
//! Rankine-Hugoniot energy jump closed by the EOS. cK (the sound speed ahead) sizes the first
//! bracket and gives the acoustic limit when p - pK underflows.
ShockState shockState(const eos::Eos& eos, double rhoK, double eK, double pK, double cK,
                      double p);

}  // namespace hvi::verify::detail
