//! @file Hand-built snapshots for the compare tests: particle lattices and grids from functions.
#pragma once
#include <cmath>
#include <functional>
#include <numbers>

#include "hvi/common/snapshot.hpp"

namespace hvi::compare::test {

//! Which part of space holds what: material/object id (-1: nothing) and density there.
struct Scene2 {
  std::function<int(Vec2)> material;
  std::function<int(Vec2)> object = [](Vec2) { return -1; };
  std::function<double(Vec2)> density = [](Vec2) { return 2.79; };
};

inline Field field(const char* name, std::vector<double> data) {
  return Field{name, "1", 1, std::move(data)};
}

//! A square lattice of spacing dx with points at ((i + 1/2) dx + ox, (k + 1/2) dz + oz) inside
//! [xmin, xmax] x [zmin, zmax] wherever `s.material` is set; h = hFactor dx. Masses are rho dx^2
//! (planar), or ring masses 2 pi r rho dx^2 / per-radian masses r rho dx^2 in r-z.
inline Snapshot lattice(const Scene2& s, double xmin, double xmax, double zmin, double zmax,
                        double dx, double hFactor = 1.0, Geometry geom = Geometry::Planar,
                        bool ringMass = true) {
  Snapshot snap;
  snap.kind = Snapshot::Kind::Particles;
  snap.solver = "sph";
  snap.geometry = geom;
  std::vector<double> rho, mass, h, mat, obj;
  const long nx = std::lround((xmax - xmin) / dx), nz = std::lround((zmax - zmin) / dx);
  for (long k = 0; k < nz; ++k)
    for (long i = 0; i < nx; ++i) {
      const double x = xmin + (i + 0.5) * dx, z = zmin + (k + 0.5) * dx;
      const Vec2 p{x, z};
      const int m = s.material(p);
      if (m < 0) continue;
      snap.positions.push_back(p);
      rho.push_back(s.density(p));
      double area = dx * dx;
      if (geom == Geometry::Axisymmetric) area *= ringMass ? 2.0 * std::numbers::pi * x : x;
      mass.push_back(rho.back() * area);
      h.push_back(hFactor * dx);
      mat.push_back(m);
      obj.push_back(s.object(p));
    }
  snap.fields = {field("density", rho), field("mass", mass), field("smoothing_length", h),
                 field("material", mat), field("object", obj)};
  snap.materialNames = {"aluminium", "steel"};
  snap.objectNames = {"striker", "shield"};
  return snap;
}

//! A grid snapshot sampling `s` at the cell centres (vacuum cells: density 0).
inline Snapshot gridOf(const Scene2& s, const GridSpec& g, Geometry geom = Geometry::Planar) {
  Snapshot snap;
  snap.kind = Snapshot::Kind::Grid;
  snap.solver = "tvd";
  snap.geometry = geom;
  snap.grid = g;
  std::vector<double> rho, mat, obj;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p{g.x0 + (i + 0.5) * g.dx, g.z0 + (k + 0.5) * g.dz};
      const int m = s.material(p);
      mat.push_back(m);
      rho.push_back(m >= 0 ? s.density(p) : 0.0);
      obj.push_back(m >= 0 ? s.object(p) : -1);
    }
  snap.fields = {field("density", rho), field("material", mat), field("object", obj)};
  snap.materialNames = {"aluminium", "steel"};
  snap.objectNames = {"striker", "shield"};
  return snap;
}

inline std::function<int(Vec2)> box(double x0, double x1, double z0, double z1, int id = 0) {
  return [=](Vec2 p) { return p.x >= x0 && p.x <= x1 && p.z >= z0 && p.z <= z1 ? id : -1; };
}

}  // namespace hvi::compare::test
