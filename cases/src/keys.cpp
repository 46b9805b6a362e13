//! @file The key tables of [time], [sph], [tvd], [riemann] and [output]: type, field, check
//! and documentation of each key, in the order the parser reads and toToml writes them (the
//! top level, [domain], [materials.*] and [[bodies]]: keys_structure.cpp).
#include "detail/keys.hpp"

#include <array>
#include <string>

#include "hvi/cases/names.hpp"

namespace hvi::cases::detail {
namespace {

using K = ValueKind;

constexpr std::array<KeyRow<Scene>, 2> kTime{{
    {.key = "start", .kind = K::Quantity, HVI_KEY_FIELD(Scene, tStart),
     .dimension = Dimension::Time, .docValue = "time", .docDefault = "`\"0 us\"`"},
    // end > start is checked once both are read (parse_scene.cpp).
    {.key = "end", .kind = K::Quantity, HVI_KEY_FIELD(Scene, tEnd), .dimension = Dimension::Time,
     .docValue = "**required**, time > start", .required = true},
}};

constexpr std::array<KeyRow<SphParams>, 20> kSph{{
    {.key = "spacing", .kind = K::Quantity, HVI_KEY_FIELD(SphParams, spacing),
     .ok = [](double v) { return v > 0.0; }, .problem = "must be > 0", .allowed = "a length > 0",
     .docValue = "length > 0, particle spacing dx", .docDefault = "`0.01 cm`"},
    {.key = "h_factor", .kind = K::Number, HVI_KEY_FIELD(SphParams, hFactor),
     .ok = [](double v) { return v > 0.0; }, .problem = "must be > 0 (h = h_factor * spacing)",
     .allowed = "h_factor > 0", .docValue = "> 0, h = h_factor * spacing", .docDefault = "1.0"},
    {.key = "kernel", .kind = K::Choice, HVI_KEY_FIELD(SphParams, kernel), .choices = kernelNames,
     .docValue = "`\"gaussian\"`, `\"cubic_spline\"`", .docDefault = "`\"gaussian\"`"},
    {.key = "lattice", .kind = K::Choice, HVI_KEY_FIELD(SphParams, lattice),
     .choices = latticeNames, .docValue = "`\"square\"`, `\"hexagonal\"`",
     .docDefault = "`\"square\"`"},
    // docs/sph.md, "Energy": the study's symmetric form stays available for reproduction.
    {.key = "energy", .kind = K::Choice, HVI_KEY_FIELD(SphParams, energy),
     .choices = energyFormNames,
     .docValue = "`\"compatible\"` (Owen 2014, exact total energy), `\"symmetric\"` (the study's)",
     .docDefault = "`\"compatible\"`"},
    // docs/sph-rz.md: the ring form (hvi's first r-z SPH) stays available for reproduction.
    {.key = "rz_form", .kind = K::Choice, HVI_KEY_FIELD(SphParams, rzForm),
     .choices = rzFormNames,
     .docValue = "`\"auto\"` (symmetric; ring with strength), `\"symmetric\"` (pair weights "
                 "r_j / (s_i s_j), axially consistent at the axis), `\"ring\"` (r_j weights, "
                 "hoop correction C; docs/sph-rz.md)",
     .docDefault = "`\"auto\"`"},
    // docs/sph-rz.md, "The viscous hoop": 0 reproduces the symmetric form as first merged.
    {.key = "rz_viscous_hoop", .kind = K::Number, HVI_KEY_FIELD(SphParams, rzViscousHoop),
     .ok = [](double v) { return v >= 0.0 && v <= 1.0; }, .problem = "must be in [0, 1]",
     .allowed = "a number in [0, 1]",
     .docValue = "in [0, 1]: share of the viscous pair term in the symmetric r-z form's hoop "
                 "term (docs/sph-rz.md, \"The viscous hoop\"); r-z symmetric form only",
     .docDefault = "0"},
    // docs/sph-rz.md, "Corrected axial gradient": a measured trial, off by default.
    {.key = "rz_axis_correction", .kind = K::Number, HVI_KEY_FIELD(SphParams, rzAxisCorrection),
     .ok = [](double v) { return v >= 0.0 && v <= 10.0; }, .problem = "must be in [0, 10]",
     .allowed = "a number in [0, 10] (units of h)",
     .docValue = "in [0, 10] h: the axial pair gradient corrected by the Bonet-Lok matrix within "
                 "this distance of the axis (docs/sph-rz.md, \"Corrected axial gradient\"); r-z "
                 "symmetric form only; 0 off",
     .docDefault = "0"},
    {.key = "alpha", .kind = K::Number, HVI_KEY_FIELD(SphParams, alpha),
     .ok = [](double v) { return v >= 0.0; }, .problem = "must be >= 0", .allowed = "alpha >= 0",
     .docValue = ">= 0, Monaghan viscosity alpha_Pi", .docDefault = "1.0"},
    {.key = "beta", .kind = K::Number, HVI_KEY_FIELD(SphParams, beta),
     .ok = [](double v) { return v >= 0.0; }, .problem = "must be >= 0", .allowed = "beta >= 0",
     .docValue = ">= 0, Monaghan viscosity beta_Pi", .docDefault = "2.0"},
    {.key = "cfl", .kind = K::Number, HVI_KEY_FIELD(SphParams, cfl),
     .ok = [](double v) { return v > 0.0 && v <= 1.0; }, .problem = "must be in (0, 1]",
     .allowed = "0 < cfl <= 1", .docValue = "(0, 1]", .docDefault = "0.3"},
    // The residual |rho0/rho - 1| is a sum of 30-60 kernel terms, each rounded to 1e-16: a
    // tolerance below 1e-13 is never met and the iteration would only stop at its cap.
    {.key = "mass_tolerance", .kind = K::Number, HVI_KEY_FIELD(SphParams, massTolerance),
     .ok = [](double v) { return v >= 1e-13 && v < 1.0; },
     .problem = "must be in [1e-13, 1) (below 1e-13 round-off keeps the residual from reaching it)",
     .allowed = "1e-13 <= mass_tolerance < 1",
     .docValue = "[1e-13, 1), bound of the mass iteration (below 1e-13 round-off never lets it "
                 "converge)",
     .docDefault = "1e-9"},
    {.key = "delete_fraction", .kind = K::Number, HVI_KEY_FIELD(SphParams, deleteFraction),
     .ok = [](double v) { return v >= 0.0 && v < 1.0; }, .problem = "must be in [0, 1)",
     .allowed = "0 <= delete_fraction < 1", .docValue = "[0, 1), delete if m_i / max m below it",
     .docDefault = "1e-4"},
    // docs/sph.md: ~550 passes at h = dx, ~4e5 at h = 2 dx (the slowest mode is damped by
    // 1 - exp(-pi^2 h^2 / 4 dx^2) per pass); a pass over 1e5 particles takes ~5 ms, so 1e6
    // passes are already ~1.5 h. More can only mean an iteration that does not converge.
    {.key = "max_mass_iterations", .kind = K::Integer, HVI_KEY_FIELD(SphParams, maxMassIterations),
     .ok = [](double v) { return v >= 1 && v <= 1e6; }, .problem = "must be in [1, 1000000]",
     .allowed = "an integer in [1, 1000000]",
     .docValue = "integer in [1, 1e6] (1e6 passes are hours; docs/sph.md)", .docDefault = "10000"},
    // Monaghan's (2000) artificial stress, used with the effect `strength` (docs/strength.md):
    // epsilon 0.3 and exponent 4 are Gray, Monaghan and Swift's (2001); 0 switches it off.
    // Above 1 it would push harder than the tension it counters. The exponent sets how fast
    // the pair weight (W(r) / W(dp))^n falls off beyond the spacing.
    {.key = "artificial_stress_epsilon", .kind = K::Number,
     HVI_KEY_FIELD(SphParams, artificialStressEpsilon),
     .ok = [](double v) { return v >= 0.0 && v <= 1.0; }, .problem = "must be in [0, 1]",
     .allowed = "0 <= artificial_stress_epsilon <= 1",
     .docValue = "[0, 1], Monaghan's artificial stress with strength (0: off)",
     .docDefault = "0.3"},
    {.key = "artificial_stress_exponent", .kind = K::Integer,
     HVI_KEY_FIELD(SphParams, artificialStressExponent),
     .ok = [](double v) { return v >= 1 && v <= 12; }, .problem = "must be in [1, 12]",
     .allowed = "an integer in [1, 12]",
     .docValue = "integer in [1, 12], n of the pair weight (W(r) / W(dp))^n", .docDefault = "4"},
    // docs/strength.md, "Viscosity switch": Morris and Monaghan (1997), with strength only (the
    // strength pass sums the switched viscosity); "off" keeps the constant alpha, beta.
    {.key = "viscosity_switch", .kind = K::Choice, HVI_KEY_FIELD(SphParams, viscositySwitch),
     .choices = viscositySwitchNames,
     .docValue = "`\"off\"`, `\"morris_monaghan\"` (per-particle alpha_i in [alpha_min, alpha], "
                 "with strength)",
     .docDefault = "`\"off\"`"},
    {.key = "alpha_min", .kind = K::Number, HVI_KEY_FIELD(SphParams, alphaMin),
     .ok = [](double v) { return v >= 0.0; }, .problem = "must be >= 0 (and <= sph.alpha)",
     .allowed = "0 <= alpha_min <= alpha",
     .docValue = ">= 0, <= alpha: the switch's floor alpha_i decays to", .docDefault = "0.1"},
    // Morris and Monaghan: decay time h / (l c) with l = 0.1 to 0.2.
    {.key = "switch_decay", .kind = K::Number, HVI_KEY_FIELD(SphParams, switchDecay),
     .ok = [](double v) { return v > 0.0 && v <= 1.0; }, .problem = "must be in (0, 1]",
     .allowed = "0 < switch_decay <= 1",
     .docValue = "(0, 1], l of the switch's decay time h / (l c)", .docDefault = "0.2"},
    // docs/strength.md, "SPH viscosity switch": the kernel gradient's total rate carries the
    // particles' jitter and ringing into the Johnson-Cook rate factor.
    {.key = "yield_strain_rate", .kind = K::Choice, HVI_KEY_FIELD(SphParams, yieldStrainRate),
     .choices = yieldStrainRateNames,
     .docValue = "`\"total\"` (the velocity gradient's), `\"plastic\"` (the last step's plastic "
                 "strain rate), with strength",
     .docDefault = "`\"total\"`"},
}};

constexpr std::array<KeyRow<TvdParams>, 7> kTvd{{
    {.key = "cell_size", .kind = K::Quantity, HVI_KEY_FIELD(TvdParams, cellSize),
     .ok = [](double v) { return v > 0.0; }, .problem = "must be > 0", .allowed = "a length > 0",
     .docValue = "length > 0, dx = dz", .docDefault = "`0.015 cm`"},
    {.key = "limiter", .kind = K::Choice, HVI_KEY_FIELD(TvdParams, limiter),
     .choices = limiterNames, .docValue = "`\"minmod\"`, `\"van_leer\"`, `\"superbee\"`",
     .docDefault = "`\"minmod\"`"},
    // The positivity fallback (Rusanov) flux of the split sweeps needs CFL <= 1/2.
    {.key = "cfl", .kind = K::Number, HVI_KEY_FIELD(TvdParams, cfl),
     .ok = [](double v) { return v > 0.0 && v <= 0.5; },
     .problem = "must be in (0, 0.5] for the TVD scheme", .allowed = "0 < cfl <= 0.5",
     .docValue = "(0, 0.5] (the positivity fallback flux)", .docDefault = "0.4"},
    {.key = "marker_spacing", .kind = K::Number, HVI_KEY_FIELD(TvdParams, markerSpacing),
     .ok = [](double v) { return v > 0.0 && v <= 10.0; }, .problem = "must be in (0, 10] cells",
     .allowed = "0 < marker_spacing <= 10 (in cells)",
     .docValue = "(0, 10], target marker spacing in cells", .docDefault = "0.5"},
    {.key = "vacuum_density", .kind = K::Number, HVI_KEY_FIELD(TvdParams, vacuumDensity),
     .ok = [](double v) { return v >= 0.0 && v < 1.0; },
     .problem = "must be in [0, 1) (a fraction of rho0; 0: the interface mode's default)",
     .allowed = "0 <= vacuum_density < 1",
     .docValue = "[0, 1), vacuum below this fraction of rho0 (0: the default)",
     .docDefault = "1e-6; 1e-9 with `interfaces = \"conservative\"`"},
    // docs/tvd.md, "Conservative interfaces": with material_interfaces only.
    {.key = "interfaces", .kind = K::Choice, HVI_KEY_FIELD(TvdParams, interfaces),
     .choices = interfaceNames,
     .docValue = "`\"whole_cell\"` (the study's owners), `\"conservative\"` (cut cells, mass exact "
                 "per material)",
     .docDefault = "`\"conservative\"`"},
    // docs/tvd.md, "Outflow sides: no re-entry": the conservative interfaces only.
    {.key = "outflow", .kind = K::Choice, HVI_KEY_FIELD(TvdParams, outflow),
     .choices = outflowModeNames,
     .docValue = "`\"auto\"` (`\"no_reentry\"` with the conservative interfaces, else "
                 "`\"open\"`), `\"open\"` (zero-gradient ghost: material may re-enter), "
                 "`\"no_reentry\"` "
                 "(a phase moving inwards meets a wall there; conservative interfaces), "
                 "`\"no_reentry_cut\"` (the same, and the marker lines are cut at the side; an "
                 "experiment, docs/tvd.md)",
     .docDefault = "`\"auto\"`"},
}};

// Measured on sod_x at 1e6 cells: 170 MB peak memory, 49 MB of HDF5 + VTK per snapshot, 2 s for
// three snapshots; 1e8 cells needed ~15 GB of each (issue 11). A 1-D exact profile finer than
// 1e6 cells resolves nothing that a 2-D solver it is compared with could (the 1.2e8-cell TVD cap
// is ~11000 cells a side).
constexpr std::array<KeyRow<RiemannParams>, 2> kRiemann{{
    {.key = "cells", .kind = K::Integer, HVI_KEY_FIELD(RiemannParams, cells),
     .ok = [](double v) { return v >= 2 && v <= 1e6; }, .problem = "must be in [2, 1e6]",
     .allowed = "an integer in [2, 1000000]",
     .docValue = "integer in [2, 1e6], sampling cells (1e6: ~170 MB of memory, ~50 MB of disk "
                 "per snapshot)",
     .docDefault = "400"},
    // Its default, where two rect bodies meet, is set before the table is read.
    {.key = "interface", .kind = K::Quantity, HVI_KEY_FIELD(RiemannParams, interface),
     .docValue = "length, where the two bodies meet", .docDefault = "where they meet, else 0.5 cm"},
}};

constexpr std::array<KeyRow<Output>, 4> kOutput{{
    {.key = "times", .kind = K::Custom,
     .docValue = "array of times, strictly increasing, in (start, end]",
     .docDefault = "`[]` (the driver always writes `end`)"},
    {.key = "hdf5", .kind = K::Flag, HVI_KEY_FIELD(Output, hdf5), .docValue = "boolean",
     .docDefault = "true"},
    {.key = "vtk", .kind = K::Flag, HVI_KEY_FIELD(Output, vtk), .docValue = "boolean",
     .docDefault = "true"},
    {.key = "checkpoint_every", .kind = K::Quantity, HVI_KEY_FIELD(Output, checkpointEvery),
     .dimension = Dimension::WallTime, .ok = [](double v) { return v >= 0.0; },
     .problem = "must be >= 0 (0: at snapshots only)",
     .allowed = "a wall-clock time >= 0 in s, min or h",
     .docValue = "wall-clock time >= 0 (`\"30 min\"`); 0: at snapshots only", .docDefault = "0"},
}};

template <class S, std::size_t N>
constexpr std::array<std::string_view, N> namesOf(const std::array<KeyRow<S>, N>& rows) {
  std::array<std::string_view, N> n{};
  for (std::size_t i = 0; i < N; ++i) n[i] = rows[i].key;
  return n;
}
constexpr auto kTimeNames = namesOf(kTime);
constexpr auto kSphNames = namesOf(kSph);
constexpr auto kTvdNames = namesOf(kTvd);
constexpr auto kRiemannNames = namesOf(kRiemann);
constexpr auto kOutputNames = namesOf(kOutput);

}  // namespace

// The top level, [domain], [materials.*] and [[bodies]]: keys_structure.cpp.
std::span<const std::string_view> structureKeyNames(std::string_view section);

std::span<const KeyRow<Scene>> timeKeys() { return kTime; }
std::span<const KeyRow<SphParams>> sphKeys() { return kSph; }
std::span<const KeyRow<TvdParams>> tvdKeys() { return kTvd; }
std::span<const KeyRow<RiemannParams>> riemannKeys() { return kRiemann; }
std::span<const KeyRow<Output>> outputKeys() { return kOutput; }

std::span<const std::string_view> keyNames(std::string_view section) {
  if (section == "time") return kTimeNames;
  if (section == "sph") return kSphNames;
  if (section == "tvd") return kTvdNames;
  if (section == "riemann") return kRiemannNames;
  if (section == "output") return kOutputNames;
  if (section == "materials.strength") return strengthKeyNames();
  return structureKeyNames(section);
}

}  // namespace hvi::cases::detail
