//! @file Symmetry of the problem: planar x-z (n = 0) or axisymmetric r-z (n = 1).
#pragma once
#include <string_view>

namespace hvi {

enum class Geometry { Planar, Axisymmetric };

//! The symmetry index n of the governing equations (docs/method.md, "Governing equations").
constexpr int symmetryIndex(Geometry g) { return g == Geometry::Axisymmetric ? 1 : 0; }
constexpr std::string_view toString(Geometry g) {
  return g == Geometry::Axisymmetric ? "rz" : "planar";
}

}  // namespace hvi
