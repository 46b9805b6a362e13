//! @file Exact Riemann solver for a general EOS: pressure-function iteration on p*.
#include "hvi/verify/riemann.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <variant>

#include "eos_traits.hpp"
#include "hugoniot.hpp"
#include "isentrope.hpp"
#include "root_find.hpp"

namespace hvi::verify {
namespace {

void checkState(const eos::Eos& eos, const RiemannState& s, const char* side) {
  const bool gas = std::holds_alternative<eos::IdealGas>(eos);
  if (!(s.rho > 0.0) || !std::isfinite(s.rho) || !std::isfinite(s.u) || !std::isfinite(s.e) ||
      (gas && s.e < 0.0)) {
    throw InputError(fmt::format(
        "ExactRiemann: {} state (rho {}, u {}, e {}) needs finite values, rho > 0 (and e >= 0 "
        "for an ideal gas)",
        side, s.rho, s.u, s.e));
  }
}

// Velocity change across the wave of one side, in the sign convention of the pressure
// function: positive for a shock (p > pK), minus the velocity gained by the rarefaction
// otherwise. f_L + f_R + u_R - u_L is increasing in p and vanishes at p*.
struct Side {
  const eos::Eos& eos;
  const RiemannState& k;
  double pK;
  const detail::Isentrope& is;

  [[nodiscard]] double f(double p) const {
    if (p > pK) return detail::shockState(eos, k.rho, k.e, pK, is.start().c, p).du;
    return -is.atPressure(p).w;
  }
};

}  // namespace

ExactRiemann::ExactRiemann(const eos::Eos& leftEos, RiemannState left, const eos::Eos& rightEos,
                           RiemannState right)
    : eosL_(leftEos), eosR_(rightEos), L_(left), R_(right) {
  checkState(eosL_, L_, "left");
  checkState(eosR_, R_, "right");
  pL_ = eos::pressure(eosL_, L_.rho, L_.e);
  pR_ = eos::pressure(eosR_, R_.rho, R_.e);
  isL_ = std::make_shared<const detail::Isentrope>(eosL_, L_.rho, L_.e);
  isR_ = std::make_shared<const detail::Isentrope>(eosR_, R_.rho, R_.e);
  const Side sl{eosL_, L_, pL_, *isL_}, sr{eosR_, R_, pR_, *isR_};
  const double du = R_.u - L_.u;
  auto f = [&](double p) { return sl.f(p) + sr.f(p) + du; };

  // Lowest interface pressure: 0 unless both sides carry tension, then the lower end of the
  // two release isentropes (beyond it the solution would need a fracture model).
  const bool tension = detail::carriesTension(eosL_) && detail::carriesTension(eosR_);
  const double pLow = tension ? std::max(isL_->end().p, isR_->end().p) : 0.0;
  const double fLow = f(pLow);
  const double cL = isL_->start().c, cR = isR_->start().c;
  if (fLow > 0.0) {
    if (tension) {
      throw SimulationError(fmt::format(
          "ExactRiemann: separation speed {} exceeds what both materials' tension can hold", du));
    }
    // Vacuum: each side releases to its free surface at P = 0.
    vacuum_ = true;
    const detail::Isentrope::Point fl = isL_->atPressure(0.0), fr = isR_->atPressure(0.0);
    vacuumFrontL_ = L_.u + fl.w;
    vacuumFrontR_ = R_.u - fr.w;
    pStar_ = 0.0;
    uStar_ = 0.5 * (vacuumFrontL_ + vacuumFrontR_);
    rhoStarL_ = fl.rho;
    rhoStarR_ = fr.rho;
    eStarL_ = fl.e;
    eStarR_ = fr.e;
    waveL_ = {false, L_.u - cL, vacuumFrontL_ - fl.c};
    waveR_ = {false, R_.u + cR, vacuumFrontR_ + fr.c};
    return;
  }
  if (fLow == 0.0) {
    pStar_ = pLow;
  } else {
    // Bracket [pLow, pHi] and solve to a few ulp of p*; the absolute floor (1e-30 of the
    // problem's pressure scale) only matters when p* is within round-off of 0.
    const double pScale = std::max({std::abs(pL_), std::abs(pR_), L_.rho * cL * cL,
                                    R_.rho * cR * cR, L_.rho * du * du, R_.rho * du * du});
    double pHi = std::max({pL_, pR_, pLow + 1e-3 * pScale});
    double fHi = f(pHi);
    while (!(fHi >= 0.0)) {
      pHi = pLow + 4.0 * (pHi - pLow);
      if (!(pHi < 1e6 * pScale)) {
        throw SimulationError(fmt::format("ExactRiemann: no star pressure below {} found", pHi));
      }
      fHi = f(pHi);
    }
    pStar_ = detail::brent(f, pLow, pHi, fLow, fHi, 1e-30 * pScale, "star pressure", 2000);
  }
  const double fl = sl.f(pStar_), fr = sr.f(pStar_);
  uStar_ = 0.5 * (L_.u + R_.u) + 0.5 * (fr - fl);

  if (pStar_ > pL_) {
    const detail::ShockState s = detail::shockState(eosL_, L_.rho, L_.e, pL_, cL, pStar_);
    rhoStarL_ = s.rho;
    eStarL_ = s.e;
    const double speed = L_.u - s.massFlux / L_.rho;
    waveL_ = {true, speed, speed};
  } else {
    const detail::Isentrope::Point q = isL_->atPressure(pStar_);
    rhoStarL_ = q.rho;
    eStarL_ = q.e;
    waveL_ = {false, L_.u - cL, uStar_ - q.c};
  }
  if (pStar_ > pR_) {
    const detail::ShockState s = detail::shockState(eosR_, R_.rho, R_.e, pR_, cR, pStar_);
    rhoStarR_ = s.rho;
    eStarR_ = s.e;
    const double speed = R_.u + s.massFlux / R_.rho;
    waveR_ = {true, speed, speed};
  } else {
    const detail::Isentrope::Point q = isR_->atPressure(pStar_);
    rhoStarR_ = q.rho;
    eStarR_ = q.e;
    waveR_ = {false, R_.u + cR, uStar_ + q.c};
  }
}

RiemannSample ExactRiemann::sample(double xi) const {
  auto initial = [](const RiemannState& s, double p, int m) {
    return RiemannSample{s.rho, s.u, p, s.e, m};
  };
  // Inside a fan the state is found on the isentrope from w - c = q.
  auto fan = [](const detail::Isentrope& is, double q, double u0, double sign, int m) {
    const detail::Isentrope::Point x = is.atWaveCoordinate(q);
    return RiemannSample{x.rho, u0 + sign * x.w, std::max(x.p, 0.0), x.e, m};
  };
  if (vacuum_) {
    if (xi <= vacuumFrontL_) {
      if (xi <= waveL_.headSpeed) return initial(L_, pL_, -1);
      if (xi < waveL_.tailSpeed) return fan(*isL_, xi - L_.u, L_.u, 1.0, -1);
      return RiemannSample{rhoStarL_, vacuumFrontL_, 0.0, eStarL_, -1};
    }
    if (xi >= vacuumFrontR_) {
      if (xi >= waveR_.headSpeed) return initial(R_, pR_, +1);
      if (xi > waveR_.tailSpeed) return fan(*isR_, R_.u - xi, R_.u, -1.0, +1);
      return RiemannSample{rhoStarR_, vacuumFrontR_, 0.0, eStarR_, +1};
    }
    return RiemannSample{0.0, 0.0, 0.0, 0.0, 0};
  }
  if (xi <= uStar_) {
    if (xi <= waveL_.headSpeed) return initial(L_, pL_, -1);
    if (waveL_.shock || xi >= waveL_.tailSpeed) {
      return RiemannSample{rhoStarL_, uStar_, pStar_, eStarL_, -1};
    }
    return fan(*isL_, xi - L_.u, L_.u, 1.0, -1);
  }
  if (xi >= waveR_.headSpeed) return initial(R_, pR_, +1);
  if (waveR_.shock || xi <= waveR_.tailSpeed) {
    return RiemannSample{rhoStarR_, uStar_, pStar_, eStarR_, +1};
  }
  return fan(*isR_, R_.u - xi, R_.u, -1.0, +1);
}

}  // namespace hvi::verify
