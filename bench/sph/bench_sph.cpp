//! @file Throughput of the SPH solver on variant 2 (rod on plate, planar, ~88 000 particles).
//!
//! Usage: hvi_bench_sph [t_end_us=5] [max_steps=-1] [spacing_cm=0.01] [strength=0]
//! strength = 1: the same impact with the effect strength (6061-T6 Steinberg-Guinan preset for
//! both bodies) instead of the tension cut-off, for the cost ratio of docs/strength.md.
//! Prints setup time (fill + mass iteration), steps, wall time and particle-updates per
//! second per thread. Run with OMP_NUM_THREADS set to the cores to measure.
#if __has_include(<malloc.h>)
#include <malloc.h>  // mallopt (glibc)
#endif
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "args.hpp"
#include "hvi/common/units.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/strength/strength.hpp"

namespace {

using hvi::cases::Effect;

hvi::cases::Scene variant2(double spacing, bool strength) {
  hvi::cases::Scene s;
  s.path = "bench:variant2";
  s.title = "rod d = 1 cm at 6.18 km/s on a 0.4 cm aluminium plate";
  s.geometry = hvi::Geometry::Planar;
  s.domain = {-12.0, 12.0, -6.0, 6.0, {}};
  s.materials = {{"aluminium", hvi::eos::aluminiumStudy()}};
  hvi::cases::Body rod, plate;
  rod.name = "striker";
  rod.material = 0;
  rod.shape = hvi::cases::Disk{{0.0, 0.9}, 0.5};
  rod.velocity = {0.0, -6.18 * hvi::units::kmPerS};
  rod.density = 2.79;
  plate.name = "shield";
  plate.material = 0;
  plate.shape = hvi::cases::Rect{-10.0, 10.0, 0.0, 0.4};
  plate.density = 2.79;
  s.bodies = {rod, plate};
  s.sph.spacing = spacing;
  s.effects = {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::TensionCutoff};
  s.tEnd = 5.0;
  if (strength) {
    s.materials[0].strength = hvi::strength::findPreset("al6061_t6")->material;
    s.effects = {Effect::ArtificialViscosity, Effect::MassAdjustment, Effect::Strength};
  }
  return s;
}

double seconds(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

}  // namespace

int run(int argc, char** argv) {
#ifdef M_MMAP_THRESHOLD
  // glibc raises its mmap threshold to the size of each large block freed (up to 32 MiB); the
  // solvers' large arrays then come from the heap and fragment it as they are rebuilt: +120 B
  // per SPH particle by step 50 of variant 2 (docs/performance.md, "SPH memory"). A fixed
  // threshold keeps large arrays mapped and returned when freed; the heap's smaller blocks are
  // kept (not trimmed and faulted in again at every step).
  mallopt(M_MMAP_THRESHOLD, 256 * 1024);
  mallopt(M_TRIM_THRESHOLD, 64 * 1024 * 1024);
#endif
  using hvi::bench::numberArg;
  const double tEnd = numberArg(argc, argv, 1, "t_end_us", 5.0, 0.0, 1e6);
  const auto maxSteps = static_cast<long>(numberArg(argc, argv, 2, "max_steps", -1, -1, 1e12));
  const double spacing = numberArg(argc, argv, 3, "spacing_cm", 0.01, 1e-4, 1.0);
  const bool strength = numberArg(argc, argv, 4, "strength", 0, 0, 1) != 0.0;
  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  const auto t0 = std::chrono::steady_clock::now();
  hvi::sph::SphSolver solver(variant2(spacing, strength));
  const double setup = seconds(t0);
  std::printf(
      "variant 2: %ld particles (mass iteration: %d iterations, %zu deleted), setup "
      "%.2f s, %d threads\n",
      solver.workItems(), solver.massAdjustment().iterations, solver.massAdjustment().deleted,
      setup, threads);
  const hvi::Totals e0 = solver.totals();
  const auto t1 = std::chrono::steady_clock::now();
  const std::clock_t c1 = std::clock();
  long steps = 0;
  double updates = 0.0;
  while (solver.time() < tEnd && (maxSteps < 0 || steps < maxSteps)) {
    updates += static_cast<double>(solver.workItems());
    solver.advance(tEnd);
    ++steps;
    if (steps % 200 == 0)
      std::printf("  step %ld, t = %.3f us, %.1f s\n", steps, solver.time(), seconds(t1));
  }
  const double wall = seconds(t1);
  const double cpu = static_cast<double>(std::clock() - c1) / CLOCKS_PER_SEC;
  const hvi::Totals e1 = solver.totals();
  std::printf("%ld steps to t = %.4f us in %.2f s: %.3e particle-updates/s, %.3e per thread\n",
              steps, solver.time(), wall, updates / wall, updates / wall / threads);
  // CPU time of all threads: on a shared machine wall time overstates the cost.
  std::printf("CPU time %.2f s: %.3e particle-updates per CPU-second\n", cpu, updates / cpu);
  std::printf("energy drift %.3e of the total, mass drift %.3e\n",
              (e1.energy() - e0.energy()) / e0.energy(), (e1.mass - e0.mass) / e0.mass);
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "hvi_bench_sph: %s\n(usage: hvi_bench_sph [t_end_us] [max_steps] [spacing_cm] "
                 "[strength 0|1])\n",
                 e.what());
    return 2;
  }
}
