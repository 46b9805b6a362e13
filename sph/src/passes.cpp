//! @file Pair-loop drivers: threading, memory layout and the r-z normalisation.
#include "detail/passes.hpp"
#include "detail/parallel.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <type_traits>
#include <vector>

#include "detail/force_lanes.hpp"
#include "detail/force_rows.hpp"
#include "detail/list_build.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/pair_force.hpp"

namespace hvi::sph::detail {
namespace {

inline PairState load(const PairArrays& a, std::size_t i) {
  PairState s{a.x[i], a.z[i],  a.vx[i], a.vz[i], a.rho[i], a.c[i],
              a.h[i], a.mu[i], a.rw[i], a.q[i],  a.lam[i]};
  if (!a.lzz.empty()) {
    s.lzx = a.lzx[i];
    s.lzz = a.lzz[i];
    s.corr = true;
  }
  return s;
}

// The compatible remainder of row i from its pair data wx, wz (compatibleEnergy), one
// expression for the stored and the recomputed pair data (the same bits).
inline void remainderRow(const int* nb, int cnt, const double* wx, const double* wz,
                         std::size_t i, const double* dax, const double* daz, const double* rw,
                         const double* hoopAx, double halfDt, double* de) {
  const double dxi = dax[i], dzi = daz[i];
  double s = 0.0;
  for (int k = 0; k < cnt; ++k) {
    const std::size_t j = static_cast<std::size_t>(nb[k]);
    s += wx[k] * (dxi - dax[j]) + wz[k] * (dzi - daz[j]);
  }
  double corr = s / rw[i];
  if (hoopAx) corr += hoopAx[i] * dxi;
  de[i] -= halfDt * corr;
}

// Each particle gathers over its own list: a pair is evaluated from both ends, which doubles
// the arithmetic but needs no atomics or per-thread copies, and makes every sum's order fixed
// (bit-for-bit reproducible at any thread count).
template <class K, bool RZ, bool Viscous, bool Cached, bool Compatible>
void forcePass(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
               const MonaghanViscosity& visc, const AxisCorrection* axis, const RingScale* ring,
               const Rates& out) {
  const long nr = static_cast<long>(nReal);
#pragma omp parallel for schedule(static) if (nr > kParallelPairs)
  for (long il = 0; il < nr; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    const PairState A = load(a, i);
    const int* nb = list.index.data() + list.start[i];
    // The state-n pass runs at the positions the list was built at: its cached W if it has
    // them, else the same W recomputed.
    const double* wc = Cached && list.cacheW ? list.w.data() + list.start[i] : nullptr;
    const int cnt = list.count[i];
    const int oi = a.obj[i];
    const double ih2i = 1.0 / (A.h * A.h);
    double sax = 0.0, saz = 0.0, sde = 0.0, sdrho = 0.0, shoop = 0.0, shoopPi = 0.0, phi = 0.0;
    const bool viscHoop = RZ && Viscous && ring && ring->viscousHoop != 0.0;
    // The compatible energy's pair data (half state only): w_ij times i's pair acceleration.
    constexpr bool kPairs = Compatible && !Cached;
    // Null pairWx: the remainder recomputes them (RemainderPass).
    double* pwx = kPairs && out.pairWx ? out.pairWx + list.start[i] : nullptr;
    double* pwz = kPairs && out.pairWx ? out.pairWz + list.start[i] : nullptr;
    for (int k = 0; k < cnt; ++k) {
      const std::size_t j = static_cast<std::size_t>(nb[k]);
      // Within an object h is constant, so h_ij = h_i for most pairs: skip the division.
      const double hj = a.h[j];
      double ih2 = ih2i;
      if (hj != A.h) {
        const double hij = 0.5 * (A.h + hj);
        ih2 = 1.0 / (hij * hij);
      }
      double w;
      if (Cached && wc) {
        w = wc[k];
      } else {
        const double dx = A.x - a.x[j], dz = A.z - a.z[j];
        w = K::value(dx * dx + dz * dz, 0.5 * (A.h + hj), ih2);
      }
      if (w == 0.0) {
        if (kPairs && pwx) pwx[k] = pwz[k] = 0.0;
        continue;
      }
      const PairResult r = pairTerms<K, RZ, Viscous, Compatible>(A, load(a, j), w, ih2, visc);
      sax += r.ax;
      saz += r.az;
      if (kPairs && pwx) {
        pwx[k] = r.share * r.ax;
        pwz[k] = r.share * r.az;
      }
      sde += r.de;
      // The continuity rate, like the summation density, sums over i's own object.
      if constexpr (Cached) {
        if (a.obj[j] == oi) sdrho += r.drho;
      }
      if constexpr (RZ) shoop += r.hoop;
      if (viscHoop) shoopPi += r.hoopPi;
      if constexpr (Viscous && Cached) phi = std::min(phi, r.phi);
    }
    forceRowRates<RZ, Viscous, Cached, Compatible, K>(
        a, i, ForceRowSums{sax, saz, sde, sdrho, shoop, shoopPi, phi}, axis, ring, out);
  }
}

// forcePass for the Gaussian kernel: the row's pair terms come from the lane kernel, then are
// added up in list order exactly as forcePass adds them (bit for bit the same rates).
template <bool RZ, bool Viscous, bool Cached, bool Compatible>
void lanePass(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
              const MonaghanViscosity& visc, const AxisCorrection* axis, const RingScale* ring,
              const Rates& out) {
  static const RowKernel kernel = rowKernel(RZ, Viscous, Cached, Compatible);
  constexpr bool kPairs = Compatible && !Cached;
  const LaneArrays la{a.x.data(),  a.z.data(), a.vx.data(), a.vz.data(), a.rho.data(),
                      a.c.data(),  a.h.data(), a.mu.data(), a.rw.data(), a.q.data(),
                      a.obj.data()};
  const std::size_t stride = list.stride;
  const std::size_t cap = (stride + 7) / 8 * 8;  // whole blocks of up to 8 lanes
  const long nr = static_cast<long>(nReal);
#pragma omp parallel if (nr > kParallelPairs)
  {
    // One scratch row per thread and pass (no allocation per pair).
    std::vector<double> scratch(7 * cap);
    RowTerms t{scratch.data(), scratch.data() + cap,     scratch.data() + 2 * cap,
               scratch.data() + 3 * cap, scratch.data() + 4 * cap, scratch.data() + 5 * cap,
               nullptr, nullptr};
    const bool viscHoop = RZ && Viscous && ring && ring->viscousHoop != 0.0;
    if (viscHoop) t.hoopPi = scratch.data() + 6 * cap;
#pragma omp for schedule(static)
    for (long il = 0; il < nr; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const int cnt = list.count[i];
      if (kPairs && out.pairWx) {
        t.pwx = out.pairWx + list.start[i];
        t.pwz = out.pairWz + list.start[i];
      }
      kernel(la, i, list.index.data() + list.start[i],
             Cached && list.cacheW ? list.w.data() + list.start[i] : nullptr,
             cnt, visc.alpha, visc.beta, t);
      laneRowRates<RZ, Viscous, Cached, Compatible>(a, i, cnt, t, viscHoop, axis, ring, out);
    }
  }
}

// ---- Half lists (planar, Gaussian lanes): each pair evaluated once, from its lower end ----
//
// Row i lists only j > i; the kernel gives both ends' terms, i's are summed in row order and
// j's added to j. The rows run in fixed blocks (halfBlockSize, not per thread): a block adds
// the other ends inside itself directly (its rows are one thread's) and those past its end
// into a spill buffer of its own; after all blocks, each particle adds the spills of the
// blocks before it in block order. So every sum has one fixed order whatever the thread
// count: the rates are bit for bit the same at 1 and 2 threads (and serial), and differ from
// the full rows' gather form only by the order of the additions (round-off).
// 16 blocks (an even share for 1, 2, 4, 8 or 16 threads), of at least 2048 rows. Fixed by the
// particle count alone, never by the thread count.
constexpr long kHalfBlocks = 16, kHalfBlockMin = 2048;
inline long halfBlockSize(long nr) {
  return std::max(kHalfBlockMin, (nr + kHalfBlocks - 1) / kHalfBlocks);
}

// The block structure's bookkeeping: F accumulators per real particle (acc), the last one a
// running minimum when LastIsMin (phi), the others sums.
template <int F, bool LastIsMin>
struct HalfAcc {
  double* acc[F];
  const NeighbourList& list;
  long nr, nb, bs;  // rows, blocks, rows per block

  // Block b's rows and its spill: zeroes its accumulators, sizes its dense spill (grow only)
  // to the other ends within a block's length past its end (a lattice's rows reach a few
  // thousand indices); farther ones (another body in contact, filled elsewhere in the order) become
  // records, so that a few such pairs do not make a block's spill as long as the particles.
  //
  // Where block b's spill of field f lies: in the arrays the stepper lends
  // (NeighbourList::lentSpill, F of them: f's at b * bs, which holds a span <= bs, the last
  // block's span being 0) or else in the list's own spill (f's at f * span).
  double* spill(long b, int f, std::size_t span) const {
    if (list.lentSpillCount >= F)
      return list.lentSpill[static_cast<std::size_t>(f)] + static_cast<std::size_t>(b * bs);
    return list.spill[static_cast<std::size_t>(b)].data() + static_cast<std::size_t>(f) * span;
  }
  std::size_t begin(long b, long b0, long b1, double** sp) const {
    int far = static_cast<int>(b1);
    for (long i = b0; i < b1; ++i) far = std::max(far, list.reach[static_cast<std::size_t>(i)]);
    const auto span = static_cast<std::size_t>(std::min<long>(far - b1, bs));
    const auto bu = static_cast<std::size_t>(b);
    if (list.lentSpillCount < F) {
      std::vector<double>& own = list.spill[bu];
      if (own.size() < F * span) own.resize(F * span);
    }
    for (int f = 0; f < F; ++f) {
      sp[f] = spill(b, f, span);
      std::fill(sp[f], sp[f] + span, 0.0);
    }
    list.spillSpan[bu] = span;
    list.farJ[bu].clear();
    list.farV[bu].clear();
    for (int f = 0; f < F; ++f) std::fill(acc[f] + b0, acc[f] + b1, 0.0);
    return span;
  }
  // Adds the other-end terms v[f][k] of row entries k (neighbours nb) to their particles.
  void scatter(long b, const int* nb, int cnt, double* const* v, long b1, std::size_t span,
               double* const* sp) const {
    for (int k = 0; k < cnt; ++k) {
      const long j = nb[k];
      if (j >= nr) continue;  // a ghost: no rate
      if (j < b1) {
        for (int f = 0; f < F; ++f) add(f, acc[f][j], v[f][k]);
      } else if (static_cast<std::size_t>(j - b1) < span) {
        const auto o = static_cast<std::size_t>(j - b1);
        for (int f = 0; f < F; ++f) add(f, sp[f][o], v[f][k]);
      } else {
        const auto bu = static_cast<std::size_t>(b);
        list.farJ[bu].push_back(static_cast<int>(j));
        for (int f = 0; f < F; ++f) list.farV[bu].push_back(v[f][k]);
      }
    }
  }
  // After every block's gather: the far records, block by block in order (serial: few).
  void applyFar() const {
    for (long b = 0; b < nb; ++b) {
      const auto bu = static_cast<std::size_t>(b);
      const std::vector<int>& js = list.farJ[bu];
      const double* v = list.farV[bu].data();
      for (std::size_t r = 0; r < js.size(); ++r)
        for (int f = 0; f < F; ++f) add(f, acc[f][js[r]], v[r * F + static_cast<std::size_t>(f)]);
    }
  }
  static void add(int f, double& to, double v) {
    if (LastIsMin && f == F - 1)
      to = std::min(to, v);
    else
      to += v;
  }
  // Block c's particles receive the spills of the blocks before it, in block order.
  void gather(long c) const {
    const long c0 = c * bs, c1 = std::min(nr, c0 + bs);
    for (long b = 0; b < c; ++b) {
      const long bb1 = std::min(nr, (b + 1) * bs);
      const std::size_t span = list.spillSpan[static_cast<std::size_t>(b)];
      const long hi = std::min(c1, bb1 + static_cast<long>(span));
      if (hi <= c0) continue;
      for (int f = 0; f < F; ++f) {
        const double* sp = spill(b, f, span);
        for (long j = c0; j < hi; ++j) add(f, acc[f][j], sp[static_cast<std::size_t>(j - bb1)]);
      }
    }
  }
};

inline long halfBlocks(const NeighbourList& list, long nr) {
  const long nb = (nr + halfBlockSize(nr) - 1) / halfBlockSize(nr);
  if (list.spill.size() < static_cast<std::size_t>(nb)) {
    list.spill.resize(static_cast<std::size_t>(nb));
    list.spillSpan.resize(static_cast<std::size_t>(nb));
    list.farJ.resize(static_cast<std::size_t>(nb));
    list.farV.resize(static_cast<std::size_t>(nb));
  }
  return nb;
}

RowKernel laneHalfKernel(bool viscous, bool cached, bool compatible) {
  RowKernel k = nullptr;
  if (laneWidth() >= 8) k = rowKernelAvx512(false, viscous, cached, compatible, true);
  if (!k && laneWidth() >= 4) k = rowKernelAvx2(false, viscous, cached, compatible, true);
  return k ? k : rowKernelBaseline(false, viscous, cached, compatible, true);
}

// The j side's data of the points the half rows read, packed 8 per point (x, z, vx, vz, h, q,
// mu, c: LaneArrays::packed) in a ring of kPackRing points per thread, for the 8-lane kernels:
// one 64-byte row per neighbour instead of 8 element gathers. Row i reads only points j > i up
// to its reach (NeighbourList::reach), so as the rows advance the ring packs each point once
// and the oldest fall out of it; a block of neighbours not all in the ring (a ghost, past the
// reals; a point packed over) reads through the gathers. The same values either way, so the
// same bits. 2 MiB per thread, whatever the particle count. (The full rows, r-z and the
// strength pass, keep the gathers: there the ring measured no faster.)
constexpr int kPackRing = 1 << 15;
class PackRing {
 public:
  explicit PackRing(bool on) {
    if (!on) return;
    thread_local std::vector<double> storage;  // kept by the thread pool's threads: no refill
    if (storage.size() < 8 * static_cast<std::size_t>(kPackRing) + 8)
      storage.resize(8 * static_cast<std::size_t>(kPackRing) + 8);
    const auto at = reinterpret_cast<std::uintptr_t>(storage.data());
    base_ = storage.data() + (8 - at / sizeof(double) % 8) % 8;  // 64-byte aligned
  }
  //! Rows from here on read points from `from` on (a new block of rows).
  void restart(int from) { start_ = end_ = from; }
  //! The next row reads points below `want`: packs those not yet held and sets la's window.
  void advance(const PairArrays& a, int want, LaneArrays& la) {
    if (!base_) return;
    if (want > end_) {
      const int from = std::max(end_, want - kPackRing);
      if (from > end_) start_ = from;  // a jump: nothing before it is held
      for (int p = from; p < want; ++p) {
        const auto i = static_cast<std::size_t>(p);
        double* r = base_ + 8 * static_cast<std::size_t>(p & (kPackRing - 1));
        r[0] = a.x[i];
        r[1] = a.z[i];
        r[2] = a.vx[i];
        r[3] = a.vz[i];
        r[4] = a.h[i];
        r[5] = a.q[i];
        r[6] = a.mu[i];
        r[7] = a.c[i];
      }
      end_ = want;
    }
    la.packed = base_;
    la.packMask = kPackRing - 1;
    la.packBegin = std::max(start_, end_ - kPackRing);
    la.packEnd = end_;
  }

 private:
  double* base_ = nullptr;
  int start_ = 0, end_ = 0;
};

// lanePass on half rows (planar): the same per-pair terms, each pair's computed once.
template <bool Viscous, bool Cached, bool Compatible>
void halfPass(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
              const MonaghanViscosity& visc, const AxisCorrection*, const RingScale*,
              const Rates& out) {
  static const RowKernel kernel = laneHalfKernel(Viscous, Cached, Compatible);
  // Only the AVX-512 kernels read packed rows (a CPU with AVX-512 and a build without runs AVX2).
  static const bool pack = kernel == rowKernelAvx512(false, Viscous, Cached, Compatible, true);
  constexpr int F = Cached ? (Viscous ? 5 : 4) : 3;
  const LaneArrays la{a.x.data(),  a.z.data(), a.vx.data(), a.vz.data(), a.rho.data(),
                      a.c.data(),  a.h.data(), a.mu.data(), a.rw.data(), a.q.data(),
                      a.obj.data()};
  const long nr = static_cast<long>(nReal);
  const long nb = halfBlocks(list, nr);
  HalfAcc<F, Cached && Viscous> acc{{}, list, nr, nb, halfBlockSize(nr)};
  double* fields[5] = {out.ax, out.az, out.de, out.drho, out.phi};
  for (int f = 0; f < F; ++f) acc.acc[f] = fields[f];
  if constexpr (Cached && !Viscous) std::fill(out.phi, out.phi + nr, 0.0);
  const std::size_t cap = (list.stride + 7) / 8 * 8;
#pragma omp parallel if (nr > kParallelPairs)
  {
    std::vector<double> scratch(11 * cap);
    double* s0 = scratch.data();
    RowTerms t{s0, s0 + cap, s0 + 2 * cap, s0 + 3 * cap, nullptr, s0 + 4 * cap, nullptr, nullptr};
    t.axj = s0 + 5 * cap;
    t.azj = s0 + 6 * cap;
    t.dej = s0 + 7 * cap;
    t.drhoj = s0 + 8 * cap;
    double* const other[5] = {t.axj, t.azj, t.dej, t.drhoj, t.phi};
    PackRing ring(pack);
    LaneArrays lr = la;
#pragma omp for schedule(static)
    for (long b = 0; b < nb; ++b) {
      const long b0 = b * acc.bs, b1 = std::min(nr, b0 + acc.bs);
      double* sp[F];
      const std::size_t span = acc.begin(b, b0, b1, sp);
      ring.restart(static_cast<int>(b0) + 1);
      for (long il = b0; il < b1; ++il) {
        const std::size_t i = static_cast<std::size_t>(il);
        const int cnt = list.count[i];
        const int* nbr = list.index.data() + list.start[i];
        ring.advance(a, list.reach[i], lr);
        kernel(lr, i, nbr, nullptr, cnt, visc.alpha, visc.beta, t);
        double sax = 0.0, saz = 0.0, sde = 0.0, sdrho = 0.0, phi = 0.0;
        for (int k = 0; k < cnt; ++k) {
          sax += t.ax[k];
          saz += t.az[k];
          sde += t.de[k];
          if constexpr (Cached) sdrho += t.drho[k];
          if constexpr (Viscous && Cached) phi = std::min(phi, t.phi[k]);
        }
        out.ax[i] += sax;
        out.az[i] += saz;
        out.de[i] += sde;
        if constexpr (Cached) out.drho[i] += sdrho;
        if constexpr (Viscous && Cached) out.phi[i] = std::min(out.phi[i], phi);
        acc.scatter(b, nbr, cnt, other, b1, span, sp);
      }
    }
#pragma omp for schedule(static)
    for (long c = 0; c < nb; ++c) acc.gather(c);
  }
  acc.applyFar();
}

// laneRemainder on half rows (planar): each pair's w_ij a_ij and w_ji a_ji computed once.
template <bool Viscous>
void halfRemainder(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                   const MonaghanViscosity& visc, const double* dax, const double* daz,
                   const double*, double halfDt, double* de) {
  static const RowKernel kernel = laneHalfKernel(Viscous, false, true);
  static const bool pack = kernel == rowKernelAvx512(false, Viscous, false, true, true);
  const LaneArrays la{a.x.data(),  a.z.data(), a.vx.data(), a.vz.data(), a.rho.data(),
                      a.c.data(),  a.h.data(), a.mu.data(), a.rw.data(), a.q.data(),
                      a.obj.data()};
  const long nr = static_cast<long>(nReal);
  const long nb = halfBlocks(list, nr);
  if (list.sums.size() < nReal) list.sums.resize(nReal);
  double* sums = list.sums.data();
  HalfAcc<1, false> acc{{sums}, list, nr, nb, halfBlockSize(nr)};
  const std::size_t cap = (list.stride + 7) / 8 * 8;
  const double* rs = a.rs.data();
#pragma omp parallel if (nr > kParallelPairs)
  {
    std::vector<double> scratch(11 * cap);
    double* s0 = scratch.data();
    // The pair data only: no rates (null ax, the kernel's shortcut).
    RowTerms t{nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, s0 + 3 * cap, s0 + 4 * cap};
    t.pwxj = s0 + 8 * cap;
    t.pwzj = s0 + 9 * cap;
    double* const other[1] = {s0 + 10 * cap};
    PackRing ring(pack);
    LaneArrays lr = la;
#pragma omp for schedule(static)
    for (long b = 0; b < nb; ++b) {
      const long b0 = b * acc.bs, b1 = std::min(nr, b0 + acc.bs);
      double* sp[1];
      const std::size_t span = acc.begin(b, b0, b1, sp);
      ring.restart(static_cast<int>(b0) + 1);
      for (long il = b0; il < b1; ++il) {
        const std::size_t i = static_cast<std::size_t>(il);
        const int cnt = list.count[i];
        const int* nbr = list.index.data() + list.start[i];
        ring.advance(a, list.reach[i], lr);
        kernel(lr, i, nbr, nullptr, cnt, visc.alpha, visc.beta, t);
        // remainderRow's sum for i; for j its own pair datum times da_j - da_i.
        const double dxi = dax[i], dzi = daz[i];
        double s = 0.0;
        for (int k = 0; k < cnt; ++k) {
          const std::size_t j = static_cast<std::size_t>(nbr[k]);
          s += t.pwx[k] * (dxi - dax[j]) + t.pwz[k] * (dzi - daz[j]);
          other[0][k] = t.pwxj[k] * (dax[j] - dxi) + t.pwzj[k] * (daz[j] - dzi);
        }
        sums[i] += s;
        acc.scatter(b, nbr, cnt, other, b1, span, sp);
      }
    }
#pragma omp for schedule(static)
    for (long c = 0; c < nb; ++c) acc.gather(c);
#pragma omp single
    acc.applyFar();
#pragma omp for schedule(static)
    for (long i = 0; i < nr; ++i) de[i] -= halfDt * (sums[i] / rs[i]);  // planar: no hoop
  }
}

template <class K, bool RZ, bool Viscous, bool Compatible>
ForcePass pick(bool cached) {
  // 2 lanes (baseline x86-64: gathers element by element into 128-bit registers) measured no
  // faster than the scalar loop, so the lanes start at AVX2's 4 (docs/performance.md).
  if constexpr (std::is_same_v<K, GaussianKernel>)
    if (laneWidth() >= 4)
      return cached ? &lanePass<RZ, Viscous, true, Compatible>
                    : &lanePass<RZ, Viscous, false, Compatible>;
  return cached ? &forcePass<K, RZ, Viscous, true, Compatible>
                : &forcePass<K, RZ, Viscous, false, Compatible>;
}

template <class K, bool RZ, bool Viscous>
ForcePass pick(bool compatible, bool cached) {
  return compatible ? pick<K, RZ, Viscous, true>(cached) : pick<K, RZ, Viscous, false>(cached);
}

template <class K, bool RZ>
ForcePass pick(bool viscous, bool compatible, bool cached) {
  return viscous ? pick<K, RZ, true>(compatible, cached) : pick<K, RZ, false>(compatible, cached);
}

template <class K>
ForcePass pick(bool rz, bool viscous, bool compatible, bool cached) {
  return rz ? pick<K, true>(viscous, compatible, cached)
            : pick<K, false>(viscous, compatible, cached);
}

template <class K>
void listPass(const PairArrays& a, std::size_t nReal, double radiusFactor, CellGrid& grid,
              NeighbourList& list, double* rhoOut) {
  if (rhoOut)
    buildList<K, true>(a.x.data(), a.z.data(), a.h.data(), a.mu.data(), a.obj.data(), a.size(),
                       nReal, radiusFactor, grid, list, rhoOut);
  else
    buildList<K, false>(a.x.data(), a.z.data(), a.h.data(), a.mu.data(), a.obj.data(), a.size(),
                        nReal, radiusFactor, grid, list, nullptr);
}

}  // namespace

int laneWidth() {
  static const int width = [] {
    int w = 2;
#if defined(__x86_64__) || defined(__i386__)
    if (__builtin_cpu_supports("avx2") && rowKernelAvx2(false, false, false, false)) w = 4;
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl") && rowKernelAvx512(false, false, false, false))
      w = 8;
#endif
    if (const char* cap = std::getenv("HVI_SPH_LANES")) w = std::min(w, std::max(2, std::atoi(cap)));
    return w;
  }();
  return width;
}

// All widths give the same bits (force_lanes.hpp).
RowKernel rowKernel(bool rz, bool viscous, bool cached, bool compatible) {
  RowKernel k = nullptr;
  if (laneWidth() >= 8) k = rowKernelAvx512(rz, viscous, cached, compatible);
  if (!k && laneWidth() >= 4) k = rowKernelAvx2(rz, viscous, cached, compatible);
  return k ? k : rowKernelBaseline(rz, viscous, cached, compatible);
}

bool halfListsAvailable(cases::Kernel kernel, bool rz) {
  return kernel == cases::Kernel::Gaussian && !rz && laneWidth() >= 4;
}

// The widest build of a kernel that the CPU (laneWidth) and the compiler have.
template <class F>
F widest(F (*avx512)(), F (*avx2)(), F (*baseline)()) {
  F k = nullptr;
  if (laneWidth() >= 8) k = avx512();
  if (!k && laneWidth() >= 4) k = avx2();
  return k ? k : baseline();
}

RowWKernel rowWKernel() {
  static const RowWKernel k = widest(&rowWKernelAvx512, &rowWKernelAvx2, &rowWKernelBaseline);
  return k;
}

ScanKernel scanKernel() {
  static const ScanKernel k = widest(&scanKernelAvx512, &scanKernelAvx2, &scanKernelBaseline);
  return k;
}

DistanceWKernel distanceWKernel() {
  static const DistanceWKernel k =
      widest(&distanceWKernelAvx512, &distanceWKernelAvx2, &distanceWKernelBaseline);
  return k;
}

ForcePass selectScalarForcePass(cases::Kernel kernel, bool rz, bool viscous, bool compatible,
                                bool cached) {
  const auto sel = [&](auto k) -> ForcePass {
    using K = decltype(k);
    if (rz)
      return viscous ? (compatible ? (cached ? &forcePass<K, true, true, true, true>
                                             : &forcePass<K, true, true, false, true>)
                                   : (cached ? &forcePass<K, true, true, true, false>
                                             : &forcePass<K, true, true, false, false>))
                     : (compatible ? (cached ? &forcePass<K, true, false, true, true>
                                             : &forcePass<K, true, false, false, true>)
                                   : (cached ? &forcePass<K, true, false, true, false>
                                             : &forcePass<K, true, false, false, false>));
    return viscous ? (compatible ? (cached ? &forcePass<K, false, true, true, true>
                                           : &forcePass<K, false, true, false, true>)
                                 : (cached ? &forcePass<K, false, true, true, false>
                                           : &forcePass<K, false, true, false, false>))
                   : (compatible ? (cached ? &forcePass<K, false, false, true, true>
                                           : &forcePass<K, false, false, false, true>)
                                 : (cached ? &forcePass<K, false, false, true, false>
                                           : &forcePass<K, false, false, false, false>));
  };
  return kernel == cases::Kernel::Gaussian ? sel(GaussianKernel{}) : sel(CubicSplineKernel{});
}

ForcePass selectForcePass(cases::Kernel kernel, bool rz, bool viscous, bool compatible,
                          bool cached, bool half) {
  if (half) {
    if (!halfListsAvailable(kernel, rz)) return nullptr;
    if (cached)
      return viscous ? (compatible ? &halfPass<true, true, true> : &halfPass<true, true, false>)
                     : (compatible ? &halfPass<false, true, true> : &halfPass<false, true, false>);
    return viscous ? (compatible ? &halfPass<true, false, true> : &halfPass<true, false, false>)
                   : (compatible ? &halfPass<false, false, true> : &halfPass<false, false, false>);
  }
  return kernel == cases::Kernel::Gaussian
             ? pick<GaussianKernel>(rz, viscous, compatible, cached)
             : pick<CubicSplineKernel>(rz, viscous, compatible, cached);
}

void compatibleEnergy(const NeighbourList& list, std::size_t nReal, const double* pairWx,
                      const double* pairWz, const double* dax, const double* daz, const double* rw,
                      const double* hoopAx, double halfDt, double* de) {
  const long nr = static_cast<long>(nReal);
#pragma omp parallel for schedule(static) if (nr > kParallelPairs)
  for (long il = 0; il < nr; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    remainderRow(list.index.data() + list.start[i], list.count[i], pairWx + list.start[i],
                 pairWz + list.start[i], i, dax, daz, rw, hoopAx, halfDt, de);
  }
}

namespace {

// compatibleEnergy without stored pair data: each row's w_ij a_ij recomputed at the half state
// (unchanged since the half-state pass) by that pass's own pair code into a scratch row, then
// the same sum: the same bits as stored, at the price of a third pair pass.
template <class K, bool RZ, bool Viscous>
void scalarRemainder(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                     const MonaghanViscosity& visc, const double* dax, const double* daz,
                     const double* hoopAx, double halfDt, double* de) {
  const std::size_t stride = list.stride;
  const long nr = static_cast<long>(nReal);
#pragma omp parallel if (nr > kParallelPairs)
  {
    std::vector<double> scratch(2 * stride);
    double* pwx = scratch.data();
    double* pwz = pwx + stride;
#pragma omp for schedule(static)
    for (long il = 0; il < nr; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const PairState A = load(a, i);
      const int* nb = list.index.data() + list.start[i];
      const int cnt = list.count[i];
      const double ih2i = 1.0 / (A.h * A.h);
      for (int k = 0; k < cnt; ++k) {  // as forcePass<..., Cached = false, Compatible = true>
        const std::size_t j = static_cast<std::size_t>(nb[k]);
        const double hj = a.h[j];
        double ih2 = ih2i;
        if (hj != A.h) {
          const double hij = 0.5 * (A.h + hj);
          ih2 = 1.0 / (hij * hij);
        }
        const double dx = A.x - a.x[j], dz = A.z - a.z[j];
        const double w = K::value(dx * dx + dz * dz, 0.5 * (A.h + hj), ih2);
        if (w == 0.0) {
          pwx[k] = pwz[k] = 0.0;
          continue;
        }
        const PairResult r = pairTerms<K, RZ, Viscous, true>(A, load(a, j), w, ih2, visc);
        pwx[k] = r.share * r.ax;
        pwz[k] = r.share * r.az;
      }
      remainderRow(nb, cnt, pwx, pwz, i, dax, daz, a.rs.data(), hoopAx, halfDt, de);
    }
  }
}

template <bool RZ, bool Viscous>
void laneRemainder(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                   const MonaghanViscosity& visc, const double* dax, const double* daz,
                   const double* hoopAx, double halfDt, double* de) {
  static const RowKernel kernel = rowKernel(RZ, Viscous, false, true);
  const LaneArrays la{a.x.data(),  a.z.data(), a.vx.data(), a.vz.data(), a.rho.data(),
                      a.c.data(),  a.h.data(), a.mu.data(), a.rw.data(), a.q.data(),
                      a.obj.data()};
  const std::size_t stride = list.stride;
  const std::size_t cap = (stride + 7) / 8 * 8;
  const long nr = static_cast<long>(nReal);
#pragma omp parallel if (nr > kParallelPairs)
  {
    std::vector<double> scratch(8 * cap);
    double* s0 = scratch.data();
    const RowTerms t{s0, s0 + cap, s0 + 2 * cap, s0 + 3 * cap,
                     s0 + 4 * cap, s0 + 5 * cap, s0 + 6 * cap, s0 + 7 * cap};
#pragma omp for schedule(static)
    for (long il = 0; il < nr; ++il) {
      const std::size_t i = static_cast<std::size_t>(il);
      const int* nb = list.index.data() + list.start[i];
      const int cnt = list.count[i];
      kernel(la, i, nb, nullptr, cnt, visc.alpha, visc.beta, t);
      remainderRow(nb, cnt, t.pwx, t.pwz, i, dax, daz, a.rs.data(), hoopAx, halfDt, de);
    }
  }
}

template <class K, bool RZ, bool Viscous>
RemainderPass pickRemainder() {
  if constexpr (std::is_same_v<K, GaussianKernel>)
    if (laneWidth() >= 4) return &laneRemainder<RZ, Viscous>;
  return &scalarRemainder<K, RZ, Viscous>;
}

template <class K>
RemainderPass pickRemainder(bool rz, bool viscous) {
  if (rz) return viscous ? pickRemainder<K, true, true>() : pickRemainder<K, true, false>();
  return viscous ? pickRemainder<K, false, true>() : pickRemainder<K, false, false>();
}

}  // namespace

RemainderPass selectScalarRemainderPass(cases::Kernel kernel, bool rz, bool viscous) {
  const auto sel = [&](auto k) -> RemainderPass {
    using K = decltype(k);
    if (rz) return viscous ? &scalarRemainder<K, true, true> : &scalarRemainder<K, true, false>;
    return viscous ? &scalarRemainder<K, false, true> : &scalarRemainder<K, false, false>;
  };
  return kernel == cases::Kernel::Gaussian ? sel(GaussianKernel{}) : sel(CubicSplineKernel{});
}

RemainderPass selectRemainderPass(cases::Kernel kernel, bool rz, bool viscous, bool half) {
  if (half) {
    if (!halfListsAvailable(kernel, rz)) return nullptr;
    return viscous ? &halfRemainder<true> : &halfRemainder<false>;
  }
  return kernel == cases::Kernel::Gaussian ? pickRemainder<GaussianKernel>(rz, viscous)
                                           : pickRemainder<CubicSplineKernel>(rz, viscous);
}

namespace {
template <class K>
void weightChangeK(const NeighbourList& list, std::size_t nReal, const double* x0,
                   const double* z0, const double* xg, const double* zg, const int* obj,
                   const double* h, const double* dmu, double* rho) {
  const long nr = static_cast<long>(nReal);
#pragma omp parallel for schedule(static) if (nr > kParallelPairs)
  for (long il = 0; il < nr; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    const int* nb = list.index.data() + list.start[i];
    const double* wc = list.cacheW ? list.w.data() + list.start[i] : nullptr;
    const int oi = obj[i];
    const double xi = x0[i], zi = z0[i], hi = h[i];
    // Over i's own object, as the summation density and the continuity rate.
    double s = dmu[i] * K::value(0.0, hi);
    for (int k = 0; k < list.count[i]; ++k) {
      const std::size_t j = static_cast<std::size_t>(nb[k]);
      if (obj[j] != oi) continue;
      double w;
      if (wc) {
        w = wc[k];
      } else {
        // W_ij at x^n as the list build computed it (the same operations, the same bits).
        const double dx = xi - (j < nReal ? x0[j] : xg[j]);
        const double dz = zi - (j < nReal ? z0[j] : zg[j]);
        const double hij = 0.5 * (hi + h[j]);
        w = K::value(dx * dx + dz * dz, hij, 1.0 / (hij * hij));
      }
      s += dmu[j] * w;
    }
    rho[i] += s;
  }
}
}  // namespace

void weightChange(const NeighbourList& list, std::size_t nReal, const double* x0,
                  const double* z0, const double* xg, const double* zg, const int* obj,
                  const double* h, const double* dmu, cases::Kernel kernel, double* rho) {
  if (kernel == cases::Kernel::Gaussian)
    weightChangeK<GaussianKernel>(list, nReal, x0, z0, xg, zg, obj, h, dmu, rho);
  else
    weightChangeK<CubicSplineKernel>(list, nReal, x0, z0, xg, zg, obj, h, dmu, rho);
}

ListPass selectListPass(cases::Kernel kernel) {
  return kernel == cases::Kernel::Gaussian ? &listPass<GaussianKernel>
                                           : &listPass<CubicSplineKernel>;
}

namespace {
template <class K>
void axisMatrixK(PairArrays& a, std::size_t nReal, const NeighbourList& list, double zone) {
  const long nr = static_cast<long>(nReal);
#pragma omp parallel for schedule(static) if (nr > kParallelPairs)
  for (long il = 0; il < nr; ++il) {
    const std::size_t i = static_cast<std::size_t>(il);
    const double xi = a.x[i], zi = a.z[i], hi = a.h[i];
    // 1 inside the zone, 0 from one h beyond it: no jump in the scheme at the zone's edge.
    const double blend = std::clamp(zone + 1.0 - std::abs(xi) / hi, 0.0, 1.0);
    a.lzx[i] = 0.0;
    a.lzz[i] = 1.0;
    if (blend == 0.0) continue;
    const int* nb = list.index.data() + list.start[i];
    double mxx = 0.0, mxz = 0.0, mzx = 0.0, mzz = 0.0;
    for (int k = 0; k < list.count[i]; ++k) {
      const std::size_t j = static_cast<std::size_t>(nb[k]);
      const double dx = xi - a.x[j], dz = zi - a.z[j];
      const double hij = 0.5 * (hi + a.h[j]);
      const double ih2 = 1.0 / (hij * hij);
      const double r2 = dx * dx + dz * dz;
      const double w = K::value(r2, hij, ih2);
      if (w == 0.0) continue;
      const double f = K::gradFactor(w, r2, hij, ih2) * a.mu[j] / a.rho[j];
      // (x_j - x_i) (x) grad_i W_ij = -(dx, dz) (x) f (dx, dz)
      mxx -= dx * f * dx;
      mxz -= dx * f * dz;
      mzx -= dz * f * dx;
      mzz -= dz * f * dz;
    }
    const double inv = 1.0 / a.rs[i];
    mxx *= inv;
    mxz *= inv;
    mzx *= inv;
    mzz *= inv;
    const double det = mxx * mzz - mxz * mzx;
    // A particle with too few neighbours (spray) keeps the plain gradient.
    if (!(det > 0.05)) continue;
    a.lzx[i] = blend * (-mzx / det);
    a.lzz[i] = 1.0 + blend * (mxx / det - 1.0);
  }
}
}  // namespace

void axisMatrix(PairArrays& a, std::size_t nReal, const NeighbourList& list, cases::Kernel kernel,
                double zone) {
  if (kernel == cases::Kernel::Gaussian)
    axisMatrixK<GaussianKernel>(a, nReal, list, zone);
  else
    axisMatrixK<CubicSplineKernel>(a, nReal, list, zone);
}

double kernelSupport(cases::Kernel kernel) {
  return kernel == cases::Kernel::Gaussian ? GaussianKernel::support : CubicSplineKernel::support;
}

double kernelSelf(cases::Kernel kernel, double h) {
  return kernel == cases::Kernel::Gaussian ? GaussianKernel::value(0.0, h)
                                           : CubicSplineKernel::value(0.0, h);
}

}  // namespace hvi::sph::detail
