//! @file [[bodies]]: name, material, shape (disk / rect / polygon) and the initial state.
#include <algorithm>
#include <cmath>
#include <vector>

#include "detail/keys.hpp"
#include "detail/parse.hpp"
#include "detail/polygon.hpp"
#include "hvi/common/error.hpp"

namespace hvi::cases::detail {
namespace {

// The keys of `shape` alone (the table's rows of that variant).
std::vector<std::string_view> shapeKeys(std::size_t shape) {
  std::vector<std::string_view> keys;
  for (const auto& r : bodyKeys())
    if (r.variant == static_cast<int>(shape)) keys.push_back(r.key);
  return keys;
}

// A key of another shape gets a message naming that shape; anything else the nearest key.
void rejectKeys(const TableReader& b, std::size_t shape) {
  std::vector<std::string_view> known;
  for (const auto& r : bodyKeys())
    if (r.variant < 0 || r.variant == static_cast<int>(shape)) known.push_back(r.key);
  const std::string_view name = shapeNames()[shape];
  for (const auto& [k, v] : b.table()) {
    const std::string_view key = k.str();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    for (const auto& r : bodyKeys())
      if (r.key == key && r.variant >= 0)
        b.fail(key,
               "belongs to shape = \"" +
                   std::string(shapeNames()[static_cast<std::size_t>(r.variant)]) + "\", not \"" +
                   std::string(name) + "\"",
               "for a " + std::string(name) + ": " + join(shapeKeys(shape)));
  }
  b.rejectUnknown(known);
}

Shape readPolygon(const TableReader& b) {
  const std::string path = b.keyPath("vertices");
  const toml::node& n = b.require("vertices", "[[x, z], ...] with at least 3 vertices");
  const auto& arr =
      readArray(b.ctx(), n, path, 0, "[[\"x\", \"z\"], ...] with at least 3 vertices");
  if (arr.size() < 3)
    fail(b.ctx(), &n, path,
         "a polygon needs at least 3 vertices, got " + std::to_string(arr.size()),
         "3 or more [x, z] pairs");
  Polygon poly;
  for (std::size_t i = 0; i < arr.size(); ++i)
    poly.vertices.push_back(
        readVec2(b.ctx(), *arr.get(i), path + "[" + std::to_string(i) + "]", Dimension::Length));
  std::string why;
  if (!makeSimpleCounterClockwise(poly, why))
    fail(b.ctx(), &n, path, why, "a simple polygon (no crossing or repeated edges), non-zero area");
  return poly;
}

Shape readShape(const TableReader& b, std::size_t shape) {
  switch (shape) {
    case 0: {
      Disk d;
      d.centre = readVec2(b.ctx(), b.require("centre", "[x, z] such as [\"0 cm\", \"1 cm\"]"),
                          b.keyPath("centre"), Dimension::Length);
      d.radius = b.quantity("radius", Dimension::Length);
      b.check(d.radius > 0.0, "radius", "must be > 0", "a length > 0");
      return d;
    }
    case 1: {
      const auto [x0, x1] =
          readInterval(b.ctx(), b.require("x", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                       b.keyPath("x"), Dimension::Length);
      const auto [z0, z1] =
          readInterval(b.ctx(), b.require("z", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                       b.keyPath("z"), Dimension::Length);
      return Rect{x0, x1, z0, z1};
    }
    default:
      return readPolygon(b);
  }
}

std::size_t materialIndex(const TableReader& b, const Scene& scene) {
  const std::string name = b.string("material");
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return i;
  std::vector<std::string_view> defined;
  for (const auto& m : scene.materials) defined.push_back(m.name);
  std::string problem = "material \"" + name + "\" is not defined in [materials]";
  if (auto near = closestKey(name, defined); !near.empty())
    problem += " (did you mean \"" + std::string(near) + "\"?)";
  b.fail("material", problem, join(defined));
}

// The initial specific energy: given, from a pressure through the EOS, or zero.
double initialEnergy(const TableReader& b, const eos::Eos& eos, double rho) {
  if (b.has("pressure") && b.has("specific_energy"))
    b.fail("pressure", "give either pressure or specific_energy, not both",
           "pressure or specific_energy");
  const double eMin = eos::lowestSpecificEnergy(eos);
  if (b.has("specific_energy")) {
    const double e = b.quantity("specific_energy", Dimension::SpecificEnergy);
    b.check(e >= eMin, "specific_energy",
            "below where the " + eos::kindName(eos) + " EOS is defined",
            "a specific energy >= " + shortNumber(eMin) + " cm^2/us^2");
    return e;
  }
  if (!b.has("pressure")) return 0.0;
  const double p = b.quantity("pressure", Dimension::Pressure);
  const std::string allowed = "a pressure the EOS reaches at this density, or specific_energy";
  double e = 0.0;
  try {
    e = eos::energyForPressure(eos, rho, p);
  } catch (const InputError& err) {
    // The EOS library names the state; the scene file names where it came from.
    b.fail("pressure", err.what(), allowed);
  }
  // The root finder converges to round-off; a residual above 1e-6 relative means no e reaches p
  // (e.g. tension under the cut-off).
  const double pe = eos::pressure(eos, rho, e);
  const bool reached =
      std::isfinite(e) && e >= eMin && std::abs(pe - p) <= 1e-6 * std::max(std::abs(p), 1e-12);
  b.check(reached, "pressure",
          "no specific energy gives this pressure at density " + shortNumber(rho) +
              " g/cm^3 with " + eos::kindName(eos),
          allowed);
  return e;
}

}  // namespace

void parseBodies(const TableReader& root, Scene& scene, Sources& sources) {
  const toml::node& n = root.require("bodies", "one or more [[bodies]] tables");
  const auto& arr = readArray(root.ctx(), n, "bodies", 0, "[[bodies]] tables");
  if (arr.empty()) fail(root.ctx(), &n, "bodies", "no body defined", "one or more [[bodies]]");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string path = "bodies[" + std::to_string(i) + "]";
    const toml::table* t = arr.get(i)->as_table();
    if (t == nullptr)
      fail(root.ctx(), arr.get(i), path,
           "expected a table, got " + std::string(typeName(*arr.get(i))), "[[bodies]] tables");
    const TableReader b(root.ctx(), *t, path);
    const std::size_t shape = b.choice("shape", shapeNames());
    rejectKeys(b, shape);

    Body body;
    body.name = b.string("name");
    b.check(!body.name.empty(), "name", "must not be empty", "a non-empty name");
    for (std::size_t j = 0; j < scene.bodies.size(); ++j)
      b.check(scene.bodies[j].name != body.name, "name",
              "\"" + body.name + "\" is already the name of bodies[" + std::to_string(j) + "]",
              "a name unique among the bodies");
    body.material = static_cast<int>(materialIndex(b, scene));
    body.shape = readShape(b, shape);
    if (b.has("velocity") && b.has("radial_velocity"))
      b.fail("radial_velocity", "give either velocity or radial_velocity, not both",
             "velocity = [vx, vz] (uniform) or radial_velocity = speed (radial field)");
    if (b.has("velocity"))
      body.velocity =
          readVec2(b.ctx(), b.require("velocity"), b.keyPath("velocity"), Dimension::Velocity);
    if (b.has("radial_velocity")) {
      body.radial = true;
      body.radialSpeed = b.quantity("radial_velocity", Dimension::Velocity);
      if (b.has("radial_centre")) {
        b.check(scene.geometry == Geometry::Planar, "radial_centre",
                "in rz geometry the radial field is about the axis; it has no centre",
                "no radial_centre in rz geometry");
        body.radialCentre = readVec2(b.ctx(), b.require("radial_centre"),
                                     b.keyPath("radial_centre"), Dimension::Length);
      }
    } else if (b.has("radial_centre")) {
      b.fail("radial_centre", "radial_centre needs radial_velocity",
             "radial_velocity = speed with radial_centre = [x, z]");
    }
    const eos::Eos& eos = scene.materials[static_cast<std::size_t>(body.material)].eos;
    body.density = eos::referenceDensity(eos);
    readKeys(b, bodyKeys(), body);  // density: the table's one non-Custom row
    body.specificEnergy = initialEnergy(b, eos, body.density);
    scene.bodies.push_back(std::move(body));
    sources.bodies.push_back(t);
  }
}

}  // namespace hvi::cases::detail
