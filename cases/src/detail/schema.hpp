//! @file The keys of the irregular scene tables (root, [domain], [materials.*], [[bodies]]): one
//! list for the parser's unknown-key check and the `--set` path check. The regular sections
//! ([time], [sph], [tvd], [riemann], [output]) are key tables: detail/keys.hpp.
#pragma once
#include <array>
#include <string_view>

namespace hvi::cases::detail {

inline constexpr std::array<std::string_view, 13> kRootKeys{
    "title",     "units",  "geometry", "solver", "effects", "time",  "domain",
    "materials", "bodies", "sph",      "tvd",    "riemann", "output"};
inline constexpr std::array<std::string_view, 3> kDomainKeys{"x", "z", "boundaries"};
inline constexpr std::array<std::string_view, 4> kBoundaryKeys{"xmin", "xmax", "zmin", "zmax"};

// Materials: common keys, then the parameters of each EOS.
inline constexpr std::array<std::string_view, 4> kMaterialCommonKeys{"preset", "eos", "rho0",
                                                                     "sound_speed_floor"};
inline constexpr std::array<std::string_view, 9> kTillotsonKeys{"a",  "b",  "A",     "B",   "e0",
                                                                "e1", "e2", "alpha", "beta"};
inline constexpr std::array<std::string_view, 1> kIdealGasKeys{"gamma"};
inline constexpr std::array<std::string_view, 3> kMieGruneisenKeys{"c0", "s", "gamma0"};
inline constexpr std::array<std::string_view, 3> kEosNames{"tillotson", "ideal_gas",
                                                           "mie_gruneisen"};
inline constexpr std::array<std::string_view, 17> kMaterialKeys{
    "preset", "eos",   "rho0", "sound_speed_floor",
    "a",      "b",     "A",    "B",
    "e0",     "e1",    "e2",   "alpha",
    "beta",   "gamma", "c0",   "s",
    "gamma0"};

// Bodies: common keys, then the keys of each shape.
inline constexpr std::array<std::string_view, 9> kBodyCommonKeys{
    "name",     "material",        "shape",           "velocity",     "density",
    "pressure", "specific_energy", "radial_velocity", "radial_centre"};
inline constexpr std::array<std::string_view, 3> kShapeNames{"disk", "rect", "polygon"};
inline constexpr std::array<std::string_view, 2> kDiskKeys{"centre", "radius"};
inline constexpr std::array<std::string_view, 2> kRectKeys{"x", "z"};
inline constexpr std::array<std::string_view, 1> kPolygonKeys{"vertices"};
inline constexpr std::array<std::string_view, 12> kBodyKeys{
    "name",   "material", "shape", "velocity", "density", "pressure", "specific_energy",
    "centre", "radius",   "x",     "z",        "vertices"};

}  // namespace hvi::cases::detail
