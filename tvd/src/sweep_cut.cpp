//! @file Sweep driver of the conservative cut-cell mode: every phase of a grid line into
//! contiguous buffers, the cut-cell line kernel, OpenMP over lines.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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
  ctx.dt = dt;
  ctx.h = h;
  ctx.axis = xdir ? 0 : 1;
  const Side lowSide = detail::sideOf(domain_.boundary[xdir ? 0 : 2]);
  const Side highSide = detail::sideOf(domain_.boundary[xdir ? 1 : 3]);

#pragma omp parallel num_threads(threads_) if (grid_.cells() >= kParallelCells)
  {
#ifdef _OPENMP
    Workspace& ws = *work_[static_cast<std::size_t>(omp_get_thread_num())];
#else
    Workspace& ws = *work_[0];
#endif
    detail::CutLineWork& W = *ws.cut;
#pragma omp for schedule(dynamic, 2)
    for (int line = 0; line < lines; ++line) {
      LineRecord& rec = lineRecords_[static_cast<std::size_t>(line)];
      rec = LineRecord{};
      if (ws.failed) continue;
      const long base = xdir ? static_cast<long>(line) * nx : line;
      auto at = [&](int pos) { return base + pos * step; };
      auto occupied = [&](int pos) {
        for (int p = 0; p < P; ++p)
          if (phases_.alpha[static_cast<std::size_t>(p)][static_cast<std::size_t>(at(pos))] >=
              kPhaseAbsent)
            return true;
        return false;
      };
      int a = 0, b = N;
      while (a < N && !occupied(a)) ++a;
      if (a == N) continue;
      while (!occupied(b - 1)) --b;
      if (a <= 2) a = 0;
      if (b >= N - 2) b = N;
      const int n = b - a;
      detail::LineSetup setup;
      setup.n = n;
      setup.left = a == 0 ? lowSide : Side::Loaded;
      setup.right = b == N ? highSide : Side::Loaded;
      setup.leftEdge = a == 0;
      setup.rightEdge = b == N;

      // Aperture of phase p at grid face gf (0..N along the line) seen from `side`; faces
      // beyond the domain mirror (reflecting side) or copy (outflow) the boundary's faces, and
      // the boundary face itself is seen from inside on both sides.
      auto aperture = [&](int p, int side, int gf) {
        if (gf <= 0) {
          if (gf < 0 && lowSide == Side::Reflect) return aperture1(p, 1 - side, -gf, xdir, line);
          return aperture1(p, 1, 0, xdir, line);
        }
        if (gf >= N) {
          if (gf > N && highSide == Side::Reflect)
            return aperture1(p, 1 - side, 2 * N - gf, xdir, line);
          return aperture1(p, 0, N, xdir, line);
        }
        return aperture1(p, side, gf, xdir, line);
      };
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
      for (int p = 0; p < P; ++p) {
        detail::PhaseLine& ph = W.phase[static_cast<std::size_t>(p)];
        // A phase the line does not touch (none of its cells, ghosts included) is skipped.
        {
          const double* al = phases_.alpha[static_cast<std::size_t>(p)].data();
          const int lo = std::max(a - 2, 0), hi = std::min(b + 2, N);
          ph.active = false;
          for (int pos = lo; pos < hi && !ph.active; ++pos) ph.active = al[at(pos)] >= kPhaseAbsent;
        }
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
          int pos = a - 2 + j;
          bool ghost = false;
          if (pos < 0) {
            pos = lowSide == Side::Reflect ? -1 - pos : 0;
            ghost = true;
          } else if (pos >= N) {
            pos = highSide == Side::Reflect ? 2 * N - 1 - pos : N - 1;
            ghost = true;
          }
          const long c = at(pos);
          ph.alpha[j] = alpha[c] >= kPhaseAbsent ? alpha[c] : 0.0;
          ph.vol0[j] = ph.alpha[j] > 0.0 ? volume[c] : 0.0;
          if (!ghost)
            for (int k = 0; k < 4; ++k) ph.q0[k][j] = arrays[k][c];
          ph.It[j] = cross[0][pos * crossStride] - cross[1][pos * crossStride];
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
        for (int j = 2; j <= n + 1; ++j) {
          const long c = at(a - 2 + j);
          for (int k = 0; k < 4; ++k) arrays[k][c] = ph.q0[k][j];
          volume[c] = ph.vol0[j];
        }
      }
      rec.floors = lb.floors.scaled(lineScale);
      const bool edge[2] = {setup.leftEdge, setup.rightEdge};
      const bool open[2] = {lowSide == Side::Outflow, highSide == Side::Outflow};
      for (int e = 0; e < 2; ++e) {
        if (!edge[e]) continue;
        if (open[e])
          rec.outflow += lb.edge[e].scaled(-lineScale);
        else
          rec.boundary += lb.edge[e].scaled(lineScale);
      }
    }
  }
  volumeFresh_ = false;
  finishSweep(lines);
}

// Aperture of phase p at face gf of line `line` (0 <= gf <= N) seen from `side`.
double TvdSolver::aperture1(int p, int side, int gf, bool xdir, int line) const {
  return xdir ? phases_.apertureX(p, side, gf, line) : phases_.apertureZ(p, side, line, gf);
}

}  // namespace hvi::tvd
