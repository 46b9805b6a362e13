//! @file Sweep driver of the conservative cut-cell mode: every phase of a grid line into
//! contiguous buffers, the cut-cell line kernel, OpenMP over lines.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cut_kernel.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/tvd.hpp"
#include "sweep_common.hpp"
#include "workspace.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hvi::tvd {
namespace {

using detail::Side;
using CutFn = bool (*)(detail::CutLineWork&, const detail::LineSetup&, const detail::SweepContext&,
                       detail::LineBudget&, detail::LineFailure&);

template <class Lim, bool Radial>
bool runCutLine(detail::CutLineWork& w, const detail::LineSetup& s, const detail::SweepContext& c,
                detail::LineBudget& b, detail::LineFailure& f) {
  return detail::CutLineSolver<Lim, Radial>(w, s, c, b).run(f);
}

template <class Lim>
CutFn pickCutFor(bool radial) {
  return radial ? &runCutLine<Lim, true> : &runCutLine<Lim, false>;
}

CutFn pickCutFunction(cases::Limiter limiter, bool radial) {
  switch (limiter) {
    case cases::Limiter::Minmod:
      return pickCutFor<Minmod>(radial);
    case cases::Limiter::VanLeer:
      return pickCutFor<VanLeer>(radial);
    case cases::Limiter::Superbee:
      return pickCutFor<Superbee>(radial);
  }
  return pickCutFor<Minmod>(radial);
}

}  // namespace

void TvdSolver::sweepCut(int direction, double dt) {
  const auto [xdir, N, lines, step, rz, radial, h] =
      detail::sweepShape(grid_, geometry_, direction);
  const int nx = grid_.nx;
  const CutFn fn = pickCutFunction(params_.limiter, radial);
  const int P = phases_.count;

  detail::SweepContext ctx;
  ctx.materials = &materials_;
  ctx.rhoCut = rhoCut_.data();
  ctx.rhoThin = rhoThin_.data();
  ctx.entropyFix = options_.entropyFix;
  ctx.contactIterations = options_.contactIterations;
  ctx.keepColdStates = options_.keepColdStates;
  ctx.closedOutflow = options_.closedOutflow;
  ctx.dt = dt;
  ctx.h = h;
  ctx.axis = xdir ? 0 : 1;
  const bool fracture = strength_ && strength_->fracture;
  if (fracture) {
    ctx.spall = strength_->spall.data();
    ctx.rhoIntact = strength_->rhoIntact.data();
  }
  const Side lowSide = detail::sideOf(domain_.boundary[xdir ? 0 : 2]);
  const Side highSide = detail::sideOf(domain_.boundary[xdir ? 1 : 3]);

  // Each phase's first and last occupied position along every line. The kernel changes
  // fractions only on its own line, so these stay valid through the sweep. The step's first
  // sweep finds them in one pass over the fractions in memory order (the rows [rowLo, rowHi)
  // hold every occupied cell) and, as it writes its lines back, records them for the lines of
  // the other direction (per thread, merged after it); the second sweep takes that record
  // instead of reading the whole fraction field again (a memory-bound pass, 2 % of the
  // conservative variant-1 run, docs/tvd.md).
  const bool firstSweep = volumeFresh_;
  int* span = phaseSpan_.data();  // [(line * P + p) * 2 + 0 / 1]
  const long stride = 2L * static_cast<long>(lineRecords_.size()) * P;  // one thread's record
  if (!firstSweep && spanNextValid_) {
    for (long e = 0; e < 2L * lines * P; e += 2) {
      int lo = std::numeric_limits<int>::max(), hi = -1;
      for (int t = 0; t < threads_; ++t) {
        lo = std::min(lo, spanNext_[static_cast<std::size_t>(t * stride + e)]);
        hi = std::max(hi, spanNext_[static_cast<std::size_t>(t * stride + e + 1)]);
      }
      span[e] = hi < 0 ? -1 : lo;
      span[e + 1] = hi;
    }
  } else {
    std::fill_n(span, 2L * lines * P, -1);
    for (int p = 0; p < P; ++p) {
      const double* al = phases_.alpha[static_cast<std::size_t>(p)].data();
      if (xdir) {
        // A row's first and last occupied cell, each searched from its end of the row: the
        // occupied middle is not read.
        for (int k = phases_.rowLo; k < phases_.rowHi; ++k) {
          const double* row = al + static_cast<long>(k) * nx;
          int i0 = 0;
          while (i0 < nx && !(row[i0] >= kPhaseAbsent)) ++i0;
          if (i0 == nx) continue;
          int i1 = nx - 1;
          while (!(row[i1] >= kPhaseAbsent)) --i1;
          int* s = span + 2 * (static_cast<long>(k) * P + p);
          s[0] = i0;
          s[1] = i1;
        }
      } else {
        // Every column's first and last occupied row, the rows read in memory order and the
        // columns kept by selects (the loop vectorises; -1 where none).
        columnSpan_.resize(2 * static_cast<std::size_t>(nx));
        double* lo = columnSpan_.data();
        double* hi = lo + nx;
        std::fill_n(columnSpan_.data(), 2 * nx, -1.0);
        for (int k = phases_.rowLo; k < phases_.rowHi; ++k) {
          const double* row = al + static_cast<long>(k) * nx;
          const double kk = k;
          for (int i = 0; i < nx; ++i) {  // (loads, selects, then stores: g++ 12 vectorises it)
            const bool occupied = row[i] >= kPhaseAbsent;
            double first = lo[i], last = hi[i];
            last = occupied ? kk : last;
            first = (occupied && first < 0.0) ? kk : first;
            lo[i] = first;
            hi[i] = last;
          }
        }
        for (int i = 0; i < nx; ++i) {
          int* s = span + 2 * (static_cast<long>(i) * P + p);
          s[0] = static_cast<int>(lo[i]);
          s[1] = static_cast<int>(hi[i]);
        }
      }
    }
  }
  const int otherLines = xdir ? nx : grid_.nz;
  if (firstSweep)
    for (int t = 0; t < threads_; ++t)
      for (long e = 0; e < 2L * otherLines * P; e += 2) {
        spanNext_[static_cast<std::size_t>(t * stride + e)] = std::numeric_limits<int>::max();
        spanNext_[static_cast<std::size_t>(t * stride + e + 1)] = -1;
      }

#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
  {
#ifdef _OPENMP
    const int thread = omp_get_thread_num();
#else
    const int thread = 0;
#endif
    Workspace& ws = *work_[static_cast<std::size_t>(thread)];
    detail::CutLineWork& W = *ws.cut;
    int* record = spanNext_.data() + thread * stride;  // this thread's spans for the next sweep
#pragma omp for schedule(dynamic, 2)
    for (int line = 0; line < lines; ++line) {
      LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
      rec = LineRecord{};
      std::fill_n(&phaseEdge_[static_cast<std::size_t>(line) * static_cast<std::size_t>(P)], P,
                  0.0);
      if (ws.failed) continue;
      // Only the rows that can hold material (Phases::rowLo) have occupied cells.
      if (xdir && (line < phases_.rowLo || line >= phases_.rowHi)) continue;
      const long base = xdir ? static_cast<long>(line) * nx : line;
      auto at = [&](int pos) { return base + pos * step; };
      const int* lineSpan = span + 2L * line * P;
      int first = N, last = -1;
      for (int p = 0; p < P; ++p)
        if (lineSpan[2 * p] >= 0) {
          first = std::min(first, lineSpan[2 * p]);
          last = std::max(last, lineSpan[2 * p + 1]);
        }
      if (last < 0) continue;
      // One cell beyond the occupied ones on either side: where an interface lies on the
      // window's end face, the kernel opens that cell to the phase (CutLineSolver::openFaces).
      const int lo = xdir ? 0 : phases_.rowLo, hi = xdir ? N : phases_.rowHi;
      int a = std::max(first - 1, lo);
      detail::LineSetup setup;
      detail::finishWindow(N, lowSide, highSide, a, std::min(last + 2, hi), setup);
      const int n = setup.n;

      // Apertures of the line's own faces, side `side`, as a strided array over the face index
      // along the line (x faces of row `line`, or z faces of column `line`).
      const FaceApertures& fa = phases_.faces;
      const long faceStride = xdir ? 1 : static_cast<long>(fa.nx);
      auto facesOf = [&](int p, int side) {
        return xdir
                   ? &fa.x[static_cast<std::size_t>(((2L * p + side) * fa.nz + line) * (fa.nx + 1))]
                   : &fa.z[static_cast<std::size_t>(((2L * p + side) * (fa.nz + 1)) * fa.nx +
                                                    line)];
      };
      // Aperture of phase p at grid face gf (0..N along the line) seen from `side`; faces
      // beyond the domain mirror (reflecting side) or copy (outflow) the boundary's faces, and
      // the boundary face itself is seen from inside on both sides.
      auto aperture = [&](int p, int side, int gf) {
        if (gf <= 0) {
          if (gf < 0 && lowSide == Side::Reflect) return facesOf(p, 1 - side)[-gf * faceStride];
          return facesOf(p, 1)[0];
        }
        if (gf >= N) {
          if (gf > N && highSide == Side::Reflect)
            return facesOf(p, 1 - side)[(2 * N - gf) * faceStride];
          return facesOf(p, 0)[N * faceStride];
        }
        return facesOf(p, side)[gf * faceStride];
      };
      for (int p = 0; p < P; ++p) {
        detail::PhaseLine& ph = W.phase[static_cast<std::size_t>(p)];
        // A phase the line does not touch (none of its cells; the window holds all) is skipped.
        ph.active = lineSpan[2 * p] >= 0;
        if (!ph.active) continue;
        const Conserved& Q = phases_.q[static_cast<std::size_t>(p)];
        const double* arrays[4] = {Q.rho.data(), xdir ? Q.mx.data() : Q.mz.data(),
                                   xdir ? Q.mz.data() : Q.mx.data(), Q.E.data()};
        // The faces across the line bounding each of its cells (side 1 of the lower face, side
        // 0 of the upper one): the in-cell interface area across the line (planar form).
        const long crossStride = xdir ? 1 : static_cast<long>(fa.nx + 1);
        const double* cross[2] = {
            xdir ? &fa.z[static_cast<std::size_t>(((2L * p + 1) * (fa.nz + 1) + line) * fa.nx)]
                 : &fa.x[static_cast<std::size_t>(((2L * p + 1) * fa.nz) * (fa.nx + 1) + line)],
            xdir ? &fa.z[static_cast<std::size_t>(((2L * p) * (fa.nz + 1) + line + 1) * fa.nx)]
                 : &fa.x[static_cast<std::size_t>(((2L * p) * fa.nz) * (fa.nx + 1) + line + 1)]};
        const double* alpha = phases_.alpha[static_cast<std::size_t>(p)].data();
        const double* volume =
            (volumeFresh_ ? phases_.alpha : phases_.volume)[static_cast<std::size_t>(p)].data();
        for (int j = 0; j < n + 4; ++j) {
          bool mirrored = false;
          const int pos = detail::ghostSource(a - 2 + j, N, lowSide, highSide, mirrored);
          const bool ghost = pos != a - 2 + j;  // beyond the domain: the kernel fills its state
          const long c = at(pos);
          ph.alpha[j] = alpha[c] >= kPhaseAbsent ? alpha[c] : 0.0;
          ph.vol0[j] = ph.alpha[j] > 0.0 ? volume[c] : 0.0;
          if (!ghost)
            for (int k = 0; k < 4; ++k) ph.q0[k][j] = arrays[k][c];
          ph.It[j] = cross[0][pos * crossStride] - cross[1][pos * crossStride];
        }
        // Effect fracture: the solid phase's damage at the sweep's start (rho_p D / rho_p), the
        // ghosts' from their source cells as their states.
        if (fracture && strength_->phases[static_cast<std::size_t>(p)].solid) {
          const double* rd =
              strength_->phases[static_cast<std::size_t>(p)].rq[detail::kDamage].data();
          for (int j = 0; j < n + 4; ++j) {
            bool mirrored = false;
            const long c = at(detail::ghostSource(a - 2 + j, N, lowSide, highSide, mirrored));
            const double m = Q.rho[static_cast<std::size_t>(c)];
            ph.damage[j] = m > 0.0 ? rd[c] / m : 0.0;
          }
        }
        // Faces inside the domain straight from the aperture arrays; the boundary faces and
        // those beyond it through `aperture`.
        const double* face[2] = {facesOf(p, 0), facesOf(p, 1)};
        for (int f = 0; f <= n + 2; ++f) {
          const int gf = a + f - 1;
          if (gf > 0 && gf < N) {
            ph.gm[f] = face[0][gf * faceStride];
            ph.gp[f] = face[1][gf * faceStride];
          } else {
            ph.gm[f] = aperture(p, 0, gf);
            ph.gp[f] = aperture(p, 1, gf);
          }
        }
      }
      const double lineScale =
          detail::lineGeometry(radial, rz, h, a, n, line, faceX_, cellX_, W.area, W.invVol, W.invR);

      detail::LineBudget lb;
      detail::LineFailure fail;
      std::fill(W.edgeMass.begin(), W.edgeMass.end(), 0.0);
      // Effect strength: each solid phase's mass before the sweep, for its state's advection.
      const bool carry = strength_ && !strength_->phases.empty();
      if (carry) {
        for (int j = 2; j <= n + 1; ++j)
          ws.strength->cells[static_cast<std::size_t>(j)] = at(a - 2 + j);
        for (int p = 0; p < P; ++p) {
          detail::PhaseLine& ph = W.phase[static_cast<std::size_t>(p)];
          if (ph.active && strength_->phases[static_cast<std::size_t>(p)].solid)
            std::copy(ph.q0[detail::kRho].begin() + 2, ph.q0[detail::kRho].begin() + n + 2,
                      ph.massOld.begin() + 2);
        }
      }
      if (!fn(W, setup, ctx, lb, fail)) {
        ws.fail(line, detail::failureMessage(step_, xdir, dt, a, line, grid_, fail));
        continue;
      }
      for (int p = 0; p < P; ++p) {
        const detail::PhaseLine& ph = W.phase[static_cast<std::size_t>(p)];
        if (!ph.active) continue;
        Conserved& Q = phases_.q[static_cast<std::size_t>(p)];
        double* arrays[4] = {Q.rho.data(), xdir ? Q.mx.data() : Q.mz.data(),
                             xdir ? Q.mz.data() : Q.mx.data(), Q.E.data()};
        double* volume = phases_.volume[static_cast<std::size_t>(p)].data();
        double* alpha = phases_.alpha[static_cast<std::size_t>(p)].data();
        for (int j = 2; j <= n + 1; ++j) {
          const long c = at(a - 2 + j);
          for (int k = 0; k < 4; ++k) arrays[k][c] = ph.q0[k][j];
          volume[c] = ph.vol0[j];
          // A cell the kernel opened and the phase entered: occupied for the next sweep (its
          // part as its fraction) until the marker step measures it.
          if (ph.virt[j] != 0 && alpha[c] < kPhaseAbsent && ph.q0[detail::kRho][j] != 0.0)
            alpha[c] = std::max(ph.vol0[j], kPhaseAbsent);
          // The cell at position pos of this line is at position `line` of line pos across.
          if (firstSweep && alpha[c] >= kPhaseAbsent) {
            int* r = record + 2 * (static_cast<long>(a - 2 + j) * P + p);
            r[0] = std::min(r[0], line);
            r[1] = std::max(r[1], line);
          }
        }
        // docs/strength.md, "TVD with interfaces": the phase's strength state moves with the
        // phase's own mass fluxes (every mass change of the kernel is between cells of the line).
        if (carry && strength_->phases[static_cast<std::size_t>(p)].solid) {
          detail::StrengthLineWork& S = *ws.strength;
          std::copy(ph.massOld.begin() + 2, ph.massOld.begin() + n + 2, S.rhoOld.begin() + 2);
          detail::advectStrengthLine(strength_->phases[static_cast<std::size_t>(p)].rq, S,
                                     ph.q0[detail::kRho].data(), W.invVol.data(), n,
                                     setup.leftEdge ? ph.edgeMass : 0.0,
                                     std::numeric_limits<double>::min());
        }
      }
      rec.floors = lb.floors.scaled(lineScale);
      rec.relaxed = lb.relaxed;
      rec.mixed = lb.mixed;
      rec.pooled = lb.pooled;
      rec.bookEdges(lb, setup, lowSide, highSide, lineScale);
      // Each phase's mass through the outflow sides (what left positive), as bookEdges books
      // the sum (a wall's faces carry no mass).
      double* out = &phaseEdge_[static_cast<std::size_t>(line) * static_cast<std::size_t>(P)];
      const bool open[2] = {setup.leftEdge && lowSide == Side::Outflow,
                            setup.rightEdge && highSide == Side::Outflow};
      for (int p = 0; p < P; ++p) {
        out[p] = 0.0;
        for (int e = 0; e < 2; ++e)
          if (open[e]) out[p] -= lineScale * W.edgeMass[2 * static_cast<std::size_t>(p) + e];
      }
    }
  }
  volumeFresh_ = false;
  spanNextValid_ = firstSweep;
  finishSweep(lines);
  for (int line = 0; line < lines; ++line) {  // in line order, as the ledger
    const double* out = &phaseEdge_[static_cast<std::size_t>(line) * static_cast<std::size_t>(P)];
    for (int p = 0; p < P; ++p) phaseOutflow_[static_cast<std::size_t>(p)] += out[p];
  }
}

}  // namespace hvi::tvd
