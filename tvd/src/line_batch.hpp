//! @file Several grid lines of a single-material planar sweep advanced together (issue 17).
//!
//! kBatch lines are stored interleaved, structure of arrays: value k of cell j of lane l at
//! [k][j * kBatch + l]. Every pass of the Heun stage is then one flat loop over j * kBatch + l
//! with neighbours at +-kBatch: the same operations on independent lanes, which the compiler
//! vectorises, with the EOS called through its concrete type (one std::get per batch, no
//! std::visit per cell). The arithmetic is that of LineSolver<Lim, false, false> operation
//! for operation (the same inline cellState, faceEigen, limiter and hartenYeeFlux), so a lane
//! gives its line's result bit for bit. A lane that needs the positivity fallback is not
//! finished here: it is flagged, and the sweep runs the scalar LineSolver on that line from the
//! same start state, so the rare path keeps one implementation.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <variant>
#include <vector>

#include "eos_line.hpp"
#include "hvi/tvd/harten_yee.hpp"
#include "hvi/tvd/limiter.hpp"
#include "line_kernel.hpp"
#include "line_work.hpp"

namespace hvi::tvd::detail {

//! Lines per batch: 4 doubles fill one AVX register, two SSE2 registers.
inline constexpr int kBatch = 4;

//! Scratch of one batch of lines of up to `capacity` cells (plus two ghosts at each end).
struct BatchWork {
  explicit BatchWork(int capacity) : capacity(capacity) {
    const auto size = (static_cast<std::size_t>(capacity) + 4) * kBatch;
    for (auto* a : {&u0, &u1, &w, &flux})
      for (auto& v : *a) v.assign(size, 0.0);
    for (auto* v : {&u, &v_, &e, &p, &c, &gam, &prho, &H, &sq, &fu, &fw, &fH, &fc, &fq2h})
      v->assign(size, 0.0);
    for (auto* a : {&alpha, &g})
      for (auto& v : *a) v.assign(size, 0.0);
  }
  int capacity;
  // U^n (overwritten with U^{n+1}), the predictor's result, the corrector's result.
  std::array<std::vector<double>, 4> u0, u1, w;
  // Cell primitives of the stage state: velocities, e, P, c, Gamma, P_rho, H, sqrt(rho).
  std::vector<double> u, v_, e, p, c, gam, prho, H, sq;
  // Face f (between cells f and f+1): Roe average and characteristic jumps; limited jumps per
  // cell; the numerical flux per face.
  std::vector<double> fu, fw, fH, fc, fq2h;
  std::array<std::vector<double>, kFields> alpha, g;
  std::array<std::vector<double>, 4> flux;
};

//! What the sweep passes to a batch (the same for every batch of a sweep).
struct BatchSetup {
  int n = 0;  //!< cells per line
  Side left = Side::Outflow, right = Side::Outflow;
  double invVol = 1.0;  //!< 1 / h: planar and r-z axial lines have unit face areas
  double rhoCut = 0.0;  //!< the material's vacuum density
};

template <class Lim, class Eos>
class BatchSolver {
 public:
  static constexpr int L = kBatch;

  BatchSolver(BatchWork& w, const BatchSetup& s, const SweepContext& c, const Eos& eos)
      : B_(w), S_(s), C_(c), eos_(eos), n_(s.n) {}

  //! Advances the kBatch lines loaded in u0 by dt. Lane l's budget goes to budget[l]; redo[l]
  //! is set if the lane needs the positivity fallback (its u0 is then not a result).
  void run(LineBudget budget[L], bool redo[L]) {
    double* u0[4] = {B_.u0[0].data(), B_.u0[1].data(), B_.u0[2].data(), B_.u0[3].data()};
    double* u1[4] = {B_.u1[0].data(), B_.u1[1].data(), B_.u1[2].data(), B_.u1[3].data()};
    double* w[4] = {B_.w[0].data(), B_.w[1].data(), B_.w[2].data(), B_.w[3].data()};
    for (int l = 0; l < L; ++l) redo[l] = false;
    fillGhosts(u0);
    stage(u0, u1, budget, redo);  // predictor: u1 = U^n + dt L(U^n)
    resetThin(u1, 0.5, budget);
    fillGhosts(u1);
    stage(u1, w, budget, redo);  // corrector: w = u1 + dt L(u1)
    const int i0 = 2 * L, i1 = (n_ + 2) * L;
    for (int k = 0; k < 4; ++k) {
      double* __restrict a = u0[k];
      const double* __restrict b = w[k];
#pragma GCC ivdep
      for (int i = i0; i < i1; ++i) a[i] = 0.5 * (a[i] + b[i]);
    }
    resetThin(u0, 1.0, budget);
  }

 private:
  // As detail::fillGhosts, lane by lane (no marker run here: no Loaded side).
  void fillGhosts(double* U[4]) const {
    auto side = [&](Side s, int in0, int in1, int g0, int g1) {
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < L; ++l) {
          U[k][g0 * L + l] = U[k][in0 * L + l];
          U[k][g1 * L + l] = U[k][(s == Side::Reflect ? in1 : in0) * L + l];
        }
      if (s == Side::Reflect)
        for (int l = 0; l < L; ++l) {
          U[kMn][g0 * L + l] = -U[kMn][g0 * L + l];
          U[kMn][g1 * L + l] = -U[kMn][g1 * L + l];
        }
    };
    side(S_.left, 2, 3, 1, 0);
    side(S_.right, n_ + 1, n_, n_ + 2, n_ + 3);
  }

  // Out = V + dt L(V) on cells 2..n+1 (LineSolver::stage without markers or r-z source).
  void stage(double* const V[4], double* const Out[4], LineBudget budget[L], bool redo[L]) {
    const int nb = n_ + 4;
    const double* __restrict r = V[kRho];
    const double* __restrict m = V[kMn];
    const double* __restrict t = V[kMt];
    const double* __restrict E = V[kE];
    double* __restrict cu = B_.u.data();
    double* __restrict cw = B_.v_.data();
    double* __restrict ce = B_.e.data();
    double* __restrict cp = B_.p.data();
    double* __restrict cc = B_.c.data();
    double* __restrict cg = B_.gam.data();
    double* __restrict cr = B_.prho.data();
    double* __restrict cH = B_.H.data();
    double* __restrict sq = B_.sq.data();
    // The EOS once per cell of the stage, through its concrete type.
#pragma GCC ivdep
    for (int i = 0; i < nb * L; ++i) {
      const CellState s = cellState(eos_, r[i], m[i], t[i], E[i]);
      cu[i] = s.u;
      cw[i] = s.w;
      ce[i] = s.e;
      cp[i] = s.p;
      cc[i] = s.c;
      cg[i] = s.gam;
      cr[i] = s.prho;
      cH[i] = s.H;
      sq[i] = std::sqrt(r[i]);
    }
    double* __restrict fu = B_.fu.data();
    double* __restrict fw = B_.fw.data();
    double* __restrict fH = B_.fH.data();
    double* __restrict fc = B_.fc.data();
    double* __restrict fq = B_.fq2h.data();
    double* __restrict a0 = B_.alpha[0].data();
    double* __restrict a1 = B_.alpha[1].data();
    double* __restrict a2 = B_.alpha[2].data();
    double* __restrict a3 = B_.alpha[3].data();
    double* __restrict a4 = B_.alpha[4].data();
    // Faces 0..n+2.
#pragma GCC ivdep
    for (int i = 0; i < (n_ + 3) * L; ++i) {
      const int j = i + L;
      const CellState sL = cellAt(i), sR = cellAt(j);
      const double dU[4] = {r[j] - r[i], m[j] - m[i], t[j] - t[i], E[j] - E[i]};
      const FaceEigen f = faceEigen(sL, sR, dU, sq[i], sq[j]);
      fu[i] = f.u;
      fw[i] = f.w;
      fH[i] = f.H;
      fc[i] = f.c;
      fq[i] = f.q2h;
      a0[i] = f.alpha[0];
      a1[i] = f.alpha[1];
      a2[i] = f.alpha[2];
      a3[i] = f.alpha[3];
      a4[i] = f.alpha[4];
    }
    // Limited jumps of cells 1..n+2 (from faces j-1 and j): the scene's limiter on the acoustic
    // fields, superbee on the linearly degenerate ones (LineSolver::stage, Yee 1989 section
    // 4.6). Stored, not evaluated for each of a cell's two faces: 10 % faster side by side.
    double* __restrict g0 = B_.g[0].data();
    double* __restrict g1 = B_.g[1].data();
    double* __restrict g2 = B_.g[2].data();
    double* __restrict g3 = B_.g[3].data();
    double* __restrict g4 = B_.g[4].data();
#pragma GCC ivdep
    for (int i = L; i < (n_ + 3) * L; ++i) {
      g0[i] = Lim::g(a0[i - L], a0[i]);
      g1[i] = Superbee::g(a1[i - L], a1[i]);
      g2[i] = Superbee::g(a2[i - L], a2[i]);
      g3[i] = Lim::g(a3[i - L], a3[i]);
      g4[i] = Superbee::g(a4[i - L], a4[i]);
    }
    // Harten-Yee fluxes of faces 1..n+1.
    double* __restrict F0 = B_.flux[0].data();
    double* __restrict F1 = B_.flux[1].data();
    double* __restrict F2 = B_.flux[2].data();
    double* __restrict F3 = B_.flux[3].data();
    const double fix = C_.entropyFix;
#pragma GCC ivdep
    for (int i = L; i < (n_ + 2) * L; ++i) {
      const int j = i + L;
      FaceEigen f;
      f.u = fu[i];
      f.w = fw[i];
      f.H = fH[i];
      f.c = fc[i];
      f.q2h = fq[i];
      f.alpha[0] = a0[i];
      f.alpha[1] = a1[i];
      f.alpha[2] = a2[i];
      f.alpha[3] = a3[i];
      f.alpha[4] = a4[i];
      const double gL[kFields] = {g0[i], g1[i], g2[i], g3[i], g4[i]};
      const double gR[kFields] = {g0[j], g1[j], g2[j], g3[j], g4[j]};
      // physicalFlux of the two cells
      const double FLc[4] = {m[i], m[i] * cu[i] + cp[i], t[i] * cu[i], (E[i] + cp[i]) * cu[i]};
      const double FRc[4] = {m[j], m[j] * cu[j] + cp[j], t[j] * cu[j], (E[j] + cp[j]) * cu[j]};
      const double delta = fix * (std::abs(f.u) + f.c);
      double out[4];
      hartenYeeFlux(f, gL, gR, FLc, FRc, delta, out);
      F0[i] = out[0];
      F1[i] = out[1];
      F2[i] = out[2];
      F3[i] = out[3];
    }
    // A wall passes only the normal momentum (LineSolver::wallFaces).
    auto wall = [&](int f) {
      for (int l = 0; l < L; ++l) F0[f * L + l] = F2[f * L + l] = F3[f * L + l] = 0.0;
    };
    if (S_.left == Side::Reflect) wall(1);
    if (S_.right == Side::Reflect) wall(n_ + 1);
    // Update of cells 2..n+1 (unit face areas: aR FR - aL FL is FR - FL exactly).
    const double lam = C_.dt * S_.invVol;
    const double* Fk[4] = {F0, F1, F2, F3};
    for (int k = 0; k < 4; ++k) {
      const double* __restrict Vk = V[k];
      const double* __restrict F = Fk[k];
      double* __restrict o = Out[k];
#pragma GCC ivdep
      for (int i = 2 * L; i < (n_ + 2) * L; ++i) o[i] = Vk[i] - lam * (F[i] - F[i - L]);
    }
    // Positivity (LineSolver::stage): a lane with an unphysical cell is redone by LineSolver.
    for (int jj = 2; jj <= n_ + 1; ++jj)
      for (int l = 0; l < L; ++l) {
        const int i = jj * L + l;
        if (!physical(Out[kRho][i], Out[kMn][i], Out[kMt][i], Out[kE][i])) redo[l] = true;
      }
    // Ledger: the two domain edges, each stage with its Heun weight (LineSolver::ledgerFaces).
    const double h = 0.5 * C_.dt;
    for (int l = 0; l < L; ++l) {
      const int iL = L + l, iR = (n_ + 1) * L + l;
      budget[l].edge[0].add(h * F0[iL], h * F1[iL], h * F2[iL], h * F3[iL], C_.axis);
      budget[l].edge[1].add(-(h * F0[iR]), -(h * F1[iR]), -(h * F2[iR]), -(h * F3[iR]), C_.axis);
    }
  }

  CellState cellAt(int i) const {
    CellState s;
    s.rho = 0.0;  // faceEigen reads rho only through sqrt(rho), passed separately
    s.u = B_.u[i];
    s.w = B_.v_[i];
    s.e = B_.e[i];
    s.p = B_.p[i];
    s.c = B_.c[i];
    s.gam = B_.gam[i];
    s.prho = B_.prho[i];
    s.H = B_.H[i];
    return s;
  }

  // LineSolver::resetThin, lane by lane: below the vacuum density a cell is put at rest.
  void resetThin(double* const U[4], double weight, LineBudget budget[L]) const {
    const double vol = weight / S_.invVol;
    for (int jj = 2; jj <= n_ + 1; ++jj)
      for (int l = 0; l < L; ++l) {
        const int i = jj * L + l;
        if (U[kRho][i] >= S_.rhoCut) continue;
        double& mn = U[kMn][i];
        double& mt = U[kMt][i];
        double& en = U[kE][i];
        if (mn == 0.0 && mt == 0.0 && en == 0.0) continue;
        budget[l].floors.add(0.0, -(mn * vol), -(mt * vol), -(en * vol), C_.axis);
        mn = mt = en = 0.0;
      }
  }

  BatchWork& B_;
  const BatchSetup& S_;
  const SweepContext& C_;
  const Eos& eos_;
  const int n_;
};

}  // namespace hvi::tvd::detail
