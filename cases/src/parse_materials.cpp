//! @file [materials.<name>]: a preset or an EOS with all its parameters, in file order.
#include <algorithm>
#include <array>
#include <vector>

#include "detail/keys.hpp"
#include "detail/parse.hpp"
#include "hvi/cases/effects.hpp"
#include "hvi/cases/presets.hpp"

namespace hvi::cases::detail {
namespace {

// A key of another EOS gets a message naming this one; anything else the nearest key.
void rejectKeys(const TableReader& m, std::string_view kind) {
  const auto known = keyNames("materials." + std::string(kind));
  const auto any = keyNames("materials");
  for (const auto& [k, v] : m.table()) {
    const std::string_view key = k.str();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    if (std::find(any.begin(), any.end(), key) != any.end())
      m.fail(key, "not a parameter of eos = \"" + std::string(kind) + "\"", join(known));
  }
  m.rejectUnknown(known);
}

// Reads the EOS's table: every key required without a preset, the preset's value otherwise.
template <class E>
E readParams(const TableReader& m, std::size_t kind, E e, bool fromPreset) {
  rejectKeys(m, eosNames()[kind]);
  readKeys(m, eosKeys(e), e, fromPreset);
  return e;
}

eos::Eos readEos(const TableReader& m) {
  std::optional<eos::Eos> preset;
  if (m.has("preset")) preset = materialPreset(presetNames()[m.choice("preset", presetNames())]);
  std::size_t kind = 0;
  if (m.has("eos")) {
    kind = m.choice("eos", eosNames());
    if (preset && preset->index() != kind)
      m.fail("eos", "the preset is a \"" + eos::kindName(*preset) + "\" EOS",
             "leave eos out or write eos = \"" + eos::kindName(*preset) + "\"");
  } else if (preset) {
    kind = preset->index();
  } else {
    m.fail("eos", "missing: give preset = \"...\" or eos = \"...\" with its parameters",
           "preset: " + join(presetNames()) + "; eos: " + join(eosNames()));
  }
  const bool p = preset.has_value();
  switch (kind) {
    case 0: {
      const auto t =
          readParams(m, kind, p ? std::get<eos::Tillotson>(*preset) : eos::Tillotson{}, p);
      m.check(t.e2 > t.e1, "e2", "must be > e1 (full vaporisation after incipient)", "e2 > e1");
      return t;
    }
    case 1:
      return readParams(m, kind, p ? std::get<eos::IdealGas>(*preset) : eos::IdealGas{}, p);
    default:
      return readParams(m, kind, p ? std::get<eos::MieGruneisen>(*preset) : eos::MieGruneisen{},
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
    Material mat{name, readEos(m), std::nullopt};
    if (const auto st = m.subTable("strength", false)) mat.strength = parseStrength(*st);
    scene.materials.push_back(std::move(mat));
  }
  // The tension cut-off is the scene's effect, switched in as every solver switches it.
  scene.materials = resolveMaterials(scene);
}

}  // namespace hvi::cases::detail
