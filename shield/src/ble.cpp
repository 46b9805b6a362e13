//! @file The Christiansen (1993) Whipple-shield BLE (docs/shield.md gives the source).
#include "hvi/shield/ble.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hvi::shield {
namespace {

constexpr double kMaxAngleDegrees = 65.0;

double cosine(const WhippleBle& s) {
  return std::cos(std::min(s.angleDegrees, kMaxAngleDegrees) * std::numbers::pi / 180.0);
}

void check(const WhippleBle& s, double v) {
  if (!(s.projectileDensity > 0 && s.bumperDensity > 0 && s.bumperThickness >= 0 &&
        s.rearWallThickness > 0 && s.rearWallYieldKsi > 0 && s.standoff > 0 && v > 0 &&
        s.angleDegrees >= 0 && s.angleDegrees < 90))
    throw std::invalid_argument(
        "Whipple BLE: densities, rear-wall thickness, yield, standoff and speed must be > 0, "
        "bumper thickness >= 0 and the angle in [0, 90) degrees");
}

// Ballistic regime at speed v (km/s): the projectile stays intact and the bumper and the rear
// wall resist it together.
double ballistic(const WhippleBle& s, double v, double c) {
  const double resist =
      s.rearWallThickness * std::sqrt(s.rearWallYieldKsi / 40.0) + s.bumperThickness;
  const double drive =
      0.6 * std::pow(c, 5.0 / 3.0) * std::sqrt(s.projectileDensity) * std::pow(v, 2.0 / 3.0);
  return std::pow(resist / drive, 18.0 / 19.0);
}

// Hypervelocity regime: the rear wall sees the impulse of a molten / vaporised debris cloud.
double hypervelocity(const WhippleBle& s, double v, double c) {
  return 3.918 * std::pow(s.rearWallThickness, 2.0 / 3.0) *
         std::pow(s.projectileDensity, -1.0 / 3.0) * std::pow(s.bumperDensity, -1.0 / 9.0) *
         std::pow(v * c, -2.0 / 3.0) * std::cbrt(s.standoff) * std::cbrt(s.rearWallYieldKsi / 70.0);
}

}  // namespace

std::string_view toString(BleRegime r) {
  switch (r) {
    case BleRegime::Ballistic:
      return "ballistic";
    case BleRegime::Shatter:
      return "shatter";
    case BleRegime::Hypervelocity:
      return "hypervelocity";
  }
  return "?";
}

BleRegime bleRegime(const WhippleBle& s, double v) {
  check(s, v);
  const double vn = v * cosine(s);
  if (vn <= kBallisticLimitSpeed) return BleRegime::Ballistic;
  if (vn >= kHypervelocitySpeed) return BleRegime::Hypervelocity;
  return BleRegime::Shatter;
}

double criticalDiameter(const WhippleBle& s, double v) {
  check(s, v);
  const double c = cosine(s);
  const double vLow = kBallisticLimitSpeed / c, vHigh = kHypervelocitySpeed / c;
  if (v <= vLow) return ballistic(s, v, c);
  if (v >= vHigh) return hypervelocity(s, v, c);
  const double w = (v - vLow) / (vHigh - vLow);
  return (1.0 - w) * ballistic(s, vLow, c) + w * hypervelocity(s, vHigh, c);
}

bool bumperAdequate(const WhippleBle& s, double d) {
  const double need = s.standoff / d >= 30.0 ? 0.20 : 0.25;
  return s.bumperThickness / d >= need;
}

}  // namespace hvi::shield
