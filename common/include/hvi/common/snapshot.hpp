//! @file Solver-independent picture of a state at one time: what output and compare consume.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "hvi/common/geometry.hpp"
#include "hvi/common/units.hpp"
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

// The snapshot builder: every solver names its fields through it, so that a quantity has one
// name, unit and layout in every solver's files (output, compare and the readers look fields
// up by name).

//! The quantities solvers write.
enum class Quantity {
  Density, Pressure, Velocity, SpecificEnergy, SoundSpeed, Mass, Material, Object,
  SmoothingLength, Id, VapourFraction, Phase
};

struct FieldSpec {
  const char* name;
  const char* unit;
  int components;
};

//! Name, unit and components of `q` in `geometry`: a mass is a whole ring's in r-z (g) and one
//! per cm of depth in planar geometry (g/cm).
constexpr FieldSpec fieldSpec(Quantity q, Geometry geometry) {
  switch (q) {
    case Quantity::Density: return {"density", units::densityName, 1};
    case Quantity::Pressure: return {"pressure", units::pressureName, 1};
    case Quantity::Velocity: return {"velocity", units::velocityName, 2};
    case Quantity::SpecificEnergy: return {"specific_energy", units::energyName, 1};
    case Quantity::SoundSpeed: return {"sound_speed", units::velocityName, 1};
    case Quantity::Mass: return {"mass", geometry == Geometry::Axisymmetric ? "g" : "g/cm", 1};
    case Quantity::Material: return {"material", "1", 1};
    case Quantity::Object: return {"object", "1", 1};
    case Quantity::SmoothingLength: return {"smoothing_length", units::lengthName, 1};
    case Quantity::Id: return {"id", "1", 1};
    case Quantity::VapourFraction: return {"vapour_fraction", "1", 1};
    case Quantity::Phase: return {"phase", "1", 1};
  }
  return {"?", "1", 1};
}

//! The field `q` for `n` particles or cells, every value `fill`.
inline Field makeField(Quantity q, Geometry geometry, std::size_t n, double fill = 0.0) {
  const FieldSpec f = fieldSpec(q, geometry);
  return {f.name, f.unit, f.components,
          std::vector<double>(n * static_cast<std::size_t>(f.components), fill)};
}

//! A snapshot's header, set alike by every solver; the caller adds positions or the grid, the
//! fields and the names.
inline Snapshot makeSnapshot(std::string solver, Snapshot::Kind kind, Geometry geometry,
                             double time, long step) {
  Snapshot s;
  s.time = time;
  s.step = step;
  s.solver = std::move(solver);
  s.geometry = geometry;
  s.kind = kind;
  return s;
}

//! Appends the one-component field `q` with the per-item values `v` (any arithmetic type).
template <class T>
void addField(Snapshot& s, Quantity q, const std::vector<T>& v) {
  Field f = makeField(q, s.geometry, v.size());
  for (std::size_t i = 0; i < v.size(); ++i) f.data[i] = static_cast<double>(v[i]);
  s.fields.push_back(std::move(f));
}

//! Appends the one-component field `q`, taking the values over (no copy: an output's peak
//! memory holds them once).
inline void addField(Snapshot& s, Quantity q, std::vector<double>&& v) {
  const FieldSpec f = fieldSpec(q, s.geometry);
  s.fields.push_back({f.name, f.unit, f.components, std::move(v)});
}

//! Appends the two-component field `q` (a vector) from its components, interleaved.
inline void addField(Snapshot& s, Quantity q, const std::vector<double>& x,
                     const std::vector<double>& z) {
  Field f = makeField(q, s.geometry, x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    f.data[2 * i] = x[i];
    f.data[2 * i + 1] = z[i];
  }
  s.fields.push_back(std::move(f));
}

}  // namespace hvi
