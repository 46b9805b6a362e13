//! @file Mirror ghosts, reflection and outflow at the domain boundary.
#include "detail/boundary.hpp"
#include "detail/parallel.hpp"

namespace hvi::sph::detail {

Boundaries::Boundaries(const cases::Domain& domain, Geometry /*geometry*/) : domain_(domain) {
  // In r-z the axis is a mirror for the same reason as a planar symmetry plane: the meridional
  // plane continues across it with v_r reversed (docs/sph-rz.md).
  const double pos[4] = {domain.xmin, domain.xmax, domain.zmin, domain.zmax};
  for (int s = 0; s < 4; ++s) {
    const cases::Boundary b = domain.boundary[s];
    if (b == cases::Boundary::Outflow) {
      outflow_[s] = true;
    } else {
      mirrors_.push_back({s / 2, pos[s], s % 2 == 0});
    }
  }
}

std::size_t Boundaries::makeGhosts(PairArrays& a, std::size_t n, double margin) {
  parent_.clear();
  transform_.clear();
  auto near = [margin](const Mirror& m, double coord) {
    const double d = m.lower ? coord - m.pos : m.pos - coord;
    return d < margin;
  };
  // x mirrors first, then z mirrors of the real particles and of the x ghosts (corners).
  for (const Mirror& m : mirrors_) {
    if (m.axis != 0) continue;
    for (std::size_t i = 0; i < n; ++i)
      if (near(m, a.x[i])) {
        parent_.push_back(static_cast<int>(i));
        transform_.push_back({-1.0, 2.0 * m.pos, 1.0, 0.0});
      }
  }
  const std::size_t nxGhosts = parent_.size();
  for (const Mirror& m : mirrors_) {
    if (m.axis != 1) continue;
    for (std::size_t i = 0; i < n; ++i)
      if (near(m, a.z[i])) {
        parent_.push_back(static_cast<int>(i));
        transform_.push_back({1.0, 0.0, -1.0, 2.0 * m.pos});
      }
    for (std::size_t g = 0; g < nxGhosts; ++g) {
      const int p = parent_[g];
      if (near(m, a.z[p])) {
        parent_.push_back(p);
        transform_.push_back({transform_[g].sx, transform_[g].ox, -1.0, 2.0 * m.pos});
      }
    }
  }
  a.resize(n + parent_.size());
  for (std::size_t g = 0; g < parent_.size(); ++g) {
    const std::size_t k = n + g, p = static_cast<std::size_t>(parent_[g]);
    a.forEachFixed([k, p](auto& v) { v[k] = v[p]; });
  }
  refreshGhosts(a, n);
  return parent_.size();
}

void Boundaries::refreshGhosts(PairArrays& a, std::size_t n) const {
  const long ng = static_cast<long>(parent_.size());
#pragma omp parallel for schedule(static) if (ng > kParallelElements)
  for (long g = 0; g < ng; ++g) {
    const std::size_t k = n + static_cast<std::size_t>(g);
    const std::size_t p = static_cast<std::size_t>(parent_[g]);
    const Transform& t = transform_[g];
    a.x[k] = t.sx * a.x[p] + t.ox;
    a.z[k] = t.sz * a.z[p] + t.oz;
    if (!a.lean) {
      a.vx[k] = t.sx * a.vx[p];
      a.vz[k] = t.sz * a.vz[p];
    }
    a.forEachCopied([k, p](auto& v) { v[k] = v[p]; });
  }
}

void Boundaries::mirrorGhostVectors(double* vx, double* vz, std::size_t n) const {
  for (std::size_t g = 0; g < parent_.size(); ++g) {
    const std::size_t p = static_cast<std::size_t>(parent_[g]);
    vx[n + g] = transform_[g].sx * vx[p];
    vz[n + g] = transform_[g].sz * vz[p];
  }
}

void Boundaries::copyGhostScalars(double* v, std::size_t n) const {
  for (std::size_t g = 0; g < parent_.size(); ++g)
    v[n + g] = v[static_cast<std::size_t>(parent_[g])];
}

void Boundaries::mirrorGhostTensors(double* xx, double* zz, double* xz, std::size_t n) const {
  for (std::size_t g = 0; g < parent_.size(); ++g) {
    const std::size_t p = static_cast<std::size_t>(parent_[g]);
    xx[n + g] = xx[p];
    zz[n + g] = zz[p];
    xz[n + g] = transform_[g].sx * transform_[g].sz * xz[p];
  }
}

bool Boundaries::outflowed(double x, double z) const {
  return (outflow_[0] && x < domain_.xmin) || (outflow_[1] && x > domain_.xmax) ||
         (outflow_[2] && z < domain_.zmin) || (outflow_[3] && z > domain_.zmax);
}

bool Boundaries::reflect(double& x, double& z, double& vx, double& vz) const {
  bool moved = false;
  for (const Mirror& m : mirrors_) {
    double& coord = m.axis == 0 ? x : z;
    double& vel = m.axis == 0 ? vx : vz;
    if (m.lower ? coord < m.pos : coord > m.pos) {
      coord = 2.0 * m.pos - coord;
      vel = -vel;
      moved = true;
    }
  }
  return moved;
}

}  // namespace hvi::sph::detail
