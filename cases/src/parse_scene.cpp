//! @file Scene files to Scene: the document, its top-level keys, effects, [time] and [domain];
//! loadScene and parseScene.
#include <array>
#include <fstream>
#include <sstream>

#include "detail/parse.hpp"
#include "detail/schema.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/common/error.hpp"

namespace hvi::cases {
namespace detail {
namespace {

constexpr std::array<std::string_view, 1> kUnitSystems{"cm-g-us"};

void parseEffects(const TableReader& root, Scene& scene) {
  const toml::node* n = root.find("effects");
  if (n == nullptr) return;
  const auto names = allEffectNames();
  const auto& arr = readArray(root.ctx(), *n, "effects", 0, "[\"tension_cutoff\", ...]");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string path = "effects[" + std::to_string(i) + "]";
    const std::string name = readString(root.ctx(), *arr.get(i), path);
    const auto e = effectFromString(name);
    if (!e) {
      std::string problem = "unknown effect \"" + name + "\"";
      if (auto near = closestKey(name, names); !near.empty())
        problem += " (did you mean \"" + std::string(near) + "\"?)";
      fail(root.ctx(), arr.get(i), path, problem, join(names));
    }
    if (!supports(scene.solver, *e)) {
      std::vector<std::string_view> ok;
      for (Effect s : supportedEffects(scene.solver)) ok.push_back(toString(s));
      fail(root.ctx(), arr.get(i), path,
           "effect \"" + name + "\" is not supported by solver \"" +
               std::string(toString(scene.solver)) + "\"",
           join(ok));
    }
    if (!scene.effects.insert(*e).second)
      fail(root.ctx(), arr.get(i), path, "effect \"" + name + "\" is listed twice",
           "each effect once");
  }
}

void parseTime(const TableReader& root, Scene& scene) {
  const auto t = root.subTable("time", true);
  t->rejectUnknown(kTimeKeys);
  scene.tStart = t->quantity("start", Dimension::Time, 0.0);
  scene.tEnd = t->quantity("end", Dimension::Time);
  t->check(scene.tEnd > scene.tStart, "end",
           "must be after time.start (" + shortNumber(scene.tStart) + " us)", "end > start");
}

void parseDomain(const TableReader& root, Scene& scene) {
  const auto d = root.subTable("domain", true);
  d->rejectUnknown(kDomainKeys);
  Domain& dom = scene.domain;
  std::tie(dom.xmin, dom.xmax) =
      readInterval(root.ctx(), d->require("x", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                   d->keyPath("x"), Dimension::Length);
  std::tie(dom.zmin, dom.zmax) =
      readInterval(root.ctx(), d->require("z", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                   d->keyPath("z"), Dimension::Length);
  const bool rz = scene.geometry == Geometry::Axisymmetric;
  if (rz)
    d->check(dom.xmin == 0.0, "x",
             "in rz geometry x is the radius and the domain starts on the axis: x[0] must be 0",
             "x = [\"0 cm\", max]");
  dom.boundary = {rz ? Boundary::Axis : Boundary::Outflow, Boundary::Outflow, Boundary::Outflow,
                  Boundary::Outflow};
  const auto b = d->subTable("boundaries", false);
  if (!b) return;
  b->rejectUnknown(kBoundaryKeys);
  for (std::size_t side = 0; side < 4; ++side) {
    const std::string_view key = kBoundaryKeys[side];
    dom.boundary[side] = static_cast<Boundary>(
        b->choice(key, boundaryNames(), static_cast<std::size_t>(dom.boundary[side])));
    const bool axis = dom.boundary[side] == Boundary::Axis;
    if (rz && side == 0)
      b->check(axis, key, "in rz geometry the xmin boundary is the symmetry axis", "axis");
    else if (rz)
      b->check(!axis, key, "axis is allowed only at xmin in rz geometry", "outflow, wall");
    else
      b->check(!axis, key, "an axis boundary needs geometry = \"rz\"", "outflow, wall");
  }
}

Scene build(const toml::table& doc, const std::string& file) {
  Context ctx{file, false};
  const TableReader root(ctx, doc, "");
  root.rejectUnknown(kRootKeys);
  if (root.has("units")) {
    (void)root.choice("units", kUnitSystems);
    ctx.bareNumbersAreInternal = true;
  }
  Scene scene;
  scene.path = file;
  scene.title = root.string("title", "");
  scene.geometry = static_cast<Geometry>(root.choice("geometry", geometryNames()));
  scene.solver = static_cast<SolverKind>(root.choice("solver", solverNames()));
  parseEffects(root, scene);
  parseTime(root, scene);
  parseDomain(root, scene);
  parseMaterials(root, scene);
  Sources sources;
  parseBodies(root, scene, sources);
  parseSolverParams(root, scene);
  parseOutput(root, scene);
  validateScene(root, scene, sources);
  return scene;
}

}  // namespace
}  // namespace detail

Scene parseScene(std::string_view text, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  toml::table doc;
  try {
    doc = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    const auto& pos = e.source().begin;
    throw InputError(sourceName + ":" + std::to_string(pos.line) + ": syntax error: " +
                     std::string(e.description()) + " (column " + std::to_string(pos.column) + ")");
  }
  detail::applyOverrides(doc, overrides, sourceName);
  return detail::build(doc, sourceName);
}

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), file.string(), overrides);
}

}  // namespace hvi::cases
