//! @file A comparison report as JSON and as a text table, and the pass/fail check.
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "hvi/compare/compare.hpp"

namespace hvi::compare {
namespace {

using nlohmann::json;

json toJson(const DensityStats& s) {
  return {{"cells", s.cells}, {"l1", s.l1}, {"l2", s.l2}, {"max", s.max}, {"rel_l1", s.relL1}};
}

json toJson(const ConfusionTable& t) {
  json perClass = json::array();
  for (const auto& s : t.stats)
    perClass.push_back({{"name", s.name},
                        {"cells_a", s.cellsA},
                        {"cells_b", s.cellsB},
                        {"intersection", s.intersection},
                        {"iou", s.iou ? json(*s.iou) : json(nullptr)}});
  return {{"classes", t.classes},
          {"counts", t.counts},
          {"per_class", perClass},
          {"mismatch_fraction", t.mismatchFraction},
          {"mismatch_fraction_material", t.mismatchFractionMaterial},
          {"min_iou", t.minIou ? json(*t.minIou) : json(nullptr)}};
}

std::string optional(const std::optional<double>& v, const char* f = "{:.4f}") {
  return v ? fmt::format(fmt::runtime(f), *v) : std::string("-");
}

void table(std::ostringstream& o, const char* title, const ConfusionTable& t) {
  o << fmt::format("{} (rows A, columns B; cells)\n  {:>12}", title, "");
  for (const auto& c : t.classes) o << fmt::format(" {:>10.10}", c);
  o << fmt::format(" {:>8}\n", "IoU");
  for (std::size_t k = 0; k < t.classes.size(); ++k) {
    o << fmt::format("  {:>12.12}", t.classes[k]);
    for (long n : t.counts[k]) o << fmt::format(" {:>10}", n);
    o << fmt::format(" {:>8}\n", optional(t.stats[k].iou));
  }
  o << fmt::format("  mismatched: {:.4f} of all cells, {:.4f} of material cells; min IoU {}\n",
                   t.mismatchFraction, t.mismatchFractionMaterial, optional(t.minIou));
}

}  // namespace

nlohmann::json toJson(const Report& r) {
  json j;
  auto side = [](const std::string& solver, double t, const std::optional<Features>& f) {
    return json{{"solver", solver}, {"time_us", t}, {"features", f ? toJson(*f) : json(nullptr)}};
  };
  j["a"] = side(r.solverA, r.timeA, r.featuresA);
  j["b"] = side(r.solverB, r.timeB, r.featuresB);
  j["grid"] = {{"geometry", toString(r.geometry)}, {"nx", r.grid.nx}, {"nz", r.grid.nz},
               {"x0", r.grid.x0}, {"z0", r.grid.z0}, {"dx", r.grid.dx}, {"dz", r.grid.dz}};
  j["mass"] = {{"a", r.massA}, {"b", r.massB}};
  j["density"] = {{"all", toJson(r.whole)}, {"material", toJson(r.material)}};
  j["materials"] = toJson(r.materials);
  j["objects"] = r.objects ? toJson(*r.objects) : json(nullptr);
  j["features_diff"] =
      r.featuresA && r.featuresB ? differenceJson(*r.featuresA, *r.featuresB) : json(nullptr);
  return j;
}

std::string formatTable(const Report& r) {
  std::ostringstream o;
  o << fmt::format("A: {} at t = {} us    B: {} at t = {} us\n", r.solverA, r.timeA, r.solverB,
                   r.timeB);
  o << fmt::format("grid ({}): {} x {} cells of {:.4g} cm from ({:.4g}, {:.4g}) cm\n",
                   toString(r.geometry), r.grid.nx, r.grid.nz, r.grid.dx, r.grid.x0, r.grid.z0);
  o << fmt::format("mass on grid: A {:.6g}  B {:.6g}  (B/A - 1 = {:.3e})\n", r.massA, r.massB,
                   r.massA > 0.0 ? r.massB / r.massA - 1.0 : 0.0);
  o << fmt::format("density B - A [g/cm^3]  {:>10} {:>10} {:>10} {:>10} {:>10}\n", "cells", "L1",
                   "L2", "max", "rel L1");
  for (const auto& [name, s] : {std::pair{"all cells", &r.whole}, {"material", &r.material}})
    o << fmt::format("  {:<21} {:>10} {:>10.4g} {:>10.4g} {:>10.4g} {:>10.4f}\n", name, s->cells,
                     s->l1, s->l2, s->max, s->relL1);
  table(o, "materials", r.materials);
  if (r.objects) table(o, "objects", *r.objects);
  if (r.featuresA && r.featuresB) {
    const json fa = toJson(*r.featuresA), fb = toJson(*r.featuresB);
    const json fd = differenceJson(*r.featuresA, *r.featuresB);
    o << fmt::format("features [cm, g/cm^3]  {:>10} {:>10} {:>10}\n", "A", "B", "B - A");
    for (const char* key :
         {"hole_radius", "cloud_leading_edge_z", "bubble_radius", "bubble_radius_90",
          "striker_z_min", "striker_z_max", "striker_centroid_z", "peak_density"}) {
      auto cell = [](const json& v) {
        return v.is_null() ? std::string("-") : fmt::format("{:.4f}", v.get<double>());
      };
      o << fmt::format("  {:<21} {:>10} {:>10} {:>10}\n", key, cell(fa[key]), cell(fb[key]),
                       cell(fd[key]));
    }
  }
  return o.str();
}

bool passes(const Report& r, const Thresholds& t, std::string* why) {
  std::string reasons;
  if (t.maxDensityL1 && !(r.material.relL1 <= *t.maxDensityL1))
    reasons += fmt::format("relative L1 density difference over the material region {:.4g} > "
                           "{:.4g}; ", r.material.relL1, *t.maxDensityL1);
  if (t.minIou) {
    const ConfusionTable& table = r.objects ? *r.objects : r.materials;
    const double iou = table.minIou.value_or(1.0);
    if (!(iou >= *t.minIou))
      reasons += fmt::format("smallest {} IoU {:.4f} < {:.4f}; ",
                             r.objects ? "object" : "material", iou, *t.minIou);
  }
  if (!reasons.empty()) reasons.resize(reasons.size() - 2);
  if (why != nullptr) *why = reasons;
  return reasons.empty();
}

}  // namespace hvi::compare
