//! @file Tillotson EOS: pressure and analytic derivatives in each region.
#include <algorithm>
#include <cmath>

#include "hvi/eos/tillotson.hpp"

namespace hvi::eos {
namespace {

struct PD {  // pressure and its partial derivatives
  double p, pRho, pE;
};

// Compressed / cold branch: Pc = (a + b/w) rho e + A mu + B mu^2, w = 1 + e/(e0 delta^2).
// The thermal term is fitted for e >= 0 (the reference state rho0, e = 0 is the cold, unstressed
// solid). Below it the formula has a pole at w = 0, only e0 delta^2 below zero (-0.0038 cm^2/us^2
// at rho = 0.77), which SPH's symmetric energy equation does reach (docs/eos.md). For e < 0 the
// thermal coefficient is frozen at its e = 0 value, a + b: P = (a + b) rho e + A mu + B mu^2, the
// tangent plane of the formula at e = 0. P and both derivatives are continuous there, so the
// round-off values of e around 0 in cold material see no kink, and there is no pole.
PD compressed(const Tillotson& t, double rho, double e) {
  const double delta = rho / t.rho0, mu = delta - 1.0;
  PD r;
  if (e < 0.0) {
    const double g0 = t.a + t.b;
    r.p = g0 * rho * e + t.A * mu + t.B * mu * mu;
    r.pE = g0 * rho;
    r.pRho = g0 * e + (t.A + 2.0 * t.B * mu) / t.rho0;
    return r;
  }
  const double w = 1.0 + e / (t.e0 * delta * delta);
  const double dwdE = 1.0 / (t.e0 * delta * delta);
  const double dwdRho = -2.0 * e / (t.e0 * delta * delta * rho);
  const double g = t.a + t.b / w;  // Gruneisen-like coefficient
  r.p = g * rho * e + t.A * mu + t.B * mu * mu;
  r.pE = g * rho - t.b * rho * e * dwdE / (w * w);
  r.pRho = g * e - t.b * rho * e * dwdRho / (w * w) + (t.A + 2.0 * t.B * mu) / t.rho0;
  return r;
}

// Expanded hot branch: PH = a rho e + [b rho e / w + A mu exp(-beta z)] exp(-alpha z^2),
// z = rho0/rho - 1.
PD hot(const Tillotson& t, double rho, double e) {
  const double delta = rho / t.rho0, mu = delta - 1.0;
  const double w = 1.0 + e / (t.e0 * delta * delta);
  const double dwdE = 1.0 / (t.e0 * delta * delta);
  const double dwdRho = -2.0 * e / (t.e0 * delta * delta * rho);
  const double z = 1.0 / delta - 1.0;
  const double dzdRho = -t.rho0 / (rho * rho);
  const double e1 = std::exp(-t.beta * z);
  const double e2 = std::exp(-t.alpha * z * z);
  const double q = t.b * rho * e / w + t.A * mu * e1;
  const double dqdRho = t.b * e / w - t.b * rho * e * dwdRho / (w * w) + t.A * e1 / t.rho0 -
                        t.beta * t.A * mu * e1 * dzdRho;
  const double dqdE = t.b * rho / w - t.b * rho * e * dwdE / (w * w);
  const double de2dRho = -2.0 * t.alpha * z * dzdRho * e2;
  PD r;
  r.p = t.a * rho * e + q * e2;
  r.pE = t.a * rho + dqdE * e2;
  r.pRho = t.a * e + dqdRho * e2 + q * de2dRho;
  return r;
}

}  // namespace

Tillotson::Region Tillotson::region(double rho, double e) const {
  if (rho >= rho0) return Region::Compressed;
  if (e <= e1) return Region::ColdExpanded;
  if (e >= e2) return Region::HotExpanded;
  return Region::Blend;
}

double Tillotson::soundSpeedFloor() const {
  return soundSpeedFloorFraction * std::sqrt(A / rho0);
}

EosState Tillotson::formulaState(double rho, double e) const {
  PD r;
  switch (region(rho, e)) {
    case Region::Compressed:
    case Region::ColdExpanded:
      r = compressed(*this, rho, e);
      break;
    case Region::HotExpanded:
      r = hot(*this, rho, e);
      break;
    case Region::Blend: {
      const PD c = compressed(*this, rho, e), h = hot(*this, rho, e);
      const double span = e2 - e1;
      r.p = (c.p * (e2 - e) + h.p * (e - e1)) / span;
      r.pRho = (c.pRho * (e2 - e) + h.pRho * (e - e1)) / span;
      r.pE = (c.pE * (e2 - e) - c.p + h.pE * (e - e1) + h.p) / span;
      break;
    }
  }
  EosState s;
  s.pressure = r.p;
  s.dPdRho = r.pRho;
  s.dPdE = r.pE;
  const double c2 = r.pRho + r.p / (rho * rho) * r.pE;
  s.soundSpeed = std::sqrt(std::max(c2, 0.0));
  return s;
}

EosState Tillotson::state(double rho, double e) const {
  EosState s = formulaState(rho, e);
  if (tensionCutoff && s.pressure < 0.0) {
    // Spalled: the material cannot carry tension, so it responds to nothing until recompressed.
    s.pressure = 0.0;
    s.dPdRho = 0.0;
    s.dPdE = 0.0;
    s.soundSpeed = 0.0;
  }
  s.soundSpeed = std::max(s.soundSpeed, soundSpeedFloor());
  return s;
}

}  // namespace hvi::eos
