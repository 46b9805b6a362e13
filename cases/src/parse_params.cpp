//! @file [sph], [tvd], [riemann] and [output]: solver parameters and what to write, read by
//! their key tables (detail/keys.hpp).
#include <fmt/format.h>

#include "detail/parse.hpp"
#include "detail/keys.hpp"

namespace hvi::cases::detail {
namespace {

// Where two rect bodies meet along x, if they do: the natural Riemann interface.
std::optional<double> meetingPoint(const Scene& scene) {
  if (scene.bodies.size() != 2) return std::nullopt;
  const auto* a = std::get_if<Rect>(&scene.bodies[0].shape);
  const auto* b = std::get_if<Rect>(&scene.bodies[1].shape);
  if (!a || !b) return std::nullopt;
  return a->xmin <= b->xmin ? a->xmax : b->xmax;
}

void parseRiemann(const TableReader& s, RiemannParams& p, const Scene& scene) {
  s.rejectUnknown(keyNames("riemann"));
  p.interface = meetingPoint(scene).value_or(p.interface);
  readKeys(s, riemannKeys(), p);
}

}  // namespace

void parseSolverParams(const TableReader& root, Scene& scene) {
  const toml::table empty;
  auto section = [&](std::string_view key) {
    auto t = root.subTable(key, false);
    return t ? *t : TableReader(root.ctx(), empty, std::string(key));
  };
  const TableReader sph = section("sph"), tvd = section("tvd");
  sph.rejectUnknown(keyNames("sph"));
  readKeys(sph, sphKeys(), scene.sph);
  tvd.rejectUnknown(keyNames("tvd"));
  readKeys(tvd, tvdKeys(), scene.tvd);
  parseRiemann(section("riemann"), scene.riemann, scene);
}

void parseOutput(const TableReader& root, Scene& scene) {
  const auto o = root.subTable("output", false);
  if (!o) return;
  o->rejectUnknown(keyNames("output"));
  Output& out = scene.output;
  if (const toml::node* n = o->find("times")) {
    const std::string path = o->keyPath("times");
    const auto& arr = readArray(root.ctx(), *n, path, 0, "[\"1 us\", \"2 us\"]");
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string p = path + "[" + std::to_string(i) + "]";
      const double t = readQuantity(root.ctx(), *arr.get(i), p, Dimension::Time);
      const std::string window =
          fmt::format("({}, {}] us", shortNumber(scene.tStart), shortNumber(scene.tEnd));
      if (!(t > scene.tStart && t <= scene.tEnd))
        fail(root.ctx(), arr.get(i), p, "outside the simulated time " + window,
             "times in (time.start, time.end]");
      if (!out.times.empty() && !(t > out.times.back()))
        fail(root.ctx(), arr.get(i), p, "output times must increase strictly",
             "ascending times, each once");
      out.times.push_back(t);
    }
  }
  readKeys(*o, outputKeys(), out);  // after the times, as the table lists them
}

}  // namespace hvi::cases::detail
