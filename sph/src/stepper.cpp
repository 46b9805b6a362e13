//! @file Predictor-corrector step driver (docs/sph.md).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "detail/eos_pass.hpp"
#include "detail/parallel.hpp"
#include "detail/stepper_impl.hpp"
#include "hvi/common/error.hpp"

namespace hvi::sph {
namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

Stepper::Impl::Impl(ParticleSystem ps, std::vector<eos::Eos> mats, StepperConfig config)
    : cfg(std::move(config)), materials(std::move(mats)), bounds(cfg.domain, cfg.geometry) {
  rz = cfg.geometry == Geometry::Axisymmetric;
  if (rz && cfg.rzForm == cases::RzForm::Symmetric) {
    // The stress terms (strength_pass.cpp) are written for the ring form's weights only.
    if (!cfg.strength.empty())
      throw InputError(
          "SPH: sph.rz_form = \"symmetric\" is not implemented with the effect strength; set "
          "sph.rz_form = \"ring\" (docs/sph-rz.md)");
    ring = &detail::ringScale(cfg.kernel);
    if (cfg.rzViscousHoop != 0.0) {
      if (!(cfg.rzViscousHoop >= 0.0 && cfg.rzViscousHoop <= 1.0))
        throw InputError(fmt::format("SPH: sph.rz_viscous_hoop = {} must be in [0, 1]",
                                     cfg.rzViscousHoop));
      ringOwn = std::make_unique<detail::RingScale>(*ring);
      ringOwn->viscousHoop = cfg.rzViscousHoop;
      ring = ringOwn.get();
    }
  } else if (rz) {
    axis = std::make_unique<detail::AxisCorrection>(cfg.kernel);
  }
  if (cfg.rzAxisCorrection != 0.0 && !(ring && cfg.rzAxisCorrection > 0.0))
    throw InputError(
        fmt::format("SPH: sph.rz_axis_correction = {} needs the symmetric r-z form and a value > 0",
                    cfg.rzAxisCorrection));
  compatible = cfg.energy == cases::EnergyForm::Compatible;
  // With the viscosity switch the strength pass sums the (switched) viscosity: the force passes
  // run inviscid (docs/strength.md, "Viscosity switch").
  const bool switched = cfg.viscositySwitch && cfg.viscosity && !cfg.strength.empty();
  if (switched && !(cfg.visc.alpha > 0.0))
    throw InputError("SPH: the viscosity switch needs sph.alpha > 0 (its maximum)");
  viscous = cfg.viscosity && !switched;
  if (!(cfg.cfl > 0.0)) throw InputError(fmt::format("sph.cfl = {} must be > 0", cfg.cfl));
  // A particle moves at most (cfl/2) h_i in the half step (dt <= cfl h_i / |v_i|), so a pair
  // closes by at most cfl h_ij: a skin of cfl h_ij (plus a margin for rounding) keeps the
  // list built at x^n complete at the half state.
  radiusFactor = detail::kernelSupport(cfg.kernel) + cfg.cfl * 1.001;
  n = ps.size();
  for (int k : ps.material)
    if (k < 0 || k >= static_cast<int>(materials.size()))
      throw InputError(
          fmt::format("particle material {} is not one of the {} materials", k, materials.size()));
  // Indices only (docs/performance.md, "SPH memory"): the passes recompute W_ij.
  list.cacheW = false;
  forEachState(*this, [&ps](auto member, auto& v) { v = std::move(ps.*member); });
  // Arrays filled by push_back grew to up to twice their size: cut to size.
  forEachState(*this, [](auto, auto& v) { v.shrink_to_fit(); });
  a.resize(n);  // after the moves: the arrays taken over are not allocated twice
  ps = ParticleSystem();  // rho, p, c: corrector() derives them
  if (!cfg.strength.empty()) {
    if (cfg.strength.size() != materials.size() || cfg.strengthRho0.size() != materials.size())
      throw InputError("SPH strength: one entry per material is needed");
    strength = std::make_unique<detail::StrengthModel>(cfg.strength, cfg.strengthRho0, cfg.kernel,
                                                       cfg.hFactor, cfg.artificialStress,
                                                       cfg.artificialStressPower, cfg.fracture);
    strength->resize(n);
    if (switched) strength->enableViscositySwitch(cfg.visc, cfg.alphaMin, cfg.switchDecay, n);
    if (cfg.plasticStrainRate) strength->enablePlasticStrainRate(n);
  }
  const char* store = std::getenv("HVI_SPH_STORE_PAIRS");
  storePairs = compatible && (strength || (store && std::atoi(store) != 0));
  // Half rows (docs/performance.md): each pair evaluated once where the passes have them
  // (planar, Gaussian lanes) and nothing else reads the list (strength's pass and its stored
  // pair data use full rows). HVI_SPH_HALF=0 keeps the full rows, for side-by-side runs.
  const char* halfEnv = std::getenv("HVI_SPH_HALF");
  const bool half = !strength && !storePairs && detail::halfListsAvailable(cfg.kernel, rz) &&
                    !(halfEnv && std::atoi(halfEnv) == 0);
  list.half = half;
  passCached = detail::selectForcePass(cfg.kernel, rz, viscous, compatible, true, half);
  // (the symmetric r-z form runs the same pair kernels; only the drivers' r-z part differs)
  passFresh = detail::selectForcePass(cfg.kernel, rz, viscous, compatible, false, half);
  passList = detail::selectListPass(cfg.kernel);
  passRemainder = detail::selectRemainderPass(cfg.kernel, rz, viscous, half);
  if (cfg.rzAxisCorrection > 0.0) {
    // The lane kernels do not read the correction: the one-pair-at-a-time passes.
    passCached = detail::selectScalarForcePass(cfg.kernel, rz, viscous, compatible, true);
    passFresh = detail::selectScalarForcePass(cfg.kernel, rz, viscous, compatible, false);
    passRemainder = detail::selectScalarRemainderPass(cfg.kernel, rz, viscous);
  }
  // The lane force kernels over full rows, the ring form (not the symmetric form, not the
  // axis matrix), and with compatible energy the pair data stored (the fused half-state pass
  // writes them).
  const char* fusedEnv = std::getenv("HVI_SPH_FUSED");
  fused = strength && strength->fusable() && !half && !ring && !(cfg.rzAxisCorrection > 0.0) &&
          (!compatible || storePairs) && !(fusedEnv && std::atoi(fusedEnv) == 0);
  t = cfg.time;
  resizeWork();
  corrector();
}

void Stepper::Impl::deriveWeights() {
  const long nl = static_cast<long>(n);
  if (ring) {
    // Symmetric form: nu = m / (2 pi s), the pair sums divided by s, no radius weight.
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
    for (long i = 0; i < nl; ++i) {
      a.rw[i] = 1.0;
      a.rs[i] = ring->value(std::abs(a.x[i]), a.h[i]);
      a.mu[i] = m[i] / (kTwoPi * a.rs[i]);
    }
  } else if (rz) {
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
    for (long i = 0; i < nl; ++i) {
      a.rw[i] = std::abs(a.x[i]);
      a.rs[i] = a.rw[i];
      a.mu[i] = m[i] / (kTwoPi * a.rw[i]);
    }
  } else {
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
    for (long i = 0; i < nl; ++i) {
      a.rw[i] = 1.0;
      a.rs[i] = 1.0;
      a.mu[i] = m[i];
    }
  }
}

void Stepper::Impl::deriveRates() {
  const long nl = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
  for (long i = 0; i < nl; ++i) {
    a.q[i] = a.rw[i] * a.p[i] / (a.rho[i] * a.rho[i]);
    a.lam[i] = rz ? -a.vx[i] / a.x[i] : 0.0;
  }
}

std::string Stepper::Impl::objectName(std::size_t i) const {
  const int o = a.obj[i];
  return (o >= 0 && o < static_cast<int>(cfg.objectNames.size()))
             ? cfg.objectNames[static_cast<std::size_t>(o)]
             : std::to_string(o);
}

void Stepper::Impl::checkState(const char* stage) const {
  const long nl = static_cast<long>(n);
  long bad = nl;
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements) reduction(min : bad)
  for (long i = 0; i < nl; ++i) {
    const bool ok = std::isfinite(a.x[i]) && std::isfinite(a.z[i]) && std::isfinite(a.vx[i]) &&
                    std::isfinite(a.vz[i]) && std::isfinite(e[i]) && std::isfinite(a.p[i]) &&
                    a.rho[i] > 0.0 && std::isfinite(a.rho[i]) && (!rz || a.rw[i] > 0.0);
    if (!ok) bad = std::min(bad, i);
  }
  if (bad == nl) return;
  const std::size_t i = static_cast<std::size_t>(bad);
  const std::string obj = objectName(i);
  throw SimulationError(fmt::format(
      "SPH {} at step {}, t = {} us: particle {} of object '{}' has x = {}, z = {} cm, "
      "v = ({}, {}) cm/us, rho = {} g/cm^3, e = {} cm^2/us^2, P = {} Mbar, m = {} g",
      stage, steps, t, id[i], obj, a.x[i], a.z[i], a.vx[i], a.vz[i], a.rho[i], e[i], a.p[i], m[i]));
}

void Stepper::Impl::corrector() {
  deriveWeights();
  double hmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) hmax = std::max(hmax, a.h[i]);
  bounds.makeGhosts(a, n, radiusFactor * hmax);
  // The grid's sorted copies (x, z, h of reals and ghosts) in x0, z0 and vx0, dead from the
  // full step to the predictor.
  grid.swapSorted(x0, z0, vx0);
  passList(a, n, radiusFactor, grid, list, a.rho.data());
  grid.swapSorted(x0, z0, vx0);
  if (ring)  // the list build sums nu_j W_ij = s_i rho_i
    for (std::size_t i = 0; i < n; ++i) a.rho[i] /= a.rs[i];
  detail::evaluateEos(materials, mat.data(), a.rho.data(), e.data(), a.p.data(), a.c.data(), n);
  if (strength) strength->limitTension(a, n, mat.data(), true);
  checkState("corrector (summation density)");
  deriveRates();
  bounds.refreshGhosts(a, n);
  if (strength) strength->refreshPoints(a, n, e.data(), mat.data(), bounds);
}

void Stepper::Impl::axisMatrix() {
  if (!(cfg.rzAxisCorrection > 0.0)) return;
  const std::size_t total = a.size();
  for (auto* v : {&a.lzx, &a.lzz, &a.lxx}) v->resize(total);
  detail::axisMatrix(a, n, list, cfg.kernel, cfg.rzAxisCorrection);
  bounds.mirrorGhostTensors(a.lxx.data(), a.lzz.data(), a.lzx.data(), n);
}

void Stepper::Impl::compatibleRemainder(double half) {
  // docs/sph.md, "Energy": the change of acceleration over the step, on ghosts as on their
  // parents (mirrored), is what the midpoint velocity adds to the half-state pair work.
  // a^{n+1/2} - a^n in drho0 and phi0 (dead since the predictor and the time step), sized to
  // the reals and ghosts; the half rows' sums in de0 (dead since the predictor).
  std::vector<double>& dax = drho0;
  std::vector<double>& daz = phi0;
  const std::size_t total = a.size();
  if (dax.size() < total) {
    detail::growExactly(dax, total);
    detail::growExactly(daz, total);
  }
  const long nl = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
  for (long i = 0; i < nl; ++i) {
    dax[i] = ax1[i] - ax0[i];
    daz[i] = az1[i] - az0[i];
  }
  bounds.mirrorGhostVectors(dax.data(), daz.data(), n);
  if (storePairs) {
    detail::compatibleEnergy(list, n, pairWx.data(), pairWz.data(), dax.data(), daz.data(),
                             a.rs.data(), rz ? hoopAx.data() : nullptr, half, de1.data());
  } else {
    list.sums.swap(de0);
    lendSpill({&ax0});  // dead once da is formed
    passRemainder(a, n, list, cfg.visc, dax.data(), daz.data(), rz ? hoopAx.data() : nullptr,
                  half, de1.data());
    lendSpill({});
    list.sums.swap(de0);
  }
}

double Stepper::Impl::particleTimeStep(std::size_t i, bool* byAcceleration) const {
  const double v = std::hypot(a.vx[i], a.vz[i]);
  // Monaghan (1989): signal speed c + 0.6 (alpha c + beta max|phi|); |v| as well, which
  // also bounds the motion in the half step (the list skin relies on it).
  // With strength the fastest signal is the longitudinal (P) wave, c_L^2 = c^2 + 4G / (3 rho).
  double signal = (strength ? strength->cL[i] : a.c[i]) + v;
  if (cfg.viscosity) signal += 0.6 * (cfg.visc.alpha * a.c[i] + cfg.visc.beta * std::abs(phi0[i]));
  const double dtSignal = cfg.cfl * a.h[i] / signal;
  const double acc = std::hypot(ax0[i], az0[i]);
  const double dtAcc = acc > 0.0 ? cfg.cfl * std::sqrt(a.h[i] / acc) : dtSignal;
  if (byAcceleration) *byAcceleration = dtAcc < dtSignal;
  return std::min(dtSignal, dtAcc);
}

double Stepper::Impl::timeStep() const {
  const long nl = static_cast<long>(n);
  double dt = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements) reduction(min : dt)
  for (long i = 0; i < nl; ++i) dt = std::min(dt, particleTimeStep(static_cast<std::size_t>(i)));
  return dt;
}

void Stepper::Impl::throwCollapse(double dt) const {
  // Only on failure: a serial pass finds the particle that set dt.
  std::size_t worst = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const double d = particleTimeStep(i);
    if (!(d >= best)) {  // also catches NaN
      best = d;
      worst = i;
    }
  }
  bool byAcc = false;
  (void)particleTimeStep(worst, &byAcc);
  const std::size_t i = worst;
  const std::string obj = objectName(i);
  throw SimulationError(fmt::format(
      "SPH time step collapsed at step {}, t = {} us: dt = {:.3e} us (first step {:.3e} us), "
      "set by the {} of particle {} of object '{}' (material {}): x = {}, z = {} cm, "
      "v = ({}, {}) cm/us, a = ({:.3e}, {:.3e}) cm/us^2, rho = {} g/cm^3, e = {} cm^2/us^2, "
      "P = {} Mbar, c = {} cm/us, h = {} cm",
      steps, t, dt, dt0, byAcc ? "acceleration" : "signal speed", id[i], obj, mat[i], a.x[i],
      a.z[i], a.vx[i], a.vz[i], ax0[i], az0[i], a.rho[i], e[i], a.p[i], a.c[i], a.h[i]));
}

void Stepper::Impl::removeOutflow() {
  std::size_t removed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bounds.reflect(a.x[i], a.z[i], a.vx[i], a.vz[i]);
    keep[i] = bounds.outflowed(a.x[i], a.z[i]) ? 0 : 1;
    if (!keep[i]) {
      ++removed;
      out.mass += m[i];
      if (!rz) out.momentumX += m[i] * a.vx[i];
      out.momentumZ += m[i] * a.vz[i];
      out.kinetic += 0.5 * m[i] * (a.vx[i] * a.vx[i] + a.vz[i] * a.vz[i]);
      out.internal += m[i] * e[i];
    }
  }
  if (removed == 0) return;
  const std::size_t n0 = n;
  n -= removed;
  // Shrinking keeps the capacity: no allocation.
  forEachState(*this, [this, n0](auto, auto& v) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < n0; ++i)
      if (keep[i]) v[k++] = v[i];
    v.resize(n);
  });
  if (strength) strength->compact(keep, n0, n);
  a.resize(n);
  resizeWork();
}

Stepper::Stepper(const ParticleSystem& ps, std::vector<eos::Eos> materials, StepperConfig config)
    : impl_(std::make_unique<Impl>(ps, std::move(materials), std::move(config))) {}
Stepper::Stepper(ParticleSystem&& ps, std::vector<eos::Eos> materials, StepperConfig config)
    : impl_(std::make_unique<Impl>(std::move(ps), std::move(materials), std::move(config))) {}
Stepper::~Stepper() = default;

double Stepper::step(double tStop) {
  Impl& s = *impl_;
  if (s.t >= tStop) return 0.0;
  if (s.n == 0) {
    // Every particle has left through an outflow boundary: nothing is left to evolve, so the
    // state at tStop is the present one. One counted step keeps snapshot names distinct.
    const double dt = tStop - s.t;
    s.t = tStop;
    ++s.steps;
    return dt;
  }
  if (s.workReleased) s.resizeWork();
  detail::PairArrays& a = s.a;
  const long nl = static_cast<long>(s.n);
  const detail::Rates ratesN{s.ax0.data(), s.az0.data(), s.de0.data(), s.drho0.data(),
                             s.phi0.data()};
  s.axisMatrix();
  // Half rows' spills in arrays dead during each pass (docs/performance.md, "SPH memory").
  if (s.fused) {
    s.strength->passWithForces(a, s.n, s.list, true, s.axis.get(), s.viscous, s.compatible,
                               s.cfg.visc, ratesN);
  } else {
    s.lendSpill({&s.x0, &s.z0, &s.vx0, &s.vz0, &s.e0});
    s.passCached(a, s.n, s.list, s.cfg.visc, s.axis.get(), s.ring, ratesN);
    s.lendSpill({});
    if (s.strength) s.strength->pass(a, s.n, s.list, true, s.axis.get(), ratesN);
  }
  double dt = s.timeStep();
  if (s.dt0 == 0.0 && dt > 0.0 && std::isfinite(dt)) s.dt0 = dt;
  // A collapsed step (common/solver.hpp): stop and name the particle.
  if (!(dt > kDtCollapseFraction * s.dt0)) s.throwCollapse(dt);
  // The last step lands on tStop exactly (an output time).
  if (s.t + dt >= tStop) dt = tStop - s.t;
  const double half = 0.5 * dt;

  // Predictor: half step with the rates of state n; density from the continuity equation.
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
  for (long i = 0; i < nl; ++i) {
    s.x0[i] = a.x[i];
    s.z0[i] = a.z[i];
    s.vx0[i] = a.vx[i];
    s.vz0[i] = a.vz[i];
    s.e0[i] = s.e[i];
    a.x[i] += half * a.vx[i];
    a.z[i] += half * a.vz[i];
    a.vx[i] += half * s.ax0[i];
    a.vz[i] += half * s.az0[i];
    s.e[i] += half * s.de0[i];
    // Symmetric r-z form: the continuity rate is that of s_i rho_i = sum_j nu_j W_ij.
    a.rho[i] = (s.ring ? a.rho[i] * a.rs[i] : a.rho[i]) + half * s.drho0[i];
  }
  if (s.rz) {
    // docs/sph-rz.md, "Density": the ring weights' change mu^{n+1/2} - mu^n is taken exactly,
    // so the summation density's own law holds through it at any dt and cannot drive rho
    // negative next to the axis (explicitly, (dt/2) v_r / r > 1 did).
    const std::size_t total = a.size();
    if (s.dmu.size() < total) s.dmu.resize(total);
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
    for (long i = 0; i < nl; ++i) {
      const double r = std::abs(a.x[i]);
      const double scale = s.ring ? s.ring->value(r, a.h[i]) : r;
      s.dmu[i] = s.m[i] / (kTwoPi * scale) - a.mu[i];
    }
    s.bounds.copyGhostScalars(s.dmu.data(), s.n);
    detail::weightChange(s.list, s.n, s.x0.data(), s.z0.data(), a.x.data(), a.z.data(),
                         a.obj.data(), a.h.data(), s.dmu.data(), s.cfg.kernel, a.rho.data());
    if (s.ring) {
      s.deriveWeights();  // s at the half state: rho = (s rho) / s
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
      for (long i = 0; i < nl; ++i) a.rho[i] /= a.rs[i];
    }
  }
  detail::evaluateEos(s.materials, s.mat.data(), a.rho.data(), s.e.data(), a.p.data(), a.c.data(),
                      s.n);
  if (s.strength) s.strength->limitTension(a, s.n, s.mat.data(), false);
  s.deriveWeights();
  s.checkState("predictor (continuity density)");
  s.deriveRates();
  s.bounds.refreshGhosts(a, s.n);
  if (s.strength) {
    // The deviator's predictor with the rate of state n, returned to the yield surface of
    // the half state (no plastic strain counted: the step's end counts it).
    s.strength->beginStep(s.n);
    s.strength->advance(half, s.n, a, s.e.data(), s.mat.data(), false);
    s.strength->refreshPoints(a, s.n, s.e.data(), s.mat.data(), s.bounds);
  }
  detail::Rates ratesHalf{s.ax1.data(), s.az1.data(), s.de1.data(), nullptr, nullptr};
  if (s.compatible) {
    if (s.storePairs) {
      // One entry per list slot (rows as the corrector's list build laid them out).
      const std::size_t entries = s.list.start[s.n];
      if (s.pairWx.size() < entries) {
        // Rewritten by the pass: freed first, not copied into the larger arrays.
        s.pairWx = std::vector<double>();
        s.pairWz = std::vector<double>();
        s.pairWx.resize(entries);
        s.pairWz.resize(entries);
      }
      ratesHalf.pairWx = s.pairWx.data();
      ratesHalf.pairWz = s.pairWz.data();
    }
    ratesHalf.hoopAx = s.rz ? s.hoopAx.data() : nullptr;
  }
  s.axisMatrix();
  // Before the compatible remainder: the stress accelerations are part of a^{n+1/2} - a^n.
  if (s.fused) {
    s.strength->passWithForces(a, s.n, s.list, false, s.axis.get(), s.viscous, s.compatible,
                               s.cfg.visc, ratesHalf);
  } else {
    s.lendSpill({&s.de0, &s.drho0, &s.phi0});
    s.passFresh(a, s.n, s.list, s.cfg.visc, s.axis.get(), s.ring, ratesHalf);
    s.lendSpill({});
    if (s.strength) s.strength->pass(a, s.n, s.list, false, s.axis.get(), ratesHalf);
  }
  if (s.compatible) s.compatibleRemainder(half);

    // Full step with the half-state rates (midpoint rule: second order).
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements)
  for (long i = 0; i < nl; ++i) {
    a.x[i] = s.x0[i] + dt * a.vx[i];
    a.z[i] = s.z0[i] + dt * a.vz[i];
    a.vx[i] = s.vx0[i] + dt * s.ax1[i];
    a.vz[i] = s.vz0[i] + dt * s.az1[i];
    s.e[i] = s.e0[i] + dt * s.de1[i];
  }
  // The deviator's full step with the half-state rate; the yield at the half state's rho, P.
  if (s.strength) s.strength->advance(dt, s.n, a, s.e.data(), s.mat.data(), true);
  s.removeOutflow();
  s.t = (s.t + dt >= tStop) ? tStop : s.t + dt;
  ++s.steps;
  if (s.n == 0) {
    s.list.count.clear();
    s.bounds.makeGhosts(a, 0, 0.0);
    return dt;
  }
  s.corrector();
  return dt;
}

void Stepper::releaseWork() { impl_->releaseWork(); }
double Stepper::time() const { return impl_->t; }
long Stepper::stepCount() const { return impl_->steps; }
std::size_t Stepper::size() const { return impl_->n; }
std::size_t Stepper::ghostCount() const { return impl_->bounds.ghostCount(); }
const NeighbourList& Stepper::neighbours() const { return impl_->list; }
const StepperConfig& Stepper::config() const { return impl_->cfg; }
Totals Stepper::outflow() const { return impl_->out; }

ParticleSystem Stepper::particles() const {
  const Impl& s = *impl_;
  ParticleSystem ps;
  // The pair arrays also hold the ghosts: only the n reals are copied.
  const auto copy = [&](auto member, const auto& v) {
    (ps.*member).assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(s.n));
  };
  Impl::forEachState(s, copy);
  Impl::forEachDerived(s, copy);
  return ps;
}

StrengthFields Stepper::strengthFields() const {
  const Impl& s = *impl_;
  StrengthFields f;
  if (!s.strength) return f;
  const auto copy = [&](std::vector<double>& to, const std::vector<double>& from) {
    to.assign(from.begin(), from.begin() + static_cast<std::ptrdiff_t>(s.n));
  };
  copy(f.sxx, s.strength->sxx);
  copy(f.szz, s.strength->szz);
  copy(f.sxz, s.strength->sxz);
  copy(f.plasticStrain, s.strength->epsP);
  copy(f.damage, s.strength->damage);
  if (s.strength->viscositySwitch()) copy(f.viscosityAlpha, s.strength->alpha);
  if (s.strength->plasticStrainRate()) copy(f.plasticStrainRate, s.strength->plasticRate);
  f.stt.resize(s.n);
  f.temperature.resize(s.n);
  for (std::size_t i = 0; i < s.n; ++i) {
    f.stt[i] = -(f.sxx[i] + f.szz[i]);
    f.temperature[i] = s.strength->temperature(s.a, s.e.data(), s.mat[i], i);
  }
  return f;
}

Totals Stepper::totals() const {
  const Impl& s = *impl_;
  Totals tot = s.out;
  const long nl = static_cast<long>(s.n);
  double mass = 0.0, px = 0.0, pz = 0.0, kin = 0.0, inn = 0.0;
#pragma omp parallel for schedule(static) if (nl > detail::kParallelElements) reduction(+ : mass, px, pz, kin, inn)
  for (long i = 0; i < nl; ++i) {
    const double mi = s.m[i], vx = s.a.vx[i], vz = s.a.vz[i];
    mass += mi;
    px += mi * vx;
    pz += mi * vz;
    kin += 0.5 * mi * (vx * vx + vz * vz);
    inn += mi * s.e[i];
  }
  tot.mass += mass;
  if (!s.rz) tot.momentumX += px;  // r-z: zero by symmetry
  tot.momentumZ += pz;
  tot.kinetic += kin;
  tot.internal += inn;
  return tot;
}

}  // namespace hvi::sph
