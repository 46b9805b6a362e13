//! @file The SPH strength pass (docs/strength.md, "SPH"): deviatoric stress update and the
//! stress pair terms of pair_stress.hpp summed over the neighbour lists.
#include "detail/strength_pass.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <variant>

#include "detail/force_lanes.hpp"
#include "detail/force_rows.hpp"
#include "detail/parallel.hpp"
#include "detail/stress_lanes.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/pair_stress.hpp"

namespace hvi::sph::detail {
namespace {

// The viscosity switch's inputs and output (docs/strength.md, "SPH viscosity switch").
struct SwitchArgs {
  const double* alpha;  // alpha_i of every point (p.alpha)
  double betaPerAlpha;  // beta_ij = betaPerAlpha alpha_ij
  double* divv;         // div v of the reals (written)
};

// A row's pair sums: the velocity gradient, the stress force and power, the hoop part (r-z)
// and the most negative phi_ij of the switched viscosity.
struct RowSums {
  double gxx = 0.0, gxz = 0.0, gzx = 0.0, gzz = 0.0;
  double ax = 0.0, az = 0.0, de = 0.0, hoop = 0.0, phiMin = 0.0;
};

// Each particle gathers over its own list, as the force pass does (fixed summation order, no
// atomics). The velocity gradient, the stress force and the stress power all sum over every
// pair (as the pressure does): the energy term then sums to exactly the stress power s : grad v
// / rho of the gradient that drives s. (A gradient over the own object only, like the
// continuity rate, was tried: at a contact next to the r-z axis it let the interface particles
// run away, v_z 40 v0 at 1 us in SphStrength.ElasticWaveTravelsAtLongitudinalSpeedInRz.)
//
// With `Switch` the Monaghan viscosity of the pair, with alpha_ij = (alpha_i + alpha_j) / 2,
// enters T_ab as -r_ab Pi_ab I: the force -mu_b r_ab Pi grad W and the power
// (1/2) mu_b r_ab Pi v_ab . grad W of pair_force.hpp's viscous part (its compatible share is
// the even 1/2 of the stress terms).
template <class K, bool RZ, bool Cached, bool Pairs, bool Switch>
RowSums scalarRow(const PairArrays& a, std::size_t i, const int* nb, const double* wc, int cnt,
                  const StressPoints& p, double q2dp, int power, const SwitchArgs& sw,
                  double* pwx, double* pwz) {
  const double xi = a.x[i], zi = a.z[i], vxi = a.vx[i], vzi = a.vz[i], hi = a.h[i];
  const Sym2 ti{p.txx[i], p.tzz[i], p.txz[i]}, ri{p.rxx[i], p.rzz[i], p.rxz[i]};
  const double ih2i = 1.0 / (hi * hi);
  const double wdpi = K::value(q2dp * hi * hi, hi, ih2i);
  RowSums r;
  for (int k = 0; k < cnt; ++k) {
    const std::size_t j = static_cast<std::size_t>(nb[k]);
    const double hj = a.h[j];
    double ih2 = ih2i, hij = hi, wdp = wdpi;
    if (hj != hi) {
      hij = 0.5 * (hi + hj);
      ih2 = 1.0 / (hij * hij);
      wdp = K::value(q2dp * hij * hij, hij, ih2);
    }
    const double dx = xi - a.x[j], dz = zi - a.z[j];
    const double r2 = dx * dx + dz * dz;
    double w;
    if (Cached && wc) {
      w = wc[k];
    } else {
      w = K::value(r2, hij, ih2);
    }
    if (w == 0.0) continue;
    const double f = K::gradFactor(w, r2, hij, ih2);
    const double gx = f * dx, gz = f * dz;  // grad_i W_ij
    const double dvx = vxi - a.vx[j], dvz = vzi - a.vz[j];
    const VelocityGradientTerm t = velocityGradientTerm(p.vol[j], -dvx, -dvz, gx, gz);
    r.gxx += t.xx;
    r.gxz += t.xz;
    r.gzx += t.zx;
    r.gzz += t.zz;
    Sym2 tab{ti.xx + p.txx[j], ti.zz + p.tzz[j], ti.xz + p.txz[j]};
    if (power > 0) {
      const double fab = w / wdp;
      double fn = fab;
      for (int e = 1; e < power; ++e) fn *= fab;
      tab.xx += fn * (ri.xx + p.rxx[j]);
      tab.zz += fn * (ri.zz + p.rzz[j]);
      tab.xz += fn * (ri.xz + p.rxz[j]);
    }
    if constexpr (Switch) {
      const double aij = 0.5 * (sw.alpha[i] + sw.alpha[j]);
      const MonaghanViscosity visc{aij, sw.betaPerAlpha * aij};
      double phi = 0.0;
      const double pi = visc(dvx * dx + dvz * dz, r2, hij, 0.5 * (a.c[i] + a.c[j]),
                             0.5 * (a.rho[i] + a.rho[j]), phi);
      const double rpi = RZ ? 0.5 * (a.rw[i] + a.rw[j]) * pi : pi;
      tab.xx -= rpi;
      tab.zz -= rpi;
      r.phiMin = std::min(r.phiMin, phi);
    }
    if constexpr (RZ) r.hoop += a.mu[j] * p.htt[j] * w;
    const StressPairTerm st = stressPairTerm(tab, a.mu[j], dvx, dvz, gx, gz);
    r.ax += st.ax;
    r.az += st.az;
    r.de += st.de;
    if constexpr (Pairs) {
      // The compatible energy's remainder needs each pair acceleration times i's share of
      // the pair's work; the stress power is split evenly (stressPairTerm), share 1/2.
      pwx[k] += 0.5 * st.ax;
      pwz[k] += 0.5 * st.az;
    }
  }
  return r;
}

// The same sums from the lane kernel's per-pair terms (stress_lanes.hpp), added in list order
// as scalarRow adds them: the same bits (a pair with W = 0 adds zeros).
template <bool RZ, bool Pairs, bool Switch>
inline void addStressTerms(RowSums& r, const StressRowTerms& t, int k, double* pwx, double* pwz) {
  r.gxx += t.gxx[k];
  r.gxz += t.gxz[k];
  r.gzx += t.gzx[k];
  r.gzz += t.gzz[k];
  if constexpr (Switch) r.phiMin = std::min(r.phiMin, t.phi[k]);
  if constexpr (RZ) r.hoop += t.hoop[k];
  r.ax += t.ax[k];
  r.az += t.az[k];
  r.de += t.de[k];
  if constexpr (Pairs) {
    pwx[k] += 0.5 * t.ax[k];
    pwz[k] += 0.5 * t.az[k];
  }
}
template <bool RZ, bool Pairs, bool Switch>
RowSums laneRow(const StressRowTerms& t, int cnt, double* pwx, double* pwz) {
  RowSums r;
  for (int k = 0; k < cnt; ++k) addStressTerms<RZ, Pairs, Switch>(r, t, k, pwx, pwz);
  return r;
}

// The force pass run row by row inside the strength pass (StrengthModel::passWithForces): its
// lane kernel (full rows), the viscosity policy and parameters.
enum class Force { None, Inviscid, Viscous };
struct ForceArgs {
  RowKernel kernel = nullptr;
  MonaghanViscosity visc{};
};

// r-z (docs/strength.md, "SPH with strength"): the in-plane tensor is weighted by the radius as
// the pressure is (T = r s / rho^2), the pair sums are divided by r_i, and the hoop stress enters
// as the pressure's hoop term does, H_i += sum_k mu_k (-r_k s_tt,k / rho_k^2) W_ik (k = i
// included, times the axis correction), with a_r += H_i / r_i^2 and de += lam_i H_i / r_i (they
// cancel particle by particle in the energy, as for the pressure).
// `lanes`: the Gaussian lane kernel (null: the scalar loop).
// F != None (lanes only): each row first runs the force pass's lane kernel, then the stress
// kernel reads the pair geometry that kernel stored (one W and one gradient per pair instead of
// two); the force rates are written as the force pass writes them (forceRowRates, the same
// code and sums), then the stress terms added. Rows are independent in both passes, so row by
// row gives the bits of the force pass over all rows followed by this one.
template <class K, bool RZ, bool Cached, bool Pairs, bool Switch, Force F = Force::None>
void stressPairs(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                 const StressPoints& p, const double* sxx, const double* szz, const double* sxz,
                 const double* g, double hFactor, int power, const AxisCorrection* axis,
                 const Rates& out, const StressRates& rs, const SwitchArgs& sw,
                 StressRowKernel lanes, const ForceArgs& force = {}) {
  constexpr bool kFused = F != Force::None;
  const long nr = static_cast<long>(nReal);
  const double q2dp = 1.0 / (hFactor * hFactor);  // (dp / h)^2
  const StressLaneArrays la{a.x.data(),   a.z.data(),   a.vx.data(),  a.vz.data(),  a.h.data(),
                            a.mu.data(),  a.rho.data(), a.c.data(),   a.rw.data(),  p.txx.data(),
                            p.tzz.data(), p.txz.data(), p.rxx.data(), p.rzz.data(), p.rxz.data(),
                            p.htt.data(), sw.alpha,     p.vol.data(), p.rec.data()};
  const StressRowParams prm{q2dp, power, sw.betaPerAlpha};
  const LaneArrays fa{a.x.data(), a.z.data(),  a.vx.data(), a.vz.data(), a.rho.data(), a.c.data(),
                      a.h.data(), a.mu.data(), a.rw.data(), a.q.data(),  a.obj.data()};
  const std::size_t cap = lanes ? (list.stride + 7) / 8 * 8 : 0;  // whole blocks of 8 lanes
#pragma omp parallel if (nr > kParallelPairs)
  {
    // One scratch row per thread and pass (no allocation per pair): the stress terms, and
    // fused the force terms (6 columns) and the pair geometry (7).
    std::vector<double> scratch((kFused ? 22 : 9) * cap + 3);
    double* s0 = scratch.data();
    StressRowTerms terms{s0,           s0 + cap,     s0 + 2 * cap, s0 + 3 * cap, s0 + 4 * cap,
                         s0 + 5 * cap, s0 + 6 * cap, s0 + 7 * cap, s0 + 8 * cap};
    terms.wdpMemo = s0 + (kFused ? 22 : 9) * cap;
    terms.wdpMemo[0] = std::numeric_limits<double>::quiet_NaN();
    PairGeometry geom{};
    RowTerms ft{};
    if constexpr (kFused) {
      double* f0 = s0 + 9 * cap;
      geom = {f0 + 6 * cap,  f0 + 7 * cap,  f0 + 8 * cap, f0 + 9 * cap,
              f0 + 10 * cap, f0 + 11 * cap, f0 + 12 * cap};
      ft = {f0, f0 + cap, f0 + 2 * cap, f0 + 3 * cap, f0 + 4 * cap, f0 + 5 * cap, nullptr, nullptr};
      ft.geom = &geom;
    }
#pragma omp for schedule(static)
    for (long il = 0; il < nr; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const int* nb = list.index.data() + list.start[i];
      // The state-n pass runs at the list's positions: cached W if the list has them, else the
      // same W recomputed.
      const double* wc = Cached && list.cacheW ? list.w.data() + list.start[i] : nullptr;
      const int cnt = list.count[i];
      double* pwx = Pairs ? out.pairWx + list.start[i] : nullptr;
      double* pwz = Pairs ? out.pairWz + list.start[i] : nullptr;
      RowSums sums;
      if constexpr (kFused) {
        ft.pwx = pwx;
        ft.pwz = pwz;
        force.kernel(fa, i, nb, wc, cnt, force.visc.alpha, force.visc.beta, ft);
        // The kernel adds the stress terms' pair data (in lanes, not in the loop below).
        terms.pwx = pwx;
        terms.pwz = pwz;
        lanes(la, i, nb, wc, cnt, prm, terms, &geom);
        // Both passes' sums in one loop: more independent chains per slot (each sum still in
        // list order). The force rates first, as the force pass writes them.
        constexpr bool kViscous = F == Force::Viscous;
        ForceRowSums fs;
        for (int k = 0; k < cnt; ++k) {
          addForceTerms<RZ, kViscous, Cached>(fs, ft, k);
          addStressTerms<RZ, false, Switch>(sums, terms, k, nullptr, nullptr);
        }
        forceRowRates<RZ, kViscous, Cached, Pairs>(a, i, fs, axis, nullptr, out);
      } else if (lanes) {
        lanes(la, i, nb, wc, cnt, prm, terms, nullptr);
        sums = laneRow<RZ, Pairs, Switch>(terms, cnt, pwx, pwz);
      } else {
        sums = scalarRow<K, RZ, Cached, Pairs, Switch>(a, i, nb, wc, cnt, p, q2dp, power, sw, pwx,
                                                      pwz);
      }
      const double xi = a.x[i], hi = a.h[i];
      const double gxx = sums.gxx, gxz = sums.gxz, gzx = sums.gzx, gzz = sums.gzz;
      const double sax = sums.ax, saz = sums.az, sde = sums.de, shoop = sums.hoop;
      const double phiMin = sums.phiMin;
      double hoopRate = 0.0;
      if constexpr (RZ) {
        const double hoop =
            (shoop + a.mu[i] * p.htt[i] * K::value(0.0, hi)) * (*axis)(a.rw[i], hi);
        const double inv = 1.0 / a.rw[i];
        const double sgn = xi >= 0.0 ? 1.0 : -1.0;  // a particle briefly past the axis
        const double hoopAx = sgn * hoop * inv * inv;
        out.ax[i] += sax * inv + hoopAx;
        out.az[i] += saz * inv;
        out.de[i] += sde * inv + a.lam[i] * hoop * inv;
        if constexpr (Pairs) {
          if (out.hoopAx) out.hoopAx[i] += hoopAx;
        }
        hoopRate = -a.lam[i];  // v_r / r
      } else {
        (void)axis;
        out.ax[i] += sax;
        out.az[i] += saz;
        out.de[i] += sde;
      }
      const strength::VelocityGradient grad{gxx, gxz, gzx, gzz, hoopRate};
      const strength::Deviator s{sxx[i], szz[i], sxz[i]};
      const strength::Deviator ds = strength::jaumannRate(s, grad, g[i]);
      rs.dsxx[i] = ds.xx;
      rs.dszz[i] = ds.zz;
      rs.dsxz[i] = ds.xz;
      rs.strainRate[i] = strength::equivalentStrainRate(grad);
      if constexpr (Switch) {
        sw.divv[i] = gxx + gzz + hoopRate;
        if constexpr (Cached) out.phi[i] = std::min(out.phi[i], phiMin);  // the time step's phi
      } else {
        (void)phiMin;
      }
    }
  }
}

template <class K, bool RZ, bool Switch>
void dispatch(bool cached, bool pairs, const PairArrays& a, std::size_t n,
              const NeighbourList& list, const StressPoints& p, const double* sxx,
              const double* szz, const double* sxz, const double* g, double hFactor, int power,
              const AxisCorrection* axis, const Rates& out, const StressRates& rs,
              const SwitchArgs& sw) {
  // The Gaussian pair terms in lanes where the CPU has 4 or more (stress_lanes.hpp).
  StressRowKernel lanes = nullptr;
  if constexpr (std::is_same_v<K, GaussianKernel>) {
    static const StressRowKernel k = [] {
      StressRowKernel r = nullptr;
      if (laneWidth() >= 8) r = stressRowKernelAvx512(RZ, Switch);
      if (!r && laneWidth() >= 4) r = stressRowKernelAvx2(RZ, Switch);
      return r;
    }();
    lanes = k;
  }
  if (cached)
    stressPairs<K, RZ, true, false, Switch>(a, n, list, p, sxx, szz, sxz, g, hFactor, power, axis,
                                            out, rs, sw, lanes);
  else if (pairs)
    stressPairs<K, RZ, false, true, Switch>(a, n, list, p, sxx, szz, sxz, g, hFactor, power, axis,
                                            out, rs, sw, lanes);
  else
    stressPairs<K, RZ, false, false, Switch>(a, n, list, p, sxx, szz, sxz, g, hFactor, power,
                                             axis, out, rs, sw, lanes);
}

template <class K>
void dispatch(bool rz, bool sw, bool cached, bool pairs, const PairArrays& a, std::size_t n,
              const NeighbourList& list, const StressPoints& p, const double* sxx,
              const double* szz, const double* sxz, const double* g, double hFactor, int power,
              const AxisCorrection* axis, const Rates& out, const StressRates& rs,
              const SwitchArgs& swa) {
  if (rz && sw)
    dispatch<K, true, true>(cached, pairs, a, n, list, p, sxx, szz, sxz, g, hFactor, power, axis,
                            out, rs, swa);
  else if (rz)
    dispatch<K, true, false>(cached, pairs, a, n, list, p, sxx, szz, sxz, g, hFactor, power, axis,
                             out, rs, swa);
  else if (sw)
    dispatch<K, false, true>(cached, pairs, a, n, list, p, sxx, szz, sxz, g, hFactor, power, axis,
                             out, rs, swa);
  else
    dispatch<K, false, false>(cached, pairs, a, n, list, p, sxx, szz, sxz, g, hFactor, power,
                              axis, out, rs, swa);
}

// The fused passes (Gaussian lanes only).
template <bool RZ, bool Switch, Force F>
void dispatchFused(bool cached, bool pairs, const PairArrays& a, std::size_t n,
                   const NeighbourList& list, const StressPoints& p, const double* sxx,
                   const double* szz, const double* sxz, const double* g, double hFactor, int power,
                   const AxisCorrection* axis, const Rates& out, const StressRates& rs,
                   const SwitchArgs& sw, const ForceArgs& force) {
  static const StressRowKernel lanes = [] {
    StressRowKernel r = nullptr;
    if (laneWidth() >= 8) r = stressRowKernelAvx512(RZ, Switch, true);
    if (!r && laneWidth() >= 4) r = stressRowKernelAvx2(RZ, Switch, true);
    return r;
  }();
  using GK = GaussianKernel;
  if (cached)
    stressPairs<GK, RZ, true, false, Switch, F>(a, n, list, p, sxx, szz, sxz, g, hFactor, power,
                                                axis, out, rs, sw, lanes, force);
  else if (pairs)
    stressPairs<GK, RZ, false, true, Switch, F>(a, n, list, p, sxx, szz, sxz, g, hFactor, power,
                                                axis, out, rs, sw, lanes, force);
  else
    stressPairs<GK, RZ, false, false, Switch, F>(a, n, list, p, sxx, szz, sxz, g, hFactor, power,
                                                 axis, out, rs, sw, lanes, force);
}

}  // namespace

StrengthModel::StrengthModel(std::vector<std::optional<strength::Material>> solids,
                             std::vector<double> rho0, cases::Kernel kernel, double hFactor,
                             double epsilon, int power, bool fracture)
    : solids_(std::move(solids)),
      rho0_(std::move(rho0)),
      kernel_(kernel),
      hFactor_(hFactor),
      epsilon_(epsilon),
      power_(epsilon > 0.0 ? power : 0),
      fracture_(fracture) {}

void StrengthModel::limitTension(PairArrays& a, std::size_t n, const int* mat, bool atStepEnd) {
  if (!fracture_) return;
  const long nl = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (nl > kParallelElements)
  for (long il = 0; il < nl; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    const auto& sm = solids_[static_cast<std::size_t>(mat[i])];
    if (!sm) continue;
    if (atStepEnd && a.p[i] < -sm->spallStrength) damage[i] = 1.0;
    a.p[i] = strength::effectivePressure(a.p[i], damage[i], sm->spallStrength);
  }
}

void StrengthModel::resize(std::size_t n) {
  forEachState(*this, [n](auto& v) { v.resize(n, 0.0); });
  for (auto* v : {&cL, &g_, &sxx0_, &szz0_, &sxz0_, &dsxx_, &dszz_, &dsxz_, &rate_})
    v->resize(n, 0.0);
  // The kept terms are recomputed after any change of the particle set.
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  etaTerms_.assign(n, EtaTerms{nan, 0.0, 0.0, nan, 0.0});
  hardTerms_.assign(n, HardTerms{nan, 0.0});
  if (switch_) {
    alpha.resize(n, visc_.alpha);
    divv_.resize(n, 0.0);
  }
  if (plasticRateOn_) plasticRate.resize(n, 0.0);
}

void StrengthModel::compact(const std::vector<unsigned char>& keep, std::size_t n0, std::size_t n) {
  forEachState(*this, [&](auto& v) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < n0; ++i)
      if (keep[i]) v[k++] = v[i];
  });
  for (auto* v : {&alpha, &plasticRate}) {
    if (v->empty()) continue;  // without the switch / the plastic rate
    std::size_t k = 0;
    for (std::size_t i = 0; i < n0; ++i)
      if (keep[i]) (*v)[k++] = (*v)[i];
  }
  resize(n);
}

StrengthModel::EtaTerms& StrengthModel::etaTerms(std::size_t i, std::size_t k, double eta) {
  EtaTerms& t = etaTerms_[i];
  if (!(t.eta == eta)) {
    const strength::Material& sm = *solids_[k];
    t.eta = eta;
    t.cold = sm.thermal.coldEnergy(eta);
    const auto* sg = std::get_if<strength::SteinbergGuinan>(&sm.yield);
    t.cbrt = sg ? std::cbrt(eta) : 0.0;
  }
  return t;
}

void StrengthModel::beginStep(std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    sxx0_[i] = sxx[i];
    szz0_[i] = szz[i];
    sxz0_[i] = sxz[i];
  }
}

void StrengthModel::advance(double dt, std::size_t n, const PairArrays& a, const double* e,
                            const int* mat, bool accumulate) {
  const long nl = static_cast<long>(n);
  if (switch_ && accumulate) {
    // Morris and Monaghan (1997), with the source bounded by (alpha - alpha_i) as in Rosswog et
    // al. (2000): explicit with the half state's div v, c and h (dt l c / h <= cfl l, small).
    const double amax = visc_.alpha, amin = alphaMin_;
#pragma omp parallel for schedule(static) if (nl > kParallelElements)
    for (long il = 0; il < nl; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const double ai = alpha[i];
      const double rate =
          std::max(-divv_[i], 0.0) * (amax - ai) - (ai - amin) * decay_ * a.c[i] / a.h[i];
      alpha[i] = std::clamp(ai + dt * rate, amin, amax);
    }
  }
  for (std::size_t k = 0; k < solids_.size(); ++k) {
    const int kk = static_cast<int>(k);
    if (!solids_[k]) {
      // A fluid carries no deviator (its rate is 0: G = 0 and s = 0).
      for (long i = 0; i < nl; ++i)
        if (mat[i] == kk) sxx[i] = szz[i] = sxz[i] = 0.0;
      continue;
    }
    const strength::Material& sm = *solids_[k];
    const double rho0 = rho0_[k];
    std::visit(
        [&](const auto& law) {
#pragma omp parallel for schedule(static) if (nl > kParallelElements)
          for (long il = 0; il < nl; ++il) {
            const std::size_t i = static_cast<std::size_t>(il);
            if (mat[i] != kk) continue;
            strength::Deviator s{sxx0_[i] + dt * dsxx_[i], szz0_[i] + dt * dszz_[i],
                                 sxz0_[i] + dt * dsxz_[i]};
            const double eta = a.rho[i] / rho0;
            const double rate = plasticRateOn_ ? plasticRate[i] : rate_[i];
            EtaTerms& et = etaTerms(i, k, eta);
            const strength::YieldInput in{epsP[i], rate, a.p[i],
                                          sm.thermal.temperatureAbove(et.cold, e[i]), eta};
            double y;
            if constexpr (std::is_same_v<std::decay_t<decltype(law)>, strength::SteinbergGuinan>) {
              HardTerms& ht = hardTerms_[i];
              if (!(ht.epsP == epsP[i])) ht = {epsP[i], law.hardening(epsP[i])};
              if (!(et.meltEta == eta)) {
                et.meltEta = eta;
                et.melt = law.meltTemperature(eta);
              }
              y = law.yieldFrom(in, et.melt, ht.hard, et.cbrt);
            } else {
              y = law.yield(in);
            }
            // Damaged material keeps (1 - D) of its shear strength (docs/strength.md).
            const double d = damage[i];
            const strength::ReturnResult rr = strength::radialReturn(s, (1.0 - d) * y, g_[i]);
            sxx[i] = s.xx;
            szz[i] = s.zz;
            sxz[i] = s.xz;
            if (!accumulate) continue;
            if (plasticRateOn_) plasticRate[i] = rr.plasticStrain / dt;
            epsP[i] += rr.plasticStrain;
            if (fracture_ && d < 1.0)
              damage[i] = strength::grownDamage(sm, d, dt, a.p[i], a.rho[i], a.c[i], g_[i], cL[i],
                                                a.h[i] / hFactor_, in, s, rr);
          }
        },
        sm.yield);
  }
}

double StrengthModel::temperature(const PairArrays& a, const double* e, int mat,
                                  std::size_t i) const {
  const auto& sm = solids_[static_cast<std::size_t>(mat)];
  if (!sm) return 0.0;
  return sm->thermal.temperature(a.rho[i] / rho0_[static_cast<std::size_t>(mat)], e[i]);
}

void StrengthModel::refreshPoints(const PairArrays& a, std::size_t n, const double* e,
                                  const int* mat, const Boundaries& bounds) {
  const std::size_t total = a.size();
  for (auto* v : {&pts_.txx, &pts_.tzz, &pts_.txz, &pts_.rxx, &pts_.rzz, &pts_.rxz, &pts_.htt,
                  &pts_.vol})
    if (v->size() < total) v->resize(total);
  // Every point's mu / rho once per state instead of once per pair (the same quotient).
  const long nt = static_cast<long>(total);
#pragma omp parallel for schedule(static) if (nt > kParallelElements)
  for (long i = 0; i < nt; ++i) pts_.vol[i] = a.mu[i] / a.rho[i];
  if (switch_) {
    if (pts_.alpha.size() < total) pts_.alpha.resize(total);
    std::copy(alpha.begin(), alpha.begin() + static_cast<std::ptrdiff_t>(n), pts_.alpha.begin());
    bounds.copyGhostScalars(pts_.alpha.data(), n);
  }
  const long nl = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (nl > kParallelElements)
  for (long il = 0; il < nl; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    const std::size_t k = static_cast<std::size_t>(mat[i]);
    const double rho = a.rho[i];
    if (!solids_[k]) {
      g_[i] = 0.0;
      cL[i] = a.c[i];
      pts_.txx[i] = pts_.tzz[i] = pts_.txz[i] = pts_.htt[i] = 0.0;
      pts_.rxx[i] = pts_.rzz[i] = pts_.rxz[i] = 0.0;
      continue;
    }
    const strength::Material& sm = *solids_[k];
    const double eta = rho / rho0_[k];
    const EtaTerms& et = etaTerms(i, k, eta);
    const double temp = sm.thermal.temperatureAbove(et.cold, e[i]);
    const auto* sg = std::get_if<strength::SteinbergGuinan>(&sm.yield);
    const double g = sg ? sg->shearModulusAt(a.p[i], temp, et.cbrt) : sm.shearModulus;
    g_[i] = g;
    // Failed material (D = 1) returns to a zero yield every step and carries no deviator: no
    // shear wave, its fastest signal is the bulk sound speed. Below D = 1 an elastic wave under
    // (1 - D) Y still travels at the intact c_L, which the crack growth also reads.
    cL[i] = fracture_ && damage[i] >= 1.0 ? a.c[i]
                                          : strength::longitudinalSoundSpeed(a.c[i], g, rho);
    // The radius weight rw (1 in planar geometry) as in the pressure's q = rw P / rho^2.
    const double rw = a.rw[i];
    const double ir2 = rw / (rho * rho);
    pts_.txx[i] = sxx[i] * ir2;
    pts_.tzz[i] = szz[i] * ir2;
    pts_.txz[i] = sxz[i] * ir2;
    pts_.htt[i] = (sxx[i] + szz[i]) * ir2;  // -rw s_tt / rho^2
    Sym2 r;
    if (power_ > 0) r = artificialStress({sxx[i] - a.p[i], szz[i] - a.p[i], sxz[i]}, rho, epsilon_);
    pts_.rxx[i] = rw * r.xx;
    pts_.rzz[i] = rw * r.zz;
    pts_.rxz[i] = rw * r.xz;
  }
  bounds.mirrorGhostTensors(pts_.txx.data(), pts_.tzz.data(), pts_.txz.data(), n);
  bounds.mirrorGhostTensors(pts_.rxx.data(), pts_.rzz.data(), pts_.rxz.data(), n);
  bounds.copyGhostScalars(pts_.htt.data(), n);
  if (laneWidth() >= 4 && kernel_ == cases::Kernel::Gaussian) {
    // The lane kernels' records (StressPoints::rec), reals and ghosts.
    if (pts_.rec.size() < 8 * total) pts_.rec.resize(8 * total);
#pragma omp parallel for schedule(static) if (nt > kParallelElements)
    for (long i = 0; i < nt; ++i) {
      double* r = pts_.rec.data() + 8 * i;
      r[0] = pts_.txx[i];
      r[1] = pts_.tzz[i];
      r[2] = pts_.txz[i];
      r[3] = pts_.rxx[i];
      r[4] = pts_.rzz[i];
      r[5] = pts_.rxz[i];
      r[6] = pts_.vol[i];
      r[7] = a.mu[i];
    }
  }
}

void StrengthModel::pass(const PairArrays& a, std::size_t n, const NeighbourList& list, bool cached,
                         const AxisCorrection* axis, const Rates& out) {
  const StressRates rs{dsxx_.data(), dszz_.data(), dsxz_.data(), rate_.data()};
  const bool pairs = !cached && out.pairWx != nullptr;
  const bool rz = axis != nullptr;
  const SwitchArgs sw{pts_.alpha.data(), switch_ ? visc_.beta / visc_.alpha : 0.0, divv_.data()};
  if (kernel_ == cases::Kernel::Gaussian)
    dispatch<GaussianKernel>(rz, switch_, cached, pairs, a, n, list, pts_, sxx.data(), szz.data(),
                             sxz.data(), g_.data(), hFactor_, power_, axis, out, rs, sw);
  else
    dispatch<CubicSplineKernel>(rz, switch_, cached, pairs, a, n, list, pts_, sxx.data(),
                                szz.data(), sxz.data(), g_.data(), hFactor_, power_, axis, out, rs,
                                sw);
}

bool StrengthModel::fusable() const {
  // The widths dispatchFused picks from.
  return kernel_ == cases::Kernel::Gaussian &&
         ((laneWidth() >= 8 && stressRowKernelAvx512(false, false, true)) ||
          (laneWidth() >= 4 && stressRowKernelAvx2(false, false, true)));
}

void StrengthModel::passWithForces(const PairArrays& a, std::size_t n, const NeighbourList& list,
                                   bool cached, const AxisCorrection* axis, bool viscous,
                                   bool compatible, const MonaghanViscosity& visc,
                                   const Rates& out) {
  const StressRates rs{dsxx_.data(), dszz_.data(), dsxz_.data(), rate_.data()};
  const bool pairs = !cached && out.pairWx != nullptr;
  const bool rz = axis != nullptr;
  const SwitchArgs sw{pts_.alpha.data(), switch_ ? visc_.beta / visc_.alpha : 0.0, divv_.data()};
  const ForceArgs force{rowKernel(rz, viscous, cached, compatible), visc};
  const auto run = [&](auto rzTag, auto swTag, auto fTag) {
    dispatchFused<decltype(rzTag)::value, decltype(swTag)::value, decltype(fTag)::value>(
        cached, pairs, a, n, list, pts_, sxx.data(), szz.data(), sxz.data(), g_.data(), hFactor_,
        power_, axis, out, rs, sw, force);
  };
  using T = std::true_type;
  using N = std::false_type;
  using Inv = std::integral_constant<Force, Force::Inviscid>;
  using Vis = std::integral_constant<Force, Force::Viscous>;
  // The switched viscosity is this pass's: the force kernel then runs inviscid.
  if (rz) {
    if (switch_)
      run(T{}, T{}, Inv{});
    else if (viscous)
      run(T{}, N{}, Vis{});
    else
      run(T{}, N{}, Inv{});
  } else {
    if (switch_)
      run(N{}, T{}, Inv{});
    else if (viscous)
      run(N{}, N{}, Vis{});
    else
      run(N{}, N{}, Inv{});
  }
}

void StrengthModel::enablePlasticStrainRate(std::size_t n) {
  plasticRateOn_ = true;
  plasticRate.assign(n, 0.0);
}

void StrengthModel::enableViscositySwitch(const MonaghanViscosity& visc, double alphaMin,
                                          double decay, std::size_t n) {
  switch_ = visc.alpha > 0.0;  // alpha = 0: no viscosity to switch
  visc_ = visc;
  alphaMin_ = alphaMin;
  decay_ = decay;
  alpha.assign(n, visc.alpha);
  divv_.assign(n, 0.0);
}

}  // namespace hvi::sph::detail
