//! @file The Whipple-shield ballistic-limit equation (BLE) of Christiansen (1993), as NASA's
//! MMOD handbook gives it: the critical projectile diameter that just perforates or detaches
//! spall from the rear wall, in three velocity regimes (docs/shield.md, "Ballistic-limit
//! equation").
#pragma once
#include <string_view>

namespace hvi::shield {

//! The equation's own units (not hvi's cm-g-us): lengths cm, densities g/cm^3, speed km/s,
//! yield stress ksi (1 ksi = 6.894757 MPa), angle degrees from the wall normal.
struct WhippleBle {
  double projectileDensity = 2.8;  //!< rho_p, g/cm^3
  double bumperDensity = 2.7;      //!< rho_b, g/cm^3
  double bumperThickness = 0.127;  //!< t_b, cm
  double rearWallThickness = 0.3;  //!< t_w, cm
  double rearWallYieldKsi = 40.0;  //!< sigma: the rear wall's 0.2 % offset yield stress, ksi
  double standoff = 10.0;          //!< S: bumper rear face to rear-wall front face, cm
  double angleDegrees = 0.0;       //!< theta, impact obliquity (0: normal)
};

enum class BleRegime { Ballistic, Shatter, Hypervelocity };
std::string_view toString(BleRegime r);

//! Regime boundaries of the normal-impact equation, km/s: V cos(theta) <= 3 ballistic
//! (projectile intact), >= 7 hypervelocity (projectile melts / vaporises), linear between.
inline constexpr double kBallisticLimitSpeed = 3.0;
inline constexpr double kHypervelocitySpeed = 7.0;

BleRegime bleRegime(const WhippleBle& s, double speedKmS);

//! Critical projectile diameter d_c (cm) at impact speed `speedKmS` (km/s):
//!  ballistic (V cos <= 3):  d_c = [(t_w (sigma/40)^0.5 + t_b) / (0.6 cos^(5/3) rho_p^0.5
//!                                  V^(2/3))]^(18/19)
//!  hypervelocity (>= 7):   d_c = 3.918 t_w^(2/3) rho_p^(-1/3) rho_b^(-1/9) (V cos)^(-2/3)
//!                                  S^(1/3) (sigma/70)^(1/3)
//!  shatter (between):      linear in V between the two at V cos = 3 and 7.
//! A projectile of diameter >= d_c fails the rear wall (perforation or detached spall). The
//! obliquity is capped at 65 degrees as NASA's implementations do. Valid for aluminium
//! projectiles on aluminium Whipple shields: fitted to light-gas-gun tests up to ~7 km/s and
//! extrapolated (analytically, not by tests) above. Throws std::invalid_argument for a
//! non-positive input.
double criticalDiameter(const WhippleBle& s, double speedKmS);

//! The hypervelocity form assumes a bumper thick enough to break the projectile up:
//! t_b / d_p >= 0.25 (S / d_p < 30) or >= 0.20 (S / d_p >= 30) (Christiansen 1993; the same
//! thresholds as Ryan and Christiansen's BLE program). False when `diameter` is too large for it.
bool bumperAdequate(const WhippleBle& s, double diameter);

//! 1 ksi in MPa (1000 lbf/in^2).
inline constexpr double kMpaPerKsi = 6.894757293168361;

}  // namespace hvi::shield
