//! @file [materials.<name>]: a preset or an EOS with all its parameters, in file order.
#include <algorithm>
#include <array>
#include <vector>

#include "detail/parse.hpp"
#include "detail/schema.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/cases/presets.hpp"

namespace hvi::cases::detail {
namespace {

constexpr std::array<std::string_view, 3> kCommonNoFloor{"preset", "eos", "rho0"};

// Reads one parameter: required without a preset, the preset's value otherwise.
class ParamReader {
 public:
  ParamReader(const TableReader& m, bool fromPreset) : m_(m), fromPreset_(fromPreset) {}
  void quantity(std::string_view key, Dimension d, double& field) const {
    field = m_.quantity(key, d, fromPreset_ ? std::optional<double>(field) : std::nullopt);
  }
  void number(std::string_view key, double& field) const {
    field = m_.number(key, fromPreset_ ? std::optional<double>(field) : std::nullopt);
  }
  void floor(double& field) const {
    field = m_.number("sound_speed_floor", field);
    m_.check(field >= 0.0 && field < 1.0, "sound_speed_floor",
             "must be in [0, 1) (a fraction of the reference sound speed)",
             "0 <= sound_speed_floor < 1");
  }

 private:
  const TableReader& m_;
  bool fromPreset_;
};

std::string keysOf(std::span<const std::string_view> common,
                   std::span<const std::string_view> params) {
  return join(common) + ", " + join(params);
}

void rejectKeys(const TableReader& m, std::span<const std::string_view> common,
                std::span<const std::string_view> params, std::string_view kind) {
  std::vector<std::string_view> known(common.begin(), common.end());
  known.insert(known.end(), params.begin(), params.end());
  for (const auto& [k, v] : m.table()) {
    const std::string_view key = k.str();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    if (std::find(kMaterialKeys.begin(), kMaterialKeys.end(), key) != kMaterialKeys.end())
      m.fail(key, "not a parameter of eos = \"" + std::string(kind) + "\"", keysOf(common, params));
  }
  m.rejectUnknown(known);
}

eos::Tillotson readTillotson(const TableReader& m, eos::Tillotson t, bool fromPreset) {
  rejectKeys(m, kMaterialCommonKeys, kTillotsonKeys, "tillotson");
  const ParamReader p(m, fromPreset);
  p.quantity("rho0", Dimension::Density, t.rho0);
  p.number("a", t.a);
  p.number("b", t.b);
  p.quantity("A", Dimension::Pressure, t.A);
  p.quantity("B", Dimension::Pressure, t.B);
  p.quantity("e0", Dimension::SpecificEnergy, t.e0);
  p.number("alpha", t.alpha);
  p.number("beta", t.beta);
  p.quantity("e1", Dimension::SpecificEnergy, t.e1);
  p.quantity("e2", Dimension::SpecificEnergy, t.e2);
  p.floor(t.soundSpeedFloorFraction);
  m.check(t.rho0 > 0.0, "rho0", "must be > 0", "a density > 0");
  m.check(t.a >= 0.0, "a", "must be >= 0", "a >= 0");
  m.check(t.b >= 0.0, "b", "must be >= 0", "b >= 0");
  m.check(t.A > 0.0, "A", "must be > 0 (the bulk modulus)", "a pressure > 0");
  m.check(t.e0 > 0.0, "e0", "must be > 0", "a specific energy > 0");
  m.check(t.alpha >= 0.0, "alpha", "must be >= 0", "alpha >= 0");
  m.check(t.beta >= 0.0, "beta", "must be >= 0", "beta >= 0");
  m.check(t.e1 >= 0.0, "e1", "must be >= 0", "a specific energy >= 0");
  m.check(t.e2 > t.e1, "e2", "must be > e1 (full vaporisation after incipient)", "e2 > e1");
  return t;
}

eos::IdealGas readIdealGas(const TableReader& m, eos::IdealGas g, bool fromPreset) {
  rejectKeys(m, kCommonNoFloor, kIdealGasKeys, "ideal_gas");
  const ParamReader p(m, fromPreset);
  p.quantity("rho0", Dimension::Density, g.rho0);
  p.number("gamma", g.gamma);
  m.check(g.rho0 > 0.0, "rho0", "must be > 0", "a density > 0");
  m.check(g.gamma > 1.0, "gamma", "must be > 1", "gamma > 1");
  return g;
}

eos::MieGruneisen readMieGruneisen(const TableReader& m, eos::MieGruneisen g, bool fromPreset) {
  rejectKeys(m, kMaterialCommonKeys, kMieGruneisenKeys, "mie_gruneisen");
  const ParamReader p(m, fromPreset);
  p.quantity("rho0", Dimension::Density, g.rho0);
  p.quantity("c0", Dimension::Velocity, g.c0);
  p.number("s", g.s);
  p.number("gamma0", g.gamma0);
  p.floor(g.soundSpeedFloorFraction);
  m.check(g.rho0 > 0.0, "rho0", "must be > 0", "a density > 0");
  m.check(g.c0 > 0.0, "c0", "must be > 0", "a velocity > 0");
  m.check(g.s > 0.0, "s", "must be > 0", "s > 0");
  m.check(g.gamma0 >= 0.0, "gamma0", "must be >= 0", "gamma0 >= 0");
  return g;
}

eos::Eos readEos(const TableReader& m) {
  std::optional<eos::Eos> preset;
  if (m.has("preset")) preset = materialPreset(presetNames()[m.choice("preset", presetNames())]);
  std::size_t kind = 0;
  if (m.has("eos")) {
    kind = m.choice("eos", kEosNames);
    if (preset && preset->index() != kind)
      m.fail("eos", "the preset is a \"" + eos::kindName(*preset) + "\" EOS",
             "leave eos out or write eos = \"" + eos::kindName(*preset) + "\"");
  } else if (preset) {
    kind = preset->index();
  } else {
    m.fail("eos", "missing: give preset = \"...\" or eos = \"...\" with its parameters",
           "preset: " + join(presetNames()) + "; eos: " + join(kEosNames));
  }
  const bool p = preset.has_value();
  switch (kind) {
    case 0:
      return readTillotson(m, p ? std::get<eos::Tillotson>(*preset) : eos::Tillotson{}, p);
    case 1:
      return readIdealGas(m, p ? std::get<eos::IdealGas>(*preset) : eos::IdealGas{}, p);
    default:
      return readMieGruneisen(m, p ? std::get<eos::MieGruneisen>(*preset) : eos::MieGruneisen{},
                              p);
  }
}

}  // namespace

void parseMaterials(const TableReader& root, Scene& scene) {
  const auto mats = root.subTable("materials", true);
  if (mats->table().empty())
    root.fail("materials", "no material defined", "one or more [materials.<name>] tables");
  // toml++ keeps keys sorted; the file's order (by line) is what a reader expects for indices.
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [k, v] : mats->table()) entries.emplace_back(std::string(k.str()), &v);
  const Context& ctx = root.ctx();
  std::stable_sort(entries.begin(), entries.end(), [&](const auto& l, const auto& r) {
    return lineInFile(ctx, *l.second) < lineInFile(ctx, *r.second);
  });
  for (const auto& [name, node] : entries) {
    const std::string path = mats->keyPath(name);
    const toml::table* t = node->as_table();
    if (t == nullptr)
      fail(root.ctx(), node, path, "expected a table, got " + std::string(typeName(*node)),
           "[" + path + "] with preset = \"...\" or eos = \"...\"");
    if (name.empty()) fail(root.ctx(), node, path, "a material needs a non-empty name");
    const TableReader m(root.ctx(), *t, path);
    scene.materials.push_back(Material{name, readEos(m)});
  }
  // The tension cut-off is the scene's effect, switched in as every solver switches it.
  scene.materials = resolveMaterials(scene);
}

}  // namespace hvi::cases::detail
