//! @file Phase geometry from the marker lines, the conservative repair after the fractions
//! change, and the mixture state (docs/tvd.md, "Conservative interfaces").
#include "hvi/tvd/phases.hpp"

#include <algorithm>
#include <cmath>

#include "cut_line.hpp"
#include "hvi/tvd/ownership.hpp"

namespace hvi::tvd {

namespace detail {

PhaseLine::PhaseLine(int capacity) {
  const auto nb = static_cast<std::size_t>(capacity) + 4;
  for (auto* a : {&q0, &q1, &w, &ex, &U})
    for (auto& v : *a) v.assign(nb, 0.0);
  for (auto* v : {&alpha, &gm, &gp, &ap, &uL, &uR, &It, &sqrtRho, &pface}) v->assign(nb, 0.0);
  present.assign(nb, 0);
  cs.assign(nb, CellState{});
  F.assign(nb, {});
  flux.assign(nb, {});
  fe.assign(nb, FaceEigen{});
  g.assign(nb, {});
  fallback.assign(nb, 0);
}

CutLineWork::CutLineWork(int cap, int phases) : capacity(cap) {
  const auto nb = static_cast<std::size_t>(cap) + 4;
  for (int p = 0; p < phases; ++p) phase.emplace_back(cap);
  area.assign(nb, 1.0);
  invVol.assign(nb, 1.0);
  invR.assign(nb, 0.0);
  scratch.assign(nb, 0.0);
}

}  // namespace detail

void Phases::resize(int phases, const GridSpec& g) {
  count = phases;
  grid = g;
  const auto cells = static_cast<std::size_t>(g.cells());
  const auto fx = static_cast<std::size_t>(2L * g.nz * (g.nx + 1));
  const auto fz = static_cast<std::size_t>(2L * (g.nz + 1) * g.nx);
  q.assign(static_cast<std::size_t>(phases), Conserved{});
  for (auto& s : q)
    for (auto* v : {&s.rho, &s.mx, &s.mz, &s.E}) v->assign(cells, 0.0);
  alpha.assign(static_cast<std::size_t>(phases), std::vector<double>(cells, 0.0));
  ax.assign(static_cast<std::size_t>(phases), std::vector<double>(fx, 0.0));
  az.assign(static_cast<std::size_t>(phases), std::vector<double>(fz, 0.0));
}

namespace {

// Sums per-object values into per-phase ones, capped at 1, then scales the phases of each
// entry down together where they exceed 1 (two bodies' lines overlapping by round-off).
void sumByPhase(const double* perObject, std::size_t n, const std::vector<int>& objectMaterial,
                std::vector<std::vector<double>>& out) {
  for (auto& v : out) std::fill(v.begin(), v.end(), 0.0);
  for (std::size_t o = 0; o < objectMaterial.size(); ++o) {
    double* dst = out[static_cast<std::size_t>(objectMaterial[o])].data();
    const double* src = perObject + o * n;
    for (std::size_t c = 0; c < n; ++c) dst[c] += src[c];
  }
  for (std::size_t c = 0; c < n; ++c) {
    double total = 0.0;
    for (auto& v : out) {
      v[c] = std::min(v[c], 1.0);
      total += v[c];
    }
    if (total > 1.0)
      for (auto& v : out) v[c] /= total;
  }
}

}  // namespace

void Phases::measure(const MarkerSet& markers, const std::vector<int>& objectMaterial,
                     const std::vector<double>& fraction, FaceApertures& apertures) {
  const auto cells = static_cast<std::size_t>(grid.cells());
  sumByPhase(fraction.data(), cells, objectMaterial, alpha);
  for (auto& a : alpha)
    for (double& v : a)
      if (v < kPhaseAbsent) v = 0.0;
  markers.faceApertures(grid, apertures);
  // x faces: objects * 2 sides * nz * (nx + 1); per side the same layout as Phases::ax.
  const auto fx = static_cast<std::size_t>(2L * grid.nz * (grid.nx + 1));
  const auto fz = static_cast<std::size_t>(2L * (grid.nz + 1) * grid.nx);
  sumByPhase(apertures.x.data(), fx, objectMaterial, ax);
  sumByPhase(apertures.z.data(), fz, objectMaterial, az);
}

void Phases::mixture(Conserved& U) const {
  const auto cells = static_cast<std::size_t>(grid.cells());
  for (auto* v : {&U.rho, &U.mx, &U.mz, &U.E}) v->assign(cells, 0.0);
  for (const auto& s : q)
    for (std::size_t c = 0; c < cells; ++c) {
      U.rho[c] += s.rho[c];
      U.mx[c] += s.mx[c];
      U.mz[c] += s.mz[c];
      U.E[c] += s.E[c];
    }
}

long Phases::repair(const CellVolumes& volumes, const std::vector<std::vector<double>>& oldAlpha) {
  const int nx = grid.nx, nz = grid.nz;
  long orphans = 0;
  for (int p = 0; p < count; ++p) {
    auto& a = alpha[static_cast<std::size_t>(p)];
    const auto& a0 = oldAlpha[static_cast<std::size_t>(p)];
    Conserved& s = q[static_cast<std::size_t>(p)];
    double* comp[4] = {s.rho.data(), s.mx.data(), s.mz.data(), s.E.data()};
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        const long c = static_cast<long>(k) * nx + i;
        const auto cc = static_cast<std::size_t>(c);
        const bool has = s.rho[cc] != 0.0;
        const bool vacated = a[cc] < kPhaseAbsent && has;
        const bool fresh = a[cc] >= kPhaseAbsent && !has;
        const bool small = a[cc] >= kPhaseAbsent && a[cc] < 0.5 && has;
        if (!vacated && !fresh && !small) continue;
        // The neighbour of this phase with the largest fraction (and material in it), within
        // one ring, else two.
        long best = -1;
        double bestA = a[cc];
        for (int reach = 1; reach <= 2 && best < 0; ++reach)
          for (int dk = -reach; dk <= reach; ++dk)
            for (int di = -reach; di <= reach; ++di) {
              const int ii = i + di, kk = k + dk;
              if ((di == 0 && dk == 0) || ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
              const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
              if (a[d] > bestA && s.rho[d] > 0.0) {
                bestA = a[d];
                best = static_cast<long>(d);
              }
            }
        if (best < 0) {
          if (vacated) {  // nowhere to go: the material keeps its last volume here
            a[cc] = a0[cc] >= kPhaseAbsent ? a0[cc] : kPhaseAbsent;
            ++orphans;
          } else if (fresh) {
            a[cc] = 0.0;  // a sliver the phase has no material near: not occupied
          }
          continue;
        }
        const auto d = static_cast<std::size_t>(best);
        const double vc = volumes(c), vd = volumes(best);
        const double pooled = a[cc] * vc + a[d] * vd;
        for (double* v : comp) {
          const double total = v[cc] * vc + v[d] * vd;
          const double u = total / pooled;
          v[cc] = a[cc] * u;
          v[d] = a[d] * u;
        }
      }
  }
  return orphans;
}

}  // namespace hvi::tvd
