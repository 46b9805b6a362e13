//! @file Marker step: move the marker lines, rebuild the configuration array, re-initialise
//! the cells that change owner.
#include <algorithm>
#include <cmath>

#include "hvi/tvd/tvd.hpp"
#include "interface_normals.hpp"

namespace hvi::tvd {
namespace {

// Vacuum cells near material get the mean velocity of their already-known 8 neighbours, in
// `layers` rings: the bilinear interpolation that moves a marker on a free surface then sees
// the material's velocity on both sides instead of the zero velocity of empty cells.
void extendIntoVacuum(const GridSpec& g, std::vector<double>& vx, std::vector<double>& vz,
                      std::vector<signed char>& known, std::vector<long>& fresh, int layers) {
  const int nx = g.nx, nz = g.nz;
  for (int layer = 0; layer < layers; ++layer) {
    fresh.clear();
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        const long c = static_cast<long>(k) * nx + i;
        if (known[static_cast<std::size_t>(c)]) continue;
        double sx = 0.0, sz = 0.0;
        int count = 0;
        for (int dk = -1; dk <= 1; ++dk)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, kk = k + dk;
            if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
            const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
            if (known[d] != 1) continue;
            sx += vx[d];
            sz += vz[d];
            ++count;
          }
        if (count == 0) continue;
        vx[static_cast<std::size_t>(c)] = sx / count;
        vz[static_cast<std::size_t>(c)] = sz / count;
        fresh.push_back(c);
      }
    for (long c : fresh) known[static_cast<std::size_t>(c)] = 1;  // usable in the next ring
  }
}

}  // namespace

void TvdSolver::updateMarkers(double dt) {
  const long cells = grid_.cells();
  const int nx = grid_.nx, nz = grid_.nz;
  // Time-centred velocity (mean of the start and end of the step) for the marker path.
  known_.assign(static_cast<std::size_t>(cells), 0);
  std::vector<signed char>& known = known_;
#pragma omp parallel for schedule(static) \
    num_threads(threads_) if (grid_.cells() >= kParallelCells)
  for (long c = 0; c < cells; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (owner_[cc] < 0 || !(U_.rho[cc] > 0.0)) {
      vxMid_[cc] = vzMid_[cc] = 0.0;
      continue;
    }
    vxMid_[cc] = 0.5 * (vxOld_[cc] + U_.mx[cc] / U_.rho[cc]);
    vzMid_[cc] = 0.5 * (vzOld_[cc] + U_.mz[cc] / U_.rho[cc]);
    known[cc] = 1;
  }
  extendIntoVacuum(grid_, vxMid_, vzMid_, known, fresh_, 2);
  markerSet_.advect(grid_, vxMid_.data(), vzMid_.data(), dt);
  markerSet_.redistribute(grid_);
  markerSet_.rasterize(grid_, ownerNew_, normalNew_);
  detail::interfaceNormals(markerSet_, grid_, ownerNew_, normalNew_, normalLength_);

  // A cell that changes owner takes the mean conserved state of its neighbours that belonged to
  // the new owner before the step (3 x 3, else 5 x 5, else the object's mean, else the body's
  // initial state); a cell that becomes vacuum is emptied. New states are computed from the
  // old arrays first and applied afterwards, so the result does not depend on the order.
  std::vector<Change>& changes = changes_;
  changes.clear();
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
    Change ch{c, 0.0, 0.0, 0.0, 0.0};
    if (to >= 0) {
      const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
      int count = 0;
      // Donors first: the face neighbours of the new owner whose flow enters this cell,
      // weighted by their velocity towards it; the material that fills the cell comes from
      // them (at an expanding surface these are the surface cells, not the denser cells
      // behind them that a plain 3 x 3 mean would also take).
      double wsum = 0.0;
      const int di4[4] = {-1, 1, 0, 0}, dk4[4] = {0, 0, -1, 1};
      for (int q = 0; q < 4; ++q) {
        const int ii = i + di4[q], kk = k + dk4[q];
        if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
        const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
        if (owner_[d] != to || !(U_.rho[d] > 0.0)) continue;
        const double toward = -(di4[q] * U_.mx[d] + dk4[q] * U_.mz[d]) / U_.rho[d];
        if (!(toward > 0.0)) continue;
        ch.rho += toward * U_.rho[d];
        ch.mx += toward * U_.mx[d];
        ch.mz += toward * U_.mz[d];
        ch.E += toward * U_.E[d];
        wsum += toward;
      }
      if (wsum > 0.0) {
        ch.rho /= wsum;
        ch.mx /= wsum;
        ch.mz /= wsum;
        ch.E /= wsum;
        changes.push_back(ch);
        continue;
      }
      for (int reach = 1; reach <= 2 && count == 0; ++reach)
        for (int dk = -reach; dk <= reach; ++dk)
          for (int di = -reach; di <= reach; ++di) {
            const int ii = i + di, kk = k + dk;
            if (ii < 0 || ii >= nx || kk < 0 || kk >= nz) continue;
            const auto d = static_cast<std::size_t>(static_cast<long>(kk) * nx + ii);
            if (owner_[d] != to || !(U_.rho[d] > 0.0)) continue;
            ch.rho += U_.rho[d];
            ch.mx += U_.mx[d];
            ch.mz += U_.mz[d];
            ch.E += U_.E[d];
            ++count;
          }
      if (count == 0) {
        for (long d = 0; d < cells; ++d) {
          const auto dd = static_cast<std::size_t>(d);
          if (owner_[dd] != to || !(U_.rho[dd] > 0.0)) continue;
          ch.rho += U_.rho[dd];
          ch.mx += U_.mx[dd];
          ch.mz += U_.mz[dd];
          ch.E += U_.E[dd];
          ++count;
        }
      }
      if (count > 0) {
        ch.rho /= count;
        ch.mx /= count;
        ch.mz /= count;
        ch.E /= count;
      } else {
        const BodyState& b = bodyStates_[static_cast<std::size_t>(to)];
        ch.rho = b.rho;
        ch.mx = b.rho * b.vx;
        ch.mz = b.rho * b.vz;
        ch.E = b.rho * (b.e + 0.5 * (b.vx * b.vx + b.vz * b.vz));
      }
    }
    changes.push_back(ch);
  }
  for (const Change& ch : changes) {
    const auto cc = static_cast<std::size_t>(ch.cell);
    const double v = cellVolume(ch.cell);
    ledger_.ownerChanges.mass += v * (ch.rho - U_.rho[cc]);
    ledger_.ownerChanges.momentumX += v * (ch.mx - U_.mx[cc]);
    ledger_.ownerChanges.momentumZ += v * (ch.mz - U_.mz[cc]);
    ledger_.ownerChanges.energy += v * (ch.E - U_.E[cc]);
    U_.rho[cc] = ch.rho;
    U_.mx[cc] = ch.mx;
    U_.mz[cc] = ch.mz;
    U_.E[cc] = ch.E;
  }
  ownerChangeCount_ += static_cast<long>(changes.size()) + relabelled;
  owner_.swap(ownerNew_);
  normal_.swap(normalNew_);
  renormaliseMaterials();
}

// Each material's mass, and its band: half the mass of its cells with a face neighbour of
// another material or vacuum.
void TvdSolver::measureMaterials() {
  std::fill(materialMass_.begin(), materialMass_.end(), 0.0);
  std::fill(materialBand_.begin(), materialBand_.end(), 0.0);
  const int nx = grid_.nx, nz = grid_.nz;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i) {
      const long c = static_cast<long>(k) * nx + i;
      const int m = cellMaterial(c);
      if (m < 0) continue;
      const double mc = U_.rho[static_cast<std::size_t>(c)] * cellVolume(c);
      materialMass_[static_cast<std::size_t>(m)] += mc;
      const bool surface = (i > 0 && cellMaterial(c - 1) != m) ||
                           (i + 1 < nx && cellMaterial(c + 1) != m) ||
                           (k > 0 && cellMaterial(c - nx) != m) ||
                           (k + 1 < nz && cellMaterial(c + nx) != m);
      if (surface) materialBand_[static_cast<std::size_t>(m)] += 0.5 * mc;
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
// velocities and specific energies are untouched. The scaled amounts are booked under owner
// changes.
void TvdSolver::renormaliseMaterials() {
  const std::size_t nm = materialTarget_.size();
  measureMaterials();
  bool any = false;
  for (std::size_t m = 0; m < nm; ++m) {
    const double mass = materialMass_[m], target = materialTarget_[m];
    const double drift = mass - target, band = materialBand_[m];
    double f = 1.0;
    if (mass > 0.0 && target > 0.0 && std::abs(drift) > band)
      f = (target + std::copysign(band, drift)) / mass;
    materialMass_[m] = f;  // reused: scale factor per material
    any = any || f != 1.0;
  }
  if (!any) return;
  Budget fix;
  const long cells = grid_.cells();
  for (long c = 0; c < cells; ++c) {
    const int m = cellMaterial(c);
    if (m < 0) continue;
    const double f = materialMass_[static_cast<std::size_t>(m)];
    if (f == 1.0) continue;
    const auto cc = static_cast<std::size_t>(c);
    const double v = cellVolume(c);
    fix.mass += (f - 1.0) * U_.rho[cc] * v;
    fix.momentumX += (f - 1.0) * U_.mx[cc] * v;
    fix.momentumZ += (f - 1.0) * U_.mz[cc] * v;
    fix.energy += (f - 1.0) * U_.E[cc] * v;
    U_.rho[cc] *= f;
    U_.mx[cc] *= f;
    U_.mz[cc] *= f;
    U_.E[cc] *= f;
  }
  if (geometry_ == Geometry::Axisymmetric) fix.momentumX = 0.0;
  ledger_.ownerChanges += fix;
}

}  // namespace hvi::tvd
