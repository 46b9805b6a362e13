//! @file The resolved scene as TOML: every default filled in, internal units as bare numbers.
#include <fmt/format.h>

#include <span>
#include <sstream>
#include <vector>

#include "detail/keys.hpp"
#include "detail/reader.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/cases/names.hpp"

namespace hvi::cases {
namespace {

using detail::tomlString;

// Always a TOML float ("7.0", "1e-09"), and it reads back to the same double.
std::string num(double v) {
  std::string s = detail::shortNumber(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string pair(double a, double b) { return fmt::format("[{}, {}]", num(a), num(b)); }
std::string vec(Vec2 v) { return pair(v.x, v.z); }

// The keys of a section table as TOML, in table order; Custom rows (strings, vectors, shapes,
// lists) are written by their section's code.
template <class S>
void writeKeys(std::ostringstream& o, std::span<const detail::KeyRow<S>> rows, const S& s) {
  using detail::ValueKind;
  for (const auto& r : rows) {
    if (r.kind == ValueKind::Custom || r.kind == ValueKind::Section) continue;
    const double v = r.get(s);
    o << r.key << " = ";
    switch (r.kind) {
      case ValueKind::Number:
      case ValueKind::Quantity:
        o << num(v);
        break;
      case ValueKind::Integer:
        o << static_cast<long long>(v);
        break;
      case ValueKind::Choice:
        o << "\"" << (v < static_cast<double>(r.choices().size())
                            ? r.choices()[static_cast<std::size_t>(v)]
                            : std::string_view("?"))
          << "\"";
        break;
      case ValueKind::Flag:
        o << (v != 0.0 ? "true" : "false");
        break;
      case ValueKind::Custom:
      case ValueKind::Section:
        break;
    }
    o << "\n";
  }
}

void writeEos(std::ostringstream& o, const eos::Eos& e) {
  o << "eos = \"" << detail::eosNames()[e.index()] << "\"\n";
  std::visit([&](const auto& params) { writeKeys(o, detail::eosKeys(params), params); }, e);
}

// Every key of the chosen yield and damage models (no preset: the values are all written).
void writeStrength(std::ostringstream& o, const std::string& name, const strength::Material& m) {
  o << "\n[materials." << detail::pathKey(name) << ".strength]\n"
    << "model = \"" << strength::yieldModelNames()[m.yield.index()] << "\"\n"
    << "damage = \"" << strength::damageModelNames()[m.damage.index()] << "\"\n";
  std::vector<detail::KeyRow<strength::Material>> rows;
  const int model = static_cast<int>(m.yield.index()), damage = static_cast<int>(m.damage.index());
  for (const auto& r : detail::strengthKeys())
    if (r.variant < 0 || r.variant == model) rows.push_back(r);
  for (const auto& r : detail::damageKeys())
    if (r.variant == damage) rows.push_back(r);
  writeKeys<strength::Material>(o, rows, m);
}

struct ShapeWriter {
  std::ostringstream& o;
  void operator()(const Disk& d) const {
    o << "shape = \"disk\"\ncentre = " << vec(d.centre) << "\nradius = " << num(d.radius) << "\n";
  }
  void operator()(const Rect& r) const {
    o << "shape = \"rect\"\nx = " << pair(r.xmin, r.xmax) << "\nz = " << pair(r.zmin, r.zmax)
      << "\n";
  }
  void operator()(const Polygon& p) const {
    o << "shape = \"polygon\"\nvertices = [";
    for (std::size_t i = 0; i < p.vertices.size(); ++i) o << (i ? ", " : "") << vec(p.vertices[i]);
    o << "]\n";
  }
};

}  // namespace

std::string toToml(const Scene& s) {
  std::ostringstream o;
  o << "# Resolved scene: every default filled in, every value in internal units.\n"
       "# cm-g-us: length cm, time us, velocity cm/us, density g/cm^3, pressure Mbar,\n"
       "# specific energy cm^2/us^2; wall-clock times in s.\n";
  if (!s.path.empty()) {
    std::string path = s.path;  // a comment ends at a line break: keep it on one line
    for (char& c : path)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    o << "# Read from " << path << "\n";
  }
  o << "units = \"cm-g-us\"\n"
    << "title = " << tomlString(s.title) << "\n";
  writeKeys(o, detail::rootKeys(), s);  // geometry, solver
  o << "effects = [";
  bool first = true;
  for (Effect e : s.effects) {
    o << (first ? "" : ", ") << "\"" << toString(e) << "\"";
    first = false;
  }
  o << "]\n\n[time]\n";
  writeKeys(o, detail::timeKeys(), s);

  const Domain& d = s.domain;
  o << "\n[domain]\nx = " << pair(d.xmin, d.xmax) << "\nz = " << pair(d.zmin, d.zmax)
    << "\nboundaries = {";
  const auto sides = detail::boundaryKeys();  // an inline table, as the shipped scenes write it
  for (std::size_t i = 0; i < sides.size(); ++i)
    o << (i ? ", " : " ") << sides[i].key << " = \""
      << sides[i].choices()[static_cast<std::size_t>(sides[i].get(d))] << "\"";
  o << " }\n";

  for (const Material& m : s.materials) {
    o << "\n[materials." << detail::pathKey(m.name) << "]\n";
    writeEos(o, m.eos);
    if (m.strength) writeStrength(o, m.name, *m.strength);
  }
  for (const Body& b : s.bodies) {
    o << "\n[[bodies]]\nname = " << tomlString(b.name) << "\nmaterial = ";
    const bool known = b.material >= 0 && static_cast<std::size_t>(b.material) < s.materials.size();
    o << tomlString(known ? s.materials[static_cast<std::size_t>(b.material)].name : "") << "\n";
    std::visit(ShapeWriter{o}, b.shape);
    if (b.radial) {
      o << "radial_velocity = " << num(b.radialSpeed) << "\n";
      if (s.geometry == Geometry::Planar) o << "radial_centre = " << vec(b.radialCentre) << "\n";
    } else {
      o << "velocity = " << vec(b.velocity) << "\n";
    }
    writeKeys(o, detail::bodyKeys(), b);  // density
    o << "specific_energy = " << num(b.specificEnergy) << "\n";
  }

  o << "\n[sph]\n";
  writeKeys(o, detail::sphKeys(), s.sph);
  o << "\n[tvd]\n";
  writeKeys(o, detail::tvdKeys(), s.tvd);
  o << "\n[riemann]\n";
  writeKeys(o, detail::riemannKeys(), s.riemann);
  o << "\n[output]\ntimes = [";
  for (std::size_t i = 0; i < s.output.times.size(); ++i)
    o << (i ? ", " : "") << num(s.output.times[i]);
  o << "]\n";
  writeKeys(o, detail::outputKeys(), s.output);
  return o.str();
}

}  // namespace hvi::cases
