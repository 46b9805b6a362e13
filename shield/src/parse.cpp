//! @file Reading a shield declaration (TOML) into a ShieldSpec; every error names file, line,
//! key and what is allowed.
#include <algorithm>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "hvi/cases/load.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/cases/quantity.hpp"
#include "hvi/common/error.hpp"
#include "hvi/shield/shield.hpp"

namespace hvi::shield {
namespace {

using cases::Dimension;

struct Reader {
  std::string file;

  [[noreturn]] void fail(const toml::node* at, std::string_view key, std::string_view problem,
                         std::string_view allowed) const {
    std::string where = file;
    if (at != nullptr && at->source().begin.line != 0)
      where += ":" + std::to_string(at->source().begin.line);
    std::string msg = where + ": " + std::string(key) + ": " + std::string(problem);
    if (!allowed.empty()) msg += "; allowed: " + std::string(allowed);
    throw InputError(msg);
  }

  void rejectUnknown(const toml::table& t, std::string_view section,
                     std::initializer_list<std::string_view> known) const {
    for (const auto& [k, v] : t) {
      if (std::find(known.begin(), known.end(), k.str()) != known.end()) continue;
      std::string list;
      for (auto n : known) list += (list.empty() ? "" : ", ") + std::string(n);
      fail(&v,
           section.empty() ? std::string(k.str())
                           : std::string(section) + "." + std::string(k.str()),
           "unknown key", list);
    }
  }

  const toml::node* need(const toml::table& t, std::string_view key, std::string_view path,
                         std::string_view allowed) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) fail(&t, path, "missing", allowed);
    return n;
  }

  double quantity(const toml::table& t, std::string_view key, std::string_view path, Dimension d,
                  bool positive, std::optional<double> fallback = std::nullopt) const {
    const toml::node* n = t.get(key);
    const std::string allowed =
        "\"<number> <unit>\" with a " + std::string(cases::dimensionName(d)) +
        " unit: " + cases::allowedUnits(d) + (positive ? ", > 0" : ", >= 0");
    if (n == nullptr) {
      if (fallback) return *fallback;
      fail(&t, path, "missing", allowed);
    }
    const auto* s = n->as_string();
    if (s == nullptr) fail(n, path, "expected a quantity with a unit", allowed);
    std::string why;
    const auto v = cases::parseQuantity(s->get(), d, &why);
    if (!v) fail(n, path, why, allowed);
    if (positive ? !(*v > 0) : !(*v >= 0))
      fail(n, path, positive ? "must be > 0" : "must be >= 0", allowed);
    return *v;
  }

  double number(const toml::table& t, std::string_view key, std::string_view path, double fallback,
                double min) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return fallback;
    const auto v = n->value<double>();
    const std::string allowed = fmt::format("a number >= {}", min);
    if (!v) fail(n, path, "expected a number", allowed);
    if (!(*v >= min)) fail(n, path, "out of range", allowed);
    return *v;
  }

  ShieldMaterial material(const toml::table& t, std::string_view path) const {
    std::string names;
    for (const auto& m : shieldMaterials()) names += (names.empty() ? "" : ", ") + m.name;
    const toml::node* n = need(t, "material", path, names);
    const auto* s = n->as_string();
    if (s == nullptr) fail(n, path, "expected a material name", names);
    const ShieldMaterial* m = findShieldMaterial(s->get());
    if (m == nullptr) fail(n, path, "unknown material \"" + s->get() + "\"", names);
    return *m;
  }
};

}  // namespace

ShieldSpec parseShield(std::string_view text, const std::string& sourceName) {
  const Reader r{sourceName};
  toml::table root;
  try {
    root = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: {}", sourceName, e.source().begin.line, e.description()));
  }
  r.rejectUnknown(root, "",
                  {"title", "source", "solver", "projectile", "walls", "resolution", "radius",
                   "end_time", "snapshots"});
  ShieldSpec s;
  s.path = sourceName;
  s.title = root["title"].value_or(std::string("shield"));
  s.source = root["source"].value_or(std::string());
  if (const toml::node* n = root.get("solver")) {
    const auto v = n->value<std::string>();
    if (!v || (*v != "sph" && *v != "tvd")) r.fail(n, "solver", "not a shield solver", "sph, tvd");
    s.solver = *v == "sph" ? cases::SolverKind::Sph : cases::SolverKind::Tvd;
  }

  const auto* p = root["projectile"].as_table();
  if (p == nullptr)
    r.fail(&root, "projectile", "missing table", "[projectile] with material, diameter, speed");
  r.rejectUnknown(*p, "projectile", {"material", "diameter", "speed"});
  s.projectile.material = r.material(*p, "projectile.material");
  s.projectile.diameter =
      r.quantity(*p, "diameter", "projectile.diameter", Dimension::Length, true);
  // Internal speeds are cm/us; the shield works in km/s (1 cm/us = 10 km/s).
  s.projectile.speed =
      10.0 * r.quantity(*p, "speed", "projectile.speed", Dimension::Velocity, true);

  const auto* walls = root["walls"].as_array();
  if (walls == nullptr || walls->size() < 2)
    r.fail(walls ? static_cast<const toml::node*>(walls) : &root, "walls",
           "a shield needs at least two [[walls]] (bumper first, rear wall last)",
           "two or more [[walls]] tables with material, thickness and (after the first) gap");
  for (std::size_t i = 0; i < walls->size(); ++i) {
    const std::string path = fmt::format("walls[{}]", i);
    const auto* w = (*walls)[i].as_table();
    if (w == nullptr) r.fail(&(*walls)[i], path, "expected a table", "[[walls]]");
    r.rejectUnknown(*w, path, {"name", "material", "thickness", "gap"});
    Wall wall;
    const bool last = i + 1 == walls->size();
    wall.name = last ? kRearWall : i == 0 ? "bumper" : fmt::format("wall_{}", i + 1);
    if (const toml::node* n = w->get("name")) {
      const auto v = n->value<std::string>();
      if (!v || v->empty() || *v == kProjectile || (last && *v != kRearWall) ||
          (!last && *v == kRearWall))
        r.fail(n, path + ".name",
               last ? "the last wall is the rear wall" : "a name other than the reserved ones",
               last ? "\"rear_wall\" (or leave it out)"
                    : "any non-empty name but projectile, rear_wall");
      wall.name = *v;
    }
    wall.material = r.material(*w, path + ".material");
    wall.thickness = r.quantity(*w, "thickness", path + ".thickness", Dimension::Length, true);
    if (i == 0) {
      if (w->contains("gap"))
        r.fail(w->get("gap"), path + ".gap", "the bumper has no gap before it", "leave gap out");
    } else {
      wall.gap = r.quantity(*w, "gap", path + ".gap", Dimension::Length, true);
    }
    for (const auto& other : s.walls)
      if (other.name == wall.name)
        r.fail(w, path + ".name", "two walls named \"" + wall.name + "\"", "unique names");
    s.walls.push_back(std::move(wall));
  }

  if (const auto* res = root["resolution"].as_table()) {
    r.rejectUnknown(*res, "resolution",
                    {"cells_across_projectile", "cells_across_thinnest_wall", "spacing"});
    // A fixed spacing replaces the two knobs; both at once would leave one of them unused
    // without a word, so that is refused.
    if (res->contains("spacing")) {
      for (const char* k : {"cells_across_projectile", "cells_across_thinnest_wall"})
        if (res->contains(k))
          r.fail(res->get(k), std::string("resolution.") + k,
                 "given with resolution.spacing, which replaces it",
                 "either spacing alone or the cells_across_* knobs");
      s.resolution.spacing =
          r.quantity(*res, "spacing", "resolution.spacing", Dimension::Length, true);
    }
    s.resolution.cellsAcrossProjectile =
        r.number(*res, "cells_across_projectile", "resolution.cells_across_projectile", 8.0, 1.0);
    s.resolution.cellsAcrossThinnestWall = r.number(
        *res, "cells_across_thinnest_wall", "resolution.cells_across_thinnest_wall", 3.0, 1.5);
  }
  if (root.contains("radius"))
    s.radius = r.quantity(root, "radius", "radius", Dimension::Length, true);
  if (root.contains("end_time"))
    s.endTime = r.quantity(root, "end_time", "end_time", Dimension::Time, true);
  s.snapshots = static_cast<int>(r.number(root, "snapshots", "snapshots", 8.0, 1.0));
  if (s.radius && *s.radius < s.projectile.diameter)
    r.fail(root.get("radius"), "radius", "smaller than the projectile's diameter",
           "a radius >= projectile.diameter");
  return s;
}

ShieldSpec loadShield(const std::filesystem::path& file) {
  return parseShield(cases::readInputFile(file.string(), "shield"), file.string());
}

}  // namespace hvi::shield
