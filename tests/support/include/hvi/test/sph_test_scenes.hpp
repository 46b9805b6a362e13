//! @file Small hand-built scenes shared by the SPH tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

#include "hvi/cases/scene.hpp"
#include "hvi/eos/eos.hpp"
#include "hvi/sph/particles.hpp"

namespace hvi::sph::test {

inline cases::Material aluminium() { return {"aluminium", eos::aluminiumStudy()}; }
inline cases::Material idealGas(double gamma, double rho0 = 1.0) {
  return {"gas", eos::IdealGas{gamma, rho0}};
}

inline cases::Body rectBody(std::string name, int material, double xmin, double xmax,
                            double zmin, double zmax, Vec2 v = {}, double rho = 0.0,
                            double e = 0.0) {
  cases::Body b;
  b.name = std::move(name);
  b.material = material;
  b.shape = cases::Rect{xmin, xmax, zmin, zmax};
  b.velocity = v;
  b.density = rho;
  b.specificEnergy = e;
  return b;
}

inline cases::Body diskBody(std::string name, int material, Vec2 centre, double radius,
                            Vec2 v = {}, double rho = 0.0, double e = 0.0) {
  cases::Body b;
  b.name = std::move(name);
  b.material = material;
  b.shape = cases::Disk{centre, radius};
  b.velocity = v;
  b.density = rho;
  b.specificEnergy = e;
  return b;
}

//! A scene with everything but bodies and materials set; bodies' density 0 means rho0.
inline cases::Scene baseScene(Geometry g, double xmin, double xmax, double zmin, double zmax,
                              double spacing, std::initializer_list<cases::Effect> effects) {
  cases::Scene s;
  s.path = "test";
  s.geometry = g;
  s.domain = {xmin, xmax, zmin, zmax, {}};
  if (g == Geometry::Axisymmetric) s.domain.boundary[0] = cases::Boundary::Axis;
  s.sph.spacing = spacing;
  s.effects = effects;
  s.tEnd = 1.0;
  return s;
}

//! Fills in body densities left at 0 with the material's rho0.
inline void resolveDensities(cases::Scene& s) {
  for (auto& b : s.bodies)
    if (b.density <= 0.0) b.density = s.materials[static_cast<std::size_t>(b.material)].rho0();
}

inline double maxSpeed(const ParticleSystem& ps) {
  double v = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) v = std::max(v, std::hypot(ps.vx[i], ps.vz[i]));
  return v;
}

}  // namespace hvi::sph::test
