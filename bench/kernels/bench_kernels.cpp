//! @file Google Benchmark kernels of both solvers (issue 17): the SPH pair pass and neighbour
//! build, the TVD face flux along a line and a whole 2-D Sod step, and the three EOS.
//!
//! Built by the default build, never run by ctest (speed is measured here, docs/performance.md):
//!   OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive build/bin/hvi_bench_kernels
//! The rates are per CPU second of the main thread (Google Benchmark's default): on the shared
//! machine the wall time also counts other processes. So run with one thread: the pair pass and
//! the Sod step are OpenMP loops whose other threads' CPU time is not counted.
//! Only the public headers are used: the pair term (hvi/sph/pair_force.hpp), the list builder
//! (hvi/sph/neighbours.hpp), the Harten-Yee flux (hvi/tvd/harten_yee.hpp) and the EOS. The
//! stepper's own fused pass (sph/src/detail) and the line solver (tvd/src/line_kernel.hpp) are
//! measured through the whole-step benchmarks instead, so this file does not follow their
//! internals as they change.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "hvi/eos/eos.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/pair_force.hpp"
#include "hvi/sph/viscosity.hpp"
#include "hvi/tvd/harten_yee.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/tvd.hpp"

namespace {

using namespace hvi;

// ---------------------------------------------------------------- SPH: a realistic block
// Variant 2's plate at its resolution: square lattice, spacing 0.01 cm, h = spacing (h_factor 1),
// aluminium at rho ~ 2.79 with a 1 % density and velocity jitter (a shocked block, so that the
// viscosity's approaching-pair branch is taken about half the time). The list radius is the
// stepper's: Gaussian support 3 h plus the CFL skin (0.3).
struct Block {
  std::size_t n = 0;
  std::vector<double> x, z, vx, vz, rho, c, h, m, q;
  sph::CellGrid grid;
  sph::NeighbourList list;
  static constexpr double kRadius = 3.0 + 0.3 * 1.001;

  explicit Block(int side) {
    const double dp = 0.01;
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> jit(-1.0, 1.0);
    for (int k = 0; k < side; ++k)
      for (int i = 0; i < side; ++i) {
        x.push_back(dp * (i + 0.05 * jit(rng)));
        z.push_back(dp * (k + 0.05 * jit(rng)));
        vx.push_back(0.01 * jit(rng));
        vz.push_back(-0.3 + 0.01 * jit(rng));
        rho.push_back(2.79 * (1.0 + 0.01 * jit(rng)));
        c.push_back(0.53);
        h.push_back(dp);
        m.push_back(2.79 * dp * dp);
        const double p = 0.05 * (rho.back() / 2.79 - 1.0) * 50.0;  // Mbar, a few tenths
        q.push_back(p / (rho.back() * rho.back()));
      }
    n = x.size();
    sph::buildNeighbourList(x.data(), z.data(), h.data(), n, n, kRadius, grid, list);
  }
  [[nodiscard]] long pairs() const {
    long s = 0;
    for (int cnt : list.count) s += cnt;
    return s;
  }
  [[nodiscard]] sph::PairState state(std::size_t i) const {
    return {x[i], z[i], vx[i], vz[i], rho[i], c[i], h[i], m[i], 1.0, q[i], 0.0};
  }
};

const Block& block() {
  static const Block b(300);  // 90 000 particles: variant 2's count (87 810)
  return b;
}

//! Pair interactions and particle updates per second of one pass over the block.
void pairRates(benchmark::State& st, const Block& b) {
  const double it = static_cast<double>(st.iterations());
  st.counters["pair-interactions/s"] =
      benchmark::Counter(it * static_cast<double>(b.pairs()), benchmark::Counter::kIsRate);
  st.counters["particle-updates/s"] =
      benchmark::Counter(it * static_cast<double>(b.n), benchmark::Counter::kIsRate);
}

// One pair pass: each particle's momentum, energy and continuity sums over its list, with the
// cached W (the stepper's first pass of a step), planar, Monaghan viscosity on.
void SphPairForce(benchmark::State& st) {
  const Block& b = block();
  std::vector<double> ax(b.n), az(b.n), de(b.n), drho(b.n);
  const sph::MonaghanViscosity visc{1.0, 2.0};
  for (auto _ : st) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < b.n; ++i) {
      const sph::PairState a = b.state(i);
      double sx = 0.0, sz = 0.0, se = 0.0, sr = 0.0;
      const std::size_t row = b.list.start[i];
      for (int k = 0; k < b.list.count[i]; ++k) {
        const auto j = static_cast<std::size_t>(b.list.index[row + k]);
        const sph::PairResult r = sph::pairTerms<sph::GaussianKernel, false, true>(
            a, b.state(j), b.list.w[row + k], visc);
        sx += r.ax;
        sz += r.az;
        se += r.de;
        sr += r.drho;
      }
      ax[i] = sx;
      az[i] = sz;
      de[i] = se;
      drho[i] = sr;
    }
    benchmark::DoNotOptimize(ax.data());
    benchmark::ClobberMemory();
  }
  pairRates(st, b);
  st.counters["neighbours"] = static_cast<double>(b.pairs()) / static_cast<double>(b.n);
}
BENCHMARK(SphPairForce)->Unit(benchmark::kMillisecond);

// The same pass with W evaluated per pair (one exponential each), as the later passes of a
// step do when the particles have moved since the list was built.
void SphPairForceFreshW(benchmark::State& st) {
  const Block& b = block();
  std::vector<double> ax(b.n), az(b.n);
  const sph::MonaghanViscosity visc{1.0, 2.0};
  for (auto _ : st) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < b.n; ++i) {
      const sph::PairState a = b.state(i);
      double sx = 0.0, sz = 0.0;
      const std::size_t row = b.list.start[i];
      for (int k = 0; k < b.list.count[i]; ++k) {
        const auto j = static_cast<std::size_t>(b.list.index[row + k]);
        const sph::PairState bj = b.state(j);
        const double dx = a.x - bj.x, dz = a.z - bj.z, hh = 0.5 * (a.h + bj.h);
        const double ih2 = 1.0 / (hh * hh);
        const double w = sph::GaussianKernel::value(dx * dx + dz * dz, hh, ih2);
        const sph::PairResult r =
            sph::pairTerms<sph::GaussianKernel, false, true>(a, bj, w, ih2, visc);
        sx += r.ax;
        sz += r.az;
      }
      ax[i] = sx;
      az[i] = sz;
    }
    benchmark::DoNotOptimize(ax.data());
    benchmark::ClobberMemory();
  }
  pairRates(st, b);
}
BENCHMARK(SphPairForceFreshW)->Unit(benchmark::kMillisecond);

// The cell-linked list and the fixed-stride lists with cached W, as each step rebuilds them.
void SphNeighbourBuild(benchmark::State& st) {
  const Block& b = block();
  sph::CellGrid grid;
  sph::NeighbourList list;
  for (auto _ : st) {
    sph::buildNeighbourList(b.x.data(), b.z.data(), b.h.data(), b.n, b.n, Block::kRadius, grid,
                            list);
    benchmark::DoNotOptimize(list.index.data());
  }
  st.counters["particle-updates/s"] = benchmark::Counter(
      static_cast<double>(st.iterations()) * static_cast<double>(b.n), benchmark::Counter::kIsRate);
}
BENCHMARK(SphNeighbourBuild)->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------- TVD: face flux along a line
// One 512-cell line of Sod's problem smeared over 20 cells (ideal gas, gamma 1.4): the cell
// states, the characteristic jumps at every face, the minmod-limited jumps per cell and the
// Harten-Yee flux at every face. One pass = one flux evaluation per face, i.e. the flux work of
// one cell-update in one direction and one stage.
struct SodLine {
  static constexpr int n = 512;
  std::vector<tvd::CellState> s;
  std::vector<double> U[4];
  SodLine() : s(n) {
    const eos::IdealGas gas{1.4, 1.0};
    for (auto& u : U) u.resize(n);
    for (int j = 0; j < n; ++j) {
      const double t = 0.5 * (1.0 + std::tanh((j - n / 2) / 4.0));
      const double rho = 1.0 - 0.875 * t, p = 1.0 - 0.9 * t, u = 0.3 * (1.0 - t);
      const double e = p / (0.4 * rho);
      const eos::EosState q = gas.state(rho, e);
      tvd::CellState& c = s[static_cast<std::size_t>(j)];
      c.rho = rho;
      c.u = u;
      c.e = e;
      c.p = q.pressure;
      c.c = q.soundSpeed;
      c.gam = q.dPdE / rho;
      c.prho = q.dPdRho;
      c.H = e + 0.5 * u * u + p / rho;
      U[0][j] = rho;
      U[1][j] = rho * u;
      U[2][j] = 0.0;
      U[3][j] = rho * (e + 0.5 * u * u);
    }
  }
};

void TvdFaceFlux(benchmark::State& st) {
  const SodLine L;
  constexpr int n = SodLine::n;
  std::vector<tvd::FaceEigen> fe(n - 1);
  std::vector<double> g(static_cast<std::size_t>(n) * tvd::kFields), out(4 * (n - 1));
  for (auto _ : st) {
    for (int f = 0; f + 1 < n; ++f) {
      const double dU[4] = {L.U[0][f + 1] - L.U[0][f], L.U[1][f + 1] - L.U[1][f],
                            L.U[2][f + 1] - L.U[2][f], L.U[3][f + 1] - L.U[3][f]};
      fe[static_cast<std::size_t>(f)] = tvd::faceEigen(L.s[f], L.s[f + 1], dU);
    }
    for (int j = 1; j + 1 < n; ++j)
      for (int l = 0; l < tvd::kFields; ++l)
        g[static_cast<std::size_t>(j * tvd::kFields + l)] = tvd::Minmod::g(
            fe[static_cast<std::size_t>(j - 1)].alpha[l], fe[static_cast<std::size_t>(j)].alpha[l]);
    for (int f = 1; f + 2 < n; ++f) {
      const tvd::CellState &a = L.s[f], &b = L.s[f + 1];
      double FL[4], FR[4];
      tvd::physicalFlux(L.U[1][f], L.U[2][f], L.U[3][f], a, FL);
      tvd::physicalFlux(L.U[1][f + 1], L.U[2][f + 1], L.U[3][f + 1], b, FR);
      tvd::hartenYeeFlux(fe[static_cast<std::size_t>(f)], &g[f * tvd::kFields],
                         &g[(f + 1) * tvd::kFields], FL, FR, 0.1 * a.c, &out[4 * f]);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  st.counters["face-fluxes/s"] = benchmark::Counter(static_cast<double>(st.iterations()) * (n - 3),
                                                    benchmark::Counter::kIsRate);
}
BENCHMARK(TvdFaceFlux)->Unit(benchmark::kMicrosecond);

// Whole TVD steps of the 2-D Sod problem of issue 17 (ideal gas, minmod, effects = [], CFL
// 0.4) on an N x N grid over [0, 1]^2, diaphragm at x = 0.5: every sweep, line kernel, EOS pass
// and time-step reduction, as the solver runs them.
cases::Scene sod2d(int cells) {
  cases::Scene s;
  s.title = "sod 2-D";
  s.geometry = Geometry::Planar;
  s.domain = {
      0.0,
      1.0,
      0.0,
      1.0,
      {cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall, cases::Boundary::Wall}};
  s.tvd.cellSize = 1.0 / cells;
  cases::Material gas;
  gas.name = "gas";
  gas.eos = eos::IdealGas{1.4, 1.0};
  s.materials = {gas};
  cases::Body l, r;
  l.name = "left";
  l.material = 0;
  l.shape = cases::Rect{0.0, 0.5, 0.0, 1.0};
  l.density = 1.0;
  l.specificEnergy = 1.0 / (0.4 * 1.0);
  r.name = "right";
  r.material = 0;
  r.shape = cases::Rect{0.5, 1.0, 0.0, 1.0};
  r.density = 0.125;
  r.specificEnergy = 0.1 / (0.4 * 0.125);
  s.bodies = {l, r};
  s.effects = {};
  s.tEnd = 0.2;
  return s;
}

void TvdSodStep(benchmark::State& st) {
  tvd::TvdSolver solver(sod2d(static_cast<int>(st.range(0))));
  solver.advance(1e9);  // first touch outside the timing
  for (auto _ : st) solver.advance(1e9);
  st.counters["cell-updates/s"] = benchmark::Counter(
      static_cast<double>(st.iterations()) * static_cast<double>(solver.workItems()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(TvdSodStep)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------- EOS
// 4096 states spanning compression, cold expansion, the blend and hot expansion (Tillotson's
// four regions), evaluated through the concrete type as the solvers' per-material loops do.
template <class E>
void evalEos(benchmark::State& st, const E& eos, double rho0) {
  constexpr int n = 4096;
  std::vector<double> rho(n), e(n), p(n), c(n);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ur(0.3, 1.6), ue(0.0, 0.5);
  for (int i = 0; i < n; ++i) {
    rho[static_cast<std::size_t>(i)] = rho0 * ur(rng);
    e[static_cast<std::size_t>(i)] = ue(rng);
  }
  for (auto _ : st) {
    for (int i = 0; i < n; ++i) {
      const eos::EosState s =
          eos.state(rho[static_cast<std::size_t>(i)], e[static_cast<std::size_t>(i)]);
      p[static_cast<std::size_t>(i)] = s.pressure;
      c[static_cast<std::size_t>(i)] = s.soundSpeed;
    }
    benchmark::DoNotOptimize(p.data());
    benchmark::DoNotOptimize(c.data());
    benchmark::ClobberMemory();
  }
  st.counters["evaluations/s"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * n, benchmark::Counter::kIsRate);
}

void EosTillotson(benchmark::State& st) { evalEos(st, eos::aluminiumStudy(), 2.79); }
void EosMieGruneisen(benchmark::State& st) { evalEos(st, eos::MieGruneisen{}, 8.93); }
void EosIdealGas(benchmark::State& st) { evalEos(st, eos::IdealGas{1.4, 1.0}, 1.0); }
// Through std::variant per call: what a per-cell std::visit would cost (issue 17 names it).
void EosTillotsonVisit(benchmark::State& st) {
  const eos::Eos v = eos::aluminiumStudy();
  constexpr int n = 4096;
  std::vector<double> rho(n), e(n), p(n);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ur(0.3, 1.6), ue(0.0, 0.5);
  for (int i = 0; i < n; ++i) {
    rho[static_cast<std::size_t>(i)] = 2.79 * ur(rng);
    e[static_cast<std::size_t>(i)] = ue(rng);
  }
  for (auto _ : st) {
    for (int i = 0; i < n; ++i)
      p[static_cast<std::size_t>(i)] =
          eos::state(v, rho[static_cast<std::size_t>(i)], e[static_cast<std::size_t>(i)]).pressure;
    benchmark::DoNotOptimize(p.data());
    benchmark::ClobberMemory();
  }
  st.counters["evaluations/s"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * n, benchmark::Counter::kIsRate);
}
BENCHMARK(EosTillotson)->Unit(benchmark::kMicrosecond);
BENCHMARK(EosTillotsonVisit)->Unit(benchmark::kMicrosecond);
BENCHMARK(EosMieGruneisen)->Unit(benchmark::kMicrosecond);
BENCHMARK(EosIdealGas)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
