//! @file Mass iteration: masses that make the summation density equal rho0 at t = 0.
#include "detail/parallel.hpp"
#include "hvi/sph/mass_adjust.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "detail/axis_correction.hpp"
#include "detail/boundary.hpp"
#include "detail/passes.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"

namespace hvi::sph {

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
  // over from ps (given back at the end) instead of copying them, the masses are not held
  // while the iteration runs (its weights are), and the cell grid goes once the list is built.
  detail::PairArrays a;
  a.lean = true;
  a.x = std::move(ps.x);
  a.z = std::move(ps.z);
  a.h = std::move(ps.h);
  a.obj = std::move(ps.object);
  std::vector<double>().swap(ps.m);
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
  {
    CellGrid grid;
    detail::selectListPass(opt.kernel)(a, n, support, grid, list, nullptr);
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
#pragma omp for schedule(static)
      for (long il = 0; il < nl; ++il) {
        const std::size_t i = static_cast<std::size_t>(il);
        if (!alive[i]) continue;
        const int obj = a.obj[i];
        double sum = a.mu[i] * detail::kernelSelf(opt.kernel, a.h[i]);
        const int* nb = list.index.data() + list.start[i];
        const double* w = list.w.data() + list.start[i];
        for (int k = 0; k < list.count[i]; ++k) {
          const std::size_t j = static_cast<std::size_t>(nb[k]);
          if (a.obj[j] == obj) sum += a.mu[j] * w[k];
        }
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
  std::vector<double>().swap(rho);
  ps.m.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    ps.m[i] = rz ? 2.0 * std::numbers::pi * a.rw[i] * a.mu[i] : a.mu[i];
  // The reals' x, z, h and object back to ps (the ghosts after them dropped).
  const auto giveBack = [n](auto& from, auto& to) {
    from.resize(n);
    to = std::move(from);
  };
  giveBack(a.x, ps.x);
  giveBack(a.z, ps.z);
  giveBack(a.h, ps.h);
  giveBack(a.obj, ps.object);
  if (report.deleted > 0) ps.compact(alive);
  return report;
}

}  // namespace hvi::sph
