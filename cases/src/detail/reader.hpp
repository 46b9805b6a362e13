//! @file Typed, located access to a parsed TOML scene: every read names file, line and key
//! path in its InputError (internal to the parser; toml++ never leaves cases/src).
#pragma once
#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "hvi/cases/quantity.hpp"
#include "hvi/common/vec2.hpp"

namespace hvi::cases::detail {

//! What a diagnostic needs besides the node.
struct Context {
  std::string file;                     //!< name used in messages
  bool bareNumbersAreInternal = false;  //!< `units = "cm-g-us"`: bare numbers are internal units
};

//! "<file>:<line>" for a node of the file, "<file> (--set <text>)" for a node from an override.
std::string location(const Context& ctx, const toml::node* node);

//! The node's line in the scene file; past every line for a node from an override.
std::uint32_t lineInFile(const Context& ctx, const toml::node& node);

//! Throws InputError "<location>: <key>: <problem>[; allowed: <allowed>]".
[[noreturn]] void fail(const Context& ctx, const toml::node* where, std::string_view key,
                       std::string_view problem, std::string_view allowed = {});

//! Shortest text that reads back to v ("7.2", "1e-09").
std::string shortNumber(double v);
std::string join(std::span<const std::string_view> names);
//! The known key nearest to `key` (edit distance), or "" if none is near enough to suggest.
std::string_view closestKey(std::string_view key, std::span<const std::string_view> known);
std::string_view typeName(const toml::node& node);
//! A TOML basic string literal, quoted and escaped.
std::string tomlString(std::string_view s);
//! `key` as it appears in a dotted path: bare if it can be, quoted otherwise.
std::string pathKey(std::string_view key);

// Element readers; `path` is the dotted key path used in messages (e.g. "bodies[1].centre[0]").
double readNumber(const Context& ctx, const toml::node& n, const std::string& path);
long long readInteger(const Context& ctx, const toml::node& n, const std::string& path);
bool readBool(const Context& ctx, const toml::node& n, const std::string& path);
std::string readString(const Context& ctx, const toml::node& n, const std::string& path);
//! A string "<number> <unit>", or a bare number when the file declares internal units.
double readQuantity(const Context& ctx, const toml::node& n, const std::string& path, Dimension d);
//! An array, of exactly `size` elements unless `size` is 0.
const toml::array& readArray(const Context& ctx, const toml::node& n, const std::string& path,
                             std::size_t size, std::string_view example);
Vec2 readVec2(const Context& ctx, const toml::node& n, const std::string& path, Dimension d);
//! [lo, hi] with lo < hi.
std::pair<double, double> readInterval(const Context& ctx, const toml::node& n,
                                       const std::string& path, Dimension d);
//! Index of the string value in `names`; unknown values list the allowed ones.
std::size_t readChoice(const Context& ctx, const toml::node& n, const std::string& path,
                       std::span<const std::string_view> names);

//! One table of the scene with its key path. Reads with a default are optional keys; reads
//! without one report a missing key at the table's line.
class TableReader {
 public:
  TableReader(const Context& ctx, const toml::table& table, std::string path)
      : ctx_(ctx), table_(table), path_(std::move(path)) {}

  [[nodiscard]] const Context& ctx() const { return ctx_; }
  [[nodiscard]] const toml::table& table() const { return table_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string keyPath(std::string_view key) const;
  [[nodiscard]] const toml::node* find(std::string_view key) const;
  //! The key's node; a missing key is reported at the table, with `hint` as what is allowed.
  [[nodiscard]] const toml::node& require(std::string_view key, std::string_view hint = {}) const;
  [[nodiscard]] bool has(std::string_view key) const { return find(key) != nullptr; }
  //! Rejects keys not in `known`, suggesting the nearest one.
  void rejectUnknown(std::span<const std::string_view> known) const;
  //! Fails at the key's node if present, else at the table.
  [[noreturn]] void fail(std::string_view key, std::string_view problem,
                         std::string_view allowed = {}) const;
  void check(bool ok, std::string_view key, std::string_view problem,
             std::string_view allowed = {}) const {
    if (!ok) fail(key, problem, allowed);
  }

  [[nodiscard]] double number(std::string_view key, std::optional<double> dflt = {}) const;
  [[nodiscard]] long long integer(std::string_view key, std::optional<long long> dflt = {}) const;
  [[nodiscard]] bool boolean(std::string_view key, std::optional<bool> dflt = {}) const;
  [[nodiscard]] std::string string(std::string_view key,
                                   std::optional<std::string> dflt = {}) const;
  [[nodiscard]] double quantity(std::string_view key, Dimension d,
                                std::optional<double> dflt = {}) const;
  [[nodiscard]] std::size_t choice(std::string_view key, std::span<const std::string_view> names,
                                   std::optional<std::size_t> dflt = {}) const;
  //! A sub-table (a [section] or an inline table); nullopt if absent and not required.
  [[nodiscard]] std::optional<TableReader> subTable(std::string_view key, bool required) const;

 private:
  const Context& ctx_;
  const toml::table& table_;
  std::string path_;
};

}  // namespace hvi::cases::detail
