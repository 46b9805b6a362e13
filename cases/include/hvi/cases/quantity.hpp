//! @file Quantities with units in scene files ("6.7 km/s"), converted to internal cm-g-us.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace hvi::cases {

//! Physical dimension of a scene-file value. WallTime is real (clock) time, not simulated time.
enum class Dimension {
  Length,
  Time,
  Velocity,
  Density,
  Pressure,
  SpecificEnergy,
  WallTime,
  SpecificHeat,       //!< cm^2/us^2/K (strength: c_v)
  StrainRate,         //!< 1/us (strength: reference rates)
  PressurePerKelvin,  //!< Mbar/K (strength: dG/dT)
};

//! A unit a scene file may write, and the factor that converts a value in it to internal units.
struct UnitSpec {
  std::string_view name;
  double toInternal;
};

//! Units allowed for a dimension, the internal one first.
std::span<const UnitSpec> unitsOf(Dimension d);
//! Name of the internal unit (cm, us, cm/us, g/cm^3, Mbar, cm^2/us^2, s, cm^2/us^2/K, 1/us,
//! Mbar/K).
std::string_view internalUnit(Dimension d);
//! "length", "time", ... for messages.
std::string_view dimensionName(Dimension d);
//! "cm, mm, m, um": the allowed units of `d`, for messages.
std::string allowedUnits(Dimension d);

//! Parses "<number> <unit>" (space optional, e.g. "6.7 km/s", "-0.5cm", "1e-3 us") into internal
//! units. Returns nullopt and, if `why` is given, the reason when the text is not a finite
//! number followed by a unit of `d`.
std::optional<double> parseQuantity(std::string_view text, Dimension d, std::string* why = nullptr);

}  // namespace hvi::cases
