//! @file Sweep driver: grid lines into contiguous buffers, the line kernel, OpenMP over lines.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "hvi/common/error.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/tvd.hpp"
#include "line_batch.hpp"
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
  damage.assign(nb, 0.0);
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

// Batches of single-material lines: the limiter and the EOS type are template parameters,
// chosen once per sweep (std::visit once per sweep, std::get once per batch).
using BatchFn = void (*)(detail::BatchWork&, const detail::BatchSetup&, const detail::SweepContext&,
                         const cases::Material&, detail::LineBudget*, bool*);

template <class Lim, class Eos>
void runBatch(detail::BatchWork& w, const detail::BatchSetup& s, const detail::SweepContext& c,
              const cases::Material& m, detail::LineBudget* b, bool* redo) {
  detail::BatchSolver<Lim, Eos>(w, s, c, std::get<Eos>(m.eos)).run(b, redo);
}

template <class Eos>
BatchFn pickBatchFor(cases::Limiter limiter) {
  switch (limiter) {
    case cases::Limiter::Minmod:
      return &runBatch<Minmod, Eos>;
    case cases::Limiter::VanLeer:
      return &runBatch<VanLeer, Eos>;
    case cases::Limiter::Superbee:
      return &runBatch<Superbee, Eos>;
  }
  return &runBatch<Minmod, Eos>;
}

BatchFn pickBatch(cases::Limiter limiter, const cases::Material& m) {
  return std::visit(
      [&](const auto& eos) { return pickBatchFor<std::decay_t<decltype(eos)>>(limiter); }, m.eos);
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
  // Effect fracture (docs/strength.md, "TVD fracture"): per line the damage at the sweep's
  // start; the four-line batches do not carry it, so its lines go through the line kernel.
  const bool fracture = strength_ && strength_->fracture;
  if (fracture) {
    ctx.spall = strength_->spall.data();
    ctx.rhoIntact = strength_->rhoIntact.data();
  }
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

  // Single-material planar and r-z axial lines go kB at a time through the batch kernel;
  // lines beyond the last whole batch, and every line otherwise, through LineSolver.
  constexpr int kB = detail::kBatch;
  const bool batched = options_.lineBatches && !markersOn_ && !radial && N >= 2 && !fracture;
  const int groups = batched ? lines / kB : 0;
  const int items = groups + (lines - groups * kB);
  const cases::Material& material = materials_[static_cast<std::size_t>(singleMaterial_)];
  const BatchFn batchFn = batched ? pickBatch(params_.limiter, material) : nullptr;
  detail::BatchSetup bsetup;
  bsetup.n = N;
  bsetup.left = lowSide;
  bsetup.right = highSide;
  bsetup.invVol = 1.0 / h;
  bsetup.rhoCut = rhoCut_[static_cast<std::size_t>(singleMaterial_)];
  detail::LineSetup lineSetup;  // a whole line without markers (lineWindow)
  lineSetup.n = N;
  lineSetup.left = lowSide;
  lineSetup.right = highSide;
  lineSetup.leftEdge = lineSetup.rightEdge = true;

#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
  {
#ifdef _OPENMP
    Workspace& ws = *work_[static_cast<std::size_t>(omp_get_thread_num())];
#else
    Workspace& ws = *work_[0];
#endif
    detail::LineWork& W = ws.line;
    // One line through the scalar kernel (markers, r-z radial lines, a batch's remainder, a
    // batch lane that needs the positivity fallback).
    auto scalarLine = [&](int line) {
      LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
      rec = LineRecord{};
      if (ws.failed) return;
      const long base = xdir ? static_cast<long>(line) * nx : line;
      auto at = [&](int pos) { return base + pos * step; };

      // Window: a marker run updates only the span between the first and last owned cell.
      int a = 0;
      detail::LineSetup setup;
      if (!detail::lineWindow(N, lowSide, highSide,
                              [&](int pos) { return own == nullptr || own[at(pos)] >= 0; }, a,
                              setup))
        return;
      const int n = setup.n;

      for (int j = 0; j < n + 4; ++j) {
        const int pos = a - 2 + j;
        if (pos < 0 || pos >= N) continue;
        const long c = at(pos);
        for (int k = 0; k < 4; ++k) W.u0[k][j] = arrays[k][c];
      }
      if (fracture) {  // rho D / rho, the ghosts' from their source cells as their states
        const double* rd = strength_->rq[detail::kDamage].data();
        const double rc = rhoCut_[static_cast<std::size_t>(singleMaterial_)];
        for (int j = 0; j < n + 4; ++j) {
          bool mirrored = false;
          const auto c = static_cast<std::size_t>(
              at(detail::ghostSource(a - 2 + j, N, lowSide, highSide, mirrored)));
          W.damage[j] = U_.rho[c] >= rc ? rd[c] / U_.rho[c] : 0.0;
        }
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
        return;
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
    };

#pragma omp for schedule(dynamic, 2)
    for (int item = 0; item < items; ++item) {
      if (item >= groups) {
        scalarLine(groups * kB + (item - groups));
        continue;
      }
      const int first = item * kB;
      if (ws.failed) {
        for (int l = 0; l < kB; ++l) lineRecords_[static_cast<std::size_t>(first + l)] = {};
        continue;
      }
      detail::BatchWork& B = *ws.batch;
      // Lane l of the batch is line first + l, cell pos at buffer (pos + 2) kB + l. The z lines
      // of a batch are neighbours in memory: one contiguous run of kB values per cell.
      if (xdir) {
        for (int l = 0; l < kB; ++l) {
          const long base = static_cast<long>(first + l) * nx;
          for (int k = 0; k < 4; ++k)
            for (int pos = 0; pos < N; ++pos) B.u0[k][(pos + 2) * kB + l] = arrays[k][base + pos];
        }
      } else {
        for (int k = 0; k < 4; ++k)
          for (int pos = 0; pos < N; ++pos)
            for (int l = 0; l < kB; ++l)
              B.u0[k][(pos + 2) * kB + l] = arrays[k][first + l + pos * step];
      }
      detail::LineBudget lb[kB];
      bool redo[kB];
      if (strength_)  // the density before the sweep: the strength advection's mass fluxes
        std::copy_n(B.u0[detail::kRho].begin(), static_cast<std::size_t>(N + 4) * kB,
                    ws.strength->lanes.begin());
      batchFn(B, bsetup, ctx, material, lb, redo);
      bool anyRedo = false;
      for (int l = 0; l < kB; ++l) anyRedo = anyRedo || redo[l];
      if (!xdir && !anyRedo)  // z lines: one contiguous run of kB values per cell
        for (int k = 0; k < 4; ++k)
          for (int pos = 0; pos < N; ++pos)
            for (int l = 0; l < kB; ++l)
              arrays[k][first + l + pos * step] = B.u0[k][(pos + 2) * kB + l];
      for (int l = 0; l < kB; ++l) {
        const int line = first + l;
        if (redo[l]) {  // the positivity fallback: the whole line again through LineSolver
          ++ws.redone;
          scalarLine(line);
          continue;
        }
        const long base = xdir ? static_cast<long>(line) * nx : line;
        if (xdir || anyRedo)
          for (int k = 0; k < 4; ++k)
            for (int pos = 0; pos < N; ++pos)
              arrays[k][base + pos * step] = B.u0[k][(pos + 2) * kB + l];
        if (strength_) {  // docs/strength.md, TVD: the lane's strength state moves with its mass
          detail::StrengthLineWork& S = *ws.strength;
          for (int j = 2; j <= N + 1; ++j) {
            const auto i = static_cast<std::size_t>(j * kB + l), jj = static_cast<std::size_t>(j);
            S.rhoOld[jj] = S.lanes[i];
            S.rhoNew[jj] = B.u0[detail::kRho][i];
            S.invVol[jj] = bsetup.invVol;
            S.cells[jj] = base + (j - 2) * step;
          }
          detail::advectStrengthLine(*strength_, S, S.rhoNew.data(), S.invVol.data(), N,
                                     lb[l].edge[0].mass, bsetup.rhoCut);
        }
        const double lineScale =
            rz ? 2.0 * std::numbers::pi * cellX_[static_cast<std::size_t>(line)] * h : h;
        LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
        rec = LineRecord{};
        rec.interfaces = lb[l].interfaces.scaled(lineScale);
        rec.floors = lb[l].floors.scaled(lineScale);
        rec.bookEdges(lb[l], lineSetup, lowSide, highSide, lineScale);
      }
    }
  }
  finishSweep(lines);
}

long TvdSolver::linesRedone() const {
  long n = 0;
  for (const auto& w : work_) n += w->redone;
  return n;
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
    poolings_ += rec.pooled;
    for (int e = 0; e < 2; ++e)
      if (rec.edgeMaterial[e] >= 0)
        ownership_.addBoundaryMass(rec.edgeMaterial[e], rec.edgeMass[e]);
  }
}

}  // namespace hvi::tvd
