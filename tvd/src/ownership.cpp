//! @file Marker step: move the marker lines, rebuild the configuration array, re-initialise
//! the cells that change owner, renormalise each material's mass.
#include "hvi/tvd/ownership.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hvi/common/stop_flag.hpp"
#include "interface_normals.hpp"

namespace hvi::tvd {

double CellVolumes::operator()(long cell) const {
  const double a = grid.dx * grid.dz;
  if (!rz) return a;
  return 2.0 * std::numbers::pi * cellX[static_cast<std::size_t>(cell % grid.nx)] * a;
}

void Ownership::setUp(const cases::Scene& scene, const CellVolumes& cells,
                      std::vector<int> material, std::vector<ObjectState> initial, int materials,
                      int threads) {
  cells_ = cells;
  threads_ = threads;
  objectMaterial_ = std::move(material);
  initial_ = std::move(initial);
  const GridSpec& g = cells_.grid;
  const auto n = static_cast<std::size_t>(g.cells());
  markers_ = MarkerSet::fromBodies(scene, g);
  throwIfStopRequested("the TVD marker lines");
  // The conservative interfaces: markers on a wall stay on it (MarkerSet::advect,
  // Options::markerWalls); the study's whole-cell mode keeps its motion.
  for (int side = 0; side < 4; ++side)
    walls_[static_cast<std::size_t>(side)] =
        cutCells_ && markerWalls_ &&
        scene.domain.boundary[static_cast<std::size_t>(side)] == cases::Boundary::Wall;
  if (cutCells_) {
    // The cut cells take their interface areas from the face apertures and never change owners
    // (update is the whole-cell mode's): no marker normals of whole-cell faces, no new-owner
    // arrays. The centred velocity overwrites the start velocity in place: signalSpeedCut
    // writes the start velocity of every cell of the rows that centredVelocity then reads, so
    // nothing reads an old value after it was replaced (bit for bit; 44 B per cell less,
    // docs/tvd.md "Threading and memory").
    markers_.rasterizeFractions(g, owner_, fraction_, 0, g.nz);
    for (auto* v : {&vxOld_, &vzOld_}) v->assign(n, 0.0);
  } else {
    markers_.rasterize(g, owner_, normal_);
    throwIfStopRequested("the TVD marker lines");
    detail::interfaceNormals(markers_, g, owner_, normal_, normalLength_);
    ownerNew_.assign(n, -1);
    normalNew_.assign(n, Vec2{});
    for (auto* v : {&vxOld_, &vzOld_, &vxMid_, &vzMid_}) v->assign(n, 0.0);
  }
  for (auto* v : {&target_, &mass_, &band_, &scale_})
    v->assign(static_cast<std::size_t>(materials), 0.0);
}

void Ownership::startTargets(const Conserved& U) {
  measure(U);
  target_ = mass_;
}

void Ownership::restore(std::vector<int> owner, std::vector<Vec2> normal,
                        std::vector<double> targets, MarkerSet markers, long changes) {
  owner_.swap(owner);
  if (!cutCells_) normal_.swap(normal);  // the cut-cell mode keeps none (cutCellNormals)
  target_.swap(targets);
  markers_ = std::move(markers);
  changeCount_ = changes;
}

// Time-centred velocity (mean of the start and end of the step) for the marker path. Raw
// pointers: the stores through `known` (char) could alias the vectors' own pointers, which the
// compiler would then reload for every cell.
//
// Cut cells: a cell below the time-step density sets no time step, and its mixture velocity,
// momentum over a mass that may be round-off, is then unbounded (a shield run at 0.042 cm cells
// flung markers thousands of cells away in one step, and the lines' redistribution filled the
// gap with points until memory ran out). Every cell that sets the step moves at most cfl <= 0.5
// of a cell per step, so each component is clamped to one cell per step: it bounds such cells
// and leaves every cell that sets the step unchanged.
void Ownership::centredVelocity(const Conserved* parts, int count, double dt, int rowLo,
                                int rowHi) {
  const long cells = cells_.grid.cells();
  const long c0 = static_cast<long>(rowLo) * cells_.grid.nx;
  const long c1 = static_cast<long>(rowHi) * cells_.grid.nx;
  known_.resize(static_cast<std::size_t>(cells));
  std::fill(known_.begin() + c0, known_.begin() + c1, 0);
  signed char* known = known_.data();
  double* vx = midX();
  double* vz = midZ();
  const double *vx0 = vxOld_.data(), *vz0 = vzOld_.data();
  const int* owner = owner_.data();
  const double vmax =
      dt > 0.0 ? std::min(cells_.grid.dx, cells_.grid.dz) / dt : std::numeric_limits<double>::max();
#pragma omp parallel for schedule(static) num_threads(threads_) if (c1 - c0 >= kParallelStream)
  for (long c = c0; c < c1; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const double rho = mixtureAt(parts, count, &Conserved::rho, cc);
    const double mx = mixtureAt(parts, count, &Conserved::mx, cc);
    const double mz = mixtureAt(parts, count, &Conserved::mz, cc);
    if ((!cutCells_ && owner[c] < 0) || !(rho > 0.0)) {
      vx[c] = vz[c] = 0.0;
      continue;
    }
    if (cutCells_) {
      // No start velocity (NaN: the cell held no material at the step's start, and the phase
      // entered it through an opened face): the end velocity alone.
      const double ux = std::clamp(mx / rho, -vmax, vmax);
      const double uz = std::clamp(mz / rho, -vmax, vmax);
      vx[c] = std::isnan(vx0[c]) ? ux : 0.5 * (std::clamp(vx0[c], -vmax, vmax) + ux);
      vz[c] = std::isnan(vz0[c]) ? uz : 0.5 * (std::clamp(vz0[c], -vmax, vmax) + uz);
    } else {
      vx[c] = 0.5 * (vx0[c] + mx / rho);
      vz[c] = 0.5 * (vz0[c] + mz / rho);
    }
    known[c] = 1;
  }
}

// Vacuum cells near material get the mean velocity of their already-known 8 neighbours, in
// `layers` rings: the bilinear interpolation that moves a marker on a free surface then sees
// the material's velocity on both sides instead of the zero velocity of empty cells.
void Ownership::extendIntoVacuum(int layers, int rowLo, int rowHi) {
  const int nx = cells_.grid.nx, nz = cells_.grid.nz;
  const signed char* known = known_.data();
  double* vx = midX();
  double* vz = midZ();
  // Most cells of the rows are vacuum far from any known cell: a byte mask per row (a known
  // cell in the column within a row) skips them before the neighbour sums, which are taken as
  // before, in the same order (same values).
  nearKnown_.resize(static_cast<std::size_t>(nx));
  unsigned char* col = nearKnown_.data();
  for (int layer = 0; layer < layers; ++layer) {
    fresh_.clear();
    for (int k = rowLo; k < rowHi; ++k) {
      const int k0 = std::max(k - 1, 0), k1 = std::min(k + 1, nz - 1);
      for (int i = 0; i < nx; ++i) col[i] = 0;
      for (int kk = k0; kk <= k1; ++kk) {
        const signed char* row = known + static_cast<long>(kk) * nx;
        for (int i = 0; i < nx; ++i) col[i] |= static_cast<unsigned char>(row[i] == 1);
      }
      for (int i = 0; i < nx; ++i) {
        const long c = static_cast<long>(k) * nx + i;
        if (known[c]) continue;
        if (!(col[i] | (i > 0 ? col[i - 1] : 0) | (i + 1 < nx ? col[i + 1] : 0))) continue;
        double sx = 0.0, sz = 0.0;
        int count = 0;
        for (int dk = -1; dk <= 1; ++dk)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, kk = k + dk;
            if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
            const long d = static_cast<long>(kk) * nx + ii;
            if (known[d] != 1) continue;
            sx += vx[d];
            sz += vz[d];
            ++count;
          }
        if (count == 0) continue;
        vx[c] = sx / count;
        vz[c] = sz / count;
        fresh_.push_back(c);
      }
    }
    for (long c : fresh_) known_[static_cast<std::size_t>(c)] = 1;  // usable in the next ring
  }
}

void Ownership::advanceLines(const Conserved* parts, int count, double dt, int rowLo, int rowHi) {
  const GridSpec& g = cells_.grid;
  centredVelocity(parts, count, dt, rowLo, rowHi);
  extendIntoVacuum(2, rowLo, rowHi);
  // The cut-cell mode: each line reads its own body's cells (the fractions lent at the
  // step's start, Phases::alpha); the whole-cell mode reads every cell, as the study did.
  markers_.advect(g, midX(), midZ(), dt, walls_, open_, false,
                  cutCells_ && ownVelocity_ ? &fraction_ : nullptr);
  markers_.clipToSides(g, cut_);  // none in the whole-cell mode (setCutSides)
  markers_.redistribute(g);
}

void Ownership::move(const Conserved* parts, int count, double dt, int rowLo, int rowHi) {
  advanceLines(parts, count, dt, rowLo, rowHi);
  // The fractions are zero outside the rows (the lines never left them): only those cleared.
  markers_.rasterizeFractions(cells_.grid, owner_, fraction_, rowLo, rowHi);
}

std::vector<std::vector<double>> Ownership::takeFractions() {
  std::vector<std::vector<double>> f;
  f.swap(fraction_);
  return f;
}

std::vector<Vec2> Ownership::cutCellNormals() const {
  // Rasterised again as the arrays were before the mode stopped keeping them (the lines have
  // not moved since the last rasterisation), so a checkpoint holds the same bytes.
  // A copy of the lines, whose per-cell scratch goes with it.
  const MarkerSet lines = markers_;
  std::vector<int> owner;
  std::vector<Vec2> normal;
  lines.rasterize(cells_.grid, owner, normal);
  return normal;
}

void Ownership::remeasure() {
  const GridSpec& g = cells_.grid;
  // The cut cells take their interface areas from the face apertures: the marker normals of
  // the whole-cell faces (interfaceNormals) are not needed.
  markers_.rasterizeFractions(g, owner_, fraction_, 0, g.nz);
}

void Ownership::update(Conserved& U, double dt, Budget& booked) {
  const GridSpec& g = cells_.grid;
  const long cells = g.cells();
  advanceLines(&U, 1, dt, 0, g.nz);
  markers_.rasterize(g, ownerNew_, normalNew_);
  detail::interfaceNormals(markers_, g, ownerNew_, normalNew_, normalLength_);

  // New states are computed from the old arrays first and applied afterwards, so the result
  // does not depend on the order.
  changes_.clear();
  std::vector<ObjectSum> sums;  // filled on first use only: most steps never need it
  long relabelled = 0;
  for (long c = 0; c < cells; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const int to = ownerNew_[cc];
    const int from = owner_[cc];
    if (to == from) continue;
    if (to >= 0 && from >= 0 &&
        objectMaterial_[static_cast<std::size_t>(to)] ==
            objectMaterial_[static_cast<std::size_t>(from)]) {
      ++relabelled;  // same medium: the state is valid for the new owner as it is
      continue;
    }
    changes_.push_back(to >= 0 ? fillFor(c, to, U, sums) : Change{c, 0.0, 0.0, 0.0, 0.0});
  }
  for (const Change& ch : changes_) {
    const auto cc = static_cast<std::size_t>(ch.cell);
    const double v = cells_(ch.cell);
    booked.mass += v * (ch.rho - U.rho[cc]);
    booked.momentumX += v * (ch.mx - U.mx[cc]);
    booked.momentumZ += v * (ch.mz - U.mz[cc]);
    booked.energy += v * (ch.E - U.E[cc]);
    U.rho[cc] = ch.rho;
    U.mx[cc] = ch.mx;
    U.mz[cc] = ch.mz;
    U.E[cc] = ch.E;
  }
  changeCount_ += static_cast<long>(changes_.size()) + relabelled;
  owner_.swap(ownerNew_);
  normal_.swap(normalNew_);
  renormalise(U, booked);
}

// A cell taken over by object `to` takes the mean conserved state of its neighbours that
// belonged to `to` before the step (donors whose flow enters it, else 3 x 3, else 5 x 5, else
// the object's mean, else the body's initial state).
Ownership::Change Ownership::fillFor(long c, int to, const Conserved& U,
                                     std::vector<ObjectSum>& sums) const {
  const int nx = cells_.grid.nx, nz = cells_.grid.nz;
  const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
  Change ch{c, 0.0, 0.0, 0.0, 0.0};
  // Donors first: the face neighbours of the new owner whose flow enters this cell, weighted by
  // their velocity towards it; the material that fills the cell comes from them (at an
  // expanding surface these are the surface cells, not the denser cells behind them that a
  // plain 3 x 3 mean would also take).
  double wsum = 0.0;
  const int di4[4] = {-1, 1, 0, 0}, dk4[4] = {0, 0, -1, 1};
  for (int q = 0; q < 4; ++q) {
    const int ii = i + di4[q], kk = k + dk4[q];
    if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
    const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
    if (owner_[d] != to || !(U.rho[d] > 0.0)) continue;
    const double toward = -(di4[q] * U.mx[d] + dk4[q] * U.mz[d]) / U.rho[d];
    if (!(toward > 0.0)) continue;
    ch.rho += toward * U.rho[d];
    ch.mx += toward * U.mx[d];
    ch.mz += toward * U.mz[d];
    ch.E += toward * U.E[d];
    wsum += toward;
  }
  if (wsum > 0.0) {
    ch.rho /= wsum;
    ch.mx /= wsum;
    ch.mz /= wsum;
    ch.E /= wsum;
    return ch;
  }
  long count = 0;
  for (int reach = 1; reach <= 2 && count == 0; ++reach)
    for (int dk = -reach; dk <= reach; ++dk)
      for (int di = -reach; di <= reach; ++di) {
        const int ii = i + di, kk = k + dk;
        if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
        const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
        if (owner_[d] != to || !(U.rho[d] > 0.0)) continue;
        ch.rho += U.rho[d];
        ch.mx += U.mx[d];
        ch.mz += U.mz[d];
        ch.E += U.E[d];
        ++count;
      }
  if (count == 0) {  // the object's mean: one pass over the grid per update, not per cell
    if (sums.empty()) sums = sumObjects(U);
    const ObjectSum& o = sums[static_cast<std::size_t>(to)];
    ch.rho = o.rho;
    ch.mx = o.mx;
    ch.mz = o.mz;
    ch.E = o.E;
    count = o.count;
  }
  if (count > 0) {
    ch.rho /= static_cast<double>(count);
    ch.mx /= static_cast<double>(count);
    ch.mz /= static_cast<double>(count);
    ch.E /= static_cast<double>(count);
  } else {
    const ObjectState& b = initial_[static_cast<std::size_t>(to)];
    ch.rho = b.rho;
    ch.mx = b.rho * b.vx;
    ch.mz = b.rho * b.vz;
    ch.E = b.rho * (b.e + 0.5 * (b.vx * b.vx + b.vz * b.vz));
  }
  return ch;
}

// Sums in cell order, as a scan of the whole grid for one object would add them.
std::vector<Ownership::ObjectSum> Ownership::sumObjects(const Conserved& U) const {
  std::vector<ObjectSum> sums(objectMaterial_.size());
  const long cells = cells_.grid.cells();
  for (long d = 0; d < cells; ++d) {
    const auto dd = static_cast<std::size_t>(d);
    const int o = owner_[dd];
    if (o < 0 || !(U.rho[dd] > 0.0)) continue;
    ObjectSum& s = sums[static_cast<std::size_t>(o)];
    s.rho += U.rho[dd];
    s.mx += U.mx[dd];
    s.mz += U.mz[dd];
    s.E += U.E[dd];
    ++s.count;
  }
  return sums;
}

// Each material's mass, and its band: half the mass of its cells with a face neighbour of
// another material or vacuum.
void Ownership::measure(const Conserved& U) {
  std::fill(mass_.begin(), mass_.end(), 0.0);
  std::fill(band_.begin(), band_.end(), 0.0);
  const int nx = cells_.grid.nx, nz = cells_.grid.nz;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const long c = static_cast<long>(k) * nx + i;
      const int m = cellMaterial(c);
      if (m < 0) continue;
      const double mc = U.rho[static_cast<std::size_t>(c)] * cells_(c);
      mass_[static_cast<std::size_t>(m)] += mc;
      const bool surface =
          (i > 0 && cellMaterial(c - 1) != m) || (i + 1 < nx && cellMaterial(c + 1) != m) ||
          (k > 0 && cellMaterial(c - nx) != m) || (k + 1 < nz && cellMaterial(c + nx) != m);
      if (surface) band_[static_cast<std::size_t>(m)] += 0.5 * mc;
    }
}

// Whole-cell ownership is not conservative: a cell taken over is filled from its new owner's
// neighbours, a vacated one is emptied, and the two-sided interface fluxes differ. For a body
// in uniform motion these balance to within the cells in flight at its surface; where a marker
// outruns its material (a dense striker) they do not, and the object keeps gaining mass. So
// after every owner update each material's mass is compared with the mass it must have (its
// initial mass plus what crossed the domain boundary). A difference within half a layer of the
// material's interface cells (sum of rho V / 2 over its cells with a face neighbour of another
// material or vacuum) is the position error of whole-cell interfaces and is left alone:
// correcting it would turn it into a density error, and a body in uniform motion would no
// longer keep its state exactly. What exceeds that band is drift: the material is scaled, as a
// whole, back to the band's edge, with one factor for density, momentum and energy, so
// velocities and specific energies are untouched. The scaled amounts are booked with the
// owner changes.
void Ownership::renormalise(Conserved& U, Budget& booked) {
  const std::size_t nm = target_.size();
  measure(U);
  bool any = false;
  for (std::size_t m = 0; m < nm; ++m) {
    const double mass = mass_[m], target = target_[m];
    const double drift = mass - target, band = band_[m];
    double f = 1.0;
    if (mass > 0.0 && target > 0.0 && std::abs(drift) > band)
      f = (target + std::copysign(band, drift)) / mass;
    scale_[m] = f;
    any = any || f != 1.0;
  }
  if (!any) return;
  Budget fix;
  const long cells = cells_.grid.cells();
  for (long c = 0; c < cells; ++c) {
    const int m = cellMaterial(c);
    if (m < 0) continue;
    const double f = scale_[static_cast<std::size_t>(m)];
    if (f == 1.0) continue;
    const auto cc = static_cast<std::size_t>(c);
    const double v = cells_(c);
    fix.mass += (f - 1.0) * U.rho[cc] * v;
    fix.momentumX += (f - 1.0) * U.mx[cc] * v;
    fix.momentumZ += (f - 1.0) * U.mz[cc] * v;
    fix.energy += (f - 1.0) * U.E[cc] * v;
    U.rho[cc] *= f;
    U.mx[cc] *= f;
    U.mz[cc] *= f;
    U.E[cc] *= f;
  }
  if (cells_.rz) fix.momentumX = 0.0;
  booked += fix;
}

}  // namespace hvi::tvd
