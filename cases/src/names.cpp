//! @file Scene-file names of the enumerations.
#include "hvi/cases/names.hpp"

#include <array>

namespace hvi::cases {
namespace {
constexpr std::array<std::string_view, 3> kSolvers{"sph", "tvd", "riemann"};
constexpr std::array<std::string_view, 2> kGeometries{"planar", "rz"};
constexpr std::array<std::string_view, 3> kBoundaries{"outflow", "wall", "axis"};
constexpr std::array<std::string_view, 2> kKernels{"gaussian", "cubic_spline"};
constexpr std::array<std::string_view, 2> kLattices{"square", "hexagonal"};
constexpr std::array<std::string_view, 3> kLimiters{"minmod", "van_leer", "superbee"};
constexpr std::array<std::string_view, 2> kInterfaces{"whole_cell", "conservative"};
constexpr std::array<std::string_view, 2> kEnergyForms{"compatible", "symmetric"};
constexpr std::array<std::string_view, 3> kRzForms{"auto", "ring", "symmetric"};
constexpr std::array<std::string_view, 2> kViscositySwitches{"off", "morris_monaghan"};
constexpr std::array<std::string_view, 2> kYieldStrainRates{"total", "plastic"};
constexpr std::array<std::string_view, 4> kOutflowModes{"open", "no_reentry", "no_reentry_cut",
                                                         "auto"};

template <class E, std::size_t N>
std::string_view nameOf(const std::array<std::string_view, N>& names, E e) {
  const auto i = static_cast<std::size_t>(e);
  return i < N ? names[i] : std::string_view("?");
}
}  // namespace

std::span<const std::string_view> solverNames() { return kSolvers; }
std::span<const std::string_view> geometryNames() { return kGeometries; }
std::span<const std::string_view> boundaryNames() { return kBoundaries; }
std::span<const std::string_view> kernelNames() { return kKernels; }
std::span<const std::string_view> latticeNames() { return kLattices; }
std::span<const std::string_view> limiterNames() { return kLimiters; }
std::span<const std::string_view> interfaceNames() { return kInterfaces; }
std::span<const std::string_view> outflowModeNames() { return kOutflowModes; }
std::span<const std::string_view> energyFormNames() { return kEnergyForms; }
std::span<const std::string_view> rzFormNames() { return kRzForms; }
std::span<const std::string_view> viscositySwitchNames() { return kViscositySwitches; }
std::span<const std::string_view> yieldStrainRateNames() { return kYieldStrainRates; }

std::string_view toString(SolverKind s) { return nameOf(kSolvers, s); }
std::string_view toString(Boundary b) { return nameOf(kBoundaries, b); }
std::string_view toString(Kernel k) { return nameOf(kKernels, k); }
std::string_view toString(Lattice l) { return nameOf(kLattices, l); }
std::string_view toString(Limiter l) { return nameOf(kLimiters, l); }
std::string_view toString(InterfaceMode m) { return nameOf(kInterfaces, m); }
std::string_view toString(OutflowMode m) { return nameOf(kOutflowModes, m); }
std::string_view toString(EnergyForm f) { return nameOf(kEnergyForms, f); }
std::string_view toString(RzForm f) { return nameOf(kRzForms, f); }
std::string_view toString(ViscositySwitch v) { return nameOf(kViscositySwitches, v); }
std::string_view toString(YieldStrainRate r) { return nameOf(kYieldStrainRates, r); }

}  // namespace hvi::cases
