//! @file Names of the scene's enumerations as written in scene files (effects: effects.hpp).
#pragma once
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hvi/cases/effects.hpp"
#include "hvi/cases/scene.hpp"

namespace hvi::cases {

// Each list is in enum order: static_cast<Enum>(index) is the value of names()[index].
std::span<const std::string_view> solverNames();    //!< sph, tvd, riemann
std::span<const std::string_view> geometryNames();  //!< planar, rz
std::span<const std::string_view> boundaryNames();  //!< outflow, wall, axis
std::span<const std::string_view> kernelNames();    //!< gaussian, cubic_spline
std::span<const std::string_view> latticeNames();   //!< square, hexagonal
std::span<const std::string_view> limiterNames();   //!< minmod, van_leer, superbee
std::span<const std::string_view> interfaceNames(); //!< whole_cell, conservative
std::span<const std::string_view> outflowModeNames();  //!< open, no_reentry, no_reentry_cut
std::span<const std::string_view> energyFormNames(); //!< compatible, symmetric
std::span<const std::string_view> rzFormNames();     //!< auto, ring, symmetric
std::span<const std::string_view> viscositySwitchNames();  //!< off, morris_monaghan
std::span<const std::string_view> yieldStrainRateNames();  //!< total, plastic

std::string_view toString(SolverKind s);
std::string_view toString(Boundary b);
std::string_view toString(Kernel k);
std::string_view toString(Lattice l);
std::string_view toString(Limiter l);
std::string_view toString(InterfaceMode m);
std::string_view toString(OutflowMode m);
std::string_view toString(EnergyForm f);
std::string_view toString(RzForm f);
std::string_view toString(ViscositySwitch v);
std::string_view toString(YieldStrainRate r);

}  // namespace hvi::cases
