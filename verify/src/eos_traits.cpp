//! @file EOS properties the exact solutions need (tension capacity, uncut pressure).
#include "eos_traits.hpp"

#include <variant>

namespace hvi::verify::detail {

bool carriesTension(const eos::Eos& eos) {
  struct V {
    bool operator()(const eos::Tillotson& t) const { return !t.tensionCutoff; }
    bool operator()(const eos::IdealGas&) const { return false; }
    bool operator()(const eos::MieGruneisen& m) const { return !m.tensionCutoff; }
  };
  return std::visit(V{}, eos);
}

double signedPressure(const eos::Eos& eos, double rho, double e) {
  return uncutState(eos, rho, e).pressure;
}

eos::EosState uncutState(const eos::Eos& eos, double rho, double e) {
  struct V {
    double rho, e;
    eos::EosState operator()(const eos::Tillotson& t) const {
      return t.formulaState(rho, e);
    }
    eos::EosState operator()(const eos::IdealGas& g) const { return g.state(rho, e); }
    eos::EosState operator()(const eos::MieGruneisen& m) const {
      eos::MieGruneisen uncut = m;
      uncut.tensionCutoff = false;
      uncut.soundSpeedFloorFraction = 0.0;
      return uncut.state(rho, e);
    }
  };
  return std::visit(V{rho, e}, eos);
}

}  // namespace hvi::verify::detail
