//! @file TVD with the effect `strength` (docs/strength.md, "TVD"): a Lagrangian strength
//! sub-step after the hydrodynamic sweeps (the deviator's Jaumann update from the cell-centred
//! velocity gradient, radial return, the stress divergence as face fluxes), and the advection
//! of the strength scalars with the sweeps' mass fluxes. Operator splitting as in CTH and
//! iSALE: the hydrodynamic step moves the material, the strength step adds what the deviator
//! does to momentum and energy.
#include "strength_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "eos_line.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"
#include "workspace.hpp"

namespace hvi::tvd {
namespace detail {

namespace {
double minmod(double a, double b) {
  if (a * b <= 0.0) return 0.0;
  return std::abs(a) < std::abs(b) ? a : b;
}
}  // namespace


void advectStrengthLine(StrengthState& st, StrengthLineWork& sw, const LineWork& w, int n,
                        double edgeMassLow, double rhoCut) {
  advectStrengthLine(st, sw, w.u0[kRho].data(), w.invVol.data(), n, edgeMassLow, rhoCut);
}

void advectStrengthLine(StrengthState& st, StrengthLineWork& sw, const double* rhoNew,
                        const double* invVol, int n, double edgeMassLow, double rhoCut) {
  advectStrengthLine(st.rq, sw, rhoNew, invVol, n, edgeMassLow, rhoCut);
}

void advectStrengthLine(std::array<std::vector<double>, kStrengthFields>& rqs, StrengthLineWork& sw,
                        const double* rhoNew, const double* invVol, int n, double edgeMassLow,
                        double rhoCut) {
  const long* cells = sw.cells.data();
  double* G = sw.massFlux.data();  // G[f]: face f between buffer cells f and f+1
  G[1] = edgeMassLow;
  for (int j = 2; j <= n + 1; ++j)
    G[j] = G[j - 1] - (rhoNew[j] - sw.rhoOld[static_cast<std::size_t>(j)]) / invVol[j];
  double* q = sw.q.data();
  for (auto& rq : rqs) {
    if (rq.empty()) continue;  // the damage without fracture
    for (int j = 2; j <= n + 1; ++j) {
      const double r = sw.rhoOld[static_cast<std::size_t>(j)];
      q[j] = r >= rhoCut ? rq[static_cast<std::size_t>(cells[j])] / r : 0.0;
    }
    // The ends: the edge cell's own value (first order at the domain's edges).
    q[0] = q[1] = q[2];
    q[n + 2] = q[n + 3] = q[n + 1];
    // The upwind value at each face f (between j = f and f + 1), Courant-corrected.
    auto face = [&](int f) {
      const double g = G[f];
      if (g == 0.0) return 0.0;
      if (g > 0.0) {
        const int j = f;
        const double r = sw.rhoOld[static_cast<std::size_t>(j)];
        const double nu = r > 0.0 && j >= 2 ? std::min(g * invVol[j] / r, 1.0) : 1.0;
        return g * (q[j] + 0.5 * (1.0 - nu) * minmod(q[j + 1] - q[j], q[j] - q[j - 1]));
      }
      const int j = f + 1;
      const double r = sw.rhoOld[static_cast<std::size_t>(j)];
      const double nu = r > 0.0 && j <= n + 1 ? std::min(-g * invVol[j] / r, 1.0) : 1.0;
      return g * (q[j] - 0.5 * (1.0 - nu) * minmod(q[j + 1] - q[j], q[j] - q[j - 1]));
    };
    double left = face(1);
    for (int j = 2; j <= n + 1; ++j) {
      const double right = face(j);
      const auto c = static_cast<std::size_t>(cells[j]);
      rq[c] = rhoNew[j] >= rhoCut ? rq[c] + invVol[j] * (left - right) : 0.0;
      left = right;
    }
  }
}

}  // namespace detail

void TvdSolver::setUpStrength(const cases::Scene& scene) {
  const bool fracture = scene.has(cases::Effect::Fracture);
  if (fracture && !scene.has(cases::Effect::Strength))
    throw InputError(
        "tvd: effect 'fracture' needs 'strength' (it removes the tensile and shear strength that "
        "'strength' gives)");
  if (!scene.has(cases::Effect::Strength)) return;
  if (markersOn_ && !cut_)
    throw InputError(
        "tvd: effect 'strength' with 'material_interfaces' runs with tvd.interfaces = "
        "\"conservative\" only (the deviator is carried per phase); the study's "
        "\"whole_cell\" interfaces have no strength (docs/strength.md, \"TVD with interfaces\")");
  if (cut_) {
    // One phase per body (materials_): each solid phase carries its own state.
    auto st = std::make_unique<detail::StrengthState>();
    const auto n = static_cast<std::size_t>(grid_.cells());
    st->phases.resize(materials_.size());
    bool anySolid = false;
    for (std::size_t p = 0; p < materials_.size(); ++p) {
      detail::StrengthState::Phase& ph = st->phases[p];
      ph.solid = materials_[p].strength.has_value();
      ph.rho0 = materials_[p].rho0();
      if (!ph.solid) continue;
      anySolid = true;
      ph.material = *materials_[p].strength;
      for (int k = 0; k < detail::kStrengthFieldsWithoutDamage; ++k)
        ph.rq[static_cast<std::size_t>(k)].assign(n, 0.0);  // bodies start unstressed
      if (fracture) ph.rq[detail::kDamage].assign(n, 0.0);   // and intact
    }
    st->solid = anySolid;
    st->fracture = fracture;
    if (fracture) {
      for (std::size_t p = 0; p < materials_.size(); ++p) {
        const detail::StrengthState::Phase& ph = st->phases[p];
        st->spall.push_back(ph.solid ? ph.material.spallStrength : -1.0);
        st->rhoIntact.push_back(kStrengthDensityFraction * ph.rho0);
      }
    }
    st->u.assign(n, 0.0);
    st->w.assign(n, 0.0);
    st->live.assign(n, 0);
    for (auto& a : st->s) a.assign(n, 0.0);
    for (auto& a : st->grad) a.assign(n, 0.0);
    strength_ = std::move(st);
    // The repair moves each phase's strength state with its mass (Phases::carried).
    phases_.carried.assign(materials_.size(), {});
    for (std::size_t p = 0; p < materials_.size(); ++p)
      if (strength_->phases[p].solid)
        for (auto& a : strength_->phases[p].rq)
          if (!a.empty()) phases_.carried[p].push_back(&a);
    for (auto& w : work_)
      w->strength = std::make_unique<detail::StrengthLineWork>(std::max(grid_.nx, grid_.nz));
    return;
  }
  auto st = std::make_unique<detail::StrengthState>();
  const cases::Material& m = materials_[static_cast<std::size_t>(singleMaterial_)];
  st->solid = m.strength.has_value();
  if (st->solid) st->material = *m.strength;
  st->rho0 = m.rho0();
  const auto n = static_cast<std::size_t>(grid_.cells());
  for (int k = 0; k < detail::kStrengthFieldsWithoutDamage; ++k)
    st->rq[static_cast<std::size_t>(k)].assign(n, 0.0);  // bodies start unstressed
  if (fracture && st->solid) {  // and intact; the sweeps read the material's entries
    st->fracture = true;
    st->rq[detail::kDamage].assign(n, 0.0);
    st->spall.assign(materials_.size(), -1.0);
    st->rhoIntact.assign(materials_.size(), 0.0);
    st->spall[static_cast<std::size_t>(singleMaterial_)] = st->material.spallStrength;
    st->rhoIntact[static_cast<std::size_t>(singleMaterial_)] = kStrengthDensityFraction * st->rho0;
  }
  st->u.assign(n, 0.0);
  st->w.assign(n, 0.0);
  st->live.assign(n, 0);
  for (auto& a : st->s) a.assign(n, 0.0);
  strength_ = std::move(st);
  for (auto& w : work_)
    w->strength = std::make_unique<detail::StrengthLineWork>(std::max(grid_.nx, grid_.nz));
}

std::vector<double>& TvdSolver::strengthStateForTesting(int k) {
  if (!strength_ || k < 0 || k >= detail::kStrengthFields ||
      strength_->rq[static_cast<std::size_t>(k)].empty())
    throw std::logic_error("tvd: no strength state component " + std::to_string(k));
  return strength_->rq[static_cast<std::size_t>(k)];
}

double TvdSolver::strengthShearModulus(double rho, double e, double p) const {
  const detail::StrengthState& st = *strength_;
  if (!st.solid || rho < kStrengthDensityFraction * st.rho0) return 0.0;
  const double eta = rho / st.rho0;
  return strength::shearModulus(st.material, p, st.material.thermal.temperature(eta, e), eta);
}

// The strength sub-step (docs/strength.md, "TVD"). Cells below kStrengthDensityFraction rho0
// carry no deviator, and a face with such a cell on one side is a free surface (no traction).
void TvdSolver::strengthStep(double dt) {
  detail::StrengthState& st = *strength_;
  if (!st.solid) return;
  const int nx = grid_.nx, nz = grid_.nz;
  const long cells = grid_.cells();
  const double h = grid_.dx;
  const bool rz = geometry_ == Geometry::Axisymmetric;
  // Solid: a cell below this density is a free surface's partly filled cell or torn material
  // and carries no deviator (docs/strength.md, "TVD").
  const double rhoSolid = kStrengthDensityFraction * st.rho0;
  const auto& bnd = domain_.boundary;  // xmin, xmax, zmin, zmax
  const detail::StrengthSides reflect = {
      bnd[0] != cases::Boundary::Outflow, bnd[1] != cases::Boundary::Outflow,
      bnd[2] != cases::Boundary::Outflow, bnd[3] != cases::Boundary::Outflow};
  const strength::Material& sm = st.material;
  const bool fracture = st.fracture;

  // 1. The cell-centred velocity (the state after the sweeps).
#pragma omp parallel for schedule(static) num_threads(threads_) if (cells >= kParallelCells)
  for (long c = 0; c < cells; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const double r = U_.rho[cc];
    const bool live = r >= rhoSolid;
    st.live[cc] = live ? 1 : 0;
    st.u[cc] = live ? U_.mx[cc] / r : 0.0;
    st.w[cc] = live ? U_.mz[cc] / r : 0.0;
  }

  // 2. The deviator: Jaumann update with the central-difference velocity gradient, radial
  // return to the yield surface at the cell's state, plastic strain.
  std::visit(
      [&](const auto& eos) {
#pragma omp parallel for schedule(static) num_threads(threads_) if (cells >= kParallelCells)
        for (long c = 0; c < cells; ++c) {
          const auto cc = static_cast<std::size_t>(c);
          if (!st.live[cc]) {
            // No deviator; the plastic strain (history) is kept.
            for (auto& a : st.s) a[cc] = 0.0;
            for (int q = detail::kSxx; q <= detail::kSxz; ++q)
              st.rq[static_cast<std::size_t>(q)][cc] = 0.0;
            continue;
          }
          const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
          auto derivative = [&](int axis, double& du, double& dw) {
            detail::strengthVelocityDerivative(st, reflect, nx, nz, h, c, i, k, axis, du, dw);
          };
          strength::VelocityGradient g;
          derivative(0, g.xx, g.zx);
          derivative(1, g.xz, g.zz);
          if (rz) g.hoop = st.u[cc] / cellX_[static_cast<std::size_t>(i)];
          const double r = U_.rho[cc];
          const double e = U_.E[cc] / r - 0.5 * (st.u[cc] * st.u[cc] + st.w[cc] * st.w[cc]);
          const eos::EosState es = eos.state(r, e);
          // Effect fracture: the pressure the sweeps saw (tension limited by the spall strength
          // and scaled by 1 - D), and the yield scaled by 1 - D.
          const double d =
              fracture ? std::clamp(st.rq[detail::kDamage][cc] / r, 0.0, 1.0) : 0.0;
          const double p =
              fracture ? strength::effectivePressure(es.pressure, d, sm.spallStrength)
                       : es.pressure;
          const double eta = r / st.rho0;
          const double temp = sm.thermal.temperature(eta, e);
          const double G = strength::shearModulus(sm, p, temp, eta);
          strength::Deviator s{st.rq[detail::kSxx][cc] / r, st.rq[detail::kSzz][cc] / r,
                               st.rq[detail::kSxz][cc] / r};
          double eps = st.rq[detail::kEps][cc] / r;
          const strength::Deviator rate = strength::jaumannRate(s, g, G);
          s.xx += dt * rate.xx;
          s.zz += dt * rate.zz;
          s.xz += dt * rate.xz;
          const strength::YieldInput in{eps, strength::equivalentStrainRate(g), p, temp, eta};
          const double y = strength::yieldStress(sm.yield, in);
          const strength::ReturnResult rr =
              strength::radialReturn(s, fracture ? (1.0 - d) * y : y, G);
          eps += rr.plasticStrain;
          // Effect fracture at the step's end: the failure rule and the damage model (as the
          // cut-cell step, strength_cut.cpp), in a cell away from free surfaces: one beside a
          // dead cell is a free surface's partly filled cell, whose EOS tension is its average
          // with the vacuum (the sweeps give it no tension across the surface either).
          auto liveAt = [&](int ii, int kk) {
            return ii < 0 || ii >= nx || kk < 0 || kk >= nz ||
                   st.live[static_cast<std::size_t>(kk) * static_cast<std::size_t>(nx) +
                           static_cast<std::size_t>(ii)] != 0;
          };
          if (fracture && d < 1.0 && liveAt(i - 1, k) && liveAt(i + 1, k) && liveAt(i, k - 1) &&
              liveAt(i, k + 1))
            st.rq[detail::kDamage][cc] =
                r *
                (es.pressure < -sm.spallStrength
                     ? 1.0
                     : strength::grownDamage(sm, d, dt, p, r, es.soundSpeed, G,
                                             strength::longitudinalSoundSpeed(es.soundSpeed, G, r),
                                             h, in, s, rr));
          st.s[0][cc] = s.xx;
          st.s[1][cc] = s.zz;
          st.s[2][cc] = s.xz;
          st.rq[detail::kSxx][cc] = r * s.xx;
          st.rq[detail::kSzz][cc] = r * s.zz;
          st.rq[detail::kSxz][cc] = r * s.xz;
          st.rq[detail::kEps][cc] = r * eps;
        }
      },
      materials_[static_cast<std::size_t>(singleMaterial_)].eos);

  // 3. The stress divergence as face fluxes: the face carries the mean of its two cells'
  // deviator and velocity, traction t = s.n and power t.v; every face adds to one cell what it
  // takes from the other, so momentum and total energy change only through the domain's edges
  // (the walls: the normal traction's impulse, no work, since the mirror makes the normal
  // velocity and the shear traction zero exactly at the wall). Plastic work needs no term of
  // its own: the stress power of the total strain rate is in the energy already.
  // Face value along `axis` between cells a (low) and b (high); b < 0: the domain's edge.
  using Flux = detail::StrengthFaceFlux;
  auto faceFlux = [&](int axis, long a, long b, bool lowEdgeFace) {
    return detail::strengthFaceFlux(st, reflect, axis, a, b, lowEdgeFace);
  };
  // Planar per cm of depth; r-z per radian (the 2 pi of the ledger below).
  const double twoPi = 2.0 * std::numbers::pi;
#pragma omp parallel for schedule(static) num_threads(threads_) if (cells >= kParallelCells)
  for (long c = 0; c < cells; ++c) {
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
    const double fx = dt / (r * h);  // x faces: area a dz over volume r dr dz
    const double fz = dt / h;
    double dmx = fx * (aR * xr.tx - aL * xl.tx) + fz * (zr.tx - zl.tx);
    const double dmz = fx * (aR * xr.tz - aL * xl.tz) + fz * (zr.tz - zl.tz);
    const double dE = fx * (aR * xr.pe - aL * xl.pe) + fz * (zr.pe - zl.pe);
    // r-z: the hoop stress, rho dv_r/dt gains -s_tt / r (s_tt = -(s_rr + s_zz)).
    if (rz) dmx += dt * (st.s[0][cc] + st.s[1][cc]) / r;
    U_.mx[cc] += dmx;
    U_.mz[cc] += dmz;
    U_.E[cc] += dE;
  }

  // The domain's edges into the ledger (amounts added to the domain; what left an outflow side).
  for (int side = 0; side < 4; ++side) {
    const bool xs = side < 2;
    const bool low = side % 2 == 0;
    const int count = xs ? nz : nx;
    Budget b;
    for (int l = 0; l < count; ++l) {
      const long c = xs ? static_cast<long>(l) * nx + (low ? 0 : nx - 1)
                        : (low ? 0L : static_cast<long>(nz - 1) * nx) + l;
      const Flux f = low ? faceFlux(xs ? 0 : 1, -1, c, true) : faceFlux(xs ? 0 : 1, c, -1, false);
      // Face area (solver units: planar per cm of depth, r-z with 2 pi r).
      double area;
      if (xs)
        area = rz ? twoPi * faceX_[low ? 0 : static_cast<std::size_t>(nx)] * h : h;
      else
        area = rz ? twoPi * cellX_[static_cast<std::size_t>(l)] * h : h;
      const double sgn = low ? -1.0 : 1.0;  // the outward normal's sign
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
