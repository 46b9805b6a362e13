//! @file TvdSolver: set-up, validation, the time step and the step sequence.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "eos_line.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"
#include "signal_speed.hpp"
#include "workspace.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hvi::tvd {

std::unique_ptr<Solver> createSolver(const cases::Scene& scene) {
  return std::make_unique<TvdSolver>(scene);
}

TvdSolver::~TvdSolver() = default;

TvdSolver::TvdSolver(const cases::Scene& scene, Options options)
    : geometry_(scene.geometry), domain_(scene.domain), params_(scene.tvd), options_(options) {
  // "auto" too: the rule acts on the cut cells' phase faces only, so it is no re-entry where the
  // conservative interfaces run and changes nothing elsewhere (docs/tvd.md, "Outflow sides: no
  // re-entry").
  if (scene.tvd.outflow != cases::OutflowMode::Open) options_.closedOutflow = true;
  if (scene.tvd.outflow == cases::OutflowMode::NoReentryCut) options_.cutOutflowLines = true;
  // The open rule is the earlier default: kept with the earlier marker motion (its thin edge
  // cells, re-entered through the side, collapse the time step when a line reads them alone).
  if (scene.tvd.outflow == cases::OutflowMode::Open) options_.ownBodyVelocity = false;
  setUpGrid(scene);
  setUpMaterials(scene);
#ifdef _OPENMP
  threads_ = options_.threads > 0 ? options_.threads : omp_get_max_threads();
#else
  threads_ = 1;
#endif
  const int lineCells = std::max(grid_.nx, grid_.nz);
  for (int t = 0; t < threads_; ++t) {
    work_.push_back(std::make_unique<Workspace>(lineCells));
    if (cut_)
      work_.back()->cut =
          std::make_unique<detail::CutLineWork>(lineCells, static_cast<int>(materials_.size()));
    if (!markersOn_ && options_.lineBatches)
      work_.back()->batch = std::make_unique<detail::BatchWork>(lineCells);
  }
  lineRecords_.resize(static_cast<std::size_t>(lineCells));
  if (cut_) {
    phaseOutflow_.assign(materials_.size(), 0.0);
    phaseEdge_.assign(static_cast<std::size_t>(lineCells) * materials_.size(), 0.0);
    phaseSpan_.assign(2 * static_cast<std::size_t>(lineCells) * materials_.size(), -1);
    spanNext_.assign(2 * static_cast<std::size_t>(threads_) * static_cast<std::size_t>(lineCells) *
                         materials_.size(),
                     -1);
  }
  time_ = scene.tStart;
  if (markersOn_) {
    std::array<bool, 4> open{};
    ownership_.setCutCells(cut_);
    ownership_.setMarkerWalls(options_.markerWalls);
    ownership_.setOwnVelocity(options_.ownBodyVelocity);
    ownership_.setUp(scene, cellVolumes_, objectMaterial_, bodyStates_,
                     static_cast<int>(materials_.size()), threads_);
    // docs/tvd.md, "Outflow sides: no re-entry" (Options::closedOutflow) and "Cutting the lines
    // at outflow sides" (Options::cutOutflowLines).
    if (cut_ && options_.closedOutflow)
      for (int side = 0; side < 4; ++side)
        open[static_cast<std::size_t>(side)] =
            scene.domain.boundary[static_cast<std::size_t>(side)] == cases::Boundary::Outflow;
    if (options_.cutOutflowLines) {
      ownership_.setCutSides(open);
      open = {};
    }
    ownership_.setOpenSides(open);
  }
  setUpStrength(scene);
  if (cut_) {
    initialiseCut(scene);
    return;
  }
  initialiseState(scene);
  if (markersOn_) ownership_.startTargets(U_);
}

// A body whose material has all left through the outflow sides (its phase holds no mass in the
// domain, to 1e-13 of what it booked as outflow) loses its lines where the lines are cut at the
// sides: its last sliver along the side would otherwise stay behind with no material, the
// emptied edge cells giving its markers no velocity, and the repair would fill it from
// round-off (TvdCutOutflow, a block leaving through zmax: the sliver's cells then moved at
// 20 cm/us). docs/tvd.md, "Cutting the lines at outflow sides".
void TvdSolver::dropEmptiedLines() {
  if (!ownership_.cutsLines()) return;
  const long nx = grid_.nx;
  for (int p = 0; p < phases_.count; ++p) {
    const double out = phaseOutflow_[static_cast<std::size_t>(p)];
    if (!(out > 0.0)) continue;
    const double* rho = phases_.q[static_cast<std::size_t>(p)].rho.data();
    double mass = 0.0;
    for (long c = phases_.rowLo * nx; c < phases_.rowHi * nx; ++c)
      mass += std::abs(rho[c]) * cellVolumes_(c);
    if (mass <= 1e-13 * out) ownership_.dropLines(p);
  }
}

void TvdSolver::measurePhases() {
  // The volume fractions are the rasterised fractions, fitted in place: no third array.
  phases_.alpha = ownership_.takeFractions();
  phases_.measure(ownership_.markers());
}

void TvdSolver::setUpGrid(const cases::Scene& scene) {
  const auto& p = scene.tvd;
  const auto& d = scene.domain;
  if (!(p.cellSize > 0.0) || !std::isfinite(p.cellSize))
    throw InputError(fmt::format("tvd.cell_size = {} cm: must be a positive length", p.cellSize));
  if (!(p.cfl > 0.0) || p.cfl > 0.5)
    throw InputError(fmt::format(
        "tvd.cfl = {}: must be in (0, 0.5] (the positivity fallback flux needs CFL <= 1/2)",
        p.cfl));
  if (!(p.vacuumDensity >= 0.0) || p.vacuumDensity >= 1.0)
    throw InputError(
        fmt::format("tvd.vacuum_density = {}: must be a fraction of rho0 in [0, 1) "
                    "(0: the interface mode's default)",
                    p.vacuumDensity));
  if (!(options_.entropyFix >= 0.0) || options_.contactIterations < 0)
    throw InputError("tvd options: entropyFix must be >= 0 and contactIterations >= 0");
  const double lx = d.xmax - d.xmin, lz = d.zmax - d.zmin;
  if (!(lx >= p.cellSize) || !(lz >= p.cellSize))
    throw InputError(fmt::format(
        "domain [{}, {}] x [{}, {}] cm is smaller than one cell of tvd.cell_size = {} cm", d.xmin,
        d.xmax, d.zmin, d.zmax, p.cellSize));
  const double nxD = std::round(lx / p.cellSize), nzD = std::round(lz / p.cellSize);
  if (nxD * nzD > 4.0e8)
    throw InputError(
        fmt::format("tvd grid of {} x {} cells is too large (at most 4e8 cells)", nxD, nzD));
  if (geometry_ == Geometry::Axisymmetric) {
    if (d.xmin < 0.0)
      throw InputError(fmt::format("r-z domain: xmin = {} cm, the radius must be >= 0", d.xmin));
    if (d.xmin == 0.0 && d.boundary[0] == cases::Boundary::Outflow)
      throw InputError("r-z domain touching the axis (xmin = 0): boundary xmin must be 'axis'");
  }
  grid_.nx = static_cast<int>(nxD);
  grid_.nz = static_cast<int>(nzD);
  grid_.x0 = d.xmin;
  grid_.z0 = d.zmin;
  grid_.dx = grid_.dz = p.cellSize;
  faceX_.resize(static_cast<std::size_t>(grid_.nx) + 1);
  cellX_.resize(static_cast<std::size_t>(grid_.nx));
  for (int i = 0; i <= grid_.nx; ++i) faceX_[static_cast<std::size_t>(i)] = grid_.x0 + i * grid_.dx;
  for (int i = 0; i < grid_.nx; ++i)
    cellX_[static_cast<std::size_t>(i)] = grid_.x0 + (i + 0.5) * grid_.dx;
  cellVolumes_ = {grid_, geometry_ == Geometry::Axisymmetric, cellX_};
}

void TvdSolver::setUpMaterials(const cases::Scene& scene) {
  // As every solver runs them (the tension cut-off follows the scene's effect), not as given:
  // a Scene built in code may carry the EOS defaults.
  materials_ = cases::resolveMaterials(scene);
  if (materials_.empty()) throw InputError("tvd: the scene defines no material");
  if (scene.bodies.empty()) throw InputError("tvd: the scene defines no body");
  for (const auto& b : scene.bodies) {
    if (b.material < 0 || b.material >= static_cast<int>(materials_.size()))
      throw InputError(fmt::format("body '{}': material index {} is not one of the {} materials",
                                   b.name, b.material, materials_.size()));
    bodyNames_.push_back(b.name);
    objectMaterial_.push_back(b.material);
    const double rho0 = materials_[static_cast<std::size_t>(b.material)].rho0();
    bodyStates_.push_back(
        {b.density > 0.0 ? b.density : rho0, b.velocity.x, b.velocity.z, b.specificEnergy});
  }
  sceneMaterials_ = materials_;
  sceneMaterialOf_.clear();
  for (std::size_t m = 0; m < materials_.size(); ++m)
    sceneMaterialOf_.push_back(static_cast<int>(m));
  markersOn_ = scene.has(cases::Effect::MaterialInterfaces);
  cut_ = markersOn_ && params_.interfaces == cases::InterfaceMode::Conservative;
  if (cut_) {
    // One phase per body (tvd.hpp, materials_).
    materials_.clear();
    sceneMaterialOf_.clear();
    for (std::size_t o = 0; o < objectMaterial_.size(); ++o) {
      materials_.push_back(sceneMaterials_[static_cast<std::size_t>(objectMaterial_[o])]);
      sceneMaterialOf_.push_back(objectMaterial_[o]);
      objectMaterial_[o] = static_cast<int>(o);
    }
  }
  for (const auto& m : materials_) {
    rhoCut_.push_back(vacuumDensity() * m.rho0());
    rhoThin_.push_back(std::max(kThinFraction * m.rho0(), rhoCut_.back()));
    rhoStep_.push_back(kStepDensityFraction * m.rho0());
  }
  phaseOn_ = scene.has(cases::Effect::PhaseBookkeeping);
  singleMaterial_ = scene.bodies.front().material;
  if (!markersOn_) {
    for (const auto& b : scene.bodies)
      if (b.material != singleMaterial_)
        throw InputError(fmt::format(
            "tvd: bodies '{}' and '{}' are of different materials; a multi-material scene needs "
            "the effect 'material_interfaces' (marker lines)",
            scene.bodies.front().name, b.name));
  }
}

// Largest signal speed max(|u|, |w|) + c over the material cells; also the check that every
// cell is physical, and (for the markers) the velocity at the start of the step.
double TvdSolver::signalSpeedPass(double* vx, double* vz, long* worstCell) const {
  const long cells = grid_.cells();
  detail::SpeedScan scan;
  const int nMat = static_cast<int>(materials_.size());
  const int* owner = markersOn_ ? ownership_.owner().data() : nullptr;
  const int* material = objectMaterial_.data();
  for (int id = 0; id < nMat; ++id) {
    if (!markersOn_ && id != singleMaterial_) continue;
    std::visit(
        [&](const auto& eos) {
          detail::scanSignalSpeed(cells, threads_, scan, [&](long c, CellState& s) {
            if (owner != nullptr && (owner[c] < 0 || material[owner[c]] != id)) return 0;
            const auto cc = static_cast<std::size_t>(c);
            const double r = U_.rho[cc];
            if (!(r > 0.0)) return -1;
            s = detail::cellState(eos, r, U_.mx[cc], U_.mz[cc], U_.E[cc]);
            // Strength: the longitudinal wave c_L = sqrt(c^2 + 4G / (3 rho)) is the fastest.
            if (strength_ && !detail::failedMaterial(strength_->rq[detail::kDamage], cc, r))
              s.c = strength::longitudinalSoundSpeed(s.c, strengthShearModulus(r, s.e, s.p), r);
            if (vx != nullptr) {  // an unphysical state stops the run below, whatever it wrote
              vx[c] = s.u;
              vz[c] = s.w;
            }
            return 1;
          });
        },
        materials_[static_cast<std::size_t>(id)].eos);
  }
  const long bad = scan.bad, worst = scan.worst;
  const double smax = scan.smax;
  if (bad >= 0) {
    const auto c = static_cast<std::size_t>(bad);
    throw SimulationError(fmt::format(
        "tvd: step {}, t = {:.6g} us: cell (i={}, k={}) is unphysical: rho = {:.6g}, "
        "momentum = ({:.6g}, {:.6g}), energy density = {:.6g}",
        step_, time_, bad % grid_.nx, bad / grid_.nx, U_.rho[c], U_.mx[c], U_.mz[c], U_.E[c]));
  }
  if (worstCell != nullptr) *worstCell = worst;
  return smax;
}

double TvdSolver::stableTimeStep() const {
  const double s =
      cut_ ? signalSpeedCut(nullptr, nullptr, nullptr) : signalSpeedPass(nullptr, nullptr, nullptr);
  return s > 0.0 ? params_.cfl * grid_.dx / s : std::numeric_limits<double>::infinity();
}

// The buffers lent to the marker step hold, until the lines' new fractions overwrite them, the
// cells each line may read its velocity from (MarkerSet::advect's `own`, nonzero): those where
// its body is present at the step's start and holds at least the time-step density at its end,
// and those that other bodies fill (a contact: both lines read the same cells there, so they
// stay together). A cell below that density sets no time step and its velocity is bounded only
// by the clamp (Ownership::centredVelocity); a partly empty cell of another body is that body's
// free surface, whose velocity is not this body's (docs/tvd.md "Marker velocity: each line its
// own body's").
void TvdSolver::markOwnCells() {
  const long c0 = phases_.cellLo(), c1 = phases_.cellHi();
  const int P = phases_.count;
  std::vector<double*> alpha(static_cast<std::size_t>(P));
  std::vector<const double*> rho(static_cast<std::size_t>(P));
  for (int p = 0; p < P; ++p) {
    alpha[static_cast<std::size_t>(p)] = phases_.alpha[static_cast<std::size_t>(p)].data();
    rho[static_cast<std::size_t>(p)] = phases_.q[static_cast<std::size_t>(p)].rho.data();
  }
  const double* rhoStep = rhoStep_.data();
  // A cell is full when its live phases cover it to the fit's round-off (kOwnFilled).
  // Two bodies, the common case: the same sums and values by selects (the general loop below,
  // with branches or with selects, took 2.1-2.3 % of variant 1's conservative run against 1.4 %).
  if (P == 2) {
    double* a0 = alpha[0];
    double* a1 = alpha[1];
    const double* r0 = rho[0];
    const double* r1 = rho[1];
    const double s0 = rhoStep[0], s1 = rhoStep[1];
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelStream)
    for (long c = c0; c < c1; ++c) {
      const double x0 = a0[c], x1 = a1[c];
      // A present phase (a > 0) below the time-step density is dropped, else it is live;
      // adding an exact 0 for the others leaves the sum's bits as the branches left them.
      const bool in0 = x0 > 0.0, in1 = x1 > 0.0;
      const bool live0 = in0 && r0[c] >= s0 * x0, live1 = in1 && r1[c] >= s1 * x1;
      const double live = 0.0 + (live0 ? x0 : 0.0) + (live1 ? x1 : 0.0);
      const bool full = live >= kOwnFilled;
      a0[c] = full ? 1.0 : in0 && !live0 ? 0.0 : x0;
      a1[c] = full ? 1.0 : in1 && !live1 ? 0.0 : x1;
    }
    return;
  }
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelStream)
  for (long c = c0; c < c1; ++c) {
    double live = 0.0;
    for (int p = 0; p < P; ++p) {
      double& a = alpha[static_cast<std::size_t>(p)][c];
      if (!(a > 0.0)) continue;
      if (!(rho[static_cast<std::size_t>(p)][c] >= rhoStep[p] * a))
        a = 0.0;
      else
        live += a;
    }
    // (A phase alone in its cell has a >= kOwnFilled already.)
    if (live >= kOwnFilled)
      for (int p = 0; p < P; ++p) alpha[static_cast<std::size_t>(p)][c] = 1.0;
  }
}

// No re-entry through outflow sides: a phase in an edge cell that moves out through the side,
// holds less of the cell than leaves in one step at its own speed (alpha h < u_n dt) and no
// longer reaches the cell's inner face (its trailing line has passed it) is released through
// the side now, booked as outflow (mass, momentum, energy, and the phase's own
// outflow). Its lines lie beyond the side (they stay there), so what is left in the cell is a
// sliver the swept volumes of the last step did not take, and the side, a wall for material
// moving inwards, would otherwise hold it while the line's fraction squeezes it (docs/tvd.md
// "Slivers at outflow sides").
void TvdSolver::releaseSlivers(double dt) {
  const int nx = grid_.nx, nz = grid_.nz;
  for (int side = 0; side < 4; ++side) {
    if (domain_.boundary[static_cast<std::size_t>(side)] != cases::Boundary::Outflow) continue;
    const bool xSide = side < 2;
    const double sign = side % 2 == 0 ? -1.0 : 1.0;  // outward normal component
    const double h = xSide ? grid_.dx : grid_.dz;
    const int count = xSide ? nz : nx;
    const int edge = side == 0 ? 0 : side == 1 ? nx - 1 : side == 2 ? 0 : nz - 1;
    // The edge cells' inner face (its index along the normal) and the aperture seen from the
    // edge cell: the limit from below on a low side's face, from above on a high side's.
    const int inner = side % 2 == 0 ? 1 : edge;
    const int from = side % 2 == 0 ? 0 : 1;
    if (!xSide && (edge < phases_.rowLo || edge >= phases_.rowHi)) continue;
    for (int j = 0; j < count; ++j) {
      if (xSide && (j < phases_.rowLo || j >= phases_.rowHi)) continue;
      const long c = xSide ? static_cast<long>(j) * nx + edge : static_cast<long>(edge) * nx + j;
      const auto cc = static_cast<std::size_t>(c);
      for (int p = 0; p < phases_.count; ++p) {
        Conserved& q = phases_.q[static_cast<std::size_t>(p)];
        const double m = q.rho[cc];
        if (!(m > 0.0)) continue;
        const double un = sign * (xSide ? q.mx[cc] : q.mz[cc]) / m;
        const double a = phases_.alpha[static_cast<std::size_t>(p)][cc];
        if (!(un > 0.0) || !(a * h < un * dt)) continue;
        // Only a trailing sliver: the phase no longer reaches the cell's inner face (a cut
        // cell of a surface lying along the side, a plate's top sliding out, still does, and
        // refilled from inside it would drain the body faster than it moves).
        const double aperture =
            xSide ? phases_.apertureX(p, from, inner, j) : phases_.apertureZ(p, from, j, inner);
        if (aperture > 0.0) continue;
        const double vol = cellVolumes_(c);
        Budget b{m * vol, q.mx[cc] * vol, q.mz[cc] * vol, q.E[cc] * vol};
        ledger_.outflow += b;
        phaseOutflow_[static_cast<std::size_t>(p)] += m * vol;
        q.rho[cc] = q.mx[cc] = q.mz[cc] = q.E[cc] = 0.0;
        phases_.alpha[static_cast<std::size_t>(p)][cc] = 0.0;
        if (static_cast<std::size_t>(p) < phases_.carried.size())
          for (std::vector<double>* f : phases_.carried[static_cast<std::size_t>(p)])
            if (f != nullptr && cc < f->size()) (*f)[cc] = 0.0;
      }
    }
  }
}

double TvdSolver::advance(double tStop) {
  if (!(tStop > time_)) return 0.0;
  long worst = -1;
  double smax;
  if (cut_)
    smax = signalSpeedCut(ownership_.startVelocityX(), ownership_.startVelocityZ(), &worst);
  else if (markersOn_)
    smax = signalSpeedPass(ownership_.startVelocityX(), ownership_.startVelocityZ(), &worst);
  else
    smax = signalSpeedPass(nullptr, nullptr, &worst);
  double dt = smax > 0.0 ? params_.cfl * grid_.dx / smax : tStop - time_;
  if (dt0_ == 0.0) dt0_ = dt;
  if (!(dt >= kDtCollapseFraction * dt0_)) {
    const auto c = static_cast<std::size_t>(std::max(worst, 0L));
    syncMixture();
    throw SimulationError(fmt::format(
        "tvd: step {}, t = {:.6g} us: time step collapsed to {:.3g} us (first step {:.3g} us); "
        "fastest cell (i={}, k={}): rho = {:.6g}, signal speed {:.6g} cm/us",
        step_, time_, dt, dt0_, worst % grid_.nx, worst / grid_.nx, U_.rho[c], smax));
  }
  bool last = false;
  if (time_ + dt >= tStop) {
    dt = tStop - time_;
    last = true;
  }
  // Strang-alternated splitting: x then z on even steps, z then x on odd steps.
  if (cut_) {
    limitThinVelocities(dt);
    sweepCut(step_ % 2 == 0 ? 0 : 1, dt);
    sweepCut(step_ % 2 == 0 ? 1 : 0, dt);
    dropEmptiedLines();
    // The old fractions, for the repair, kept where nonzero; the lines' new fractions go into
    // their buffers (zero outside the rows, as move requires), which measurePhases takes back.
    alphaOld_.keep(phases_);
    if (options_.ownBodyVelocity) markOwnCells();
    ownership_.lendFractions(std::move(phases_.alpha));
    phases_.alpha.clear();
    // The markers move with the mixture velocity, summed from the phases where it is read (the
    // mixture state itself is formed once, below, after the repair).
    ownership_.move(phases_.q.data(), phases_.count, dt, phases_.rowLo, phases_.rowHi);
    measurePhases();
    orphans_ += phases_.repair(cellVolumes_, alphaOld_);
    if (options_.closedOutflow && options_.releaseSlivers) releaseSlivers(dt);
    volumeFresh_ = true;  // the first sweep of the next step starts from alpha
    mixtureStale_ = true;
  } else if (step_ % 2 == 0) {
    sweep(0, dt);
    sweep(1, dt);
  } else {
    sweep(1, dt);
    sweep(0, dt);
  }
  if (strength_) {
    if (cut_)
      strengthStepCut(dt);
    else
      strengthStep(dt);
  }
  if (markersOn_ && !cut_) ownership_.update(U_, dt, ledger_.ownerChanges);
  time_ = last ? tStop : time_ + dt;
  ++step_;
  return dt;
}

}  // namespace hvi::tvd
