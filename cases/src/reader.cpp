//! @file Located, typed reads of scene-file values; the only place messages are formatted.
#include "detail/reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hvi/common/error.hpp"

namespace hvi::cases::detail {
namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string lower(std::string_view s) {
  std::string r(s);
  for (auto& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

std::string quoted(std::string_view s) { return fmt::format("\"{}\"", s); }

std::string unitHint(Dimension d) {
  return "\"<number> <unit>\" with a " + std::string(dimensionName(d)) +
         " unit: " + allowedUnits(d);
}

}  // namespace

std::string location(const Context& ctx, const toml::node* node) {
  if (node == nullptr) return ctx.file;
  const auto& src = node->source();
  if (src.path && src.path->rfind("--set ", 0) == 0) return ctx.file + " (" + *src.path + ")";
  if (src.begin.line == 0) return ctx.file;
  return ctx.file + ":" + std::to_string(src.begin.line);
}

std::uint32_t lineInFile(const Context& ctx, const toml::node& node) {
  const auto& src = node.source();
  if (!src.path || *src.path != ctx.file || src.begin.line == 0) return ~std::uint32_t{0};
  return src.begin.line;
}

void fail(const Context& ctx, const toml::node* where, std::string_view key,
          std::string_view problem, std::string_view allowed) {
  std::string msg = location(ctx, where) + ": ";
  if (!key.empty()) msg += std::string(key) + ": ";
  msg += problem;
  if (!allowed.empty()) msg += "; allowed: " + std::string(allowed);
  throw InputError(msg);
}

std::string shortNumber(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string join(std::span<const std::string_view> names) {
  std::string s;
  for (auto n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

std::string_view closestKey(std::string_view key, std::span<const std::string_view> known) {
  std::string_view best;
  std::size_t bestD = ~std::size_t{0};
  const std::string k = lower(key);
  for (auto cand : known) {
    const std::size_t d = lower(cand) == k ? 0 : editDistance(key, cand);
    if (d < bestD) {
      bestD = d;
      best = cand;
    }
  }
  // Near enough to be a typo: a third of the letters, at least two edits for short keys.
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
  return bestD <= limit ? best : std::string_view{};
}

std::string_view typeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time of day";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

std::string tomlString(std::string_view s) {
  std::string q = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      q += '\\';
      q += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else {
      q += ch;
    }
  }
  return q + "\"";
}

std::string pathKey(std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  return bare ? std::string(key) : tomlString(key);
}

double readNumber(const Context& ctx, const toml::node& n, const std::string& path) {
  double v = 0.0;
  if (auto i = n.as_integer())
    v = static_cast<double>(i->get());
  else if (auto f = n.as_floating_point())
    v = f->get();
  else
    fail(ctx, &n, path, "expected a number, got " + std::string(typeName(n)),
         "a dimensionless number such as 1.5");
  if (!std::isfinite(v)) fail(ctx, &n, path, "must be finite", "a finite number");
  return v;
}

long long readInteger(const Context& ctx, const toml::node& n, const std::string& path) {
  if (auto i = n.as_integer()) return i->get();
  fail(ctx, &n, path, "expected an integer, got " + std::string(typeName(n)),
       "an integer such as 400");
}

bool readBool(const Context& ctx, const toml::node& n, const std::string& path) {
  if (auto b = n.as_boolean()) return b->get();
  fail(ctx, &n, path, "expected a boolean, got " + std::string(typeName(n)), "true, false");
}

std::string readString(const Context& ctx, const toml::node& n, const std::string& path) {
  if (auto s = n.as_string()) return s->get();
  fail(ctx, &n, path, "expected a string, got " + std::string(typeName(n)), "a quoted string");
}

double readQuantity(const Context& ctx, const toml::node& n, const std::string& path, Dimension d) {
  if (auto s = n.as_string()) {
    std::string why;
    if (auto v = parseQuantity(s->get(), d, &why)) return *v;
    fail(ctx, &n, path, why, unitHint(d));
  }
  if (n.is_number()) {
    if (!ctx.bareNumbersAreInternal)
      fail(ctx, &n, path,
           "a bare number has no unit; write it as a string like \"1.5 " +
               std::string(internalUnit(d)) +
               "\", or put units = \"cm-g-us\" at the top of the file to read bare numbers "
               "as internal units",
           unitHint(d));
    return readNumber(ctx, n, path);
  }
  fail(ctx, &n, path,
       "expected a " + std::string(dimensionName(d)) + ", got " + std::string(typeName(n)),
       unitHint(d));
}

const toml::array& readArray(const Context& ctx, const toml::node& n, const std::string& path,
                             std::size_t size, std::string_view example) {
  const toml::array* a = n.as_array();
  if (a == nullptr)
    fail(ctx, &n, path, "expected an array, got " + std::string(typeName(n)), example);
  if (size != 0 && a->size() != size)
    fail(ctx, &n, path,
         "expected " + std::to_string(size) + " values, got " + std::to_string(a->size()), example);
  return *a;
}

Vec2 readVec2(const Context& ctx, const toml::node& n, const std::string& path, Dimension d) {
  const std::string u(internalUnit(d));
  const auto& a = readArray(ctx, n, path, 2, "[x, z] such as [\"0 " + u + "\", \"1 " + u + "\"]");
  return {readQuantity(ctx, *a.get(0), path + "[0]", d),
          readQuantity(ctx, *a.get(1), path + "[1]", d)};
}

std::pair<double, double> readInterval(const Context& ctx, const toml::node& n,
                                       const std::string& path, Dimension d) {
  const std::string u(internalUnit(d));
  const auto& a =
      readArray(ctx, n, path, 2, "[min, max] such as [\"0 " + u + "\", \"1 " + u + "\"]");
  const double lo = readQuantity(ctx, *a.get(0), path + "[0]", d);
  const double hi = readQuantity(ctx, *a.get(1), path + "[1]", d);
  if (!(lo < hi)) fail(ctx, &n, path, "must be increasing, min < max", "[min, max] with min < max");
  return {lo, hi};
}

std::size_t readChoice(const Context& ctx, const toml::node& n, const std::string& path,
                       std::span<const std::string_view> names) {
  const std::string s = readString(ctx, n, path);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == s) return i;
  std::string problem = "unknown value " + quoted(s);
  if (auto near = closestKey(s, names); !near.empty())
    problem += " (did you mean " + quoted(near) + "?)";
  fail(ctx, &n, path, problem, join(names));
}

std::string TableReader::keyPath(std::string_view key) const {
  return path_.empty() ? pathKey(key) : path_ + "." + pathKey(key);
}

const toml::node* TableReader::find(std::string_view key) const { return table_.get(key); }

const toml::node& TableReader::require(std::string_view key, std::string_view hint) const {
  if (const toml::node* n = find(key)) return *n;
  detail::fail(ctx_, &table_, keyPath(key), "missing required key", hint);
}

void TableReader::rejectUnknown(std::span<const std::string_view> known) const {
  for (const auto& [k, v] : table_) {
    const std::string_view key = k.str();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string problem = "unknown key";
    if (auto near = closestKey(key, known); !near.empty())
      problem += " (did you mean " + quoted(near) + "?)";
    detail::fail(ctx_, &v, keyPath(key), problem, join(known));
  }
}

void TableReader::fail(std::string_view key, std::string_view problem,
                       std::string_view allowed) const {
  const toml::node* n = find(key);
  detail::fail(ctx_, n ? n : &table_, keyPath(key), problem, allowed);
}

double TableReader::number(std::string_view key, std::optional<double> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readNumber(ctx_, require(key, "a number"), keyPath(key));
}

long long TableReader::integer(std::string_view key, std::optional<long long> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readInteger(ctx_, require(key, "an integer"), keyPath(key));
}

bool TableReader::boolean(std::string_view key, std::optional<bool> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readBool(ctx_, require(key, "true, false"), keyPath(key));
}

std::string TableReader::string(std::string_view key, std::optional<std::string> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readString(ctx_, require(key, "a quoted string"), keyPath(key));
}

double TableReader::quantity(std::string_view key, Dimension d, std::optional<double> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readQuantity(ctx_, require(key, unitHint(d)), keyPath(key), d);
}

std::size_t TableReader::choice(std::string_view key, std::span<const std::string_view> names,
                                std::optional<std::size_t> dflt) const {
  if (dflt && !has(key)) return *dflt;
  return readChoice(ctx_, require(key, join(names)), keyPath(key), names);
}

std::optional<TableReader> TableReader::subTable(std::string_view key, bool required) const {
  const toml::node* n = required ? &require(key, "a [" + keyPath(key) + "] section") : find(key);
  if (n == nullptr) return std::nullopt;
  const toml::table* t = n->as_table();
  if (t == nullptr)
    detail::fail(ctx_, n, keyPath(key), "expected a table, got " + std::string(typeName(*n)),
                 "a [" + keyPath(key) + "] section or an inline table { ... }");
  return TableReader(ctx_, *t, keyPath(key));
}

}  // namespace hvi::cases::detail
