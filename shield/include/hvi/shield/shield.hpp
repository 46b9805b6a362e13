//! @file A shield declaration (walls, standoffs, projectile, resolution knobs) and the hvi
//! scene it generates: r-z, normal impact, for SPH or TVD (docs/shield.md).
#pragma once
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/shield/ble.hpp"

namespace hvi::shield {

//! A shield material: the EOS preset it runs with, its density and yield stress (for the BLE
//! and, once the strength effect exists, for the solvers). Catalogue: shieldMaterials().
struct ShieldMaterial {
  std::string name;       //!< as written in shield files, e.g. "al6061_t6"
  std::string eosPreset;  //!< a cases preset, e.g. "aluminium_tillotson"
  double density = 0.0;   //!< g/cm^3 (overrides the preset's rho0)
  double yieldMpa = 0.0;  //!< 0.2 % offset yield stress, MPa (0: none)
  std::string source;     //!< where the values come from
};
std::span<const ShieldMaterial> shieldMaterials();
const ShieldMaterial* findShieldMaterial(std::string_view name);

//! One plate of the shield, normal to the impact. Lengths in cm.
struct Wall {
  std::string name;
  ShieldMaterial material;
  double thickness = 0.0;
  double gap = 0.0;  //!< clear space from the previous wall's rear face (0 for the bumper)
};

struct Projectile {
  ShieldMaterial material;
  double diameter = 0.0;  //!< cm
  double speed = 0.0;     //!< km/s
};

//! The resolution knobs: the cell size (TVD) or particle spacing (SPH) is the smaller of
//! diameter / cellsAcrossProjectile and thinnest wall / cellsAcrossThinnestWall, or, when
//! `spacing` is given, that one length for every case (a sweep's small projectiles then cost
//! no more than its large ones: the coarse setting, docs/shield.md).
struct Resolution {
  double cellsAcrossProjectile = 8.0;
  double cellsAcrossThinnestWall = 3.0;
  std::optional<double> spacing;  //!< cm; replaces the two knobs when set
};

struct ShieldSpec {
  std::string path;  //!< declaration file
  std::string title;
  std::string source;  //!< where the shield comes from (test series, handbook page)
  cases::SolverKind solver = cases::SolverKind::Tvd;
  Projectile projectile;
  std::vector<Wall> walls;  //!< impact side first: bumper, [intermediate...], rear wall
  Resolution resolution;
  std::optional<double> radius;   //!< cm, the plates' radius and the domain's (default: derived)
  std::optional<double> endTime;  //!< us (default: derived)
  int snapshots = 8;              //!< output times, evenly spaced up to the end

  //! Bumper rear face to rear-wall front face, cm (the BLE's S).
  [[nodiscard]] double standoff() const;
  [[nodiscard]] double thinnestWall() const;
  [[nodiscard]] double spacing() const;  //!< cell size / particle spacing, cm
};

//! Reads a shield declaration (TOML; docs/shield.md). Throws hvi::InputError naming the file,
//! the line, the key and the allowed values.
ShieldSpec loadShield(const std::filesystem::path& file);
ShieldSpec parseShield(std::string_view text, const std::string& sourceName);

//! The Whipple BLE of a two-wall shield (bumper and rear wall; intermediate walls are not in
//! the equation, which then does not apply: throws InputError).
WhippleBle whippleBle(const ShieldSpec& s);

//! Sets the total standoff by scaling every gap (a two-wall shield: the rear wall's gap).
void setStandoff(ShieldSpec& s, double standoff);

//! The generated scene file (TOML) of the shield: the layout and derivations are written into
//! its comments. parseScene reads it.
std::string sceneToml(const ShieldSpec& s);
//! The same, parsed and validated.
cases::Scene buildScene(const ShieldSpec& s);

//! Names of the generated bodies: the projectile, then the walls by their names; the last wall
//! is always named kRearWall (rear-wall failure is looked for in the body of that name).
inline constexpr const char* kProjectile = "projectile";
inline constexpr const char* kRearWall = "rear_wall";

}  // namespace hvi::shield
