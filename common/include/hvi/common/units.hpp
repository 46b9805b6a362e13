//! @file Internal unit system of hvi: centimetre, gram, microsecond (cm-g-us).
#pragma once

namespace hvi::units {

// Derived units in cm-g-us:
//   velocity          cm/us        = 10 km/s
//   density           g/cm^3       = 1000 kg/m^3
//   pressure          g/(cm us^2)  = 1 Mbar = 100 GPa
//   specific energy   cm^2/us^2    = 1e8 J/kg = 100 MJ/kg
// Scene files may write values with a unit suffix (see cases/); these factors convert to internal.
inline constexpr double kmPerS = 0.1;       //!< 1 km/s in cm/us
inline constexpr double mPerS = 1.0e-4;     //!< 1 m/s in cm/us
inline constexpr double GPa = 0.01;         //!< 1 GPa in Mbar
inline constexpr double Mbar = 1.0;
inline constexpr double MJPerKg = 0.01;     //!< 1 MJ/kg in cm^2/us^2
inline constexpr double kgPerM3 = 1.0e-3;   //!< 1 kg/m^3 in g/cm^3
inline constexpr double mm = 0.1;           //!< 1 mm in cm
inline constexpr double us = 1.0;

inline constexpr const char* lengthName = "cm";
inline constexpr const char* timeName = "us";
inline constexpr const char* massName = "g";
inline constexpr const char* densityName = "g/cm^3";
inline constexpr const char* velocityName = "cm/us";
inline constexpr const char* pressureName = "Mbar";
inline constexpr const char* energyName = "cm^2/us^2";

}  // namespace hvi::units
