//! @file Exact binary checkpoint of the TVD state (restart continues bit for bit).
#include <fmt/format.h>

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>

#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"
#include "strength_step.hpp"

namespace hvi::tvd {
namespace {

constexpr std::uint64_t kMagic = 0x31304456544956ULL;  // "VITVD01" little-endian tag
// 7 (written with the effect fracture only; every other scene writes exactly what it wrote
// before): as 6, and a fracture flag after the strength flag, and each solid phase's rho_p D after
// its four strength arrays; 6 (written with the effect strength or the cut-cell mode; a whole-cell
// scene without strength still writes 4, unchanged): as 5, and every phase's outflow mass after the
// orphan count (phaseOutflowMass); 5 (read too): a strength flag after the interface-mode flag and
// rho times the deviator and the plastic strain at the end; 4: an interface-mode flag after the
// markers flag, and the cut-cell phases after the marker lines; 3 (read too): the outflow budget
// after the ledger (Ledger::outflow); 2 (read too) had none, its boundary budget held the outflow
// sides and the walls together.
constexpr std::uint32_t kVersion = 7;
constexpr std::uint32_t kVersionWithoutFracture = 6;
constexpr std::uint32_t kVersionWithoutStrength = 4;

void putBudget(BinaryWriter& w, const Budget& b) {
  for (double v : {b.mass, b.momentumX, b.momentumZ, b.energy}) w.value(v);
}
Budget getBudget(BinaryReader& r) {
  Budget b;
  for (double* v : {&b.mass, &b.momentumX, &b.momentumZ, &b.energy}) *v = r.value<double>();
  return b;
}

void putConserved(BinaryWriter& w, const Conserved& U) {
  for (const auto* a : {&U.rho, &U.mx, &U.mz, &U.E}) w.array(*a);
}
//! `what`: the name of the state in the error messages ("" for the mixture, "phase " for a phase).
void getConserved(BinaryReader& r, Conserved& U, std::size_t n, const std::string& what) {
  r.array(U.rho, n, what + "density");
  r.array(U.mx, n, what + "momentum x");
  r.array(U.mz, n, what + "momentum z");
  r.array(U.E, n, what + "energy");
}

}  // namespace

void TvdSolver::writeCheckpoint(std::ostream& out) const {
  BinaryWriter w(out, "tvd checkpoint");
  w.value(kMagic);
  const bool flagged = strength_ || cut_;  // version 6: the strength flag is written
  const bool fracture = strength_ && strength_->fracture;
  w.value(fracture ? kVersion : (flagged ? kVersionWithoutFracture : kVersionWithoutStrength));
  w.value<std::int32_t>(grid_.nx);
  w.value<std::int32_t>(grid_.nz);
  w.value<std::int32_t>(geometry_ == Geometry::Axisymmetric ? 1 : 0);
  w.value<std::int32_t>(markersOn_ ? 1 : 0);
  w.value<std::int32_t>(cut_ ? 1 : 0);
  if (flagged) w.value<std::int32_t>(strength_ ? 1 : 0);
  if (fracture) w.value<std::int32_t>(1);
  w.value(time_);
  w.value(dt0_);
  w.value<std::int64_t>(step_);
  w.value<std::int64_t>(ownership_.changes());
  for (const Budget* b : {&ledger_.boundary, &ledger_.interfaces, &ledger_.ownerChanges,
                          &ledger_.floors, &ledger_.outflow})
    putBudget(w, *b);
  syncMixture();
  putConserved(w, U_);
  if (markersOn_) {
    w.array(ownership_.owner());
    if (cut_)
      w.array(ownership_.cutCellNormals());
    else
      w.array(ownership_.normal());
    w.array(ownership_.targets());
    ownership_.markers().write(out);  // its own record, checked by itself
  }
  if (cut_) {
    // The apertures follow from the marker lines; the fractions are kept, since the repair
    // after a marker step may leave an orphan's fraction off the geometry.
    w.value<std::int64_t>(orphans_);
    w.array(phaseOutflow_);
    for (int p = 0; p < phases_.count; ++p) {
      putConserved(w, phases_.q[static_cast<std::size_t>(p)]);
      w.array(phases_.alpha[static_cast<std::size_t>(p)]);
    }
  }
  if (strength_ && cut_) {  // each solid phase's rho_p q (its strength state)
    for (const auto& ph : strength_->phases)
      if (ph.solid)
        for (const auto& a : ph.rq)
          if (!a.empty()) w.array(a);  // the damage with fracture only
  } else if (strength_) {
    for (const auto& a : strength_->rq)
      if (!a.empty()) w.array(a);
  }
}

void TvdSolver::readCheckpoint(std::istream& in) {
  BinaryReader r(in, "tvd checkpoint");
  if (r.value<std::uint64_t>() != kMagic)
    throw InputError("tvd checkpoint: not a TVD solver state (wrong magic number)");
  const auto version = r.value<std::uint32_t>();
  if (version < 2 || version > kVersion)
    throw InputError(fmt::format("tvd checkpoint: format version {}, this build reads 2 to {}",
                                 version, kVersion));
  const auto nx = r.value<std::int32_t>(), nz = r.value<std::int32_t>();
  const auto rz = r.value<std::int32_t>(), markers = r.value<std::int32_t>();
  const auto cut = version >= 4 ? r.value<std::int32_t>() : 0;
  const auto withStrength = version >= 5 ? r.value<std::int32_t>() : 0;
  if ((withStrength == 1) != (strength_ != nullptr))
    throw InputError(
        fmt::format("tvd checkpoint: written {} the effect strength, this scene runs {} it",
                    withStrength == 1 ? "with" : "without", strength_ ? "with" : "without"));
  const auto withFracture = version >= 7 ? r.value<std::int32_t>() : 0;
  const bool fracture = strength_ && strength_->fracture;
  if ((withFracture == 1) != fracture)
    throw InputError(
        fmt::format("tvd checkpoint: written {} the effect fracture, this scene runs {} it",
                    withFracture == 1 ? "with" : "without", fracture ? "with" : "without"));
  if (nx != grid_.nx || nz != grid_.nz || (rz == 1) != (geometry_ == Geometry::Axisymmetric) ||
      (markers == 1) != markersOn_ || (cut == 1) != cut_)
    throw InputError(fmt::format(
        "tvd checkpoint: written for a {} x {} {} grid {} markers ({} interfaces); this scene "
        "gives {} x {} {} {} markers ({} interfaces)",
        nx, nz, rz == 1 ? "r-z" : "planar", markers == 1 ? "with" : "without",
        cut == 1 ? "conservative" : "whole-cell", grid_.nx, grid_.nz, toString(geometry_),
        markersOn_ ? "with" : "without", cut_ ? "conservative" : "whole-cell"));
  const double t = r.value<double>(), dt0 = r.value<double>();
  const auto step = r.value<std::int64_t>(), changes = r.value<std::int64_t>();
  Ledger ledger;
  for (Budget* b : {&ledger.boundary, &ledger.interfaces, &ledger.ownerChanges, &ledger.floors})
    *b = getBudget(r);
  if (version >= 3) {
    ledger.outflow = getBudget(r);
  } else {  // the walls' impulse cannot be told apart: all of it counts as outflow
    ledger.outflow = ledger.boundary.scaled(-1.0);
    ledger.boundary = Budget{};
  }
  const auto n = static_cast<std::size_t>(grid_.cells());
  Conserved U;
  getConserved(r, U, n, "");
  if (markersOn_) {
    std::vector<int> owner;
    std::vector<Vec2> normal;
    r.array(owner, n, "owner");
    r.array(normal, n, "normal");
    std::vector<double> target;
    r.array(target, materials_.size(), "material target mass");
    MarkerSet ms;
    ms.read(in);
    ownership_.restore(std::move(owner), std::move(normal), std::move(target), std::move(ms),
                       static_cast<long>(changes));
  }
  if (cut_) {
    const auto orphans = r.value<std::int64_t>();
    std::vector<double> phaseOut(materials_.size(), 0.0);  // before version 6: not kept
    if (version >= 6) r.array(phaseOut, materials_.size(), "phase outflow mass");
    Phases ph = phases_;
    for (int p = 0; p < ph.count; ++p) {
      getConserved(r, ph.q[static_cast<std::size_t>(p)], n, "phase ");
      r.array(ph.alpha[static_cast<std::size_t>(p)], n, "phase volume fraction");
    }
    ownership_.remeasure();  // the fractions and apertures of the restored lines
    std::vector<std::vector<double>> saved = ph.alpha;
    phases_ = std::move(ph);
    measurePhases();
    phases_.alpha = std::move(saved);  // as saved (orphans included)
    phases_.coverOccupied();
    volumeFresh_ = true;
    orphans_ = static_cast<long>(orphans);
    phaseOutflow_ = std::move(phaseOut);
  }
  if (strength_) {
    const char* names[detail::kStrengthFields] = {"rho s_xx", "rho s_zz", "rho s_xz",
                                                  "rho plastic strain", "rho damage"};
    if (cut_) {
      // In place: Phases::carried points at these arrays.
      for (auto& ph : strength_->phases)
        if (ph.solid)
          for (int k = 0; k < detail::kStrengthFields; ++k) {
            if (ph.rq[static_cast<std::size_t>(k)].empty()) continue;  // no fracture
            std::vector<double> a;
            r.array(a, n, std::string("phase ") + names[k]);
            ph.rq[static_cast<std::size_t>(k)] = std::move(a);
          }
    } else {
      std::array<std::vector<double>, detail::kStrengthFields> rq;
      for (int k = 0; k < detail::kStrengthFields; ++k)
        if (!strength_->rq[static_cast<std::size_t>(k)].empty())  // the damage: with fracture
          r.array(rq[static_cast<std::size_t>(k)], n, names[k]);
      strength_->rq = std::move(rq);
    }
  }
  U_ = std::move(U);
  mixtureStale_ = false;
  time_ = t;
  dt0_ = dt0;
  step_ = static_cast<long>(step);
  ledger_ = ledger;
}

}  // namespace hvi::tvd
