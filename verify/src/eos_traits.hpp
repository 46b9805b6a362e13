//! @file What the exact solutions need to know about an EOS beyond P(rho, e) (internal).
#pragma once
#include "hvi/eos/eos.hpp"

namespace hvi::verify::detail {

//! Whether the material can carry tension (P < 0). False for an ideal gas (P >= 0 for e >= 0)
//! and for any EOS with its tension cut-off on.
bool carriesTension(const eos::Eos& eos);

//! The state with the formula pressure and its derivatives (no tension cut-off) and the
//! physical sound speed sqrt(max(c^2, 0)) from them, not floored: the floor is a device for the
//! solvers' time steps, the exact solution follows the true characteristics.
eos::EosState uncutState(const eos::Eos& eos, double rho, double e);

//! The formula pressure before any tension cut-off: it changes sign smoothly where the cut-off
//! pressure only touches zero, so it is what a root finder needs to locate the spall density.
double signedPressure(const eos::Eos& eos, double rho, double e);

}  // namespace hvi::verify::detail
