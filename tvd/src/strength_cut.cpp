//! @file TVD strength with conservative interfaces (docs/strength.md, "TVD with interfaces"):
//! the strength sub-step of the cut-cell mode. Every solid phase (body) carries its own
//! deviator and plastic strain (rho_p q per unit cell volume, advected with the phase's mass
//! fluxes by the sweeps and moved with its mass by the repair); the cell's stress is the
//! volume-fraction-weighted deviator of its phases (a fluid phase contributes zero), and its
//! divergence acts on the cell's momentum and total energy as face fluxes, as in the
//! single-material step (strength_step.cpp), shared out among the cell's phases.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "eos_line.hpp"
#include "hvi/tvd/tvd.hpp"
#include "strength_step.hpp"

namespace hvi::tvd {

std::vector<double>& TvdSolver::phaseStrengthStateForTesting(int p, int k) {
  if (!strength_ || p < 0 || p >= static_cast<int>(strength_->phases.size()) ||
      !strength_->phases[static_cast<std::size_t>(p)].solid || k < 0 ||
      k >= detail::kStrengthFields ||
      strength_->phases[static_cast<std::size_t>(p)].rq[static_cast<std::size_t>(k)].empty())
    throw std::logic_error(fmt::format("tvd: no strength state of phase {} component {}", p, k));
  return strength_->phases[static_cast<std::size_t>(p)].rq[static_cast<std::size_t>(k)];
}

double TvdSolver::phaseShearModulus(int p, double rho, double e, double pressure) const {
  const detail::StrengthState::Phase& ph = strength_->phases[static_cast<std::size_t>(p)];
  if (!ph.solid || rho < kStrengthDensityFraction * ph.rho0) return 0.0;
  const double eta = rho / ph.rho0;
  return strength::shearModulus(ph.material, pressure, ph.material.thermal.temperature(eta, e),
                                eta);
}

// The cut-cell strength sub-step, after the repair and the mixture (docs/strength.md, "TVD with
// interfaces"):
//  1. a solid phase is live in a cell where its own density q_rho / alpha is at least
//     kStrengthDensityFraction rho0; the cell is live where its live solid phases fill at least
//     kStrengthDensityFraction of it (the single-material rule: a partly filled cell at a free
//     surface, a thin film, or a solid sliver in vapour carries no deviator, so that no small
//     mass is pushed by a full neighbour's stress);
//  2. the velocity gradient of the cell's mixture velocity (central differences, as the
//     single-material step: a wall or the axis mirrors, an outflow side repeats, a dead
//     neighbour is left out);
//  3. every live solid phase: Jaumann update with its own G, radial return with its own yield
//     at its own eps_p, P, T, eta; a phase that is not live, or in a dead cell, has no deviator
//     (its plastic strain is kept);
//  4. the cell's deviator S = sum alpha_p s_p over its live phases; face tractions S.n and their
//     power from the mean of the two cells (none where either is dead), so momentum and total
//     energy are conserved exactly, as in the single-material step;
//  5. the cell's increments shared out: every phase holding mass gets the momentum in
//     proportion to its mass (one acceleration for the cell, as CTH's and Autodyn's mixed
//     cells), its total energy changes by its kinetic energy's change, and what is left of the
//     cell's energy increment (the stress power of the deformation, plastic work included)
//     goes to its live solid phases in proportion to their mass. The sum over the phases is
//     the cell's increment (to round-off).
void TvdSolver::strengthStepCut(double dt) {
  detail::StrengthState& st = *strength_;
  if (!st.solid) return;
  const int nx = grid_.nx, nz = grid_.nz;
  const long c0 = phases_.cellLo(), c1 = phases_.cellHi();
  const double h = grid_.dx;
  const bool rz = geometry_ == Geometry::Axisymmetric;
  const int P = phases_.count;
  const bool fracture = st.fracture;
  const auto& bnd = domain_.boundary;  // xmin, xmax, zmin, zmax
  const detail::StrengthSides reflect = {
      bnd[0] != cases::Boundary::Outflow, bnd[1] != cases::Boundary::Outflow,
      bnd[2] != cases::Boundary::Outflow, bnd[3] != cases::Boundary::Outflow};
  auto livePhase = [&](int p, std::size_t c) {
    const detail::StrengthState::Phase& ph = st.phases[static_cast<std::size_t>(p)];
    if (!ph.solid) return false;
    const double a = phases_.alpha[static_cast<std::size_t>(p)][c];
    const double m = phases_.q[static_cast<std::size_t>(p)].rho[c];
    return a >= kPhaseAbsent && m >= kStrengthDensityFraction * ph.rho0 * a;
  };

  // 1. Live cells and the mixture velocity (U_ is the mixture of the phases).
  syncMixture();
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelCells)
  for (long c = c0; c < c1; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    double solid = 0.0;
    for (int p = 0; p < P; ++p)
      if (livePhase(p, cc)) solid += phases_.alpha[static_cast<std::size_t>(p)][cc];
    const bool live = solid >= kStrengthDensityFraction;
    const double r = U_.rho[cc];
    st.live[cc] = live ? 1 : 0;
    st.u[cc] = live ? U_.mx[cc] / r : 0.0;
    st.w[cc] = live ? U_.mz[cc] / r : 0.0;
  }

  // 2. The velocity gradient of every live cell.
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelCells)
  for (long c = c0; c < c1; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (!st.live[cc]) continue;
    const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
    auto derivative = [&](int axis, double& du, double& dw) {
      detail::strengthVelocityDerivative(st, reflect, nx, nz, h, c, i, k, axis, du, dw);
    };
    derivative(0, st.grad[0][cc], st.grad[2][cc]);  // dvx/dx, dvz/dx
    derivative(1, st.grad[1][cc], st.grad[3][cc]);  // dvx/dz, dvz/dz
    st.grad[4][cc] = rz ? st.u[cc] / cellX_[static_cast<std::size_t>(i)] : 0.0;
  }

  // 3. Each solid phase's deviator (the EOS visited once per phase), and 4. the cell's deviator.
  for (auto& a : st.s) std::fill(a.begin() + c0, a.begin() + c1, 0.0);
  for (int p = 0; p < P; ++p) {
    detail::StrengthState::Phase& ph = st.phases[static_cast<std::size_t>(p)];
    if (!ph.solid) continue;
    const auto& alpha = phases_.alpha[static_cast<std::size_t>(p)];
    const Conserved& q = phases_.q[static_cast<std::size_t>(p)];
    const strength::Material& sm = ph.material;
    std::visit(
        [&](const auto& eos) {
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelCells)
          for (long c = c0; c < c1; ++c) {
            const auto cc = static_cast<std::size_t>(c);
            if (!st.live[cc] || !livePhase(p, cc)) {
              for (int k = detail::kSxx; k <= detail::kSxz; ++k)
                ph.rq[static_cast<std::size_t>(k)][cc] = 0.0;
              // Effect fracture: the failure rule holds in a cell without stress too (a solid
              // at its own density in a partly filled cell); below that density the sweeps
              // carry no tension anyway.
              if (fracture && livePhase(p, cc)) {
                const double m = q.rho[cc];
                const double vx = q.mx[cc] / m, vz = q.mz[cc] / m;
                const double e = q.E[cc] / m - 0.5 * (vx * vx + vz * vz);
                if (eos.state(m / alpha[cc], e).pressure < -sm.spallStrength)
                  ph.rq[detail::kDamage][cc] = m;
              }
              continue;
            }
            const double m = q.rho[cc], a = alpha[cc];
            const double r = m / a;
            const double vx = q.mx[cc] / m, vz = q.mz[cc] / m;
            const double e = q.E[cc] / m - 0.5 * (vx * vx + vz * vz);
            const eos::EosState es = eos.state(r, e);
            // Effect fracture: the pressure the sweeps saw (tension limited by the spall
            // strength and scaled by 1 - D), and the yield scaled by 1 - D.
            const double d = fracture ? std::clamp(ph.rq[detail::kDamage][cc] / m, 0.0, 1.0) : 0.0;
            const double pr = fracture
                                  ? strength::effectivePressure(es.pressure, d, sm.spallStrength)
                                  : es.pressure;
            const double eta = r / ph.rho0;
            const double temp = sm.thermal.temperature(eta, e);
            const double G = strength::shearModulus(sm, pr, temp, eta);
            strength::VelocityGradient g;
            g.xx = st.grad[0][cc];
            g.xz = st.grad[1][cc];
            g.zx = st.grad[2][cc];
            g.zz = st.grad[3][cc];
            g.hoop = st.grad[4][cc];
            strength::Deviator s{ph.rq[detail::kSxx][cc] / m, ph.rq[detail::kSzz][cc] / m,
                                 ph.rq[detail::kSxz][cc] / m};
            double eps = ph.rq[detail::kEps][cc] / m;
            const strength::Deviator rate = strength::jaumannRate(s, g, G);
            s.xx += dt * rate.xx;
            s.zz += dt * rate.zz;
            s.xz += dt * rate.xz;
            const strength::YieldInput in{eps, strength::equivalentStrainRate(g), pr, temp, eta};
            const double y = strength::yieldStress(sm.yield, in);
            const strength::ReturnResult rr =
                strength::radialReturn(s, fracture ? (1.0 - d) * y : y, G);
            eps += rr.plasticStrain;
            ph.rq[detail::kSxx][cc] = m * s.xx;
            ph.rq[detail::kSzz][cc] = m * s.zz;
            ph.rq[detail::kSxz][cc] = m * s.xz;
            ph.rq[detail::kEps][cc] = m * eps;
            // Effect fracture at the step's end: tension of the EOS beyond the spall strength
            // fails the phase outright (D = 1, the hydrocodes' pressure cut-off spall, as SPH);
            // else its damage model grows D.
            if (fracture && d < 1.0)
              ph.rq[detail::kDamage][cc] =
                  m *
                  (es.pressure < -sm.spallStrength
                       ? 1.0
                       : strength::grownDamage(
                             sm, d, dt, pr, r, es.soundSpeed, G,
                             strength::longitudinalSoundSpeed(es.soundSpeed, G, r), h, in, s, rr));
            st.s[0][cc] += a * s.xx;
            st.s[1][cc] += a * s.zz;
            st.s[2][cc] += a * s.xz;
          }
        },
        materials_[static_cast<std::size_t>(p)].eos);
  }

  // 4. Face tractions and their power, as in the single-material step.
  using Flux = detail::StrengthFaceFlux;
  auto faceFlux = [&](int axis, long a, long b, bool lowEdgeFace) {
    return detail::strengthFaceFlux(st, reflect, axis, a, b, lowEdgeFace);
  };

  // 5. Per live cell: the increments, shared out among its phases.
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelCells)
  for (long c = c0; c < c1; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (!st.live[cc]) continue;
    const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
    const double r = rz ? cellX_[static_cast<std::size_t>(i)] : 1.0;
    const double aL = rz ? faceX_[static_cast<std::size_t>(i)] : 1.0;
    const double aR = rz ? faceX_[static_cast<std::size_t>(i) + 1] : 1.0;
    const Flux xl = faceFlux(0, i > 0 ? c - 1 : -1, c, i == 0);
    const Flux xr = faceFlux(0, c, i < nx - 1 ? c + 1 : -1, false);
    const Flux zl = faceFlux(1, k > 0 ? c - nx : -1, c, k == 0);
    const Flux zr = faceFlux(1, c, k < nz - 1 ? c + nx : -1, false);
    const double fx = dt / (r * h);
    const double fz = dt / h;
    double dmx = fx * (aR * xr.tx - aL * xl.tx) + fz * (zr.tx - zl.tx);
    const double dmz = fx * (aR * xr.tz - aL * xl.tz) + fz * (zr.tz - zl.tz);
    const double dE = fx * (aR * xr.pe - aL * xl.pe) + fz * (zr.pe - zl.pe);
    if (rz) dmx += dt * (st.s[0][cc] + st.s[1][cc]) / r;
    double M = 0.0, Msolid = 0.0;
    for (int p = 0; p < P; ++p) {
      const double m = phases_.q[static_cast<std::size_t>(p)].rho[cc];
      if (!(m > 0.0)) continue;
      M += m;
      if (livePhase(p, cc)) Msolid += m;
    }
    // Kinetic energy changes of the phases; the rest of dE is the deviatoric stress power.
    double heat = dE;
    for (int p = 0; p < P; ++p) {
      Conserved& q = phases_.q[static_cast<std::size_t>(p)];
      const double m = q.rho[cc];
      if (!(m > 0.0)) continue;
      const double share = m / M;
      const double px = q.mx[cc], pz = q.mz[cc];
      const double nxm = px + share * dmx, nzm = pz + share * dmz;
      const double dK = 0.5 * ((nxm * nxm - px * px) + (nzm * nzm - pz * pz)) / m;
      q.mx[cc] = nxm;
      q.mz[cc] = nzm;
      q.E[cc] += dK;
      heat -= dK;
    }
    for (int p = 0; p < P; ++p) {
      if (!livePhase(p, cc)) continue;
      Conserved& q = phases_.q[static_cast<std::size_t>(p)];
      q.E[cc] += heat * (q.rho[cc] / Msolid);
    }
  }
  mixtureStale_ = true;  // formed when read (syncMixture)

  // The domain's edges into the ledger.
  const double twoPi = 2.0 * std::numbers::pi;
  for (int side = 0; side < 4; ++side) {
    const bool xs = side < 2;
    const bool low = side % 2 == 0;
    const int count = xs ? nz : nx;
    Budget b;
    for (int l = 0; l < count; ++l) {
      const long c = xs ? static_cast<long>(l) * nx + (low ? 0 : nx - 1)
                        : (low ? 0L : static_cast<long>(nz - 1) * nx) + l;
      if (c < c0 || c >= c1) continue;  // no material outside the phases' rows
      const Flux f = low ? faceFlux(xs ? 0 : 1, -1, c, true) : faceFlux(xs ? 0 : 1, c, -1, false);
      double area;
      if (xs)
        area = rz ? twoPi * faceX_[low ? 0 : static_cast<std::size_t>(nx)] * h : h;
      else
        area = rz ? twoPi * cellX_[static_cast<std::size_t>(l)] * h : h;
      const double sgn = low ? -1.0 : 1.0;
      b.momentumX += sgn * dt * area * f.tx;
      b.momentumZ += sgn * dt * area * f.tz;
      b.energy += sgn * dt * area * f.pe;
    }
    if (reflect[side])
      ledger_.boundary += b;
    else
      ledger_.outflow += b.scaled(-1.0);
  }
}

}  // namespace hvi::tvd
