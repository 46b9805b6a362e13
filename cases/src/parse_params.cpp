//! @file [sph], [tvd], [riemann] and [output]: solver parameters and what to write.
#include <fmt/format.h>

#include <climits>

#include "detail/parse.hpp"
#include "detail/schema.hpp"
#include "hvi/cases/names.hpp"

namespace hvi::cases::detail {
namespace {

constexpr double kMinMassTolerance = 1e-13;
constexpr long long kMaxMassIterations = 1000000;
constexpr long long kMaxRiemannCells = 1000000;

void parseSph(const TableReader& s, SphParams& p) {
  s.rejectUnknown(kSphKeys);
  p.spacing = s.quantity("spacing", Dimension::Length, p.spacing);
  s.check(p.spacing > 0.0, "spacing", "must be > 0", "a length > 0");
  p.hFactor = s.number("h_factor", p.hFactor);
  s.check(p.hFactor > 0.0, "h_factor", "must be > 0 (h = h_factor * spacing)", "h_factor > 0");
  p.kernel =
      static_cast<Kernel>(s.choice("kernel", kernelNames(), static_cast<std::size_t>(p.kernel)));
  p.lattice = static_cast<Lattice>(
      s.choice("lattice", latticeNames(), static_cast<std::size_t>(p.lattice)));
  p.alpha = s.number("alpha", p.alpha);
  s.check(p.alpha >= 0.0, "alpha", "must be >= 0", "alpha >= 0");
  p.beta = s.number("beta", p.beta);
  s.check(p.beta >= 0.0, "beta", "must be >= 0", "beta >= 0");
  p.cfl = s.number("cfl", p.cfl);
  s.check(p.cfl > 0.0 && p.cfl <= 1.0, "cfl", "must be in (0, 1]", "0 < cfl <= 1");
  p.massTolerance = s.number("mass_tolerance", p.massTolerance);
  // The residual |rho0/rho - 1| is a sum of 30-60 kernel terms, each rounded to 1e-16: a
  // tolerance below 1e-13 is never met and the iteration would only stop at its cap.
  s.check(p.massTolerance >= kMinMassTolerance && p.massTolerance < 1.0, "mass_tolerance",
          "must be in [1e-13, 1) (below 1e-13 round-off keeps the residual from reaching it)",
          "1e-13 <= mass_tolerance < 1");
  p.deleteFraction = s.number("delete_fraction", p.deleteFraction);
  s.check(p.deleteFraction >= 0.0 && p.deleteFraction < 1.0, "delete_fraction", "must be in [0, 1)",
          "0 <= delete_fraction < 1");
  const long long it = s.integer("max_mass_iterations", p.maxMassIterations);
  // docs/sph.md: ~550 passes at h = dx, ~4e5 at h = 2 dx (the slowest mode is damped by
  // 1 - exp(-pi^2 h^2 / 4 dx^2) per pass); a pass over 1e5 particles takes ~5 ms, so 1e6
  // passes are already ~1.5 h. More can only mean an iteration that does not converge.
  s.check(it >= 1 && it <= kMaxMassIterations, "max_mass_iterations", "must be in [1, 1000000]",
          "an integer in [1, 1000000]");
  p.maxMassIterations = static_cast<int>(it);
}

void parseTvd(const TableReader& s, TvdParams& p) {
  s.rejectUnknown(kTvdKeys);
  p.cellSize = s.quantity("cell_size", Dimension::Length, p.cellSize);
  s.check(p.cellSize > 0.0, "cell_size", "must be > 0", "a length > 0");
  p.limiter = static_cast<Limiter>(
      s.choice("limiter", limiterNames(), static_cast<std::size_t>(p.limiter)));
  p.cfl = s.number("cfl", p.cfl);
  // The positivity fallback (Rusanov) flux of the split sweeps needs CFL <= 1/2.
  s.check(p.cfl > 0.0 && p.cfl <= 0.5, "cfl", "must be in (0, 0.5] for the TVD scheme",
          "0 < cfl <= 0.5");
  p.markerSpacing = s.number("marker_spacing", p.markerSpacing);
  s.check(p.markerSpacing > 0.0 && p.markerSpacing <= 10.0, "marker_spacing",
          "must be in (0, 10] cells", "0 < marker_spacing <= 10 (in cells)");
  p.vacuumDensity = s.number("vacuum_density", p.vacuumDensity);
  s.check(p.vacuumDensity > 0.0 && p.vacuumDensity < 1.0, "vacuum_density",
          "must be in (0, 1) (a fraction of rho0)", "0 < vacuum_density < 1");
}

// Where two rect bodies meet along x, if they do: the natural Riemann interface.
std::optional<double> meetingPoint(const Scene& scene) {
  if (scene.bodies.size() != 2) return std::nullopt;
  const auto* a = std::get_if<Rect>(&scene.bodies[0].shape);
  const auto* b = std::get_if<Rect>(&scene.bodies[1].shape);
  if (!a || !b) return std::nullopt;
  return a->xmin <= b->xmin ? a->xmax : b->xmax;
}

void parseRiemann(const TableReader& s, RiemannParams& p, const Scene& scene) {
  s.rejectUnknown(kRiemannKeys);
  const long long cells = s.integer("cells", p.cells);
  // Measured on sod_x at 1e6 cells: 170 MB peak memory, 49 MB of HDF5 + VTK per snapshot, 2 s
  // for three snapshots; 1e8 cells needed ~15 GB of each (issue 11). A 1-D exact profile finer
  // than 1e6 cells resolves nothing that a 2-D solver it is compared with could (the 5e7-cell
  // TVD cap is ~7000 cells a side).
  s.check(cells >= 2 && cells <= kMaxRiemannCells, "cells", "must be in [2, 1e6]",
          "an integer in [2, 1000000]");
  p.cells = static_cast<int>(cells);
  p.interface =
      s.quantity("interface", Dimension::Length, meetingPoint(scene).value_or(p.interface));
}

}  // namespace

void parseSolverParams(const TableReader& root, Scene& scene) {
  const toml::table empty;
  auto section = [&](std::string_view key) {
    auto t = root.subTable(key, false);
    return t ? *t : TableReader(root.ctx(), empty, std::string(key));
  };
  parseSph(section("sph"), scene.sph);
  parseTvd(section("tvd"), scene.tvd);
  parseRiemann(section("riemann"), scene.riemann, scene);
}

void parseOutput(const TableReader& root, Scene& scene) {
  const auto o = root.subTable("output", false);
  if (!o) return;
  o->rejectUnknown(kOutputKeys);
  Output& out = scene.output;
  if (const toml::node* n = o->find("times")) {
    const std::string path = o->keyPath("times");
    const auto& arr = readArray(root.ctx(), *n, path, 0, "[\"1 us\", \"2 us\"]");
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string p = path + "[" + std::to_string(i) + "]";
      const double t = readQuantity(root.ctx(), *arr.get(i), p, Dimension::Time);
      const std::string window =
          fmt::format("({}, {}] us", shortNumber(scene.tStart), shortNumber(scene.tEnd));
      if (!(t > scene.tStart && t <= scene.tEnd))
        fail(root.ctx(), arr.get(i), p, "outside the simulated time " + window,
             "times in (time.start, time.end]");
      if (!out.times.empty() && !(t > out.times.back()))
        fail(root.ctx(), arr.get(i), p, "output times must increase strictly",
             "ascending times, each once");
      out.times.push_back(t);
    }
  }
  out.hdf5 = o->boolean("hdf5", out.hdf5);
  out.vtk = o->boolean("vtk", out.vtk);
  out.checkpointEvery = o->quantity("checkpoint_every", Dimension::WallTime, out.checkpointEvery);
  o->check(out.checkpointEvery >= 0.0, "checkpoint_every", "must be >= 0 (0: at snapshots only)",
           "a wall-clock time >= 0 in s, min or h");
}

}  // namespace hvi::cases::detail
