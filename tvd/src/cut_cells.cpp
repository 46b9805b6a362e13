//! @file The conservative cut-cell mode's set-up and time-step pass (docs/tvd.md,
//! "Conservative interfaces").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "eos_line.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"
#include "signal_speed.hpp"
#include "strength_step.hpp"

namespace hvi::tvd {

// Each phase takes, on its part of every cell, the state of its body covering most of the cell
// (a radial velocity field at the cell centre): every body starts with its exact polygon volume
// and mass, not that of its rasterised cells.
void TvdSolver::initialiseCut(const cases::Scene& scene) {
  const int M = static_cast<int>(materials_.size());
  phases_.resize(M, grid_);
  phases_.rho0.resize(static_cast<std::size_t>(M));
  for (int p = 0; p < M; ++p)
    phases_.rho0[static_cast<std::size_t>(p)] =
        eos::referenceDensity(materials_[static_cast<std::size_t>(p)].eos);
  measurePhases();
  const long cells = grid_.cells();
  const auto n = static_cast<std::size_t>(cells);
  // Phase p is body p (one material per body in this mode, TvdSolver's constructor), and a
  // phase is present only where its body's fraction is (the fit only scales fractions down).
  for (std::size_t c = 0; c < n; ++c) {
    for (int p = 0; p < M; ++p) {
      const double a = phases_.alpha[static_cast<std::size_t>(p)][c];
      if (!(a >= kPhaseAbsent)) continue;
      addState(phases_.q[static_cast<std::size_t>(p)], c,
               stateAtCentre(scene, static_cast<std::size_t>(p), c), a);
    }
  }
  volumeFresh_ = true;
  phases_.mixture(U_);
  mixtureStale_ = false;
}

// Largest signal speed over every phase cell, the check that each is physical, and (for the
// markers) the mixture velocity of every cell that holds material.
double TvdSolver::signalSpeedCut(double* vx, double* vz, long* worstCell) const {
  // Only the rows that can hold material (Phases::rowLo): outside, every phase is absent and
  // the mixture velocity 0, as the arrays already hold there.
  const long c0 = phases_.cellLo(), c1 = phases_.cellHi();
  detail::SpeedScan scan;
  int badPhase = -1;
  for (int p = 0; p < phases_.count; ++p) {
    const auto& alpha = phases_.alpha[static_cast<std::size_t>(p)];
    const Conserved& q = phases_.q[static_cast<std::size_t>(p)];
    const double rhoStep = rhoStep_[static_cast<std::size_t>(p)];
    const bool solid = strength_ && strength_->phases[static_cast<std::size_t>(p)].solid;
    std::visit(
        [&](const auto& eos) {
          const bool found =
              detail::scanSignalSpeed(c0, c1, threads_, scan, [&](long c, CellState& s) {
                const auto cc = static_cast<std::size_t>(c);
                const double a = alpha[cc];
                if (!(a >= kPhaseAbsent)) return 0;
                const double r = q.rho[cc] / a;
                if (r == 0.0) return 0;  // emptied by the positivity limiter; filled by repair
                // Below the vacuum density a cell is vacuum whatever the sign of its mass and
                // whatever it still moves with: the kernel's resetThin puts it at rest and cold
                // in the next sweep, booked (docs/tvd.md, "Vacuum cells of negative mass"); its
                // mass still counts, and it sets no time step.
                if (r < 0.0 && r > -rhoCut_[static_cast<std::size_t>(p)]) return 0;
                if (!(r > 0.0)) return -1;
                if (r < rhoStep) return 0;  // below the time-step density: not in the CFL
                s = detail::cellState(eos, r, q.mx[cc] / a, q.mz[cc] / a, q.E[cc] / a);
                // Strength: a solid phase's longitudinal wave c_L = sqrt(c^2 + 4G / (3 rho)).
                if (solid && !detail::failedMaterial(
                                 strength_->phases[static_cast<std::size_t>(p)].rq[detail::kDamage],
                                 cc, q.rho[cc]))
                  s.c = strength::longitudinalSoundSpeed(s.c, phaseShearModulus(p, r, s.e, s.p), r);
                return 1;
              });
          if (found) badPhase = p;
        },
        materials_[static_cast<std::size_t>(p)].eos);
  }
  const long bad = scan.bad, worst = scan.worst;
  const double smax = scan.smax;
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
    // The mixture velocity from the phases' sums in phase order (Phases::mixture's values).
    const int P = phases_.count;
    const Conserved* parts = phases_.q.data();
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelCells)
    for (long c = c0; c < c1; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      const double r = mixtureAt(parts, P, &Conserved::rho, cc);
      const double mx = mixtureAt(parts, P, &Conserved::mx, cc);
      const double mz = mixtureAt(parts, P, &Conserved::mz, cc);
      // A cell without material has no start velocity (NaN): one the phase enters during the
      // step (an opened cell, CutLineSolver::openFaces) moves its markers with its end velocity
      // alone (Ownership::centredVelocity), not half of it.
      constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
      vx[c] = r > 0.0 ? mx / r : kNone;
      vz[c] = r > 0.0 ? mz / r : kNone;
    }
  }
  if (worstCell != nullptr) *worstCell = worst;
  return smax;
}

// A phase cell below the time-step density sets no time step, so nothing bounds its velocity:
// round-off mass left behind by the interface exchange and the positivity limiter can move
// at thousands of cm/us (a Whipple run at 0.042 cm cells: 2140 cm/us in a cell of 1e-6 g/cm^3
// beside dense debris, 22 cells per step, until the fallback could not keep a neighbour
// positive). No conservative explicit flux keeps a cell positive once its velocity carries it
// beyond a cell per step (the donor-cell bound |u| dt / h <= 1), so each component is limited
// to h / dt before the sweeps: its momentum and the kinetic energy that takes are booked under
// floors, its internal energy and mass are kept. A cell that sets the step moves at most
// cfl <= 0.5 of a cell and is never touched. What can be: vapour below the time-step density
// expanding faster than h / dt = (fastest signal speed) / cfl, its mass under 1e-4 rho0 a cell.
namespace {

// A phase cell below the time-step density (limitThinVelocities).
inline bool isThin(double a, double m, double rhoStep) {
  return (a >= kPhaseAbsent) & (m > 0.0) & (m < rhoStep * a);
}

// Whether any of kThinBlock cells is thin: the flag kept by a select, no branch, so that it
// vectorises (out of line: inlined into its caller, g++ 12 unrolls the loop instead).
constexpr long kThinBlock = 16;
[[gnu::noinline]] bool anyThin(const double* a, const double* m, double rhoStep) {
  double any = 0.0;
  for (long k = 0; k < kThinBlock; ++k) {
    const bool thin = isThin(a[k], m[k], rhoStep);
    any = thin ? 1.0 : any;
  }
  return any != 0.0;
}

}  // namespace

void TvdSolver::limitThinVelocities(double dt) {
  const double vmax = std::min(grid_.dx, grid_.dz) / dt;
  const long c0 = phases_.cellLo(), c1 = phases_.cellHi();
  for (int p = 0; p < phases_.count; ++p) {
    const auto& alpha = phases_.alpha[static_cast<std::size_t>(p)];
    Conserved& q = phases_.q[static_cast<std::size_t>(p)];
    const double rhoStep = rhoStep_[static_cast<std::size_t>(p)];
    // Sequential, in cell order: the ledger's sums do not depend on the thread count. Thin
    // cells are few: a block of cells without one is passed over after a test by selects (it
    // vectorises), the same test as the one per cell below.
    const double* ap = alpha.data();
    const double* mp = q.rho.data();
    for (long b0 = c0; b0 < c1; b0 += kThinBlock) {
      const long b1 = std::min(b0 + kThinBlock, c1);
      if (b1 - b0 == kThinBlock && !anyThin(ap + b0, mp + b0, rhoStep)) continue;
      for (long c = b0; c < b1; ++c) {
        const auto cc = static_cast<std::size_t>(c);
        const double a = alpha[cc], m = q.rho[cc];
        if (!isThin(a, m, rhoStep)) continue;
        const double ux = q.mx[cc] / m, uz = q.mz[cc] / m;
        if (std::abs(ux) <= vmax && std::abs(uz) <= vmax) continue;
        const double vx = std::clamp(ux, -vmax, vmax), vz = std::clamp(uz, -vmax, vmax);
        const double dmx = m * (vx - ux), dmz = m * (vz - uz);
        const double dE = 0.5 * m * ((vx * vx + vz * vz) - (ux * ux + uz * uz));
        q.mx[cc] += dmx;
        q.mz[cc] += dmz;
        q.E[cc] += dE;
        const double vol = cellVolumes_(c);
        ledger_.floors.momentumX += dmx * vol;
        ledger_.floors.momentumZ += dmz * vol;
        ledger_.floors.energy += dE * vol;
      }
    }
  }
}

}  // namespace hvi::tvd
