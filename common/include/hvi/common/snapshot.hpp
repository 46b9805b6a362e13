//! @file Solver-independent picture of a state at one time: what output and compare consume.
#pragma once
#include <string>
#include <vector>

#include "hvi/common/geometry.hpp"
#include "hvi/common/vec2.hpp"

namespace hvi {

//! A named field, one value (or `components` values, interleaved) per particle or per cell.
struct Field {
  std::string name;   //!< e.g. "density", "pressure", "velocity", "material"
  std::string unit;   //!< e.g. "g/cm^3"; "1" for dimensionless
  int components = 1;
  std::vector<double> data;
};

//! Uniform cell-centred grid: cell (i, k) has centre (x0 + (i + 1/2) dx, z0 + (k + 1/2) dz);
//! cell data are stored row-major with i fastest: index = k * nx + i.
struct GridSpec {
  int nx = 0, nz = 0;
  double x0 = 0.0, z0 = 0.0;
  double dx = 0.0, dz = 0.0;
  [[nodiscard]] long cells() const { return static_cast<long>(nx) * nz; }
};

//! An ordered chain of points (a marker line of the TVD solver); closed if `closed`.
struct Polyline {
  int object = -1;
  bool closed = true;
  std::vector<Vec2> points;
};

struct Snapshot {
  enum class Kind { Particles, Grid };

  double time = 0.0;      //!< us
  long step = 0;
  std::string solver;     //!< "sph", "tvd", "riemann"
  Geometry geometry = Geometry::Planar;
  Kind kind = Kind::Grid;

  std::vector<Vec2> positions;   //!< particles only
  GridSpec grid;                 //!< grid only
  std::vector<Field> fields;
  std::vector<Polyline> markers; //!< optional interface lines

  //! Material names indexed by the integer values of the "material" field (-1 = vacuum).
  std::vector<std::string> materialNames;
  //! Body (object) names indexed by the "object" field.
  std::vector<std::string> objectNames;

  [[nodiscard]] long count() const {
    return kind == Kind::Particles ? static_cast<long>(positions.size()) : grid.cells();
  }
  [[nodiscard]] const Field* find(const std::string& name) const {
    for (const auto& f : fields)
      if (f.name == name) return &f;
    return nullptr;
  }
};

}  // namespace hvi
