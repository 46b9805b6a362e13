//! @file Filling bodies on the global lattice.
#include "hvi/sph/fill.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"

namespace hvi::sph {
namespace {

struct LatticeGeometry {
  double ax = 0.0;      // spacing along x
  double az = 0.0;      // spacing between rows
  bool shiftOdd = false;
};

LatticeGeometry latticeGeometry(const cases::SphParams& p) {
  if (!(p.spacing > 0.0))
    throw InputError(fmt::format("sph.spacing = {} must be > 0", p.spacing));
  if (!(p.hFactor > 0.0))
    throw InputError(fmt::format("sph.h_factor = {} must be > 0", p.hFactor));
  if (p.lattice == cases::Lattice::Square) return {p.spacing, p.spacing, false};
  // Hexagonal: neighbour distance a, row distance a sqrt(3)/2, area per site a^2 sqrt(3)/2,
  // which equals spacing^2 for a = spacing sqrt(2/sqrt(3)).
  const double a = p.spacing * std::sqrt(2.0 / std::sqrt(3.0));
  return {a, 0.5 * std::sqrt(3.0) * a, true};
}

}  // namespace

double latticeCellArea(const cases::SphParams& params) {
  const LatticeGeometry g = latticeGeometry(params);
  return g.ax * g.az;
}

ParticleSystem fillBodies(const cases::Scene& scene) {
  const auto& sp = scene.sph;
  const LatticeGeometry g = latticeGeometry(sp);
  const auto& dom = scene.domain;
  const double h = sp.hFactor * sp.spacing;
  const double cellArea = g.ax * g.az;
  const bool rz = scene.geometry == Geometry::Axisymmetric;
  ParticleSystem ps;
  std::int64_t nextId = 0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const cases::Body& body = scene.bodies[b];
    if (body.material < 0 || body.material >= static_cast<int>(scene.materials.size()))
      throw InputError(fmt::format("body '{}': material index {} is not one of the {} materials",
                                   body.name, body.material, scene.materials.size()));
    const double rhoRef =
        body.density > 0.0 ? body.density : scene.materials[body.material].rho0();
    const cases::Box box = cases::boundingBox(body.shape);
    const double zlo = std::max(box.zmin, dom.zmin), zhi = std::min(box.zmax, dom.zmax);
    const double xlo = std::max(box.xmin, dom.xmin), xhi = std::min(box.xmax, dom.xmax);
    const long k0 = std::max(0L, static_cast<long>(std::floor((zlo - dom.zmin) / g.az - 0.5)));
    const long k1 = static_cast<long>(std::ceil((zhi - dom.zmin) / g.az));
    std::size_t filled = 0;
    for (long k = k0; k <= k1; ++k) {
      // Up to 6e6 particles (the validation cap) with a containment test each: seconds, so a
      // stop request is honoured once per lattice row.
      throwIfStopRequested("the SPH particle fill");
      const double z = dom.zmin + (static_cast<double>(k) + 0.5) * g.az;
      if (z < zlo || z > zhi || z > dom.zmax) continue;
      const double shift = (g.shiftOdd && (k & 1)) ? 0.5 : 0.0;
      const long i0 =
          std::max(0L, static_cast<long>(std::floor((xlo - dom.xmin) / g.ax - 0.5 - shift)));
      const long i1 = static_cast<long>(std::ceil((xhi - dom.xmin) / g.ax));
      for (long i = i0; i <= i1; ++i) {
        const double x = dom.xmin + (static_cast<double>(i) + 0.5 + shift) * g.ax;
        if (x < xlo || x > xhi || x > dom.xmax) continue;
        const Vec2 pt{x, z};
        if (!cases::contains(body.shape, pt)) continue;
        bool claimed = false;  // first body in scene order owns a shared site
        for (std::size_t o = 0; o < b && !claimed; ++o)
          claimed = cases::contains(scene.bodies[o].shape, pt);
        if (claimed) continue;
        const double m = rhoRef * cellArea * (rz ? 2.0 * std::numbers::pi * x : 1.0);
        const Vec2 v = cases::initialVelocity(body, scene.geometry, pt);
        ps.push(x, z, v.x, v.z, rhoRef, body.specificEnergy, m, h, rhoRef,
                body.material, static_cast<int>(b), nextId++);
        ++filled;
      }
    }
    if (filled == 0)
      throw InputError(fmt::format(
          "body '{}' holds no particle: it is smaller than the particle spacing {} cm or lies "
          "outside the domain; use a smaller sph.spacing or move the body",
          body.name, sp.spacing));
  }
  return ps;
}

}  // namespace hvi::sph
