//! @file [materials.<name>.strength]: a strength preset or a yield model with all its
//! parameters, the temperature model and the damage model (docs/strength.md).
#include <algorithm>
#include <string>
#include <vector>

#include "detail/keys.hpp"
#include "detail/parse.hpp"

namespace hvi::cases::detail {
namespace {

// The rows of `rows` that apply to alternative `index` (variant -1: every alternative).
std::vector<KeyRow<strength::Material>> rowsFor(std::span<const KeyRow<strength::Material>> rows,
                                                int index, bool common) {
  std::vector<KeyRow<strength::Material>> out;
  for (const auto& r : rows)
    if (common ? r.variant < 0 : r.variant == index) out.push_back(r);
  return out;
}

std::vector<std::string_view> presetNamesOf() {
  std::vector<std::string_view> n;
  for (const auto& p : strength::presets()) n.push_back(p.name);
  return n;
}

template <class Variant>
Variant defaultAlternative(std::size_t i) {
  Variant v;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((i == I ? (void)v.template emplace<I>() : void()), ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
  return v;
}

// Keys of another yield or damage model get a message naming the chosen one.
void rejectOtherModels(const TableReader& t, int model, int damage) {
  std::vector<std::string_view> known;
  for (const auto& r : strengthKeys())
    if (r.variant < 0 || r.variant == model) known.push_back(r.key);
  for (const auto& r : damageKeys())
    if (r.variant == damage) known.push_back(r.key);
  const auto any = strengthKeyNames();
  for (const auto& [k, v] : t.table()) {
    const std::string_view key = k.str();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    if (std::find(any.begin(), any.end(), key) != any.end())
      t.fail(key,
             "not a parameter of model = \"" +
                 std::string(strength::yieldModelNames()[static_cast<std::size_t>(model)]) +
                 "\" with damage = \"" +
                 std::string(strength::damageModelNames()[static_cast<std::size_t>(damage)]) + "\"",
             join(known));
  }
  t.rejectUnknown(known);
}

}  // namespace

strength::Material parseStrength(const TableReader& t) {
  const auto presets = presetNamesOf();
  const strength::Preset* preset = nullptr;
  if (t.has("preset")) preset = &strength::presets()[t.choice("preset", presets)];
  strength::Material m = preset != nullptr ? preset->material : strength::Material{};

  const auto models = strength::yieldModelNames();
  const auto damages = strength::damageModelNames();
  std::size_t model = 0;
  if (t.has("model")) {
    model = t.choice("model", models);
  } else if (preset != nullptr) {
    model = m.yield.index();
  } else {
    t.fail("model", "missing: give preset = \"...\" or model = \"...\" with its parameters",
           "preset: " + join(presets) + "; model: " + join(models));
  }
  const bool samePreset = preset != nullptr && model == preset->material.yield.index();
  if (!samePreset && model != m.yield.index())
    m.yield = defaultAlternative<strength::YieldModel>(model);
  std::size_t damage = t.has("damage") ? t.choice("damage", damages) : m.damage.index();
  const bool sameDamage = preset != nullptr && damage == preset->material.damage.index();
  if (!sameDamage && damage != m.damage.index())
    m.damage = defaultAlternative<strength::DamageModel>(damage);
  rejectOtherModels(t, static_cast<int>(model), static_cast<int>(damage));

  const int mi = static_cast<int>(model), di = static_cast<int>(damage);
  const auto common = rowsFor(strengthKeys(), -1, true);
  readKeys<strength::Material>(t, common, m, preset != nullptr);
  readKeys<strength::Material>(t, rowsFor(strengthKeys(), mi, false), m, samePreset);
  readKeys<strength::Material>(t, rowsFor(damageKeys(), di, false), m, sameDamage);

  // One shear modulus: Steinberg-Guinan's G0 is the material's.
  if (auto* sg = std::get_if<strength::SteinbergGuinan>(&m.yield)) sg->g0 = m.shearModulus;
  if (const auto* jc = std::get_if<strength::JohnsonCook>(&m.yield))
    t.check(jc->meltTemperature > jc->roomTemperature, "jc_melt_temperature",
            "must be > jc_room_temperature", "jc_melt_temperature > jc_room_temperature");
  return m;
}

}  // namespace hvi::cases::detail
