//! @file `--set dotted.key=value` overrides: the path is checked against the scene schema, the
//! value is read as TOML (or, failing that, as a string) and replaces the document's value.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <span>
#include <utility>
#include <variant>

#include "detail/keys.hpp"
#include "detail/parse.hpp"
#include "hvi/common/error.hpp"

namespace hvi::cases::detail {
namespace {

using Component = std::variant<std::string, std::size_t>;  // key or array index

// What a path component lands on, to know the keys allowed below it.
enum class Kind {
  Root,
  Time,
  Domain,
  Boundaries,
  Materials,
  Material,
  Strength,
  Bodies,
  Body,
  Sph,
  Tvd,
  Riemann,
  Output,
  Leaf
};

struct Override {
  std::string text;  // the whole "key=value", for messages
  std::string file;
  [[noreturn]] void fail(const std::string& key, const std::string& problem,
                         const std::string& allowed = {}) const {
    std::string msg = file + " (--set " + text + "): " + key + ": " + problem;
    if (!allowed.empty()) msg += "; allowed: " + allowed;
    throw InputError(msg);
  }
};

std::string show(const std::vector<Component>& path, std::size_t upto) {
  std::string s;
  for (std::size_t i = 0; i < upto && i < path.size(); ++i) {
    if (const auto* k = std::get_if<std::string>(&path[i]))
      s += fmt::format("{}{}", s.empty() ? "" : ".", pathKey(*k));
    else
      s += fmt::format("[{}]", std::get<std::size_t>(path[i]));
  }
  return s;
}

std::vector<Component> parsePath(const Override& ov, std::string_view key) {
  std::vector<Component> path;
  std::size_t i = 0;
  const std::string usage = "dotted keys with [index], e.g. sph.alpha or bodies[1].radius";
  while (i < key.size()) {
    std::string name;
    if (key[i] == '"') {
      const std::size_t end = key.find('"', i + 1);
      if (end == std::string_view::npos) ov.fail(std::string(key), "unterminated quote", usage);
      name = std::string(key.substr(i + 1, end - i - 1));
      i = end + 1;
    } else {
      while (i < key.size() && key[i] != '.' && key[i] != '[') name += key[i++];
      if (name.empty()) ov.fail(std::string(key), "empty key in the path", usage);
    }
    path.emplace_back(name);
    while (i < key.size() && key[i] == '[') {
      const std::size_t end = key.find(']', i);
      const std::string_view digits =
          end == std::string_view::npos ? std::string_view{} : key.substr(i + 1, end - i - 1);
      if (digits.empty() || digits.size() > 9 ||
          !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(c); }))
        ov.fail(std::string(key), "bad array index", usage);
      path.emplace_back(static_cast<std::size_t>(std::stoul(std::string(digits))));
      i = end + 1;
    }
    if (i < key.size()) {
      if (key[i] != '.') ov.fail(std::string(key), "unexpected character", usage);
      if (++i == key.size()) ov.fail(std::string(key), "path ends with '.'", usage);
    }
  }
  if (path.empty()) ov.fail(std::string(key), "empty key", usage);
  return path;
}

std::span<const std::string_view> keysOf(Kind k) {
  // The key table of each kind of path node (keyNames' section names).
  static constexpr std::pair<Kind, std::string_view> kSections[] = {
      {Kind::Root, "root"},          {Kind::Time, "time"},   {Kind::Domain, "domain"},
      {Kind::Boundaries, "domain.boundaries"}, {Kind::Material, "materials"},
      {Kind::Strength, "materials.strength"},
      {Kind::Body, "bodies"},        {Kind::Sph, "sph"},     {Kind::Tvd, "tvd"},
      {Kind::Riemann, "riemann"},    {Kind::Output, "output"}};
  for (const auto& [kind, section] : kSections)
    if (kind == k) return keyNames(section);
  return {};
}

Kind childKind(Kind parent, std::string_view key) {
  if (parent == Kind::Materials) return Kind::Material;
  if (parent == Kind::Root) {
    if (key == "time") return Kind::Time;
    if (key == "domain") return Kind::Domain;
    if (key == "materials") return Kind::Materials;
    if (key == "bodies") return Kind::Bodies;
    if (key == "sph") return Kind::Sph;
    if (key == "tvd") return Kind::Tvd;
    if (key == "riemann") return Kind::Riemann;
    if (key == "output") return Kind::Output;
  }
  if (parent == Kind::Domain && key == "boundaries") return Kind::Boundaries;
  if (parent == Kind::Material && key == "strength") return Kind::Strength;
  return Kind::Leaf;
}

// The value: TOML if it reads as one ("1.5", "true", "[\"1 us\"]"), a string otherwise
// ("2 us", "superbee"). The source name marks its nodes so messages point at the override.
toml::table parseValue(const Override& ov, std::string_view value) {
  const std::string source = "--set " + ov.text;
  try {
    toml::table t = toml::parse("v = " + std::string(value), source);
    if (t.size() == 1 && t.contains("v")) return t;
  } catch (const toml::parse_error&) {
    // not TOML: a string
  }
  const std::string quoted = "v = " + tomlString(value);
  try {
    return toml::parse(quoted, source);
  } catch (const toml::parse_error& e) {
    ov.fail(std::string(value), "cannot read the value: " + std::string(e.description()));
  }
}

void apply(toml::table& doc, const Override& ov) {
  const std::size_t eq = ov.text.find('=');
  if (eq == std::string::npos)
    ov.fail(ov.text, "expected key=value", "e.g. --set sph.alpha=1.5 or --set time.end=\"2 us\"");
  auto trim = [](std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
  };
  const auto path = parsePath(ov, trim(std::string_view(ov.text).substr(0, eq)));
  toml::table value = parseValue(ov, trim(std::string_view(ov.text).substr(eq + 1)));

  toml::node* cur = &doc;
  Kind kind = Kind::Root;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const bool last = i + 1 == path.size();
    const std::string here = show(path, i + 1);
    if (const auto* key = std::get_if<std::string>(&path[i])) {
      if (kind == Kind::Leaf || kind == Kind::Bodies)
        ov.fail(here, "\"" + show(path, i) + "\" has no keys below it");
      const auto known = keysOf(kind);
      if (kind != Kind::Materials && std::find(known.begin(), known.end(), *key) == known.end()) {
        std::string problem = "unknown key";
        if (auto near = closestKey(*key, known); !near.empty())
          problem += " (did you mean \"" + std::string(near) + "\"?)";
        ov.fail(here, problem, join(known));
      }
      toml::table* table = cur->as_table();
      if (table == nullptr)
        ov.fail(here, "\"" + show(path, i) + "\" is " + std::string(typeName(*cur)) +
                          " in the scene, not a table");
      if (last) {
        table->insert_or_assign(*key, std::move(*value.get("v")));
        return;
      }
      if (!table->contains(*key)) {
        if (std::holds_alternative<std::size_t>(path[i + 1]))
          ov.fail(here, "the scene has no array here to index");
        table->insert(*key, toml::table{});
      }
      cur = table->get(*key);
      kind = childKind(kind, *key);
    } else {
      const std::size_t index = std::get<std::size_t>(path[i]);
      toml::array* arr = cur->as_array();
      if (arr == nullptr)
        ov.fail(here, "\"" + show(path, i) + "\" is " + std::string(typeName(*cur)) +
                          " in the scene, not an array");
      if (index >= arr->size())
        ov.fail(here,
                "no element " + std::to_string(index) + ": \"" + show(path, i) + "\" has " +
                    std::to_string(arr->size()),
                arr->empty() ? std::string("none: the array is empty")
                             : "indices 0 to " + std::to_string(arr->size() - 1));
      if (last) {
        arr->replace(arr->cbegin() + static_cast<std::ptrdiff_t>(index),
                     std::move(*value.get("v")));
        return;
      }
      cur = arr->get(index);
      kind = kind == Kind::Bodies ? Kind::Body : Kind::Leaf;
    }
  }
}

}  // namespace

void applyOverrides(toml::table& doc, const std::vector<std::string>& overrides,
                    const std::string& file) {
  for (const auto& text : overrides) apply(doc, Override{text, file});
}

}  // namespace hvi::cases::detail
