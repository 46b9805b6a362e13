//! @file Material strength shared by both solvers (docs/strength.md): the deviatoric stress and
//! its objective (Jaumann) rate, the hypoelastic update, radial return to the von Mises surface,
//! the yield laws behind one std::variant, temperature and melt, damage (Grady-Kipp tensile
//! damage, Johnson-Cook failure strain) and spall. Units: cm-g-us (pressure and moduli in Mbar,
//! strain rates in 1/us), temperature in K. No solver type appears here.
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>
#include <variant>

namespace hvi::strength {

//! Deviatoric stress, trace free. Planar (x-z, plane strain): tt is the out-of-plane s_yy, not
//! zero in plane strain. r-z: x = r, z = z, tt = the hoop s_thetatheta. Three components are
//! stored and tt = -(xx + zz), so the trace is zero exactly in both geometries.
struct Deviator {
  double xx = 0.0, zz = 0.0, xz = 0.0;
  [[nodiscard]] double tt() const { return -(xx + zz); }
};

//! J2 = s:s / 2.
inline double secondInvariant(const Deviator& s) {
  const double tt = s.tt();
  return 0.5 * (s.xx * s.xx + s.zz * s.zz + tt * tt) + s.xz * s.xz;
}
//! von Mises equivalent stress sqrt(3 J2): the uniaxial stress the state is equivalent to.
inline double vonMises(const Deviator& s) { return std::sqrt(3.0 * secondInvariant(s)); }

//! Velocity gradient at a point: dvx/dx, dvx/dz, dvz/dx, dvz/dz and the hoop strain rate
//! (v_r / r in r-z; 0 in plane strain).
struct VelocityGradient {
  double xx = 0.0, xz = 0.0, zx = 0.0, zz = 0.0, hoop = 0.0;
  [[nodiscard]] double divergence() const { return xx + zz + hoop; }
};

//! sqrt(2/3 e':e'), e' the deviatoric strain rate: the axial rate in incompressible uniaxial
//! stress.
inline double equivalentStrainRate(const VelocityGradient& g) {
  const double third = g.divergence() / 3.0;
  const double dxx = g.xx - third, dzz = g.zz - third, dtt = g.hoop - third;
  const double dxz = 0.5 * (g.xz + g.zx);
  return std::sqrt(2.0 / 3.0 * (dxx * dxx + dzz * dzz + dtt * dtt + 2.0 * dxz * dxz));
}

//! Jaumann rate of the deviator with shear modulus G (Libersky and Petschek 1991; Gray,
//! Monaghan and Swift 2001, eq. 2.6): ds/dt = 2G (eps' - tr(eps')/3 I) + s Omega^T + Omega s,
//! Omega_xz = (dvx/dz - dvz/dx) / 2. Axisymmetric flow without swirl has no rotation about the
//! hoop direction, so tt changes by strain only (and stays -(xx + zz)).
inline Deviator jaumannRate(const Deviator& s, const VelocityGradient& g, double G) {
  const double third = g.divergence() / 3.0;
  const double w = 0.5 * (g.xz - g.zx);
  const double exz = 0.5 * (g.xz + g.zx);
  return {2.0 * G * (g.xx - third) + 2.0 * w * s.xz, 2.0 * G * (g.zz - third) - 2.0 * w * s.xz,
          2.0 * G * exz + w * (s.zz - s.xx)};
}

//! The state a yield law may depend on.
struct YieldInput {
  double plasticStrain = 0.0;  //!< equivalent plastic strain
  double strainRate = 0.0;     //!< equivalent strain rate, 1/us
  double pressure = 0.0;       //!< Mbar
  double temperature = 300.0;  //!< K
  double compression = 1.0;    //!< eta = rho / rho0
};

//! Elastic-perfectly plastic: Y = Y0.
struct ConstantYield {
  double y0 = 0.0;  //!< Mbar
  [[nodiscard]] double yield(const YieldInput&) const { return y0; }
};

//! Johnson and Cook (1983): Y = (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m), with
//! eps_dot* = max(eps_dot / eps_dot0, 1) (no softening below the reference rate) and
//! T* = (T - T_room) / (T_melt - T_room) clamped to [0, 1]: zero strength at T_melt.
struct JohnsonCook {
  double a = 0.0, b = 0.0, n = 1.0, c = 0.0, m = 1.0;       //!< A, B in Mbar
  double referenceRate = 1e-6;                              //!< eps_dot0, 1/us (1/s)
  double roomTemperature = 294.0, meltTemperature = 1.0e4;  //!< K
  [[nodiscard]] double homologous(double t) const {
    return std::clamp((t - roomTemperature) / (meltTemperature - roomTemperature), 0.0, 1.0);
  }
  [[nodiscard]] double yield(const YieldInput& in) const {
    const double hard = a + (in.plasticStrain > 0.0 ? b * std::pow(in.plasticStrain, n) : 0.0);
    const double rate = 1.0 + c * std::log(std::max(in.strainRate / referenceRate, 1.0));
    const double ts = homologous(in.temperature);
    return hard * rate * (1.0 - (ts > 0.0 ? std::pow(ts, m) : 0.0));
  }
};

//! Steinberg, Cochran and Guinan (1980), Steinberg (1991, UCRL-MA-106439):
//!   G(P, T) = G0 [1 + (G'_P / G0) P eta^(-1/3) + (G'_T / G0)(T - 300 K)]
//!   Y = min(Y0 [1 + beta (eps_p + eps_i)]^n, Ymax) G(P, T) / G0, and 0 at or above T_m(eta)
//!   T_m(eta) = T_m0 exp(2a (1 - 1/eta)) eta^(2 (gamma0 - a - 1/3))  (modified Lindemann)
//! (SG's Y'_P / Y0 = G'_P / G0, so one ratio scales both.) G and Y are kept >= 0 in deep tension
//! and heat, where the linear forms would cross zero.
struct SteinbergGuinan {
  double g0 = 0.0;    //!< Mbar
  double y0 = 0.0;    //!< Mbar
  double yMax = 0.0;  //!< Mbar
  double beta = 0.0, n = 0.0, initialStrain = 0.0;
  double dGdP = 0.0;                //!< G'_P, dimensionless
  double dGdT = 0.0;                //!< G'_T, Mbar/K (negative)
  double meltTemperature0 = 1.0e4;  //!< T_m0, K
  double gamma0 = 2.0, a = 1.5;
  [[nodiscard]] double meltTemperature(double eta) const {
    return meltTemperature0 * std::exp(2.0 * a * (1.0 - 1.0 / eta)) *
           std::pow(eta, 2.0 * (gamma0 - a - 1.0 / 3.0));
  }
  [[nodiscard]] double shearModulus(double p, double t, double eta) const {
    return shearModulusAt(p, t, std::cbrt(eta));
  }
  [[nodiscard]] double yield(const YieldInput& in) const {
    return yieldFrom(in, meltTemperature(in.compression), hardening(in.plasticStrain),
                     std::cbrt(in.compression));
  }
  // The pieces of yield and shearModulus, for a caller that keeps the terms of one eta or
  // eps_p between calls (SPH: the two advances of a step share eta and eps_p): the same
  // operations, so the same bits.
  //! G with cbrt(eta) given.
  [[nodiscard]] double shearModulusAt(double p, double t, double cbrtEta) const {
    return std::max(g0 + dGdP * p / cbrtEta + dGdT * (t - 300.0), 0.0);
  }
  //! min(Y0 [1 + beta (eps_p + eps_i)]^n, Ymax).
  [[nodiscard]] double hardening(double plasticStrain) const {
    return std::min(y0 * std::pow(1.0 + beta * (plasticStrain + initialStrain), n), yMax);
  }
  //! Y from T_m(eta), the hardening and cbrt(eta) of `in`.
  [[nodiscard]] double yieldFrom(const YieldInput& in, double meltT, double hard,
                                 double cbrtEta) const {
    if (in.temperature >= meltT) return 0.0;
    return hard * shearModulusAt(in.pressure, in.temperature, cbrtEta) / g0;
  }
};

//! Zerilli and Armstrong (1987, J. Appl. Phys. 61, 1816), the fcc form (their c1 = c5 = 0):
//!   Y = C0 + C2 sqrt(eps_p) exp(-C3 T + C4 T ln eps_dot),  eps_dot in 1/s, T in K,
//! the form of their copper relation (and of Uintah's ZAFlow and OpenRadioss's law 131 fcc
//! branch). The rate is floored at 1/s (ln eps_dot >= 0): as Johnson-Cook's clamp, no softening
//! below the rate the constants' unit names, and no ln 0 at rest. The law has no melt of its own
//! (it only decays with T), so Y = 0 at or above T_melt, a material constant as Johnson-Cook's.
struct ZerilliArmstrong {
  double c0 = 0.0, c2 = 0.0;                  //!< athermal stress and hardening coefficient, Mbar
  double c3 = 0.0, c4 = 0.0;                  //!< 1/K
  double meltTemperature = 1.0e4;             //!< K
  static constexpr double kPerSecond = 1e-6;  //!< 1/s in 1/us: the constants' rate unit
  [[nodiscard]] double yield(const YieldInput& in) const {
    if (in.temperature >= meltTemperature) return 0.0;
    if (!(in.plasticStrain > 0.0)) return c0;
    const double t = in.temperature;
    const double lnRate = std::log(std::max(in.strainRate / kPerSecond, 1.0));
    return c0 + c2 * std::sqrt(in.plasticStrain) * std::exp(-c3 * t + c4 * t * lnRate);
  }
};

//! One yield law per material, dispatched once per material outside the hot loops.
using YieldModel = std::variant<ConstantYield, JohnsonCook, SteinbergGuinan, ZerilliArmstrong>;
inline double yieldStress(const YieldModel& m, const YieldInput& in) {
  return std::visit([&](const auto& y) { return y.yield(in); }, m);
}

//! Temperature from specific energy: T = T0 + max(e - e_c(eta), 0) / c_v, with the cold
//! compression energy of a linear cold curve P_c = K0 (eta - 1), K0 = rho0 c0^2:
//!   e_c(eta) = integral of P_c / rho^2 drho = c0^2 (ln eta + 1/eta - 1) >= 0,
//! so elastic compression or stretching does not read as heating. e = 0 is the reference state
//! at T0 (the solvers' convention). A simple model (docs/strength.md): no Debye c_v, no melt
//! latent heat; it feeds the thermal softening and the melt test only.
struct Thermal {
  double cv = 1.0e-5;           //!< specific heat, cm^2/us^2/K (1e-5 = 1000 J/(kg K))
  double t0 = 300.0;            //!< K at e = 0, eta = 1
  double bulkSoundSpeed = 0.0;  //!< c0, cm/us (from the EOS: cases::resolveMaterials)
  [[nodiscard]] double coldEnergy(double eta) const {
    return bulkSoundSpeed * bulkSoundSpeed * (std::log(eta) + 1.0 / eta - 1.0);
  }
  [[nodiscard]] double temperature(double eta, double e) const {
    return temperatureAbove(coldEnergy(eta), e);
  }
  //! temperature(eta, e) with coldEnergy(eta) given (the same bits).
  [[nodiscard]] double temperatureAbove(double cold, double e) const {
    return t0 + std::max(e - cold, 0.0) / cv;
  }
};

//! Radial return (Wilkins 1964) of a trial deviator onto the von Mises surface sqrt(3 J2) = Y.
struct ReturnResult {
  double plasticStrain = 0.0;  //!< increment of the equivalent plastic strain
  double plasticWork = 0.0;    //!< Y * increment: plastic work per unit volume, Mbar
};
inline ReturnResult radialReturn(Deviator& s, double yield, double G) {
  const double trial = vonMises(s);
  if (trial <= yield) return {};
  const double y = std::max(yield, 0.0);
  const double f = y / trial;
  s.xx *= f;
  s.zz *= f;
  s.xz *= f;
  // The return along s is the plastic flow direction of an associated von Mises law:
  // d eps_p = (sigma_trial - Y) / 3G (the elastic deviatoric strain removed, in equivalent form).
  const double dEps = G > 0.0 ? (trial - y) / (3.0 * G) : 0.0;
  return {dEps, y * dEps};
}

//! No damage variable.
struct NoDamage {};

//! Grady-Kipp tensile damage as in Benz and Asphaug (1995), deterministic per particle: of the
//! Weibull flaws n(eps) = k eps^m per unit volume, a particle of volume V carries its expected
//! weakest one, activated at eps_min = (k V)^(-1/m) (the strain at which k V eps^m = 1). Once
//! the local tensile strain eps = sigma_1 / ((1 - D) E) exceeds it, the crack grows:
//! d(D^(1/3))/dt = c_g / R_s with c_g = crackSpeed * c_L and R_s the particle's radius. With one
//! flaw per particle Benz and Asphaug's limit D <= n_active / n_total is D <= 1.
struct GradyKipp {
  double k = 0.0;           //!< Weibull coefficient, cm^-3
  double m = 9.0;           //!< Weibull exponent
  double crackSpeed = 0.4;  //!< c_g / c_L
  [[nodiscard]] double activationStrain(double volume) const {
    return std::pow(k * volume, -1.0 / m);
  }
  //! D after dt of growth from D (capped at 1).
  [[nodiscard]] static double grow(double d, double dt, double cg, double radius) {
    const double r = std::cbrt(std::max(d, 0.0)) + dt * cg / radius;
    return std::min(r * r * r, 1.0);
  }
};

//! Johnson and Cook (1985) failure strain: D += d eps_p / eps_f with
//! eps_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln eps_dot*][1 + D5 T*], sigma* = -P / sigma_eq.
struct JohnsonCookFailure {
  double d1 = 0.0, d2 = 0.0, d3 = 0.0, d4 = 0.0, d5 = 0.0;
  double referenceRate = 1e-6;  //!< 1/us
  [[nodiscard]] double failureStrain(double triaxiality, double rate, double homologous) const {
    return (d1 + d2 * std::exp(d3 * triaxiality)) *
           (1.0 + d4 * std::log(std::max(rate / referenceRate, 1.0))) * (1.0 + d5 * homologous);
  }
};

using DamageModel = std::variant<NoDamage, GradyKipp, JohnsonCookFailure>;

//! Largest principal value of the total stress -P I + s (x-z block and the tt component).
inline double maxPrincipalStress(const Deviator& s, double p) {
  const double mean = 0.5 * (s.xx + s.zz);
  const double rad = std::sqrt(0.25 * (s.xx - s.zz) * (s.xx - s.zz) + s.xz * s.xz);
  return std::max(mean + rad, s.tt()) - p;
}

//! Young's modulus from the bulk and shear moduli.
inline double youngsModulus(double k, double g) { return 9.0 * k * g / (3.0 * k + g); }

//! Damaged material keeps compression only: tension and the deviator scale by 1 - D (Benz and
//! Asphaug 1995), and tension never exceeds the spall strength (P >= -spallStrength).
inline double effectivePressure(double p, double damage, double spallStrength) {
  if (p >= 0.0) return p;
  return (1.0 - damage) * std::max(p, -spallStrength);
}

//! A material's strength description (everything but the EOS).
struct Material {
  double shearModulus = 0.0;  //!< G0, Mbar (Steinberg-Guinan: its g0; G(P, T) varies)
  YieldModel yield = ConstantYield{};
  Thermal thermal;
  DamageModel damage = NoDamage{};
  //! Effect fracture: the largest tension the material carries, Mbar (>= 0); the study's zero
  //! cut-off is spallStrength = 0.
  double spallStrength = 0.0;
};

//! G at a state: G(P, T) for Steinberg-Guinan, else the constant G0.
inline double shearModulus(const Material& m, double p, double t, double eta) {
  if (const auto* sg = std::get_if<SteinbergGuinan>(&m.yield)) return sg->shearModulus(p, t, eta);
  return m.shearModulus;
}

//! The longitudinal (P-wave) sound speed sqrt(c_bulk^2 + 4G / (3 rho)): the time step's speed
//! with strength.
inline double longitudinalSoundSpeed(double cBulk, double g, double rho) {
  return std::sqrt(cBulk * cBulk + 4.0 * g / (3.0 * rho));
}

//! Effect fracture: damage after a step of dt by the material's damage model, shared by both
//! solvers (docs/strength.md). Grady-Kipp tensile damage as in Benz and Asphaug (1995),
//! deterministic per element of size `size` (volume size^3, radius size / 2: the SPH particle's
//! spacing, the TVD cell's side), or Johnson and Cook's (1985) failure strain. `p` is the
//! effective pressure, `s` the deviator after the return, `c` the EOS's bulk sound speed, `cL`
//! the longitudinal one.
inline double grownDamage(const Material& sm, double d, double dt, double p, double rho, double c,
                          double g, double cL, double size, const YieldInput& in, const Deviator& s,
                          const ReturnResult& rr) {
  if (const auto* gk = std::get_if<GradyKipp>(&sm.damage)) {
    const double sigma1 = maxPrincipalStress(s, p);
    if (sigma1 <= 0.0) return d;
    const double e = youngsModulus(rho * c * c, g);
    const double eps = sigma1 / (std::max(1.0 - d, 1e-12) * e);
    if (eps < gk->activationStrain(size * size * size)) return d;
    return GradyKipp::grow(d, dt, gk->crackSpeed * cL, 0.5 * size);
  }
  if (const auto* jc = std::get_if<JohnsonCookFailure>(&sm.damage)) {
    if (rr.plasticStrain <= 0.0) return d;
    const double seq = vonMises(s);
    const double triax = seq > 0.0 ? -p / seq : 0.0;
    double th = 0.0;
    if (const auto* law = std::get_if<JohnsonCook>(&sm.yield)) th = law->homologous(in.temperature);
    const double ef = jc->failureStrain(triax, in.strainRate, th);
    return ef > 0.0 ? std::min(d + rr.plasticStrain / ef, 1.0) : 1.0;
  }
  return d;
}

//! "constant", "johnson_cook", "steinberg_guinan", "zerilli_armstrong" (YieldModel's order).
std::span<const std::string_view> yieldModelNames();
//! "none", "grady_kipp", "johnson_cook" (DamageModel's order).
std::span<const std::string_view> damageModelNames();

//! A published strength set (docs/strength.md, Presets).
struct Preset {
  std::string_view name;
  std::string_view source;
  Material material;  //!< thermal.bulkSoundSpeed left 0: set from the EOS
};
std::span<const Preset> presets();
const Preset* findPreset(std::string_view name);

}  // namespace hvi::strength
