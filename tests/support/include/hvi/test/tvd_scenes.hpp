//! @file Scene builders and error norms shared by the TVD tests.
#pragma once
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/eos/eos.hpp"
#include "hvi/tvd/tvd.hpp"

namespace hvi::tvd::testing {

//! Uniform state of a body: density, velocity, specific energy.
struct BodyInit {
  double rho = 1.0;
  Vec2 v{};
  double e = 0.0;
};

inline cases::Body body(std::string name, int material, cases::Shape shape, BodyInit s) {
  cases::Body b;
  b.name = std::move(name);
  b.material = material;
  b.shape = std::move(shape);
  b.density = s.rho;
  b.velocity = s.v;
  b.specificEnergy = s.e;
  return b;
}

inline cases::Material material(std::string name, eos::Eos eos) {
  cases::Material m;
  m.name = std::move(name);
  m.eos = std::move(eos);
  return m;
}

//! A TVD scene with outflow boundaries on the given domain and cell size.
inline cases::Scene baseScene(double xmin, double xmax, double zmin, double zmax, double h,
                              Geometry g = Geometry::Planar) {
  cases::Scene s;
  s.title = "tvd test";
  s.geometry = g;
  s.solver = cases::SolverKind::Tvd;
  s.domain.xmin = xmin;
  s.domain.xmax = xmax;
  s.domain.zmin = zmin;
  s.domain.zmax = zmax;
  s.tvd.cellSize = h;
  s.tvd.cfl = 0.4;
  s.tvd.limiter = cases::Limiter::Minmod;
  return s;
}

//! baseScene with the conservative cut-cell interfaces (marker lines, tension cut-off).
inline cases::Scene cutScene(double xmin, double xmax, double zmin, double zmax, double h,
                             Geometry g = Geometry::Planar) {
  cases::Scene s = baseScene(xmin, xmax, zmin, zmax, h, g);
  s.effects.insert(cases::Effect::MaterialInterfaces);
  s.effects.insert(cases::Effect::TensionCutoff);
  s.tvd.interfaces = cases::InterfaceMode::Conservative;
  return s;
}

//! Runs the solver to time t (exactly).
inline void runTo(Solver& s, double t) {
  while (s.time() < t) s.advance(t);
}

//! Density of cell (i, k).
inline double rhoAt(const TvdSolver& s, int i, int k) {
  return s.conserved().rho[static_cast<std::size_t>(k) * s.grid().nx + i];
}

//! Each phase's mass in the domain (cut-cell mode), by phase index.
inline std::vector<double> phaseMasses(const TvdSolver& s) {
  const Phases& ph = s.phases();
  std::vector<double> m(static_cast<std::size_t>(ph.count), 0.0);
  for (int p = 0; p < ph.count; ++p)
    for (long c = 0; c < s.grid().cells(); ++c)
      m[static_cast<std::size_t>(p)] +=
          ph.q[static_cast<std::size_t>(p)].rho[static_cast<std::size_t>(c)] * s.cellVolume(c);
  return m;
}

//! A snapshot's field by name (throws if the snapshot lacks it).
inline const Field& field(const Snapshot& s, const std::string& name) {
  for (const Field& f : s.fields)
    if (f.name == name) return f;
  throw std::runtime_error("no field " + name);
}

}  // namespace hvi::tvd::testing
