//! @file Unit tables and the "<number> <unit>" parser for scene-file quantities.
#include "hvi/cases/quantity.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <string>

#include "hvi/common/units.hpp"

namespace hvi::cases {
namespace {

// Factors to internal cm-g-us (common/units.hpp); the internal unit first in each list.
constexpr std::array<UnitSpec, 4> kLength{
    {{"cm", 1.0}, {"mm", units::mm}, {"m", 100.0}, {"um", 1.0e-4}}};
constexpr std::array<UnitSpec, 4> kTime{
    {{"us", units::us}, {"ns", 1.0e-3}, {"ms", 1.0e3}, {"s", 1.0e6}}};
constexpr std::array<UnitSpec, 4> kVelocity{
    {{"cm/us", 1.0}, {"km/s", units::kmPerS}, {"mm/us", units::kmPerS}, {"m/s", units::mPerS}}};
constexpr std::array<UnitSpec, 2> kDensity{{{"g/cm^3", 1.0}, {"kg/m^3", units::kgPerM3}}};
constexpr std::array<UnitSpec, 6> kPressure{{{"Mbar", units::Mbar},
                                             {"GPa", units::GPa},
                                             {"kbar", 1.0e-3},
                                             {"MPa", 1.0e-5},
                                             {"bar", 1.0e-6},
                                             {"Pa", 1.0e-11}}};
constexpr std::array<UnitSpec, 4> kEnergy{
    {{"cm^2/us^2", 1.0}, {"MJ/kg", units::MJPerKg}, {"kJ/kg", 1.0e-5}, {"J/kg", 1.0e-8}}};
constexpr std::array<UnitSpec, 3> kWall{{{"s", 1.0}, {"min", 60.0}, {"h", 3600.0}}};
constexpr std::array<UnitSpec, 2> kSpecificHeat{{{"cm^2/us^2/K", 1.0}, {"J/kg/K", 1.0e-8}}};
constexpr std::array<UnitSpec, 2> kStrainRate{{{"1/us", 1.0}, {"1/s", 1.0e-6}}};
constexpr std::array<UnitSpec, 3> kPressurePerKelvin{
    {{"Mbar/K", 1.0}, {"GPa/K", units::GPa}, {"MPa/K", 1.0e-5}}};

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

}  // namespace

std::span<const UnitSpec> unitsOf(Dimension d) {
  switch (d) {
    case Dimension::Length:
      return kLength;
    case Dimension::Time:
      return kTime;
    case Dimension::Velocity:
      return kVelocity;
    case Dimension::Density:
      return kDensity;
    case Dimension::Pressure:
      return kPressure;
    case Dimension::SpecificEnergy:
      return kEnergy;
    case Dimension::WallTime:
      return kWall;
    case Dimension::SpecificHeat:
      return kSpecificHeat;
    case Dimension::StrainRate:
      return kStrainRate;
    case Dimension::PressurePerKelvin:
      return kPressurePerKelvin;
  }
  return {};
}

std::string_view internalUnit(Dimension d) { return unitsOf(d).front().name; }

std::string_view dimensionName(Dimension d) {
  switch (d) {
    case Dimension::Length:
      return "length";
    case Dimension::Time:
      return "time";
    case Dimension::Velocity:
      return "velocity";
    case Dimension::Density:
      return "density";
    case Dimension::Pressure:
      return "pressure";
    case Dimension::SpecificEnergy:
      return "specific energy";
    case Dimension::WallTime:
      return "wall-clock time";
    case Dimension::SpecificHeat:
      return "specific heat";
    case Dimension::StrainRate:
      return "strain rate";
    case Dimension::PressurePerKelvin:
      return "pressure per kelvin";
  }
  return "?";
}

std::string allowedUnits(Dimension d) {
  std::string s;
  for (const auto& u : unitsOf(d)) {
    if (!s.empty()) s += ", ";
    s += u.name;
  }
  return s;
}

std::optional<double> parseQuantity(std::string_view text, Dimension d, std::string* why) {
  auto failWith = [&](std::string reason) -> std::optional<double> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  std::string_view s = trim(text);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);  // from_chars rejects a leading '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range)
    return failWith(fmt::format("\"{}\" is out of range", text));
  if (ec != std::errc{} || end == s.data())
    return failWith(fmt::format("\"{}\" does not start with a number", text));
  if (!std::isfinite(value)) return failWith(fmt::format("\"{}\" is not finite", text));
  const std::string_view unit = trim(std::string_view(end, s.data() + s.size() - end));
  if (unit.empty())
    return failWith(fmt::format("\"{}\" has no unit (a {})", text, dimensionName(d)));
  for (const auto& u : unitsOf(d))
    if (u.name == unit) {
      const double v = value * u.toInternal;
      if (!std::isfinite(v)) return failWith(fmt::format("\"{}\" overflows", text));
      return v;
    }
  return failWith(fmt::format("unknown {} unit \"{}\"", dimensionName(d), unit));
}

}  // namespace hvi::cases
