//! @file Sweep driver: grid lines into contiguous buffers, the line kernel, OpenMP over lines.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hvi/common/error.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/tvd.hpp"
#include "line_kernel.hpp"
#include "sweep_common.hpp"
#include "workspace.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hvi::tvd {
namespace detail {

LineWork::LineWork(int cells) : capacity(cells) {
  const auto nb = static_cast<std::size_t>(cells) + 4;
  for (auto* a : {&u0, &u1, &w})
    for (auto& v : *a) v.assign(nb, 0.0);
  cs.assign(nb, CellState{});
  sqrtRho.assign(nb, 0.0);
  F.assign(nb, {});
  fe.assign(nb, FaceEigen{});
  g.assign(nb, {});
  fluxL.assign(nb, {});
  fluxR.assign(nb, {});
  fallback.assign(nb, 0);
  owner.assign(nb, -1);
  mat.assign(nb, -1);
  nn.assign(nb, 0.0);
  nt.assign(nb, 0.0);
  kind.assign(nb, FaceKind::Regular);
  area.assign(nb, 1.0);
  invVol.assign(nb, 1.0);
  invR.assign(nb, 0.0);
  pface.assign(nb, 0.0);
}

}  // namespace detail

namespace {

using detail::FaceKind;
using detail::Side;
using LineFn = bool (*)(detail::LineWork&, const detail::LineSetup&, const detail::SweepContext&,
                        detail::LineBudget&, detail::LineFailure&);

template <class Lim, bool Radial, bool Markers>
bool runLine(detail::LineWork& w, const detail::LineSetup& s, const detail::SweepContext& c,
             detail::LineBudget& b, detail::LineFailure& f) {
  return detail::LineSolver<Lim, Radial, Markers>(w, s, c, b).run(f);
}

template <class Lim>
LineFn pickFor(bool radial, bool markers) {
  if (radial) return markers ? &runLine<Lim, true, true> : &runLine<Lim, true, false>;
  return markers ? &runLine<Lim, false, true> : &runLine<Lim, false, false>;
}

// The limiter, the r-z source and the marker treatment are template parameters of the line
// kernel, chosen here once per sweep: an effect the scene does not name costs no branch.
LineFn pickLineFunction(cases::Limiter limiter, bool radial, bool markers) {
  switch (limiter) {
    case cases::Limiter::Minmod:
      return pickFor<Minmod>(radial, markers);
    case cases::Limiter::VanLeer:
      return pickFor<VanLeer>(radial, markers);
    case cases::Limiter::Superbee:
      return pickFor<Superbee>(radial, markers);
  }
  return pickFor<Minmod>(radial, markers);
}

// Objects of one material are one medium: across their common boundary the flow is computed
// as inside one object (mass crosses, the configuration array only labels the cells), so an
// aluminium striker on an aluminium shield loses no mass at the contact. Only a boundary
// between different materials is a contact with its own flux (slip, no mixing).
FaceKind faceKind(int ownerL, int ownerR, int matL, int matR) {
  if (ownerL >= 0 && ownerR >= 0) return matL == matR ? FaceKind::Regular : FaceKind::Contact;
  if (ownerL >= 0) return FaceKind::VacuumRight;
  if (ownerR >= 0) return FaceKind::VacuumLeft;
  return FaceKind::Void;
}

}  // namespace

void TvdSolver::sweep(int direction, double dt) {
  const auto [xdir, N, lines, step, rz, radial, h] =
      detail::sweepShape(grid_, geometry_, direction);
  const int nx = grid_.nx;
  const LineFn fn = pickLineFunction(params_.limiter, radial, markersOn_);

  detail::SweepContext ctx;
  ctx.materials = &materials_;
  ctx.rhoCut = rhoCut_.data();
  ctx.rhoThin = rhoThin_.data();
  ctx.singleMaterial = singleMaterial_;
  ctx.entropyFix = options_.entropyFix;
  ctx.contactIterations = options_.contactIterations;
  ctx.dt = dt;
  ctx.axis = xdir ? 0 : 1;
  const Side lowSide = detail::sideOf(domain_.boundary[xdir ? 0 : 2]);
  const Side highSide = detail::sideOf(domain_.boundary[xdir ? 1 : 3]);
  // The grid arrays in line components (detail::Component): normal and tangential momentum.
  double* arrays[4];
  arrays[detail::kRho] = U_.rho.data();
  arrays[detail::kMn] = xdir ? U_.mx.data() : U_.mz.data();
  arrays[detail::kMt] = xdir ? U_.mz.data() : U_.mx.data();
  arrays[detail::kE] = U_.E.data();
  const int* own = markersOn_ ? ownership_.owner().data() : nullptr;
  const Vec2* normal = markersOn_ ? ownership_.normal().data() : nullptr;

#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
  {
#ifdef _OPENMP
    Workspace& ws = *work_[static_cast<std::size_t>(omp_get_thread_num())];
#else
    Workspace& ws = *work_[0];
#endif
    detail::LineWork& W = ws.line;
#pragma omp for schedule(dynamic, 2)
    for (int line = 0; line < lines; ++line) {
      LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
      rec = LineRecord{};
      if (ws.failed) continue;
      const long base = xdir ? static_cast<long>(line) * nx : line;
      auto at = [&](int pos) { return base + pos * step; };

      // Window: a marker run updates only the span between the first and last owned cell.
      int a = 0;
      detail::LineSetup setup;
      if (!detail::lineWindow(N, lowSide, highSide,
                              [&](int pos) { return own == nullptr || own[at(pos)] >= 0; }, a,
                              setup))
        continue;
      const int n = setup.n;

      for (int j = 0; j < n + 4; ++j) {
        const int pos = a - 2 + j;
        if (pos < 0 || pos >= N) continue;
        const long c = at(pos);
        for (int k = 0; k < 4; ++k) W.u0[k][j] = arrays[k][c];
      }
      if (own != nullptr) {
        for (int j = 0; j < n + 4; ++j) {
          bool mirrored = false;
          const int pos = detail::ghostSource(a - 2 + j, N, lowSide, highSide, mirrored);
          const double sign = mirrored ? -1.0 : 1.0;
          const long c = at(pos);
          const int o = own[c];
          W.owner[j] = o;
          W.mat[j] = o >= 0 ? objectMaterial_[static_cast<std::size_t>(o)] : -1;
          const Vec2 nv = normal[c];
          W.nn[j] = sign * (xdir ? nv.x : nv.z);
          W.nt[j] = xdir ? nv.z : nv.x;
        }
        for (int f = 0; f <= n + 2; ++f)
          W.kind[f] = faceKind(W.owner[f], W.owner[f + 1], W.mat[f], W.mat[f + 1]);
      }
      // Geometry (line units): r-z radial lines have face areas r_f and volumes r_j dr.
      const double lineScale =
          detail::lineGeometry(radial, rz, h, a, n, line, faceX_, cellX_, W.area, W.invVol, W.invR);

      detail::LineBudget lb;
      detail::LineFailure fail;
      if (strength_)  // the density before the sweep: the strength advection's mass fluxes
        for (int j = 2; j <= n + 1; ++j) {
          ws.strength->rhoOld[static_cast<std::size_t>(j)] = W.u0[detail::kRho][j];
          ws.strength->cells[static_cast<std::size_t>(j)] = at(a - 2 + j);
        }
      if (!fn(W, setup, ctx, lb, fail)) {
        ws.fail(line, detail::failureMessage(step_, xdir, dt, a, line, grid_, fail));
        continue;
      }
      for (int j = 2; j <= n + 1; ++j) {
        const long c = at(a - 2 + j);
        for (int k = 0; k < 4; ++k) arrays[k][c] = W.u0[k][j];
      }
      if (strength_)
        detail::advectStrengthLine(*strength_, *ws.strength, W, n, lb.edge[0].mass,
                                   rhoCut_[static_cast<std::size_t>(singleMaterial_)]);
      rec.interfaces = lb.interfaces.scaled(lineScale);
      rec.floors = lb.floors.scaled(lineScale);
      rec.bookEdges(lb, setup, lowSide, highSide, lineScale);
      // per material, for the renormalisation targets
      const bool edge[2] = {setup.leftEdge, setup.rightEdge};
      const int edgeCell[2] = {2, n + 1};
      for (int e = 0; e < 2; ++e) {
        if (edge[e] && own != nullptr && W.mat[edgeCell[e]] >= 0) {
          rec.edgeMass[e] = lb.edge[e].scaled(lineScale).mass;
          rec.edgeMaterial[e] = W.mat[edgeCell[e]];
        }
      }
    }
  }
  finishSweep(lines);
}

// The lowest failed line's report, if any line failed; else the line records summed into the
// ledger in line order (the totals do not depend on the schedule).
void TvdSolver::finishSweep(int lines) {
  const Workspace* failed = nullptr;
  for (const auto& w : work_)
    if (w->failed && (failed == nullptr || w->failedLine < failed->failedLine)) failed = w.get();
  if (failed != nullptr) {
    const std::string msg = failed->message;
    for (auto& v : work_) v->failed = false;
    throw SimulationError(msg);
  }
  for (int line = 0; line < lines; ++line) {
    const LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
    ledger_.boundary += rec.boundary;
    ledger_.interfaces += rec.interfaces;
    ledger_.floors += rec.floors;
    ledger_.outflow += rec.outflow;
    relaxations_ += rec.relaxed;
    mixings_ += rec.mixed;
    for (int e = 0; e < 2; ++e)
      if (rec.edgeMaterial[e] >= 0)
        ownership_.addBoundaryMass(rec.edgeMaterial[e], rec.edgeMass[e]);
  }
}

}  // namespace hvi::tvd
