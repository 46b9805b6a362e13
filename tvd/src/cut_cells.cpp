//! @file The conservative cut-cell mode's set-up and time-step pass (docs/tvd.md,
//! "Conservative interfaces").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "eos_line.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"

namespace hvi::tvd {

// Each phase takes, on its part of every cell, the state of its body covering most of the cell
// (a radial velocity field at the cell centre): every body starts with its exact polygon volume
// and mass, not that of its rasterised cells.
void TvdSolver::initialiseCut(const cases::Scene& scene) {
  const int M = static_cast<int>(materials_.size());
  phases_.resize(M, grid_);
  measurePhases();
  const long cells = grid_.cells();
  const auto n = static_cast<std::size_t>(cells);
  const auto& frac = ownership_.fractions();
  const std::size_t objects = objectMaterial_.size();
  for (std::size_t c = 0; c < n; ++c) {
    for (int p = 0; p < M; ++p) {
      const double a = phases_.alpha[static_cast<std::size_t>(p)][c];
      if (!(a >= kPhaseAbsent)) continue;
      std::size_t best = objects;
      double bestF = 0.0;
      for (std::size_t o = 0; o < objects; ++o)
        if (objectMaterial_[o] == p && frac[o * n + c] > bestF) {
          bestF = frac[o * n + c];
          best = o;
        }
      if (best == objects) continue;
      Ownership::ObjectState st = bodyStates_[best];
      if (scene.bodies[best].radial) {
        const long i = static_cast<long>(c) % grid_.nx, k = static_cast<long>(c) / grid_.nx;
        const Vec2 v = cases::initialVelocity(
            scene.bodies[best], geometry_,
            {grid_.x0 + (i + 0.5) * grid_.dx, grid_.z0 + (k + 0.5) * grid_.dz});
        st.vx = v.x;
        st.vz = v.z;
      }
      Conserved& q = phases_.q[static_cast<std::size_t>(p)];
      q.rho[c] = a * st.rho;
      q.mx[c] = a * st.rho * st.vx;
      q.mz[c] = a * st.rho * st.vz;
      q.E[c] = a * st.rho * (st.e + 0.5 * (st.vx * st.vx + st.vz * st.vz));
    }
  }
  volumeFresh_ = true;
  phases_.mixture(U_);
}

// Largest signal speed over every phase cell, the check that each is physical, and (for the
// markers) the mixture velocity of every cell that holds material.
double TvdSolver::signalSpeedCut(double* vx, double* vz, long* worstCell) const {
  const long cells = grid_.cells();
  double smax = 0.0;
  long worst = -1, bad = -1;
  int badPhase = -1;
  for (int p = 0; p < phases_.count; ++p) {
    const auto& alpha = phases_.alpha[static_cast<std::size_t>(p)];
    const Conserved& q = phases_.q[static_cast<std::size_t>(p)];
    std::visit(
        [&](const auto& eos) {
#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
          {
            double sLocal = 0.0;
            long wLocal = -1, bLocal = -1;
#pragma omp for schedule(static)
            for (long c = 0; c < cells; ++c) {
              const auto cc = static_cast<std::size_t>(c);
              const double a = alpha[cc];
              if (!(a >= kPhaseAbsent)) continue;
              const double r = q.rho[cc] / a;
              if (r == 0.0) continue;  // emptied by the positivity limiter; filled by repair
              if (!(r > 0.0)) {
                if (bLocal < 0) bLocal = c;
                continue;
              }
              const CellState s =
                  detail::cellState(eos, r, q.mx[cc] / a, q.mz[cc] / a, q.E[cc] / a);
              const double v = std::max(std::abs(s.u), std::abs(s.w)) + s.c;
              if (!std::isfinite(v)) {
                if (bLocal < 0) bLocal = c;
                continue;
              }
              if (v > sLocal) {
                sLocal = v;
                wLocal = c;
              }
            }
#pragma omp critical(hvi_tvd_signal_cut)
            {
              if (sLocal > smax || (sLocal == smax && wLocal >= 0 && wLocal < worst)) {
                smax = sLocal;
                worst = wLocal;
              }
              if (bLocal >= 0 && (bad < 0 || bLocal < bad)) {
                bad = bLocal;
                badPhase = p;
              }
            }
          }
        },
        materials_[static_cast<std::size_t>(p)].eos);
  }
  if (bad >= 0) {
    const auto c = static_cast<std::size_t>(bad);
    const Conserved& q = phases_.q[static_cast<std::size_t>(badPhase)];
    throw SimulationError(fmt::format(
        "tvd: step {}, t = {:.6g} us: material '{}' in cell (i={}, k={}) is unphysical: volume "
        "fraction {:.6g}, partial density {:.6g}, momentum = ({:.6g}, {:.6g}), energy density "
        "{:.6g}",
        step_, time_, materials_[static_cast<std::size_t>(badPhase)].name, bad % grid_.nx,
        bad / grid_.nx, phases_.alpha[static_cast<std::size_t>(badPhase)][c], q.rho[c], q.mx[c],
        q.mz[c], q.E[c]));
  }
  if (vx != nullptr) {
#pragma omp parallel for schedule(static) num_threads(threads_) if (cells >= kParallelCells)
    for (long c = 0; c < cells; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      const double r = U_.rho[cc];
      vx[c] = r > 0.0 ? U_.mx[cc] / r : 0.0;
      vz[c] = r > 0.0 ? U_.mz[cc] / r : 0.0;
    }
  }
  if (worstCell != nullptr) *worstCell = worst;
  return smax;
}

}  // namespace hvi::tvd
