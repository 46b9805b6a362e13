//! @file Particle resampling: interior density, material boundary, r-z axis and mass conventions.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "hvi/common/error.hpp"
#include "hvi/compare/resample.hpp"
#include "synthetic.hpp"

namespace hvi::compare {
namespace {

using test::box;
using test::lattice;
using test::Scene2;

constexpr double kDx = 0.01;  // particle spacing, cm (the study's SPH resolution)

//! Kernel normalisation error of a square lattice with h = dx: aliasing (Poisson summation) adds
//! at most 4 exp(-pi^2 h^2 / dx^2) = 2.1e-4, cutting the Gaussian at 3h removes exp(-9) = 1.2e-4.
constexpr double kNormError = 4.0 * 5.17e-5 + 1.24e-4;

//! Row-wise extent of material cells [first face, last face] in row k (NaN if none).
std::pair<double, double> rowExtent(const Resampled& r, int k) {
  double lo = NAN, hi = NAN;
  for (int i = 0; i < r.grid.nx; ++i)
    if (r.material[static_cast<long>(k) * r.grid.nx + i] >= 0) {
      if (std::isnan(lo)) lo = r.xCentre(i) - 0.5 * r.grid.dx;
      hi = r.xCentre(i) + 0.5 * r.grid.dx;
    }
  return {lo, hi};
}

TEST(ResampleParticles, UniformLatticeInteriorDensityAndBoundary) {
  // A 0.4 x 0.3 cm block whose density rises linearly in x (Shepard interpolation reproduces a
  // linear field exactly on a symmetric neighbourhood; the lattice breaks symmetry only through
  // the same aliasing term, of relative size ~1e-4 of grad(rho) * h).
  const double grad = 1.4;
  Scene2 s{box(0.0, 0.4, 0.0, 0.3)};
  s.density = [&](Vec2 p) { return 2.79 + grad * p.x; };
  const Snapshot snap = lattice(s, 0.0, 0.4, 0.0, 0.3, kDx);
  // A target grid that matches neither the spacing nor the offset of the lattice.
  GridSpec g{45, 35, -0.0503, -0.0497, 0.0111, 0.0111};
  const Resampled r = resample(snap, g);

  const double h = kDx, margin = 3.0 * h + g.dx;
  double maxRhoErr = 0.0, maxFracErr = 0.0;
  int interior = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const double x = r.xCentre(i), z = r.zCentre(k);
      if (x < margin || x > 0.4 - margin || z < margin || z > 0.3 - margin) continue;
      const long c = static_cast<long>(k) * g.nx + i;
      ASSERT_EQ(r.material[c], 0);
      maxRhoErr = std::max(maxRhoErr, std::abs(r.density[c] - (2.79 + grad * x)));
      maxFracErr = std::max(maxFracErr, std::abs(r.fraction[c] - 1.0));
      ++interior;
    }
  EXPECT_GT(interior, 400);
  EXPECT_LT(maxFracErr, kNormError) << "kernel-weighted volume fraction inside the block";
  EXPECT_LT(maxRhoErr, 1e-3 * grad * h) << "linear density inside the block";
  RecordProperty("max_interior_density_error", fmt::format("{:.3e}", maxRhoErr));
  RecordProperty("max_interior_fraction_error", fmt::format("{:.3e}", maxFracErr));

  // The material boundary: within one particle spacing of the block's faces x = 0, 0.4.
  double maxEdgeErr = 0.0;
  for (int k = 0; k < g.nz; ++k) {
    const double z = r.zCentre(k);
    if (z < margin || z > 0.3 - margin) continue;
    const auto [lo, hi] = rowExtent(r, k);
    maxEdgeErr = std::max({maxEdgeErr, std::abs(lo - 0.0), std::abs(hi - 0.4)});
  }
  EXPECT_LE(maxEdgeErr, kDx);
  // Vacuum is vacuum: no material more than a cell beyond the block.
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i)
      if (r.xCentre(i) < -g.dx || r.xCentre(i) > 0.4 + g.dx || r.zCentre(k) < -g.dx ||
          r.zCentre(k) > 0.3 + g.dx) {
        const long c = static_cast<long>(k) * g.nx + i;
        ASSERT_EQ(r.material[c], -1);
        ASSERT_EQ(r.density[c], 0.0);
      }
}

TEST(ResampleParticles, BoundaryOnAFineGridSitsAtTheFace) {
  // On a grid of half the particle spacing, the 0.5 crossing of the fraction is at the face by
  // the lattice's mirror symmetry, so the boundary is found to within one target cell.
  const Snapshot snap = lattice(Scene2{box(0.0, 0.2, 0.0, 0.2)}, 0.0, 0.2, 0.0, 0.2, kDx);
  GridSpec g{60, 60, -0.05, -0.05, 0.005, 0.005};
  const Resampled r = resample(snap, g);
  const auto [lo, hi] = rowExtent(r, 30);
  EXPECT_NEAR(lo, 0.0, g.dx);
  EXPECT_NEAR(hi, 0.2, g.dx);
}

TEST(ResampleParticles, ModifiedSphMassesKeepTheBoundaryWithinOneSpacing) {
  // Modified SPH (spec section 3, docs/method.md) iterates the masses until sum_j m_j W_ij =
  // rho0 at every particle: surface particles end up ~1.45 times heavier, so m / rho there
  // exceeds dx^2 and the 0.5 contour of the fraction moves outward (by ~0.27 dx for h = dx). It
  // must stay within one spacing, and the interior must be untouched.
  Snapshot snap = lattice(Scene2{box(0.0, 0.3, 0.0, 0.3)}, 0.0, 0.3, 0.0, 0.3, kDx);
  const auto n = static_cast<long>(snap.positions.size());
  std::vector<double>& m = snap.fields[1].data;
  const double rho0 = 2.79, h = kDx;
  for (int it = 0; it < 60; ++it) {  // converges geometrically; 60 sweeps reach ~1e-9
    std::vector<double> rho(n, 0.0);
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < n; ++j) {
        const Vec2 d = snap.positions[i] - snap.positions[j];
        const double r2 = dot(d, d);
        if (r2 < 9 * h * h) rho[i] += m[j] * std::exp(-r2 / (h * h)) / (std::numbers::pi * h * h);
      }
    for (long i = 0; i < n; ++i) m[i] *= rho0 / rho[i];
  }
  const GridSpec g{200, 200, -0.1, -0.1, 0.25 * kDx, 0.25 * kDx};
  ResampleOptions study;
  study.sphReconstruction = SphReconstruction::Constant;
  const Resampled r = resample(snap, g, study);
  const auto [lo, hi] = rowExtent(r, 100);
  EXPECT_NEAR(lo, 0.0, kDx);
  EXPECT_NEAR(hi, 0.3, kDx);
  EXPECT_LT(lo, 0.0);  // the shift is outward, as the heavier surface particles imply
  RecordProperty("modified_sph_edge_shift_dx", fmt::format("{:.3f}", (0.3 - hi) / kDx));
  const long centre = 100L * g.nx + 100;  // (0.15, 0.15), the middle of the block
  EXPECT_NEAR(r.density[centre], rho0, 1e-6 * rho0);
  // The adaptive reading gives each particle at least the area dx^2 its neighbours leave it. The
  // iterated interior masses make m / rho = dx^2 / (lattice kernel sum), which differs from dx^2
  // by at most the normalisation error: that bounds the change of density; the surface
  // particles are heavier (m / rho > dx^2) and keep theirs, so the boundary does not move.
  const Resampled a = resample(snap, g);
  EXPECT_NEAR(a.density[centre], rho0, kNormError * rho0);
  EXPECT_EQ(rowExtent(a, 100), rowExtent(r, 100));
}

TEST(ResampleParticles, MaterialIdFromLargestContribution) {
  Scene2 s{[](Vec2 p) { return p.x < 0.2 ? 0 : 1; }};
  s.density = [](Vec2 p) { return p.x < 0.2 ? 2.79 : 7.85; };
  const Snapshot snap = lattice(s, 0.0, 0.4, 0.0, 0.2, kDx);
  GridSpec g{40, 20, 0.0, 0.0, 0.01, 0.01};
  const Resampled r = resample(snap, g);
  for (int k = 4; k < 16; ++k) {
    int first = -1;
    for (int i = 0; i < g.nx && first < 0; ++i)
      if (r.material[static_cast<long>(k) * g.nx + i] == 1) first = i;
    ASSERT_GE(first, 0);
    EXPECT_NEAR(r.xCentre(first) - 0.5 * g.dx, 0.2, kDx);
    // Far from the interface each material has its own density (Shepard mixes only within 3h).
    EXPECT_NEAR(r.density[static_cast<long>(k) * g.nx + 5], 2.79, 1e-12);
    EXPECT_NEAR(r.density[static_cast<long>(k) * g.nx + 35], 7.85, 1e-12);
  }
}

TEST(ResampleParticles, AxisymmetricMirrorAndMassConventions) {
  // A cylinder r < 0.3, 0 < z < 0.2: cells at the axis must be full (the mirror images supply the
  // kernel weight from r < 0) and both mass conventions must give the same field.
  const Scene2 s{box(0.0, 0.3, 0.0, 0.2)};
  const Snapshot ring = lattice(s, 0.0, 0.3, 0.0, 0.2, kDx, 1.0, Geometry::Axisymmetric, true);
  const Snapshot perRad = lattice(s, 0.0, 0.3, 0.0, 0.2, kDx, 1.0, Geometry::Axisymmetric, false);
  const GridSpec g = coveringGrid(ring, kDx);
  EXPECT_EQ(g.x0, 0.0);
  const Resampled a = resample(ring, g), b = resample(perRad, g);
  ResampleOptions wrong;
  wrong.rzMass = RzMass::PerRadian;  // forcing the wrong convention must show (fraction ~ 2 pi)
  const Resampled c = resample(ring, g, wrong);
  double maxFracErr = 0.0;
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const long cell = static_cast<long>(k) * g.nx + i;
      ASSERT_NEAR(a.fraction[cell], b.fraction[cell], 1e-12);
      const double r = a.xCentre(i), z = a.zCentre(k);
      if (r < 0.3 - 4 * kDx && z > 4 * kDx && z < 0.2 - 4 * kDx) {
        maxFracErr = std::max(maxFracErr, std::abs(a.fraction[cell] - 1.0));
        EXPECT_NEAR(c.fraction[cell], 2.0 * std::numbers::pi, 2.0 * std::numbers::pi * 0.05);
        EXPECT_NEAR(a.density[cell], 2.79, 1e-12);
      }
    }
  // Ring masses divided by 2 pi r rho give back the meridional areas dx^2, and the mirror images
  // continue the lattice across the axis, so the kernel sum is 1 up to the normalisation error.
  EXPECT_LT(maxFracErr, kNormError);
  RecordProperty("rz_max_interior_fraction_error", fmt::format("{:.3e}", maxFracErr));
  // The first column (touching the axis) is material, the outer face within one spacing.
  for (int k = 4; k < g.nz - 4; ++k) {
    EXPECT_EQ(a.material[static_cast<long>(k) * g.nx], 0);
    const auto [lo, hi] = rowExtent(a, k);
    EXPECT_EQ(lo, 0.0);
    if (a.zCentre(k) > 2 * kDx && a.zCentre(k) < 0.2 - 2 * kDx) {
      EXPECT_NEAR(hi, 0.3, kDx);
    }
  }
}

// --- The adaptive reading (docs/compare.md, "Sparse particles") --------------------------------

//! Share of the cells whose centre lies at least `margin` inside [x0, x1] x [z0, z1] that are
//! vacuum, and the largest |density - rho| and |fraction - 1| over the material ones.
struct Interior {
  double vacuumShare = 0.0, maxRhoErr = 0.0, maxFracErr = 0.0;
};
Interior interior(const Resampled& r, double x0, double x1, double z0, double z1, double margin,
                  double rho) {
  Interior out;
  long cells = 0, vacuum = 0;
  for (int k = 0; k < r.grid.nz; ++k)
    for (int i = 0; i < r.grid.nx; ++i) {
      const double x = r.xCentre(i), z = r.zCentre(k);
      if (x < x0 + margin || x > x1 - margin || z < z0 + margin || z > z1 - margin) continue;
      const long c = static_cast<long>(k) * r.grid.nx + i;
      ++cells;
      if (r.material[c] < 0) {
        ++vacuum;
        continue;
      }
      out.maxRhoErr = std::max(out.maxRhoErr, std::abs(r.density[c] - rho));
      out.maxFracErr = std::max(out.maxFracErr, std::abs(r.fraction[c] - 1.0));
    }
  out.vacuumShare = cells ? static_cast<double>(vacuum) / cells : 1.0;
  return out;
}

//! A spray: particles with h = kDx on a square lattice of spacing 3 h, standing for a cloud of
//! density rhoCloud. `fragments`: each particle keeps a solid density 9 rhoCloud (volume h^2, a
//! droplet, as an SPH particle that left its neighbours' kernels keeps the density it had);
//! else its density is the cloud's (volume (3h)^2).
Snapshot spray(double rhoCloud, bool fragments, Geometry geom, double x0, double x1, double z0,
               double z1) {
  const double spacing = 3.0 * kDx;
  Scene2 sc{box(x0, x1, z0, z1)};
  sc.density = [&](Vec2) { return rhoCloud; };
  Snapshot snap = lattice(sc, x0, x1, z0, z1, spacing, kDx / spacing, geom);
  if (fragments)
    for (double& rho : snap.fields[0].data) rho *= 9.0;  // same mass, a ninth of the volume
  return snap;
}

TEST(ResampleParticles, AdaptiveReadingFillsASparseSprayThatTheConstantReadingLeavesEmpty) {
  // Expected, for a spray of spacing 3h (Gaussian cut at 3h):
  // - constant reading, cloud density: at the centre of each square of four particles (2.12 h
  //   from each) the fraction is 4 (9 / pi) exp(-4.5) = 0.13 < 1/2: a hole; next to a particle
  //   it is 9 / pi > 1/2. The cloud reads as material blobs with holes between them;
  // - constant reading, fragments (volume h^2): the fraction peaks at ~1/pi < 1/2: all vacuum;
  // - adaptive: each particle's second neighbour is at s = 3h, so it is read with length 3h and
  //   volume (3h)^2, density rhoCloud: a lattice read at h = spacing, whose fraction is 1 to the
  //   normalisation error kNormError and whose Shepard density of a uniform field is exact.
  const double rhoCloud = 2.79 / 9.0, spacing = 3.0 * kDx;
  // Ring masses named: RzMass::Auto tells them from per-radian ones by the kernel sum inside a
  // body, which a spray of fragments does not have.
  ResampleOptions adaptive, study;
  adaptive.rzMass = study.rzMass = RzMass::Ring;
  study.sphReconstruction = SphReconstruction::Constant;
  for (const Geometry geom : {Geometry::Planar, Geometry::Axisymmetric})
    for (const bool fragments : {false, true}) {
      SCOPED_TRACE(fmt::format("{} {}", geom == Geometry::Planar ? "planar" : "r-z",
                               fragments ? "fragments" : "cloud density"));
      const double x0 = 0.0, x1 = 0.6, z0 = 0.0, z1 = 0.6;
      const Snapshot snap = spray(rhoCloud, fragments, geom, x0, x1, z0, z1);
      const GridSpec g = coveringGrid(snap, kDx / 3.0);
      // In r-z the axis is inside the cloud (the mirror images continue it): no margin there.
      const double margin = 3.0 * spacing;
      const double xl = geom == Geometry::Planar ? x0 : x0 - margin;
      const Resampled ra = resample(snap, g, adaptive), rc = resample(snap, g, study);
      const Interior a = interior(ra, xl, x1, z0, z1, margin, rhoCloud);
      EXPECT_EQ(a.vacuumShare, 0.0);
      EXPECT_LT(a.maxRhoErr, 1e-12);
      EXPECT_LT(a.maxFracErr, kNormError);
      const Interior c = interior(rc, xl, x1, z0, z1, margin, rhoCloud);
      if (fragments) {
        EXPECT_EQ(c.vacuumShare, 1.0);
      }
      // The holes: the cell holding each square's centre.
      int holes = 0, squares = 0;
      for (double x = x0 + spacing; x < x1 - margin; x += spacing)
        for (double z = z0 + margin; z < z1 - margin; z += spacing) {
          if (geom == Geometry::Planar && x < x0 + margin) continue;
          const int i = static_cast<int>((x - g.x0) / g.dx), k = static_cast<int>((z - g.z0) / g.dz);
          const long cell = static_cast<long>(k) * g.nx + i;
          ++squares;
          holes += rc.material[cell] < 0;
          EXPECT_EQ(ra.material[cell], 0);
        }
      EXPECT_GT(squares, 50);
      EXPECT_EQ(holes, squares);
      RecordProperty(fmt::format("constant_vacuum_share_{}_{}", geom == Geometry::Planar ? 0 : 1,
                                 fragments ? 1 : 0),
                     fmt::format("{:.3f}", c.vacuumShare));
    }
}

TEST(ResampleParticles, AdaptiveReadingLeavesALatticeAsTheConstantOne) {
  // A body's lattice at rest or compressed 2x along z (masses keep rho consistent with the
  // area per particle), h = dx and 1.5 dx: the second neighbour is at the smaller spacing,
  // which is <= h and <= sqrt(m / rho), so the adaptive reading changes nothing but the
  // round-off of the lattice positions in s (the two readings agree to 1e-12).
  ResampleOptions study;
  study.sphReconstruction = SphReconstruction::Constant;
  for (const double stretch : {1.0, 0.5})
    for (const double hFactor : {1.0, 1.5})
    for (const Geometry geom : {Geometry::Planar, Geometry::Axisymmetric}) {
      SCOPED_TRACE(fmt::format("stretch {} h {} dx {}", stretch, hFactor,
                               geom == Geometry::Planar ? "planar" : "r-z"));
      Scene2 sc{box(0.0, 0.3, 0.0, 0.2)};
      sc.density = [&](Vec2 p) { return (2.79 + 1.4 * p.x) / stretch; };
      Snapshot snap = lattice(sc, 0.0, 0.3, 0.0, 0.2, kDx, hFactor, geom);
      for (Vec2& p : snap.positions) p.z *= stretch;
      const GridSpec g = coveringGrid(snap, 0.7 * kDx);
      const Resampled a = resample(snap, g), c = resample(snap, g, study);
      ASSERT_EQ(a.material, c.material);
      for (std::size_t i = 0; i < a.density.size(); ++i) {
        ASSERT_NEAR(a.density[i], c.density[i], 1e-12 * 4.0);
        ASSERT_NEAR(a.fraction[i], c.fraction[i], 1e-12);
      }
    }
}

TEST(ResampleParticles, AdaptiveReadingOptionsAreChecked) {
  EXPECT_EQ(parseSphReconstruction("constant"), SphReconstruction::Constant);
  EXPECT_EQ(parseSphReconstruction("adaptive"), SphReconstruction::Adaptive);
  EXPECT_THROW(parseSphReconstruction("knn"), InputError);
  const Snapshot snap = lattice(Scene2{box(0.0, 0.1, 0.0, 0.1)}, 0.0, 0.1, 0.0, 0.1, kDx);
  ResampleOptions o;
  o.adaptiveMaxFactor = 0.5;
  EXPECT_THROW(resample(snap, coveringGrid(snap, kDx), o), InputError);
}

TEST(ResampleParticles, NativeSpacingAndMissingFields) {
  Snapshot snap = lattice(Scene2{box(0.0, 0.1, 0.0, 0.1)}, 0.0, 0.1, 0.0, 0.1, kDx, 1.3);
  EXPECT_NEAR(nativeSpacing(snap), kDx, 1e-12);
  snap.fields.erase(snap.fields.begin() + 2);  // smoothing_length
  EXPECT_THROW(resample(snap, coveringGrid(snap, 0.05)), InputError);
}

}  // namespace
}  // namespace hvi::compare
