//! @file One table per scene section (top level, [time], [domain], [materials.*] per EOS,
//! [[bodies]], [sph], [tvd], [riemann], [output]): each row is a key with its type, its field,
//! its check and its documentation. The parser reads, toToml writes, `--set` checks paths
//! against and docs/scenes.md shows these rows, so a key is added in one place. A Custom row
//! (a string, a vector, a shape, a list) is read and written by its section's own code; the
//! table still names it for the unknown-key checks, `--set` and the docs.
#pragma once
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "detail/reader.hpp"
#include "hvi/cases/scene.hpp"

namespace hvi::cases::detail {

enum class ValueKind {
  Number,    //!< a bare number
  Quantity,  //!< a number with a unit of `dimension`
  Integer,
  Choice,    //!< one of choices(), stored as the enum's index
  Flag,      //!< a boolean
  Custom,    //!< read and written by the section's own code (strings, vectors, lists)
  Section,   //!< a sub-table of the top level, documented in its own table
};

//! A key of section struct S. Every value travels as a double (integers up to 1e6 and enum
//! indices are exact), so one row type serves every field.
template <class S>
struct KeyRow {
  std::string_view key;
  ValueKind kind;
  double (*get)(const S&) = nullptr;
  void (*set)(S&, double) = nullptr;
  Dimension dimension = Dimension::Length;
  std::span<const std::string_view> (*choices)() = nullptr;
  bool (*ok)(double) = nullptr;  //!< checked as soon as the key is read
  std::string_view problem = {}, allowed = {};
  std::string_view docValue = {}, docDefault = {};
  bool required = false;  //!< no default: a missing key is an error
  int variant = -1;       //!< [[bodies]]: the shape (index in shapeNames()) it belongs to; -1: all
};

template <class T>
constexpr double toValue(T x) {
  if constexpr (std::is_enum_v<T>) return static_cast<double>(static_cast<std::size_t>(x));
  else return static_cast<double>(x);
}
template <class T>
constexpr T fromValue(double v) {
  if constexpr (std::is_enum_v<T>) return static_cast<T>(static_cast<std::size_t>(v));
  else return static_cast<T>(v);
}

// The field `member` of S as a row's get and set (a macro: a member pointer's type would differ
// per field, and the rows must share one type).
#define HVI_KEY_FIELD(S, member)                                             \
  .get = [](const S& s) { return ::hvi::cases::detail::toValue(s.member); }, \
  .set = [](S& s, double v) {                                                \
    s.member = ::hvi::cases::detail::fromValue<decltype(S::member)>(v);      \
  }

std::span<const KeyRow<Scene>> rootKeys();  //!< title, units, geometry, solver, effects, sections
std::span<const KeyRow<Scene>> timeKeys();  //!< Scene::tStart, tEnd
std::span<const KeyRow<Domain>> domainKeys();
std::span<const KeyRow<Domain>> boundaryKeys();  //!< domain.boundaries, in Domain::boundary order
std::span<const KeyRow<Material>> materialKeys();  //!< preset, eos: the keys of every EOS
std::span<const KeyRow<eos::Tillotson>> tillotsonKeys();
std::span<const KeyRow<eos::IdealGas>> idealGasKeys();
std::span<const KeyRow<eos::MieGruneisen>> mieGruneisenKeys();
std::span<const KeyRow<Body>> bodyKeys();
//! [materials.<name>.strength]: the keys of every solid, then per yield model (variant = its
//! index in strength::YieldModel); damageKeys: per damage model (index in DamageModel).
std::span<const KeyRow<strength::Material>> strengthKeys();
std::span<const KeyRow<strength::Material>> damageKeys();
std::span<const std::string_view> strengthKeyNames();  //!< both tables, in order
std::span<const KeyRow<SphParams>> sphKeys();
std::span<const KeyRow<TvdParams>> tvdKeys();
std::span<const KeyRow<RiemannParams>> riemannKeys();
std::span<const KeyRow<Output>> outputKeys();

//! The table of an EOS's parameters, chosen by its type (for std::visit over eos::Eos).
inline std::span<const KeyRow<eos::Tillotson>> eosKeys(const eos::Tillotson&) {
  return tillotsonKeys();
}
inline std::span<const KeyRow<eos::IdealGas>> eosKeys(const eos::IdealGas&) {
  return idealGasKeys();
}
inline std::span<const KeyRow<eos::MieGruneisen>> eosKeys(const eos::MieGruneisen&) {
  return mieGruneisenKeys();
}

std::span<const std::string_view> eosNames();    //!< in eos::Eos's variant order
std::span<const std::string_view> shapeNames();  //!< in Shape's variant order

//! The key names of a section, in table order (for unknown-key checks and `--set` paths):
//! "root", "time", "domain", "domain.boundaries", "bodies", "sph", "tvd", "riemann", "output";
//! "materials": every key of any [materials.*] table; "materials.<eos>": those of one EOS
//! (preset, eos, then the EOS's table); "materials.strength": [materials.<name>.strength].
std::span<const std::string_view> keyNames(std::string_view section);

//! Reads every key of `rows` from `t` into `s`, in table order, each checked as it is read;
//! the default of an optional key is the value `s` already holds. With `allHaveDefaults` (a
//! material from a preset) no key is required.
template <class S>
void readKeys(const TableReader& t, std::span<const KeyRow<S>> rows, S& s,
              bool allHaveDefaults = false) {
  for (const KeyRow<S>& r : rows) {
    if (r.kind == ValueKind::Custom || r.kind == ValueKind::Section) continue;
    const std::optional<double> dflt =
        r.required && !allHaveDefaults ? std::nullopt : std::optional<double>(r.get(s));
    double v = 0.0;
    switch (r.kind) {
      case ValueKind::Number:
        v = t.number(r.key, dflt);
        break;
      case ValueKind::Quantity:
        v = t.quantity(r.key, r.dimension, dflt);
        break;
      case ValueKind::Integer:
        v = static_cast<double>(t.integer(
            r.key, dflt ? std::optional<long long>(static_cast<long long>(*dflt)) : std::nullopt));
        break;
      case ValueKind::Choice:
        v = static_cast<double>(t.choice(
            r.key, r.choices(),
            dflt ? std::optional<std::size_t>(static_cast<std::size_t>(*dflt)) : std::nullopt));
        break;
      case ValueKind::Flag:
        v = t.boolean(r.key, dflt ? std::optional<bool>(*dflt != 0.0) : std::nullopt) ? 1.0 : 0.0;
        break;
      case ValueKind::Custom:
      case ValueKind::Section:
        break;
    }
    if (r.ok) t.check(r.ok(v), r.key, r.problem, r.allowed);
    r.set(s, v);
  }
}

}  // namespace hvi::cases::detail
