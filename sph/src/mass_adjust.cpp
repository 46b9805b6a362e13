//! @file Mass iteration: masses that make the summation density equal rho0 at t = 0.
#include "detail/parallel.hpp"
#include "hvi/sph/mass_adjust.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "detail/axis_correction.hpp"
#include "detail/boundary.hpp"
#include "detail/force_lanes.hpp"
#include "detail/passes.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/sph/kernel.hpp"

namespace hvi::sph {

namespace {

// W_ij of row i into w (the list's stride plus a lane width) as the list build computed them:
// the Gaussian's in lanes (detail::rowWKernel, the scan's operations), the spline's as the
// build's second pass (h_ij = (h_i + h_j) / 2). The same bits.
template <class K>
void rowWeights(const detail::PairArrays& a, const NeighbourList& list, std::size_t i,
                double* w) {
  const double xi = a.x[i], zi = a.z[i], hi = a.h[i];
  const int* nb = list.index.data() + list.start[i];
  const int cnt = list.count[i];
  if constexpr (std::is_same_v<K, GaussianKernel>) {
    static const detail::RowWKernel rowW = detail::rowWKernel();
    rowW(a.x.data(), a.z.data(), a.h.data(), i, nb, cnt, w);
  } else {
    for (int k = 0; k < cnt; ++k) {
      const std::size_t j = static_cast<std::size_t>(nb[k]);
      const double dx = xi - a.x[j], dz = zi - a.z[j];
      const double hij = 0.5 * (hi + a.h[j]);
      w[k] = K::value(dx * dx + dz * dz, hij, 1.0 / (hij * hij));
    }
  }
}

// One sweep's sum_j mu_j W_ij over i's own object (mu_i W_ii included), W_ij from `cached`
// (the row's, if not null) or recomputed into the scratch `w`.
template <class K>
double sweepRow(const detail::PairArrays& a, const NeighbourList& list, std::size_t i,
                const double* cached, double* w) {
  const int obj = a.obj[i];
  double sum = a.mu[i] * K::value(0.0, a.h[i]);
  const int* nb = list.index.data() + list.start[i];
  const int cnt = list.count[i];
  const double* wr = cached;
  if (!wr) {
    rowWeights<K>(a, list, i, w);
    wr = w;
  }
  for (int k = 0; k < cnt; ++k) {
    const std::size_t j = static_cast<std::size_t>(nb[k]);
    if (a.obj[j] == obj) sum += a.mu[j] * wr[k];
  }
  return sum;
}

}  // namespace

MassAdjustReport adjustMasses(ParticleSystem& ps, const MassAdjustOptions& opt) {
  const std::size_t n = ps.size();
  const bool rz = opt.geometry == Geometry::Axisymmetric;
  // Symmetric r-z form (docs/sph-rz.md): rho_i = sum_j nu_j W_ij / s_i with nu = m / (2 pi s),
  // so the unknown is nu and the sum's target is s_i rho0_i.
  const bool sym = rz && opt.rzForm == cases::RzForm::Symmetric;
  const detail::RingScale* ring = sym ? &detail::ringScale(opt.kernel) : nullptr;
  MassAdjustReport report;
  if (n == 0) return report;
  // Memory (docs/performance.md, "SPH memory"): the pair arrays take x, z, h and the object
  // over from ps instead of copying them, and the cell grid goes once the list is built.
  detail::PairArrays a;
  a.lean = true;
  a.x = std::move(ps.x);
  a.z = std::move(ps.z);
  a.h = std::move(ps.h);
  a.obj = std::move(ps.object);
  // ps gets them back on every exit, a stop or an error included (nothing half-done escapes to
  // the caller); the ghosts after the reals are dropped.
  struct GiveBack {
    detail::PairArrays& a;
    ParticleSystem& ps;
    std::size_t n;
    bool done = false;
    void now() {
      if (done) return;
      done = true;
      a.x.resize(n);
      a.z.resize(n);
      a.h.resize(n);
      a.obj.resize(n);
      ps.x = std::move(a.x);
      ps.z = std::move(a.z);
      ps.h = std::move(a.h);
      ps.object = std::move(a.obj);
    }
    ~GiveBack() { now(); }
  } lent{a, ps, n};
  a.resize(n);
  double hmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    a.mu[i] = 1.0;
    a.rw[i] = rz ? std::abs(a.x[i]) : 1.0;
    if (sym) a.rw[i] = ring->value(std::abs(a.x[i]), a.h[i]);  // s_i here
    hmax = std::max(hmax, a.h[i]);
  }
  // Positions do not move, so the list (radius = kernel support) is built once.
  const double support = detail::kernelSupport(opt.kernel);
  detail::Boundaries bounds(opt.domain, opt.geometry);
  bounds.makeGhosts(a, n, support * hmax);
  NeighbourList list;
  list.fixedPoints = true;
  // W_ij is cached for the first rows only, up to kCachedSlots per particle on average, and
  // recomputed in each sweep for the others (the same bits): caching them all (8 B per slot,
  // ~200 B per particle on variant 2) made the set-up the run's peak memory; with this budget
  // it stays below the stepping's (docs/performance.md, "SPH memory"), and a sweep recomputes
  // ~40 % of the rows of a 26-neighbour lattice.
  list.cacheW = false;
  {
    CellGrid grid;
    detail::selectListPass(opt.kernel)(a, n, support, grid, list, nullptr);
  }
  const bool gauss = opt.kernel == cases::Kernel::Gaussian;
  constexpr std::size_t kCachedSlots = 16;
  std::size_t cachedRows = 0;
  while (cachedRows < n && list.start[cachedRows + 1] <= kCachedSlots * n) ++cachedRows;
  std::vector<double> wCache(list.start[cachedRows]);
  {
    const long nc = static_cast<long>(cachedRows);
#pragma omp parallel if (nc > detail::kParallelPairs)
    {
      std::vector<double> w(list.stride + 8);
#pragma omp for schedule(static)
      for (long il = 0; il < nc; ++il) {
        const std::size_t i = static_cast<std::size_t>(il);
        if (gauss)
          rowWeights<GaussianKernel>(a, list, i, w.data());
        else
          rowWeights<CubicSplineKernel>(a, list, i, w.data());
        std::copy(w.begin(), w.begin() + list.count[i], wCache.begin() + static_cast<long>(list.start[i]));
      }
    }
  }

  std::vector<double> rho(n);
  std::vector<unsigned char> alive(n, 1);
  std::map<int, double> maxMu;
  const long nl = static_cast<long>(n);
  for (;;) {
    // Each pass is one sweep over the particles; a tight sph.mass_tolerance with a large
    // sph.max_mass_iterations can run for hours, so a stop request is honoured between passes.
    if (stopRequested())
      throw StopDuringSetUp(fmt::format("stopped during the SPH mass iteration (pass {})",
                                        report.iterations));
    double residual = 0.0;
    long worst = -1;
#pragma omp parallel if (nl > detail::kParallelPairs)
    {
      double myRes = 0.0;
      long myWorst = -1;
      std::vector<double> w(list.stride + 8);
#pragma omp for schedule(static)
      for (long il = 0; il < nl; ++il) {
        const std::size_t i = static_cast<std::size_t>(il);
        if (!alive[i]) continue;
        const double* cached = i < cachedRows ? wCache.data() + list.start[i] : nullptr;
        const double sum = gauss ? sweepRow<GaussianKernel>(a, list, i, cached, w.data())
                                 : sweepRow<CubicSplineKernel>(a, list, i, cached, w.data());
        rho[i] = sym ? sum / a.rw[i] : sum;
        const double r = std::abs(ps.rhoRef[i] / rho[i] - 1.0);
        if (r > myRes) {
          myRes = r;
          myWorst = il;
        }
      }
#pragma omp critical
      if (myRes > residual || (myRes == residual && myWorst < worst)) {
        residual = myRes;
        worst = myWorst;
      }
    }
    report.maxResidual = residual;
    if (residual < opt.tolerance) break;
    if (report.iterations >= opt.maxIterations)
      throw SimulationError(fmt::format(
          "mass iteration did not converge in {} iterations: max |rho0/rho - 1| = {:.3e} at "
          "particle {} (x = {}, z = {} cm, object {}); raise sph.max_mass_iterations or check "
          "the lattice",
          report.iterations, residual, ps.id[static_cast<std::size_t>(worst)],
          a.x[static_cast<std::size_t>(worst)], a.z[static_cast<std::size_t>(worst)],
          a.obj[static_cast<std::size_t>(worst)]));
    for (std::size_t i = 0; i < n; ++i)
      if (alive[i]) a.mu[i] *= ps.rhoRef[i] / rho[i];
    // Deletion compares with the largest *new* weight of the object. The spec (section 3,
    // docs/method.md) writes the old maximum, but the first update rescales every weight from 1
    // by ~rho0 dx^2, so against the old maximum whole bodies would vanish for fine spacings or
    // light materials; after the first update the two agree to the per-iteration change of the
    // masses.
    maxMu.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (alive[i]) maxMu[a.obj[i]] = std::max(maxMu[a.obj[i]], a.mu[i]);
    for (std::size_t i = 0; i < n; ++i) {
      if (alive[i] && a.mu[i] / maxMu[a.obj[i]] < opt.deleteFraction) {
        // Badly placed: its equilibrium mass would be ~0 or negative (spec section 3,
        // docs/method.md).
        alive[i] = 0;
        a.mu[i] = 0.0;
        ++report.deleted;
      }
    }
    bounds.refreshGhosts(a, n);
    ++report.iterations;
  }
  list = NeighbourList();
  std::vector<double>().swap(wCache);
  std::vector<double>().swap(rho);
  for (std::size_t i = 0; i < n; ++i)
    ps.m[i] = rz ? 2.0 * std::numbers::pi * a.rw[i] * a.mu[i] : a.mu[i];
  lent.now();
  if (report.deleted > 0) ps.compact(alive);
  return report;
}

}  // namespace hvi::sph
