//! @file Resampling an SPH or TVD snapshot onto a common uniform grid (docs/compare.md).
#pragma once
#include <string>
#include <vector>

#include "hvi/common/geometry.hpp"
#include "hvi/common/snapshot.hpp"

namespace hvi::compare {

//! How particle masses are to be read in r-z (docs/compare.md, "Particle volumes").
enum class RzMass {
  Auto,       //!< decide between Ring and PerRadian from the data (interior kernel sum)
  Ring,       //!< m = 2 pi r rho A (the whole ring; what Totals::mass adds up)
  PerRadian,  //!< m = r rho A
};

//! The reconstruction length of a particle when it is read onto a grid (docs/compare.md,
//! "Sparse particles").
enum class SphReconstruction {
  //! Each particle's own smoothing length and volume m/rho: the study's reading. Particles that
  //! ended several h apart (an expanded debris cloud) leave vacuum between them.
  Constant,
  //! A particle stands for its share of the space around it: volume V' = max(m/rho, s^2), with
  //! s the distance to its second-nearest neighbour (at most adaptiveMaxFactor h), length
  //! max(h, sqrt(V')), density m / V'. A body's lattice at rest or compressed (h >= spacing)
  //! reads as with Constant.
  Adaptive,
};

struct ResampleOptions {
  //! A cell is material when the kernel-weighted particle fraction (or, for a grid source, the
  //! covered non-vacuum share of its area) is at least this.
  double materialThreshold = 0.5;
  //! Gaussian kernel support in units of h (the spec cuts it at 3h: section 3, docs/method.md).
  double kernelSupport = 3.0;
  RzMass rzMass = RzMass::Auto;
  SphReconstruction sphReconstruction = SphReconstruction::Adaptive;
  //! Adaptive: the largest reconstruction length, in units of the particle's own h. It bounds the
  //! share of space a lone particle can claim and the neighbour search (cost ~ this^2).
  double adaptiveMaxFactor = 4.0;
};

//! "constant" / "adaptive"; parseSphReconstruction throws InputError naming the allowed values.
const char* toString(SphReconstruction r);
SphReconstruction parseSphReconstruction(const std::string& name);

//! A snapshot on a uniform grid. Vectors are indexed like Snapshot cells: k * nx + i.
struct Resampled {
  GridSpec grid;
  Geometry geometry = Geometry::Planar;
  double time = 0.0;
  std::string solver;
  std::vector<double> density;   //!< g/cm^3; 0 in vacuum cells of a particle source
  std::vector<double> fraction;  //!< material (non-vacuum) share of the cell, 0..1 (~1 inside)
  std::vector<int> material;     //!< -1 vacuum, else index into materialNames
  std::vector<int> object;       //!< -1 vacuum or unknown, else index into objectNames
  bool hasObject = false;        //!< whether the source carried an "object" field
  //! Each class's own partial density, g/cm^3, class-major: materialDensity[m * cells + c] (and
  //! objectDensity likewise; empty without an "object" field). They add up to `density` where
  //! all the mass belongs to some class. A mixed cell's majority class is its `material`/`object`;
  //! these say how much of its mass each class holds (a particle source: kernel-weighted; a grid
  //! source: by the source cells' classes, whose own mixed cells count for their majority).
  std::vector<double> materialDensity;
  std::vector<double> objectDensity;
  std::vector<std::string> materialNames;
  std::vector<std::string> objectNames;

  //! Volume of cell (i, k) per unit depth (planar, cm^2) or per radian (r-z, cm^3 / rad).
  [[nodiscard]] double cellVolume(int i) const;
  [[nodiscard]] double xCentre(int i) const { return grid.x0 + (i + 0.5) * grid.dx; }
  [[nodiscard]] double zCentre(int k) const { return grid.z0 + (k + 0.5) * grid.dz; }
};

//! Resamples `s` onto `grid`. Particles: Shepard-normalised Gaussian kernel interpolation with
//! each particle's "smoothing_length" and volume m/rho (r-z: meridional area, mirrored across the
//! axis). Grids: area-overlap (r-z: r dr dz volume-overlap) average, which conserves mass
//! exactly. Throws InputError naming a missing or inconsistent field.
Resampled resample(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt = {});

//! The resolution of a snapshot, cm: max(dx, dz) of a grid; the median nearest-neighbour
//! distance of particles (independent of any mass convention).
double nativeSpacing(const Snapshot& s);

//! A grid of spacing `spacing` that covers every cell of a grid snapshot, or every particle of a
//! particle snapshot with 2 h to spare; r-z grids start at the axis. Where an input is a grid of
//! the same spacing the result shares its cell faces, so resampling that input is the identity.
GridSpec coveringGrid(const Snapshot& s, double spacing);
//! The smallest such grid covering both `a` and `b` (the common grid of compareSnapshots).
GridSpec coveringGrid(const Snapshot& a, const Snapshot& b, double spacing);

}  // namespace hvi::compare
