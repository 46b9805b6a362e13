//! @file compareSnapshots: two states on one grid, density norms and class agreement.
#include "hvi/compare/compare.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hvi/common/error.hpp"

namespace hvi::compare {
namespace {

//! Class index (0 = vacuum) of each id of A and of B, classes matched by name.
struct ClassMap {
  std::vector<std::string> classes{"vacuum"};
  std::vector<int> fromA, fromB;  // id -> class
  [[nodiscard]] int a(int id) const { return id < 0 ? 0 : fromA[id]; }
  [[nodiscard]] int b(int id) const { return id < 0 ? 0 : fromB[id]; }
};

ClassMap matchClasses(const std::vector<std::string>& namesA,
                      const std::vector<std::string>& namesB) {
  ClassMap m;
  auto add = [&m](const std::string& n) {
    const auto it = std::find(m.classes.begin() + 1, m.classes.end(), n);
    if (it != m.classes.end()) return static_cast<int>(it - m.classes.begin());
    m.classes.push_back(n);
    return static_cast<int>(m.classes.size()) - 1;
  };
  for (const auto& n : namesA) m.fromA.push_back(add(n));
  for (const auto& n : namesB) m.fromB.push_back(add(n));
  return m;
}

//! `names` extended so that every id in `ids` has one (hand-built fields may lack names).
std::vector<std::string> covering(std::vector<std::string> names, const std::vector<int>& ids,
                                  const char* prefix) {
  const int maxId = ids.empty() ? -1 : *std::max_element(ids.begin(), ids.end());
  for (int i = static_cast<int>(names.size()); i <= maxId; ++i)
    names.push_back(fmt::format("{}{}", prefix, i));
  return names;
}

ConfusionTable confusion(const std::vector<int>& idsA, const std::vector<int>& idsB,
                         const ClassMap& map, std::vector<int>& classA, std::vector<int>& classB) {
  ConfusionTable t;
  t.classes = map.classes;
  const std::size_t nc = t.classes.size();
  t.counts.assign(nc, std::vector<long>(nc, 0));
  classA.resize(idsA.size());
  classB.resize(idsB.size());
  long mismatch = 0, material = 0;
  for (std::size_t c = 0; c < idsA.size(); ++c) {
    classA[c] = map.a(idsA[c]);
    classB[c] = map.b(idsB[c]);
    ++t.counts[classA[c]][classB[c]];
    if (classA[c] != classB[c]) ++mismatch;
    if (classA[c] != 0 || classB[c] != 0) ++material;
  }
  const auto n = static_cast<double>(idsA.size());
  t.mismatchFraction = n > 0 ? mismatch / n : 0.0;
  t.mismatchFractionMaterial = material > 0 ? static_cast<double>(mismatch) / material : 0.0;
  for (std::size_t k = 0; k < nc; ++k) {
    ClassStats s;
    s.name = t.classes[k];
    for (std::size_t j = 0; j < nc; ++j) {
      s.cellsA += t.counts[k][j];
      s.cellsB += t.counts[j][k];
    }
    s.intersection = t.counts[k][k];
    const long uni = s.cellsA + s.cellsB - s.intersection;
    if (uni > 0) s.iou = static_cast<double>(s.intersection) / static_cast<double>(uni);
    if (k > 0 && s.iou) t.minIou = t.minIou ? std::min(*t.minIou, *s.iou) : *s.iou;
    t.stats.push_back(s);
  }
  return t;
}

//! Accumulates the density norms over the cells for which `in` holds.
template <class Pred>
DensityStats densityStats(const Resampled& a, const Resampled& b, Pred in) {
  DensityStats s;
  double w = 0.0, l1 = 0.0, l2 = 0.0, ref = 0.0;
  for (int k = 0; k < a.grid.nz; ++k)
    for (int i = 0; i < a.grid.nx; ++i) {
      const long c = static_cast<long>(k) * a.grid.nx + i;
      if (!in(c)) continue;
      const double v = a.cellVolume(i), d = b.density[c] - a.density[c];
      ++s.cells;
      w += v;
      l1 += std::abs(d) * v;
      l2 += d * d * v;
      ref += 0.5 * (std::abs(a.density[c]) + std::abs(b.density[c])) * v;
      s.max = std::max(s.max, std::abs(d));
    }
  if (w > 0.0) {
    s.l1 = l1 / w;
    s.l2 = std::sqrt(l2 / w);
  }
  s.relL1 = ref > 0.0 ? l1 / ref : 0.0;
  return s;
}

Field cellField(const char* name, const char* unit, std::vector<double> data) {
  return Field{name, unit, 1, std::move(data)};
}

}  // namespace

Report compareResampled(const Resampled& a, const Resampled& b, const CompareOptions& opt) {
  const GridSpec &ga = a.grid, &gb = b.grid;
  if (ga.nx != gb.nx || ga.nz != gb.nz || ga.x0 != gb.x0 || ga.z0 != gb.z0 || ga.dx != gb.dx ||
      ga.dz != gb.dz || a.geometry != b.geometry)
    throw InputError("compare: the two resampled fields are not on the same grid");
  Report r;
  r.grid = ga;
  r.geometry = a.geometry;
  r.timeA = a.time, r.timeB = b.time;
  r.solverA = a.solver, r.solverB = b.solver;
  const long n = ga.cells();
  for (int k = 0; k < ga.nz; ++k)
    for (int i = 0; i < ga.nx; ++i) {
      const long c = static_cast<long>(k) * ga.nx + i;
      r.massA += a.density[c] * a.cellVolume(i);
      r.massB += b.density[c] * b.cellVolume(i);
    }
  r.whole = densityStats(a, b, [](long) { return true; });
  r.material = densityStats(a, b, [&](long c) { return a.material[c] >= 0 || b.material[c] >= 0; });

  std::vector<int> matA, matB, objA, objB;
  const ClassMap mm = matchClasses(covering(a.materialNames, a.material, "material"),
                                   covering(b.materialNames, b.material, "material"));
  r.materials = confusion(a.material, b.material, mm, matA, matB);
  ClassMap om;
  if (a.hasObject && b.hasObject) {
    om = matchClasses(covering(a.objectNames, a.object, "object"),
                      covering(b.objectNames, b.object, "object"));
    r.objects = confusion(a.object, b.object, om, objA, objB);
  }

  Snapshot& d = r.difference;
  d.kind = Snapshot::Kind::Grid;
  d.time = b.time;
  d.solver = "compare";
  d.geometry = a.geometry;
  d.grid = ga;
  d.materialNames.assign(mm.classes.begin() + 1, mm.classes.end());
  std::vector<double> diff(n), mA(n), mB(n), mis(n);
  const bool byObject = r.objects.has_value();
  for (long c = 0; c < n; ++c) {
    diff[c] = b.density[c] - a.density[c];
    mA[c] = matA[c] - 1;
    mB[c] = matB[c] - 1;
    mis[c] = byObject ? (objA[c] != objB[c]) : (matA[c] != matB[c]);
  }
  d.fields.push_back(cellField("density_a", "g/cm^3", a.density));
  d.fields.push_back(cellField("density_b", "g/cm^3", b.density));
  d.fields.push_back(cellField("density_diff", "g/cm^3", std::move(diff)));
  d.fields.push_back(cellField("material_a", "1", std::move(mA)));
  d.fields.push_back(cellField("material_b", "1", std::move(mB)));
  d.fields.push_back(cellField("material_mismatch", "1", std::move(mis)));
  if (byObject) {
    d.objectNames.assign(om.classes.begin() + 1, om.classes.end());
    std::vector<double> oA(n), oB(n);
    for (long c = 0; c < n; ++c) oA[c] = objA[c] - 1, oB[c] = objB[c] - 1;
    d.fields.push_back(cellField("object_a", "1", std::move(oA)));
    d.fields.push_back(cellField("object_b", "1", std::move(oB)));
  }

  if (opt.features) {
    r.featuresA = measureFeatures(a, *opt.features);
    r.featuresB = measureFeatures(b, opt.featuresB ? *opt.featuresB : *opt.features);
  }
  return r;
}

Report compareSnapshots(const Snapshot& a, const Snapshot& b, const CompareOptions& opt) {
  const double d = opt.spacing > 0.0 ? opt.spacing : std::max(nativeSpacing(a), nativeSpacing(b));
  const GridSpec grid = coveringGrid(a, b, d);
  return compareResampled(resample(a, grid, opt.resample), resample(b, grid, opt.resample), opt);
}

}  // namespace hvi::compare
