//! @file The key tables of the scene's structure: the top level, [domain], [materials.*] (the
//! keys every material has, then one table per EOS) and [[bodies]], in the order the parser
//! reads and toToml writes them (Custom rows: by their section's own code).
#include <algorithm>
#include <array>
#include <vector>

#include "detail/keys.hpp"
#include "hvi/cases/names.hpp"

namespace hvi::cases::detail {
namespace {

using K = ValueKind;

constexpr std::array<std::string_view, 3> kEosNames{"tillotson", "ideal_gas", "mie_gruneisen"};
constexpr std::array<std::string_view, 3> kShapeNames{"disk", "rect", "polygon"};

constexpr std::array<KeyRow<Scene>, 13> kRoot{{
    {.key = "title", .kind = K::Custom, .docValue = "string", .docDefault = "`\"\"`"},
    {.key = "units", .kind = K::Custom,
     .docValue = "`\"cm-g-us\"` (bare numbers are internal units)",
     .docDefault = "absent: units required"},
    {.key = "geometry", .kind = K::Choice, HVI_KEY_FIELD(Scene, geometry),
     .choices = geometryNames, .docValue = "**required**: `\"planar\"` or `\"rz\"`",
     .required = true},
    {.key = "solver", .kind = K::Choice, HVI_KEY_FIELD(Scene, solver), .choices = solverNames,
     .docValue = "**required**: `\"sph\"`, `\"tvd\"` or `\"riemann\"`", .required = true},
    {.key = "effects", .kind = K::Custom, .docValue = "array of effect names (below), each once",
     .docDefault = "`[]`"},
    {.key = "time", .kind = K::Section},
    {.key = "domain", .kind = K::Section},
    {.key = "materials", .kind = K::Section},
    {.key = "bodies", .kind = K::Section},
    {.key = "sph", .kind = K::Section},
    {.key = "tvd", .kind = K::Section},
    {.key = "riemann", .kind = K::Section},
    {.key = "output", .kind = K::Section},
}};

constexpr std::array<KeyRow<Domain>, 3> kDomain{{
    {.key = "x", .kind = K::Custom,
     .docValue = "**required**, `[min, max]` lengths with min < max"},
    {.key = "z", .kind = K::Custom,
     .docValue = "**required**, `[min, max]` lengths with min < max"},
    {.key = "boundaries", .kind = K::Custom,
     .docValue = "table with `xmin`, `xmax`, `zmin`, `zmax`, each `\"outflow\"`, `\"wall\"` or "
                 "`\"axis\"`",
     .docDefault = "all `\"outflow\"`, except `xmin = \"axis\"` in rz"},
}};

// Domain::boundary[side] as a row's get and set. The default (axis at xmin in rz) is set before
// the table is read, the checks that depend on the geometry after (parse_scene.cpp).
#define HVI_BOUNDARY(side)                                                                         \
  .key = #side, .kind = K::Choice,                                                                 \
  .get = [](const Domain& d) { return toValue(d.boundary[Side::side]); },                          \
  .set = [](Domain& d, double v) { d.boundary[Side::side] = fromValue<Boundary>(v); },             \
  .choices = boundaryNames
struct Side {
  enum : std::size_t { xmin, xmax, zmin, zmax };
};
constexpr std::array<KeyRow<Domain>, 4> kBoundaries{{
    {HVI_BOUNDARY(xmin)}, {HVI_BOUNDARY(xmax)}, {HVI_BOUNDARY(zmin)}, {HVI_BOUNDARY(zmax)}}};
#undef HVI_BOUNDARY

constexpr std::array<KeyRow<Material>, 3> kMaterial{{
    {.key = "preset", .kind = K::Custom,
     .docValue = "a preset (below); its values may then be overridden one by one",
     .docDefault = "none"},
    {.key = "eos", .kind = K::Custom,
     .docValue = "`\"tillotson\"`, `\"ideal_gas\"` or `\"mie_gruneisen\"`, with **all** its keys; "
                 "with a preset, that preset's",
     .docDefault = "the preset's"},
    {.key = "strength", .kind = K::Section},
}};

// The keys several EOS share. Without a preset a required key must be given; with one, every
// key defaults to the preset's value (parse_materials.cpp).
#define HVI_EOS_RHO0(S)                                                                            \
  {.key = "rho0", .kind = K::Quantity, HVI_KEY_FIELD(S, rho0),                                     \
   .dimension = Dimension::Density, .ok = [](double v) { return v > 0.0; },                        \
   .problem = "must be > 0", .allowed = "a density > 0", .docValue = "**required**, density > 0",  \
   .required = true}
#define HVI_EOS_FLOOR(S)                                                                           \
  {.key = "sound_speed_floor", .kind = K::Number, HVI_KEY_FIELD(S, soundSpeedFloorFraction),       \
   .ok = [](double v) { return v >= 0.0 && v < 1.0; },                                             \
   .problem = "must be in [0, 1) (a fraction of the reference sound speed)",                       \
   .allowed = "0 <= sound_speed_floor < 1",                                                        \
   .docValue = "[0, 1), the sound-speed floor as a fraction of the reference sound speed",         \
   .docDefault = "0.05"}
#define HVI_EOS_NONNEGATIVE(S, name)                                                               \
  {.key = #name, .kind = K::Number, HVI_KEY_FIELD(S, name),                                        \
   .ok = [](double v) { return v >= 0.0; }, .problem = "must be >= 0", .allowed = #name " >= 0",   \
   .docValue = "**required**, >= 0", .required = true}

using eos::Tillotson;
constexpr std::array<KeyRow<Tillotson>, 11> kTillotson{{
    HVI_EOS_RHO0(Tillotson),
    HVI_EOS_NONNEGATIVE(Tillotson, a),
    HVI_EOS_NONNEGATIVE(Tillotson, b),
    {.key = "A", .kind = K::Quantity, HVI_KEY_FIELD(Tillotson, A),
     .dimension = Dimension::Pressure, .ok = [](double v) { return v > 0.0; },
     .problem = "must be > 0 (the bulk modulus)", .allowed = "a pressure > 0",
     .docValue = "**required**, pressure > 0 (the bulk modulus)", .required = true},
    {.key = "B", .kind = K::Quantity, HVI_KEY_FIELD(Tillotson, B),
     .dimension = Dimension::Pressure, .docValue = "**required**, pressure", .required = true},
    {.key = "e0", .kind = K::Quantity, HVI_KEY_FIELD(Tillotson, e0),
     .dimension = Dimension::SpecificEnergy, .ok = [](double v) { return v > 0.0; },
     .problem = "must be > 0", .allowed = "a specific energy > 0",
     .docValue = "**required**, specific energy > 0", .required = true},
    HVI_EOS_NONNEGATIVE(Tillotson, alpha),
    HVI_EOS_NONNEGATIVE(Tillotson, beta),
    {.key = "e1", .kind = K::Quantity, HVI_KEY_FIELD(Tillotson, e1),
     .dimension = Dimension::SpecificEnergy, .ok = [](double v) { return v >= 0.0; },
     .problem = "must be >= 0", .allowed = "a specific energy >= 0",
     .docValue = "**required**, specific energy >= 0 (incipient vaporisation)", .required = true},
    // e2 > e1 is checked once both are read (parse_materials.cpp).
    {.key = "e2", .kind = K::Quantity, HVI_KEY_FIELD(Tillotson, e2),
     .dimension = Dimension::SpecificEnergy,
     .docValue = "**required**, specific energy > e1 (full vaporisation)", .required = true},
    HVI_EOS_FLOOR(Tillotson),
}};

constexpr std::array<KeyRow<eos::IdealGas>, 2> kIdealGas{{
    HVI_EOS_RHO0(eos::IdealGas),
    {.key = "gamma", .kind = K::Number, HVI_KEY_FIELD(eos::IdealGas, gamma),
     .ok = [](double v) { return v > 1.0; }, .problem = "must be > 1", .allowed = "gamma > 1",
     .docValue = "**required**, > 1", .required = true},
}};

using eos::MieGruneisen;
constexpr std::array<KeyRow<MieGruneisen>, 5> kMieGruneisen{{
    HVI_EOS_RHO0(MieGruneisen),
    {.key = "c0", .kind = K::Quantity, HVI_KEY_FIELD(MieGruneisen, c0),
     .dimension = Dimension::Velocity, .ok = [](double v) { return v > 0.0; },
     .problem = "must be > 0", .allowed = "a velocity > 0",
     .docValue = "**required**, velocity > 0 (bulk sound speed)", .required = true},
    {.key = "s", .kind = K::Number, HVI_KEY_FIELD(MieGruneisen, s),
     .ok = [](double v) { return v > 0.0; }, .problem = "must be > 0", .allowed = "s > 0",
     .docValue = "**required**, > 0 (Us = c0 + s up)", .required = true},
    HVI_EOS_NONNEGATIVE(MieGruneisen, gamma0),
    HVI_EOS_FLOOR(MieGruneisen),
}};
#undef HVI_EOS_RHO0
#undef HVI_EOS_FLOOR
#undef HVI_EOS_NONNEGATIVE

// The keys of every shape, then those of one shape (variant: its index in kShapeNames).
constexpr std::array<KeyRow<Body>, 14> kBodies{{
    {.key = "name", .kind = K::Custom, .docValue = "**required**, non-empty, unique"},
    {.key = "material", .kind = K::Custom,
     .docValue = "**required**, a name defined under `[materials]`"},
    {.key = "shape", .kind = K::Custom,
     .docValue = "**required**: `\"disk\"`, `\"rect\"` or `\"polygon\"`"},
    {.key = "velocity", .kind = K::Custom, .docValue = "`[vx, vz]` velocities",
     .docDefault = "`[\"0 cm/us\", \"0 cm/us\"]`"},
    // Its default, the material's rho0, is set before the table is read.
    {.key = "density", .kind = K::Quantity, HVI_KEY_FIELD(Body, density),
     .dimension = Dimension::Density, .ok = [](double v) { return v > 0.0; },
     .problem = "must be > 0", .allowed = "a density > 0", .docValue = "density > 0",
     .docDefault = "the material's rho0"},
    {.key = "pressure", .kind = K::Custom,
     .docValue = "pressure; the energy is solved from the EOS (not with `specific_energy`)"},
    {.key = "specific_energy", .kind = K::Custom,
     .docValue = "specific energy (ideal gas >= 0; Tillotson and Mie-Gruneisen any, docs/eos.md)",
     .docDefault = "0"},
    {.key = "radial_velocity", .kind = K::Custom,
     .docValue = "a speed along the radius instead of `velocity` (negative: converging), about "
                 "`radial_centre` (planar) or the axis (rz)",
     .docDefault = "none"},
    {.key = "radial_centre", .kind = K::Custom,
     .docValue = "planar only, with `radial_velocity`: `[x, z]` lengths",
     .docDefault = "`[\"0 cm\", \"0 cm\"]`"},
    {.key = "centre", .kind = K::Custom, .docValue = "disk: **required**, `[x, z]` lengths",
     .variant = 0},
    {.key = "radius", .kind = K::Custom, .docValue = "disk: **required**, length > 0",
     .variant = 0},
    {.key = "x", .kind = K::Custom, .docValue = "rect: **required**, `[min, max]` lengths",
     .variant = 1},
    {.key = "z", .kind = K::Custom, .docValue = "rect: **required**, `[min, max]` lengths",
     .variant = 1},
    {.key = "vertices", .kind = K::Custom,
     .docValue = "polygon: **required**, >= 3 `[x, z]` pairs, simple, non-zero area; clockwise "
                 "input is reordered counter-clockwise",
     .variant = 2},
}};

using Names = std::vector<std::string_view>;

template <class S>
void addNames(Names& n, std::span<const KeyRow<S>> rows) {
  for (const auto& r : rows)
    if (std::find(n.begin(), n.end(), r.key) == n.end()) n.push_back(r.key);
}
template <class S>
Names namesOf(std::span<const KeyRow<S>> rows) {
  Names n;
  addNames(n, rows);
  return n;
}
// preset and eos, then the keys of one EOS, then the sub-table strength.
template <class S>
Names materialNames(std::span<const KeyRow<S>> rows) {
  Names n;
  for (const auto& r : materialKeys())
    if (r.kind != K::Section) n.push_back(r.key);
  addNames(n, rows);
  for (const auto& r : materialKeys())
    if (r.kind == K::Section) n.push_back(r.key);
  return n;
}

}  // namespace

std::span<const KeyRow<Scene>> rootKeys() { return kRoot; }
std::span<const KeyRow<Domain>> domainKeys() { return kDomain; }
std::span<const KeyRow<Domain>> boundaryKeys() { return kBoundaries; }
std::span<const KeyRow<Material>> materialKeys() { return kMaterial; }
std::span<const KeyRow<eos::Tillotson>> tillotsonKeys() { return kTillotson; }
std::span<const KeyRow<eos::IdealGas>> idealGasKeys() { return kIdealGas; }
std::span<const KeyRow<eos::MieGruneisen>> mieGruneisenKeys() { return kMieGruneisen; }
std::span<const KeyRow<Body>> bodyKeys() { return kBodies; }
std::span<const std::string_view> eosNames() { return kEosNames; }
std::span<const std::string_view> shapeNames() { return kShapeNames; }

std::span<const std::string_view> structureKeyNames(std::string_view section) {
  static const Names root = namesOf(rootKeys()), domain = namesOf(domainKeys());
  static const Names boundaries = namesOf(boundaryKeys()), bodies = namesOf(bodyKeys());
  static const Names tillotson = materialNames(tillotsonKeys());
  static const Names idealGas = materialNames(idealGasKeys());
  static const Names mieGruneisen = materialNames(mieGruneisenKeys());
  static const Names materials = [] {  // any EOS: the union, in table order
    Names n = tillotson;
    addNames(n, idealGasKeys());
    addNames(n, mieGruneisenKeys());
    return n;
  }();
  if (section == "root") return root;
  if (section == "domain") return domain;
  if (section == "domain.boundaries") return boundaries;
  if (section == "bodies") return bodies;
  if (section == "materials") return materials;
  if (section == "materials.tillotson") return tillotson;
  if (section == "materials.ideal_gas") return idealGas;
  if (section == "materials.mie_gruneisen") return mieGruneisen;
  return {};
}

}  // namespace hvi::cases::detail
