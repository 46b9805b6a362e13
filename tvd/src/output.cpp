//! @file Snapshot fields and integral totals of the TVD state.
#include <cmath>

#include "eos_line.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/common/units.hpp"
#include "hvi/tvd/tvd.hpp"
#include "strength_step.hpp"

namespace hvi::tvd {

Snapshot TvdSolver::snapshot() const {
  syncMixture();
  const long cells = grid_.cells();
  const auto n = static_cast<std::size_t>(cells);
  Snapshot s = makeSnapshot("tvd", Snapshot::Kind::Grid, geometry_, time_, step_);
  s.grid = grid_;
  Field rho = makeField(Quantity::Density, geometry_, n);
  Field p = makeField(Quantity::Pressure, geometry_, n);
  Field v = makeField(Quantity::Velocity, geometry_, n);
  Field e = makeField(Quantity::SpecificEnergy, geometry_, n);
  Field mat = makeField(Quantity::Material, geometry_, n, -1.0);
  Field obj = makeField(Quantity::Object, geometry_, n, -1.0);

  // Effect fracture: per material (phase) its spall strength, < 0 for a fluid.
  const double* fractureSpall =
      strength_ && strength_->fracture ? strength_->spall.data() : nullptr;
  for (int id = 0; id < static_cast<int>(materials_.size()); ++id) {
    if (!markersOn_ && id != singleMaterial_) continue;
    std::visit(
        [&](const auto& eos) {
#pragma omp parallel for schedule(static) num_threads(threads_) if (grid_.cells() >= kParallelCells)
          for (long c = 0; c < cells; ++c) {
            const auto cc = static_cast<std::size_t>(c);
            int object = 0;
            if (markersOn_) {
              object = ownership_.owner()[cc];
              if (object < 0 || objectMaterial_[static_cast<std::size_t>(object)] != id) continue;
            } else if (!(U_.rho[cc] >= rhoCut_[static_cast<std::size_t>(id)])) {
              object = -1;  // below the vacuum density: reported as vacuum
            }
            // Cut cells: the owning material's own state on its part of the cell.
            const double a = cut_ ? phases_.alpha[static_cast<std::size_t>(id)][cc] : 1.0;
            if (!(a >= kPhaseAbsent)) continue;
            const Conserved& q = cut_ ? phases_.q[static_cast<std::size_t>(id)] : U_;
            const double r = q.rho[cc] / a;
            if (!(r > 0.0)) continue;
            CellState st = detail::cellState(eos, r, q.mx[cc] / a, q.mz[cc] / a, q.E[cc] / a);
            // Effect fracture: the pressure the sweeps see (tension limited, scaled by 1 - D).
            if (fractureSpall != nullptr && fractureSpall[id] >= 0.0) {
              const auto& rd =
                  cut_ ? strength_->phases[static_cast<std::size_t>(id)].rq : strength_->rq;
              detail::limitTension(st, rd[detail::kDamage][cc] / q.rho[cc], fractureSpall[id],
                                   r >= strength_->rhoIntact[static_cast<std::size_t>(id)]);
            }
            rho.data[cc] = r;
            p.data[cc] = st.p;
            v.data[2 * cc] = st.u;
            v.data[2 * cc + 1] = st.w;
            e.data[cc] = st.e;
            if (object >= 0) {
              mat.data[cc] = sceneMaterialOf_[static_cast<std::size_t>(id)];
              obj.data[cc] = object;
            }
          }
        },
        materials_[static_cast<std::size_t>(id)].eos);
  }
  Field frac, phase;
  if (phaseOn_) {
    // As in the SPH snapshots (eos::phaseState); vacuum cells stay 0.
    frac = makeField(Quantity::VapourFraction, geometry_, n);
    phase = makeField(Quantity::Phase, geometry_, n);
    for (std::size_t c = 0; c < n; ++c) {
      if (mat.data[c] < 0.0) continue;
      const eos::PhaseState st =
          eos::phaseState(sceneMaterials_[static_cast<std::size_t>(mat.data[c])].eos, e.data[c]);
      frac.data[c] = st.vapourFraction;
      phase.data[c] = static_cast<double>(static_cast<int>(st.phase));
    }
  }
  // Moved in one by one: an initializer list would be copied from, and for a moment hold every
  // field twice (56 B per cell more at the run's memory peak, issue 17).
  s.fields.reserve(phaseOn_ ? 8 : 6);
  for (Field* f : {&rho, &p, &v, &e, &mat, &obj}) s.fields.push_back(std::move(*f));
  if (phaseOn_) {
    s.fields.push_back(std::move(frac));
    s.fields.push_back(std::move(phase));
  }
  if (strength_) {
    // docs/strength.md, "TVD": the specific deviator (stt = -(sxx + szz): the out-of-plane
    // component in plane strain, the hoop one in r-z), the equivalent plastic strain and the
    // temperature model's T; 0 in vacuum cells and for a fluid.
    const detail::StrengthState& st = *strength_;
    std::vector<double> sxx(n, 0.0), szz(n, 0.0), sxz(n, 0.0), stt(n, 0.0), eps(n, 0.0),
        temp(n, 0.0), dmg;
    if (st.fracture) dmg.assign(n, 0.0);
    const double rc = rhoCut_[static_cast<std::size_t>(singleMaterial_)];
    // Conservative interfaces: the owning phase's own values (as the other fields report its own
    // state on its part of the cell).
    for (std::size_t c = 0; cut_ && c < n; ++c) {
      const int o = ownership_.owner()[c];
      if (o < 0) continue;
      const auto& ph = st.phases[static_cast<std::size_t>(o)];
      const Conserved& q = phases_.q[static_cast<std::size_t>(o)];
      const double m = q.rho[c], a = phases_.alpha[static_cast<std::size_t>(o)][c];
      if (!ph.solid || !(m > 0.0) || !(a >= kPhaseAbsent)) continue;
      sxx[c] = ph.rq[detail::kSxx][c] / m;
      szz[c] = ph.rq[detail::kSzz][c] / m;
      sxz[c] = ph.rq[detail::kSxz][c] / m;
      stt[c] = -(sxx[c] + szz[c]);
      eps[c] = ph.rq[detail::kEps][c] / m;
      if (st.fracture) dmg[c] = ph.rq[detail::kDamage][c] / m;
      const double es = (q.E[c] - 0.5 * (q.mx[c] * q.mx[c] + q.mz[c] * q.mz[c]) / m) / m;
      temp[c] = ph.material.thermal.temperature(m / a / ph.rho0, es);
    }
    for (std::size_t c = 0; !cut_ && c < n; ++c) {
      const double r = U_.rho[c];
      if (!(r >= rc)) continue;
      sxx[c] = st.rq[detail::kSxx][c] / r;
      szz[c] = st.rq[detail::kSzz][c] / r;
      sxz[c] = st.rq[detail::kSxz][c] / r;
      stt[c] = -(sxx[c] + szz[c]);
      eps[c] = st.rq[detail::kEps][c] / r;
      if (st.fracture) dmg[c] = st.rq[detail::kDamage][c] / r;
      const double es = (U_.E[c] - 0.5 * (U_.mx[c] * U_.mx[c] + U_.mz[c] * U_.mz[c]) / r) / r;
      if (st.solid) temp[c] = st.material.thermal.temperature(r / st.rho0, es);
    }
    const auto add = [&](const char* name, const char* unit, std::vector<double>& v) {
      s.fields.push_back({name, unit, 1, std::move(v)});
    };
    add("stress_deviator_xx", units::pressureName, sxx);
    add("stress_deviator_zz", units::pressureName, szz);
    add("stress_deviator_xz", units::pressureName, sxz);
    add("stress_deviator_tt", units::pressureName, stt);
    add("plastic_strain", "1", eps);
    add("temperature", "K", temp);
    if (st.fracture) add("damage", "1", dmg);
  }
  for (const auto& m : sceneMaterials_) s.materialNames.push_back(m.name);
  if (markersOn_) {
    s.objectNames = bodyNames_;
    s.markers = ownership_.markers().polylines();
  } else {
    // Without marker lines the bodies of the one material are not told apart.
    std::string all;
    for (const auto& b : bodyNames_) all += (all.empty() ? "" : "+") + b;
    s.objectNames = {all};
  }
  return s;
}

Totals TvdSolver::totals() const {
  const long cells = grid_.cells();
  double mass = 0.0, px = 0.0, pz = 0.0, kin = 0.0, eint = 0.0;
  // A mixture not formed since the step (cut cells, syncMixture): summed from the phases here,
  // in phase order, as Phases::mixture sums it (the same values; zero outside its rows).
  const int P = mixtureStale_ ? phases_.count : 0;
  const Conserved* parts = phases_.q.data();
#pragma omp parallel for schedule(static) reduction(+ : mass, px, pz, kin, eint) \
    num_threads(threads_) if (grid_.cells() >= kParallelCells)
  for (long c = 0; c < cells; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    const double r = P > 0 ? mixtureAt(parts, P, &Conserved::rho, cc) : U_.rho[cc];
    const double mx = P > 0 ? mixtureAt(parts, P, &Conserved::mx, cc) : U_.mx[cc];
    const double mz = P > 0 ? mixtureAt(parts, P, &Conserved::mz, cc) : U_.mz[cc];
    const double E = P > 0 ? mixtureAt(parts, P, &Conserved::E, cc) : U_.E[cc];
    if (r < 0.0) mass += cellVolume(c) * r;  // vacuum of negative mass (cut cells), at rest
    if (!(r > 0.0)) continue;
    const double vol = cellVolume(c);
    const double k = 0.5 * (mx * mx + mz * mz) / r;
    mass += vol * r;
    px += vol * mx;
    pz += vol * mz;
    kin += vol * k;
    eint += vol * (E - k);
  }
  const Totals out = outflow();
  Totals t;
  t.mass = mass + out.mass;
  t.momentumX = geometry_ == Geometry::Axisymmetric ? 0.0 : px + out.momentumX;
  t.momentumZ = pz + out.momentumZ;
  t.kinetic = kin;
  t.internal = eint + out.internal;
  return t;
}

// The fluxes carry total energy, not kinetic and internal apart: what left is booked as
// internal energy (docs/output.md, "Conservation").
Totals TvdSolver::outflow() const {
  Totals t;
  t.mass = ledger_.outflow.mass;
  t.momentumX = geometry_ == Geometry::Axisymmetric ? 0.0 : ledger_.outflow.momentumX;
  t.momentumZ = ledger_.outflow.momentumZ;
  t.internal = ledger_.outflow.energy;
  return t;
}

}  // namespace hvi::tvd
