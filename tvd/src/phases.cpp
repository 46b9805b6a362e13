//! @file Phase geometry from the marker lines, the conservative repair after the fractions
//! change, and the mixture state (docs/tvd.md, "Conservative interfaces").
#include "hvi/tvd/phases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "cut_line.hpp"
#include "hvi/tvd/ownership.hpp"

namespace hvi::tvd {

namespace detail {

PhaseLine::PhaseLine(int capacity) {
  const auto nb = static_cast<std::size_t>(capacity) + 4;
  for (auto* a : {&q0, &q1, &w, &ex, &U})
    for (auto& v : *a) v.assign(nb, 0.0);
  for (auto* v : {&alpha, &vol0, &vol1, &volW, &gm, &gp, &ap, &uL, &uR, &It, &sqrtRho, &pface,
                  &massOld, &damage, &vflux})
    v->assign(nb, 0.0);
  present.assign(nb, 0);
  virt.assign(nb, 0);
  dry.assign(nb, 0);
  into.assign(nb, -1);
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
  relax.assign(7 * static_cast<std::size_t>(phases), 0.0);
  edgeMass.assign(2 * static_cast<std::size_t>(phases), 0.0);
  shared.assign(nb, 0);
}

}  // namespace detail

void Phases::resize(int phases, const GridSpec& g) {
  count = phases;
  grid = g;
  const auto cells = static_cast<std::size_t>(g.cells());
  q.assign(static_cast<std::size_t>(phases), Conserved{});
  for (auto& s : q)
    for (auto* v : {&s.rho, &s.mx, &s.mz, &s.E}) v->assign(cells, 0.0);
  alpha.assign(static_cast<std::size_t>(phases), std::vector<double>(cells, 0.0));
  volume = alpha;
  rho0.assign(static_cast<std::size_t>(phases), 0.0);
  faces = FaceApertures{};
}

void Phases::coverRows(int lo, int hi) {
  lo = std::max(lo, 0);
  hi = std::min(hi, grid.nz);
  if (lo >= hi) return;
  if (rowLo >= rowHi) {
    rowLo = lo;
    rowHi = hi;
    return;
  }
  rowLo = std::min(rowLo, lo);
  rowHi = std::max(rowHi, hi);
}

void Phases::coverOccupied() {
  const int nx = grid.nx;
  for (int k = 0; k < grid.nz; ++k)
    for (int p = 0; p < count; ++p) {
      const auto b = static_cast<std::size_t>(k) * static_cast<std::size_t>(nx);
      const Conserved& s = q[static_cast<std::size_t>(p)];
      bool any = false;
      const std::vector<double>* arrays[5] = {&alpha[static_cast<std::size_t>(p)], &s.rho, &s.mx,
                                              &s.mz, &s.E};
      for (const std::vector<double>* v : arrays)
        for (int i = 0; i < nx && !any; ++i) any = (*v)[b + static_cast<std::size_t>(i)] != 0.0;
      if (any) coverRows(k - kRowMargin, k + 1 + kRowMargin);
    }
}

namespace {

// Where the phases together exceed 1 (a cell where two bodies' lines overlap by round-off),
// each is scaled down to fit, in place over cells [lo, hi), and a fraction below kPhaseAbsent is
// set to 0. One pass; the sum in phase order, as the scaling always took it. (The faces are
// fitted in Phases::measure, only where two bodies' wet spans overlap.)
void fitTogether(double* const* alpha, int P, long lo, long hi) {
  constexpr int kMax = 16;
  if (P == 2) {  // one phase per body: two bodies is the common case (a striker and a target)
    double* f0 = alpha[0];
    double* f1 = alpha[1];
#pragma omp parallel for schedule(static) if (hi - lo >= kParallelStream)
    for (long i = lo; i < hi; ++i) {
      // x / 1 is x exactly: the division by a select keeps the loop free of branches (it
      // vectorises) with the values of the scaling only where the sum exceeds 1.
      const double total = 0.0 + f0[i] + f1[i];
      const double scale = total > 1.0 ? total : 1.0;
      const double a0 = f0[i] / scale, a1 = f1[i] / scale;
      f0[i] = a0 < kPhaseAbsent ? 0.0 : a0;
      f1[i] = a1 < kPhaseAbsent ? 0.0 : a1;
    }
    return;
  }
  if (P > kMax || P < 2) {  // one phase never exceeds 1; many: the plain loops
#pragma omp parallel for schedule(static) if (hi - lo >= kParallelStream)
    for (long i = lo; i < hi; ++i) {
      double total = 0.0;
      for (int p = 0; p < P; ++p) total += alpha[p][i];
      for (int p = 0; p < P; ++p) {
        double a = alpha[p][i];
        if (P > 1 && total > 1.0) a /= total;
        alpha[p][i] = a < kPhaseAbsent ? 0.0 : a;
      }
    }
    return;
  }
#pragma omp parallel for schedule(static) if (hi - lo >= kParallelStream)
  for (long i = lo; i < hi; ++i) {
    double v[kMax];
    double total = 0.0;
    for (int p = 0; p < P; ++p) {
      v[p] = alpha[p][i];
      total += v[p];
    }
    for (int p = 0; p < P; ++p) {
      double a = v[p];
      if (total > 1.0) a /= total;
      alpha[p][i] = a < kPhaseAbsent ? 0.0 : a;
    }
  }
}

}  // namespace

void Phases::measure(const MarkerSet& markers) {
  int lo = 0, hi = 0;
  markers.rowSpan(grid, lo, hi);
  coverRows(lo - kRowMargin, hi + kRowMargin);
  std::vector<double*> to(static_cast<std::size_t>(count));
  for (int p = 0; p < count; ++p)  // phase p is body (object) p; fitted in place
    to[static_cast<std::size_t>(p)] = alpha[static_cast<std::size_t>(p)].data();
  fitTogether(to.data(), count, cellLo(), cellHi());
  markers.faceApertures(grid, faces);
  if (count < 2) return;
  // The bodies' apertures can sum to more than 1 only on faces that two of them wet: on each
  // grid line and side, between the second-smallest start and the second-largest end of the
  // bodies' wet spans (FaceApertures::xSpan). There they are fitted as fitTogether fits the
  // cells (sum in phase order, scaled where it exceeds 1); elsewhere one aperture is at most 1
  // and the fit is the identity, so it is skipped (the faces were 4 of the fit's 5 arrays).
  const int P = count;
  std::vector<int> los(static_cast<std::size_t>(P)), his(static_cast<std::size_t>(P));
  for (const bool xFaces : {true, false}) {
    auto& side = xFaces ? faces.x : faces.z;
    const auto& span = xFaces ? faces.xSpan : faces.zSpan;
    const long n = static_cast<long>(side.size()) / P;  // one object: both sides
    const long perSide = n / 2;
    const int lines = xFaces ? grid.nx + 1 : grid.nz + 1;
    const long lineStride = xFaces ? 1 : grid.nx;
    const long faceStride = xFaces ? grid.nx + 1 : 1;
    for (int s = 0; s < 2; ++s)
      for (int line = 0; line < lines; ++line) {
        int wet = 0;
        for (int p = 0; p < P; ++p) {
          const int* sp = &span[static_cast<std::size_t>(2L * ((2L * p + s) * lines + line))];
          if (sp[0] >= sp[1]) continue;
          los[static_cast<std::size_t>(wet)] = sp[0];
          his[static_cast<std::size_t>(wet)] = sp[1];
          ++wet;
        }
        if (wet < 2) continue;
        std::nth_element(los.begin(), los.begin() + 1, los.begin() + wet);
        std::nth_element(his.begin(), his.begin() + (wet - 2), his.begin() + wet);
        const int f0 = los[1], f1 = his[static_cast<std::size_t>(wet - 2)];
        for (int p = 0; p < P; ++p)
          to[static_cast<std::size_t>(p)] = side.data() + p * n + s * perSide + line * lineStride;
        for (int f = f0; f < f1; ++f) {
          const long i = f * faceStride;
          double total = 0.0;
          for (int p = 0; p < P; ++p) total += to[static_cast<std::size_t>(p)][i];
          if (total > 1.0)
            for (int p = 0; p < P; ++p) to[static_cast<std::size_t>(p)][i] /= total;
        }
      }
  }
}

void Phases::mixture(Conserved& U) const {
  const auto cells = static_cast<std::size_t>(grid.cells());
  for (auto* v : {&U.rho, &U.mx, &U.mz, &U.E}) v->resize(cells);  // zero where new
  const long c0 = cellLo(), c1 = cellHi();
  const long n = c1 - c0;
  double* out[4] = {U.rho.data(), U.mx.data(), U.mz.data(), U.E.data()};
  // One parallel region: each loop is statically scheduled over the same cells, so a thread
  // gets the same cells in every loop and needs no barrier between them (nowait); the sums per
  // cell keep their order, phase by phase (the same bits as a region per loop, which woke the
  // threads 2 x 4 times per call: with a passive wait policy that cost more than the copies).
#pragma omp parallel if (n >= kParallelStream)
  for (int k = 0; k < 4; ++k) {
    // Component by component, phase by phase: contiguous streams (the phases are few).
    double* o = out[k];
    auto component = [&](int p) {
      const Conserved& s = q[static_cast<std::size_t>(p)];
      return k == 0 ? s.rho.data() : k == 1 ? s.mx.data() : k == 2 ? s.mz.data() : s.E.data();
    };
    // The first two phases in one pass (in0 + in1 is what o = in0, o += in1 gives, bit for bit):
    // two streams read and one written instead of five.
    if (count >= 2) {
      const double* in0 = component(0);
      const double* in1 = component(1);
#pragma omp for schedule(static) nowait
      for (long c = c0; c < c1; ++c) o[c] = in0[c] + in1[c];
    }
    for (int p = count >= 2 ? 2 : 0; p < count; ++p) {
      const double* in = component(p);
      if (p == 0) {
#pragma omp for schedule(static) nowait
        for (long c = c0; c < c1; ++c) o[c] = in[c];
      } else {
#pragma omp for schedule(static) nowait
        for (long c = c0; c < c1; ++c) o[c] += in[c];
      }
    }
  }
}

namespace {

// The cells (in index order) for which needA(c) holds and those for which needB(c) holds, found
// in one scan (a parallel one for large grids), so that the serial passes of the repair visit
// only them. One pass per chunk of cells, compacting without a branch (every cell's index is
// written, the end advanced where it is needed: each chunk's hits stay inside its own part of
// `foundA` / `foundB`), then the chunks' hits appended in order.
// (The scratch holds offsets from lo in 32 bits: no grid that fits in memory has 2^32 cells in
// its rows, and two such arrays take the room one array of cell indices took.)
// anyIn(c) says whether a block of kScanBlock cells from c may hold a hit: hits are few (cells
// along the lines), and a block without one is passed over after a test that compacts nothing.
constexpr long kScanBlock = 16;
template <class NeedA, class NeedB, class AnyIn>
void findCells(long lo, long hi, std::vector<std::uint32_t>& foundA,
               std::vector<std::uint32_t>& foundB, std::vector<long>& outA, std::vector<long>& outB,
               NeedA needA, NeedB needB, AnyIn anyIn) {
  outA.clear();
  outB.clear();
  if (hi <= lo) return;
  const long n = hi - lo;
  for (auto* f : {&foundA, &foundB})
    if (f->size() < static_cast<std::size_t>(n)) f->resize(static_cast<std::size_t>(n));
  std::uint32_t* fa = foundA.data();
  std::uint32_t* fb = foundB.data();
  constexpr int kMaxChunks = 64;
  long hitsA[kMaxChunks], hitsB[kMaxChunks];
  int chunks = 1;
#ifdef _OPENMP
  if (n >= kParallelStream) chunks = std::clamp(omp_get_max_threads(), 1, kMaxChunks);
#endif
#pragma omp parallel for schedule(static, 1) num_threads(chunks) if (chunks > 1)
  for (int t = 0; t < chunks; ++t) {
    const long b = n * t / chunks, e = n * (t + 1) / chunks;
    long ka = b, kb = b;
    for (long i0 = b; i0 < e; i0 += kScanBlock) {
      const long i1 = std::min(i0 + kScanBlock, e);
      if (i1 - i0 == kScanBlock && !anyIn(lo + i0)) continue;
      for (long i = i0; i < i1; ++i) {
        fa[ka] = static_cast<std::uint32_t>(i);
        fb[kb] = static_cast<std::uint32_t>(i);
        ka += needA(lo + i) ? 1 : 0;
        kb += needB(lo + i) ? 1 : 0;
      }
    }
    hitsA[t] = ka - b;
    hitsB[t] = kb - b;
  }
  for (int t = 0; t < chunks; ++t) {
    const long b = n * t / chunks;
    for (long k = b; k < b + hitsA[t]; ++k) outA.push_back(lo + fa[k]);
    for (long k = b; k < b + hitsB[t]; ++k) outB.push_back(lo + fb[k]);
  }
}

// Whether the repair must visit a cell of fraction a and phase density rho: material where the
// phase is absent (vacated), a fraction without material (fresh), or a part below half the
// cell (small: pooled with a neighbour).
inline bool repairNeeds(double a, double rho) {
  const bool has = rho != 0.0;
  return (a < kPhaseAbsent && has) | (a >= kPhaseAbsent && (!has | (a < 0.5)));
}

// The cells of `from` (in index order) for which need(c) holds now.
template <class Need>
void keepCells(const std::vector<long>& from, std::vector<long>& out, Need need) {
  out.clear();
  for (const long c : from)
    if (need(c)) out.push_back(c);
}

}  // namespace

// Where the marker lines give a cell more of the phase than the sweeps moved its part to (the
// working fraction), material comes from the neighbours that the sweeps left with more than the
// lines give them, nearest first (face neighbours, diagonals, then the ring beyond: with one
// ring a disk carried through vacuum kept 2.4 % of the step's mismatch, with two 1.3 %), at the
// donor's own state: exactly what crossed a face
// ahead of the geometry (a leading edge passing into the next cell) goes back where the lines
// put it, and a uniform flow stays uniform.
void Phases::settle(const CellVolumes& volumes, int p) {
  const int nx = grid.nx, nz = grid.nz;
  auto& a = alpha[static_cast<std::size_t>(p)];
  auto& w = volume[static_cast<std::size_t>(p)];
  Conserved& s = q[static_cast<std::size_t>(p)];
  double* comp[4] = {s.rho.data(), s.mx.data(), s.mz.data(), s.E.data()};
  constexpr double kTiny = 1e-12;
  // Face neighbours, then the diagonals, then the ring beyond (by distance).
  constexpr int kOffsets = 24;
  static const int* const order = [] {
    static int o[2 * kOffsets];
    int n = 0;
    for (int r2 = 1; r2 <= 8; ++r2)
      for (int dk = -2; dk <= 2; ++dk)
        for (int di = -2; di <= 2; ++di)
          if (di * di + dk * dk == r2) {
            o[2 * n] = di;
            o[2 * n + 1] = dk;
            ++n;
          }
    return o;
  }();
  const double* ap = a.data();
  const double* wp = w.data();
  const double* rp = s.rho.data();
  // One scan for the three passes of the phase's repair: the cells whose working part differs
  // from the lines' fraction (settle's and route's candidates: both passes only shrink a
  // mismatch, in cells that have one, so none appears elsewhere), and the cells the repair
  // needs as they stand (repairNeeds; repair adds the cells settle and route change).
  findCells(
      cellLo(), cellHi(), found_, foundB_, band_, seeds_,
      [&](long c) { return std::abs(ap[c] - wp[c]) > kTiny; },
      [&](long c) { return repairNeeds(ap[c], rp[c]); },
      [ap, wp, rp](long c0) {
        // Both tests without a branch, the flag kept by a select: the loop vectorises
        // (an integer or'ed from the double compares does not, g++ 12).
        double any = 0.0;
        for (long c = c0; c < c0 + kScanBlock; ++c) {
          const double a = ap[c], r = rp[c];
          const bool hit = (std::abs(a - wp[c]) > kTiny) | ((a < kPhaseAbsent) & (r != 0.0)) |
                           ((a >= kPhaseAbsent) & ((r == 0.0) | (a < 0.5)));
          any = hit ? 1.0 : any;
        }
        return any != 0;
      });
  hopped_.clear();
  keepCells(band_, todo_, [&](long c) { return ap[c] - wp[c] > kTiny; });
  for (const long cell : todo_) {
    const int i = static_cast<int>(cell % nx), k = static_cast<int>(cell / nx);
    const auto c = static_cast<std::size_t>(cell);
    if (!(a[c] - w[c] > kTiny)) continue;
    const double vc = volumes(static_cast<long>(c));
    for (int n = 0; n < kOffsets && a[c] - w[c] > kTiny; ++n) {
      const int ii = i + order[2 * n], kk = k + order[2 * n + 1];
      if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
      const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
      if (!(w[d] - a[d] > kTiny) || !(s.rho[d] > 0.0) || !(w[d] > 0.0)) continue;
      const double vd = volumes(static_cast<long>(d));
      const double take = std::min((a[c] - w[c]) * vc, (w[d] - a[d]) * vd);  // volume
      const double f = take / (w[d] * vd);  // share of the donor's part moved
      for (double* v : comp) {
        const double moved = f * v[d] * vd;
        v[c] += moved / vc;
        v[d] -= moved / vd;
      }
      if (static_cast<std::size_t>(p) < carried.size())
        for (std::vector<double>* a : carried[static_cast<std::size_t>(p)]) {
          double* v = a->data();
          const double moved = f * v[d] * vd;
          v[c] += moved / vc;
          v[d] -= moved / vd;
        }
      w[c] += take / vc;
      w[d] -= take / vd;
    }
  }
  route(volumes, p);
}

// What the two rings leave: a uniform body translating diagonally leaves a deficit at one end of
// an edge and the matching excess at the other end of the column or row (the split sweeps use
// the start-of-step apertures, so the second sweep misses the first one's motion at the body's
// corners), and a curved body leaves them at its front and back (docs/tvd.md, "Uniform motion").
// Left there, the deficit cell is rarefied and the excess cell compressed, and a uniform state
// stops being uniform. Each deficit left takes from the nearest cells with an excess, found
// breadth first through face neighbours that hold the phase, up to kRouteReach faces away; the
// volume moves hop by hop along the path, each hop at its own cell's state (the intermediate
// cells receive and pass on the same volume: their parts are unchanged, their content is
// advected upwind by it). Each hop moves at most what its cell holds after receiving, so every
// share is convex; for a uniform state every hop moves that state, exactly.
void Phases::route(const CellVolumes& volumes, int p) {
  constexpr double kTiny = 1e-12;  // as settle
  constexpr int kRouteReach = 32;
  // Balance of the leftovers for a rearrangement: uniform motion leaves |deficit - excess| ~
  // 1e-13 of the phase's volume against leftovers of 1e-3..1e-2 of a cell per step.
  constexpr double kRouteBalance = 1e-6;
  const int nx = grid.nx;
  auto& a = alpha[static_cast<std::size_t>(p)];
  auto& w = volume[static_cast<std::size_t>(p)];
  Conserved& s = q[static_cast<std::size_t>(p)];
  double* comp[4] = {s.rho.data(), s.mx.data(), s.mz.data(), s.E.data()};
  const double* ap = a.data();
  const double* wp = w.data();
  const double* rp = s.rho.data();
  // Nothing to do unless the phase has both a deficit and an excess left (among settle's band:
  // only its cells can still have a mismatch).
  keepCells(band_, todo_, [&](long c) {
    return std::abs(ap[c] - wp[c]) > kTiny && (ap[c] > wp[c] || (wp[c] > 0.0 && rp[c] > 0.0));
  });
  // Routing rearranges volume, it creates none: it can close the mismatch only where what the
  // sweeps moved adds up to what the lines hold, the excess left equal to the deficit left
  // (uniform motion: both are the phase's volume, to round-off). Where they differ (the volume
  // changed: compression, expansion, the lines lagging the material), the deficit is not a
  // rearrangement, and filling it from up to kRouteReach cells away moved material across
  // variant 1's hole (its radius 1.02 -> 0.12 cm at 7.2 us); it is left to the repair, as before.
  double deficit = 0.0, excess = 0.0;
  for (const long c : todo_)
    (ap[c] > wp[c] ? deficit : excess) += std::abs(ap[c] - wp[c]) * volumes(c);
  if (!(deficit > 0.0) || !(excess > 0.0) ||
      std::abs(deficit - excess) > kRouteBalance * (deficit + excess))
    return;
  const auto cells = static_cast<std::size_t>(grid.cells());
  if (stamp_.size() < cells) {
    stamp_.assign(cells, 0);
    parent_.assign(cells, -1);
  }
  // One hop: `take` (volume) of cell `from`'s part, at its state, to cell `to`.
  auto hop = [&](long from, long to, double take) {
    const auto f = static_cast<std::size_t>(from), t = static_cast<std::size_t>(to);
    const double vf = volumes(from), vt = volumes(to);
    const double share = take / (w[f] * vf);
    for (double* v : comp) {
      const double moved = share * v[f] * vf;
      v[t] += moved / vt;
      v[f] -= moved / vf;
    }
    if (static_cast<std::size_t>(p) < carried.size())
      for (std::vector<double>* e : carried[static_cast<std::size_t>(p)]) {
        double* v = e->data();
        const double moved = share * v[f] * vf;
        v[t] += moved / vt;
        v[f] -= moved / vf;
      }
    w[t] += take / vt;
    w[f] -= take / vf;
    hopped_.push_back(from);  // for repair: cells whose content changed
    hopped_.push_back(to);
  };
  const long lo = cellLo(), hi = cellHi();
  const std::vector<long> deficits = [&] {
    std::vector<long> d;
    for (const long c : todo_)
      if (ap[c] > wp[c]) d.push_back(c);
    return d;
  }();
  for (const long c : deficits) {
    const auto cc = static_cast<std::size_t>(c);
    if (!(a[cc] - w[cc] > kTiny)) continue;
    if (++epoch_ == 0) {  // the stamps wrapped: start afresh
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      epoch_ = 1;
    }
    queue_.assign(1, c);
    depth_.assign(1, 0);
    stamp_[cc] = epoch_;
    const double vc = volumes(c);
    for (std::size_t head = 0; head < queue_.size() && a[cc] - w[cc] > kTiny; ++head) {
      const long x = queue_[head];
      const int dx = depth_[head];
      if (dx >= kRouteReach) break;
      const int i = static_cast<int>(x % nx);
      const long nb[4] = {i > 0 ? x - 1 : -1, i + 1 < nx ? x + 1 : -1, x - nx, x + nx};
      for (const long y : nb) {
        if (y < lo || y >= hi) continue;
        const auto yy = static_cast<std::size_t>(y);
        if (stamp_[yy] == epoch_ || !(w[yy] > 0.0) || !(s.rho[yy] > 0.0)) continue;
        stamp_[yy] = epoch_;
        parent_[yy] = x;
        queue_.push_back(y);
        depth_.push_back(dx + 1);
        if (!(w[yy] - a[yy] > kTiny)) continue;
        const double take = std::min((a[cc] - w[cc]) * vc, (w[yy] - a[yy]) * volumes(y));
        for (long from = y; from != c; from = parent_[static_cast<std::size_t>(from)])
          hop(from, parent_[static_cast<std::size_t>(from)], take);
        if (!(a[cc] - w[cc] > kTiny)) break;
      }
    }
  }
}

void OldFractions::keep(const Phases& phases) {
  const auto P = static_cast<std::size_t>(phases.count);
  cell.resize(P);
  value.resize(P);
  for (std::size_t p = 0; p < P; ++p) {
    cell[p].clear();  // the capacity stays: no allocation once the phases' extent is reached
    value[p].clear();
    const double* a = phases.alpha[p].data();
    for (long c = phases.cellLo(); c < phases.cellHi(); ++c)
      if (a[c] != 0.0) {
        cell[p].push_back(c);
        value[p].push_back(a[c]);
      }
  }
}

double OldFractions::at(int p, long c) const {
  const auto& cs = cell[static_cast<std::size_t>(p)];
  const auto it = std::lower_bound(cs.begin(), cs.end(), c);
  return it != cs.end() && *it == c
             ? value[static_cast<std::size_t>(p)][static_cast<std::size_t>(it - cs.begin())]
             : 0.0;
}

namespace {
// An orphan whose last volume packs it beyond this many times its reference density has no
// volume of the material (Phases::repair).
constexpr double kOrphanCompression = 10.0;
}  // namespace

long Phases::repair(const CellVolumes& volumes, const OldFractions& oldAlpha) {
  const int nx = grid.nx, nz = grid.nz;
  long orphans = 0;
  for (int p = 0; p < count; ++p) {
    settle(volumes, p);
    auto& a = alpha[static_cast<std::size_t>(p)];
    Conserved& s = q[static_cast<std::size_t>(p)];
    double* comp[4] = {s.rho.data(), s.mx.data(), s.mz.data(), s.E.data()};
    const double* ap = a.data();
    const double* rp = s.rho.data();
    // The cells that need the repair now: among those that did before settle (its scan's
    // seeds) and those settle and route changed (the band, the hops); the fractions are
    // unchanged since the scan, and only a change of content can make a cell need it.
    std::sort(hopped_.begin(), hopped_.end());
    merged_.clear();
    std::merge(seeds_.begin(), seeds_.end(), band_.begin(), band_.end(),
               std::back_inserter(merged_));
    if (!hopped_.empty()) {
      std::vector<long>& both = seeds_;  // no longer needed: reused as the merge's output
      both.clear();
      std::merge(merged_.begin(), merged_.end(), hopped_.begin(), hopped_.end(),
                 std::back_inserter(both));
      merged_.swap(both);
    }
    merged_.erase(std::unique(merged_.begin(), merged_.end()), merged_.end());
    keepCells(merged_, todo_, [&](long c) { return repairNeeds(ap[c], rp[c]); });
    for (const long c : todo_) {
      const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
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
          // A last volume that packs the mass above ten times the material's reference
          // density is no volume of the material (no shock here compresses a material beyond
          // (gamma + 1) / (gamma - 1) ~ 4-5 times; Tillotson's and Mie-Gruneisen's fits end well
          // below): the placeholder of a cell the kernel opened (CutLineSolver::openFaces) and no
          // line measured. Such an orphan takes its mass's volume at the reference density
          // instead, within the cell's room beside the other phases, so that it does not sit at
          // an absurd density whose sound speed holds the step (variant 1 at 0.00375 cm: 1.8e-6 g
          // per cm^3 of cell at 1795 g/cm^3, the step 6e-5 us). Mass, momentum and energy stay;
          // only the orphan's density, which no line defines, is chosen.
          const double a0 = oldAlpha.at(p, c);
          const auto pp = static_cast<std::size_t>(p);
          const bool packed = rho0[pp] > 0.0 && !(s.rho[cc] <= kOrphanCompression * rho0[pp] * a0);
          if (!packed) {
            a[cc] = a0 >= kPhaseAbsent ? a0 : kPhaseAbsent;
          } else {
            double room = 1.0;
            for (int o = 0; o < count; ++o)
              if (o != p) room -= alpha[static_cast<std::size_t>(o)][cc];
            a[cc] = std::max(kPhaseAbsent, std::min(s.rho[cc] / rho0[pp], room));
          }
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
      if (static_cast<std::size_t>(p) < carried.size())
        for (std::vector<double>* e : carried[static_cast<std::size_t>(p)]) {
          double* v = e->data();
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
