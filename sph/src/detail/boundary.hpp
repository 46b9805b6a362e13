//! @file Domain boundaries for particles: mirror ghosts at walls and the axis, outflow.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "detail/arrays.hpp"
#include "hvi/cases/scene.hpp"

namespace hvi::sph::detail {

//! A wall (or the r-z axis, or a planar symmetry plane) is a mirror: every particle within the
//! search radius of it has a ghost at its mirror image with the normal velocity reversed and
//! every other value copied, so the sums see the material continued symmetrically. Corners get
//! the ghosts of ghosts. An outflow side removes the particles that cross it.
class Boundaries {
 public:
  Boundaries(const cases::Domain& domain, Geometry geometry);

  //! Rebuilds the ghosts of the real particles [0, n) that lie within `margin` of a mirror and
  //! appends them (arrays resized to n + ghosts); copies the parents' values. Returns #ghosts.
  std::size_t makeGhosts(PairArrays& a, std::size_t n, double margin);
  //! Copies the parents' current values into the ghosts made by the last makeGhosts.
  void refreshGhosts(PairArrays& a, std::size_t n) const;
  //! Sets the ghost entries [n, n + ghosts) of a vector field (vx, vz) to their parents',
  //! mirrored as velocities are.
  void mirrorGhostVectors(double* vx, double* vz, std::size_t n) const;
  //! Sets the ghost entries [n, n + ghosts) of a scalar field to their parents'.
  void copyGhostScalars(double* v, std::size_t n) const;
  //! Sets the ghost entries of a symmetric in-plane tensor (xx, zz, xz) to their parents':
  //! a mirror normal to x or to z keeps xx and zz and changes the sign of xz (strength).
  void mirrorGhostTensors(double* xx, double* zz, double* xz, std::size_t n) const;
  [[nodiscard]] std::size_t ghostCount() const { return parent_.size(); }

  //! True if (x, z) lies beyond an outflow side of the domain.
  [[nodiscard]] bool outflowed(double x, double z) const;
  //! A particle that went through a mirror is put back at its image, normal velocity reversed.
  //! Returns true if it moved.
  bool reflect(double& x, double& z, double& vx, double& vz) const;

 private:
  struct Mirror {
    int axis;  // 0: plane x = pos, 1: plane z = pos
    double pos;
    bool lower;  // the domain lies at coordinates >= pos
  };
  struct Transform {
    double sx, ox, sz, oz;  // x' = sx x + ox, z' = sz z + oz
  };
  cases::Domain domain_;
  std::vector<Mirror> mirrors_;
  std::array<bool, 4> outflow_{};
  std::vector<int> parent_;
  std::vector<Transform> transform_;
};

}  // namespace hvi::sph::detail
