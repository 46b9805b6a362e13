//! @file Initial conserved state of the grid from the scene's bodies.
#include <algorithm>
#include <cmath>
#include <vector>

#include "hvi/common/stop_flag.hpp"
#include "hvi/tvd/tvd.hpp"

namespace hvi::tvd {

// With markers, each cell takes the state of the object that covers most of it (the
// configuration array from the marker lines), vacuum cells are empty. Without markers the
// conserved state of a cell is the volume average over 4 x 4 sample points, each in the first
// body (scene order) that contains it or in vacuum, which there is the single material at half
// the vacuum density, at rest and at e = 0: bodies keep their mass to the sampling accuracy
// and a discontinuity crossing a cell starts smeared over that cell only.
Ownership::ObjectState TvdSolver::stateAtCentre(const cases::Scene& scene, std::size_t body,
                                                std::size_t cell) const {
  Ownership::ObjectState st = bodyStates_[body];
  if (scene.bodies[body].radial) {  // a radial field is sampled at the cell centre
    const long i = static_cast<long>(cell) % grid_.nx, k = static_cast<long>(cell) / grid_.nx;
    const Vec2 v =
        cases::initialVelocity(scene.bodies[body], geometry_,
                               {grid_.x0 + (i + 0.5) * grid_.dx, grid_.z0 + (k + 0.5) * grid_.dz});
    st.vx = v.x;
    st.vz = v.z;
  }
  return st;
}

void TvdSolver::addState(Conserved& U, std::size_t c, const Ownership::ObjectState& b,
                         double weight) {
  U.rho[c] += weight * b.rho;
  U.mx[c] += weight * b.rho * b.vx;
  U.mz[c] += weight * b.rho * b.vz;
  U.E[c] += weight * b.rho * (b.e + 0.5 * (b.vx * b.vx + b.vz * b.vz));
}

void TvdSolver::initialiseState(const cases::Scene& scene) {
  const long cells = grid_.cells();
  const auto n = static_cast<std::size_t>(cells);
  U_.rho.assign(n, 0.0);
  U_.mx.assign(n, 0.0);
  U_.mz.assign(n, 0.0);
  U_.E.assign(n, 0.0);
  auto put = [&](std::size_t c, const Ownership::ObjectState& b, double weight) {
    addState(U_, c, b, weight);
  };

  if (markersOn_) {
    const std::vector<int>& owner = ownership_.owner();  // rasterised by Ownership::setUp
    for (std::size_t c = 0; c < n; ++c) {
      if (owner[c] < 0) continue;
      put(c, stateAtCentre(scene, static_cast<std::size_t>(owner[c]), c), 1.0);
    }
    return;
  }

  const Ownership::ObjectState vacuum{0.5 * rhoCut_[static_cast<std::size_t>(singleMaterial_)], 0.0, 0.0, 0.0};
  constexpr int S = 4;
  const bool rz = geometry_ == Geometry::Axisymmetric;
  const std::size_t nb = scene.bodies.size();
  // Up to 5e7 cells of 16 samples each (tens of seconds): built in blocks of 2^20 cells so that
  // a stop request is honoured between blocks. Each cell's state depends on that cell only, so
  // the blocking changes no bit.
  constexpr long kBlock = 1L << 20;
  for (long c0 = 0; c0 < cells; c0 += kBlock) {
    throwIfStopRequested("the TVD initial state");
    const long c1 = std::min(cells, c0 + kBlock);
#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
    {
      // Weights are summed per body and the states combined in body order, so the result does
      // not depend on the order of the samples: mirror-image cells get bitwise mirrored states.
      // A radial field is averaged over the samples: momentum sum(w v) per body, and the kinetic
      // energy of that mean velocity (the spread of directions in a cell at the centre must not
      // become heat in a cold stream). A uniform body needs neither.
      std::vector<double> weight(nb + 1), wvx(nb + 1), wvz(nb + 1);
#pragma omp for schedule(static)
      for (long c = c0; c < c1; ++c) {
        const int i = static_cast<int>(c % grid_.nx), k = static_cast<int>(c / grid_.nx);
        std::fill(weight.begin(), weight.end(), 0.0);
        std::fill(wvx.begin(), wvx.end(), 0.0);
        std::fill(wvz.begin(), wvz.end(), 0.0);
        for (int a = 0; a < S; ++a) {
          for (int b = 0; b < S; ++b) {
            const Vec2 p{grid_.x0 + (i + (a + 0.5) / S) * grid_.dx,
                         grid_.z0 + (k + (b + 0.5) / S) * grid_.dz};
            std::size_t owner = nb;  // vacuum
            for (std::size_t bi = 0; bi < nb; ++bi)
              if (cases::contains(scene.bodies[bi].shape, p)) {
                owner = bi;
                break;
              }
            const double w = rz ? p.x : 1.0;  // r-z: volume weight r
            weight[owner] += w;
            if (owner < nb && scene.bodies[owner].radial) {
              const Vec2 v = cases::initialVelocity(scene.bodies[owner], geometry_, p);
              wvx[owner] += w * v.x;
              wvz[owner] += w * v.z;
            }
          }
        }
        double wsum = 0.0;
        for (double w : weight) wsum += w;
        const auto cc = static_cast<std::size_t>(c);
        for (std::size_t bi = 0; bi <= nb; ++bi) {
          if (!(weight[bi] > 0.0)) continue;
          if (bi < nb && scene.bodies[bi].radial) {
            const Ownership::ObjectState& b = bodyStates_[bi];
            U_.rho[cc] += b.rho * weight[bi] / wsum;
            U_.mx[cc] += b.rho * wvx[bi] / wsum;
            U_.mz[cc] += b.rho * wvz[bi] / wsum;
            const double vx = wvx[bi] / weight[bi], vz = wvz[bi] / weight[bi];
            U_.E[cc] += b.rho * (b.e + 0.5 * (vx * vx + vz * vz)) * weight[bi] / wsum;
          } else {
            put(cc, bi < nb ? bodyStates_[bi] : vacuum, weight[bi] / wsum);
          }
        }
      }
    }
  }
}

}  // namespace hvi::tvd
