//! @file Rear-wall failure: through-holes and detached spall, from one snapshot.
#include "hvi/shield/failure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/resample.hpp"
#include "hvi/io/output.hpp"

namespace hvi::shield {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Connected components (8-neighbours) of the cells where `in` holds; labels -1 elsewhere.
int label(const std::vector<char>& in, int nx, int nz, std::vector<int>& lab) {
  lab.assign(in.size(), -1);
  int n = 0;
  std::vector<long> stack;
  for (long c0 = 0; c0 < static_cast<long>(in.size()); ++c0) {
    if (!in[c0] || lab[c0] >= 0) continue;
    lab[c0] = n;
    stack.push_back(c0);
    while (!stack.empty()) {
      const long c = stack.back();
      stack.pop_back();
      const int i = static_cast<int>(c % nx), k = static_cast<int>(c / nx);
      for (int dk = -1; dk <= 1; ++dk)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, kk = k + dk;
          if (ii < 0 || kk < 0 || ii >= nx || kk >= nz) continue;
          const long nb = static_cast<long>(kk) * nx + ii;
          if (in[nb] && lab[nb] < 0) {
            lab[nb] = n;
            stack.push_back(nb);
          }
        }
    }
    ++n;
  }
  return n;
}

}  // namespace

std::string RearWallState::mode() const {
  if (throughHole() && detachedSpall()) return "through_hole_and_spall";
  if (throughHole()) return "through_hole";
  if (detachedSpall()) return "detached_spall";
  return "intact";
}

namespace {
RearWallConfig plateConfig(const cases::Scene& scene, const cases::Body& body) {
  const auto& r = std::get<cases::Rect>(body.shape);
  RearWallConfig c;
  c.name = body.name;
  c.zMin = r.zmin;
  c.zMax = r.zmax;
  c.radius = r.xmax;
  c.rho0 = scene.materials.at(static_cast<std::size_t>(body.material)).rho0();
  // The impact runs along the projectile's velocity (the first moving body).
  for (const auto& b : scene.bodies)
    if (b.velocity.z != 0.0) {
      c.direction = b.velocity.z < 0.0 ? -1 : 1;
      break;
    }
  return c;
}
}  // namespace

std::optional<RearWallConfig> rearWallConfigFromScene(const cases::Scene& scene) {
  const auto it = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                               [](const cases::Body& b) { return b.name == "rear_wall"; });
  if (it == scene.bodies.end() || !std::holds_alternative<cases::Rect>(it->shape))
    return std::nullopt;
  return plateConfig(scene, *it);
}

std::vector<RearWallConfig> plateConfigsFromScene(const cases::Scene& scene) {
  std::vector<RearWallConfig> out;
  // Columns of an r-z grid are rings about the axis, so an opening that starts at the first
  // column is an aperture on the impact axis; a planar plate has no such axis in its grid.
  if (scene.geometry != Geometry::Axisymmetric) return out;
  for (const auto& b : scene.bodies) {
    if (!std::holds_alternative<cases::Rect>(b.shape)) continue;
    const auto& r = std::get<cases::Rect>(b.shape);
    if (r.xmin > 1e-12 || b.velocity.x != 0.0 || b.velocity.z != 0.0) continue;
    out.push_back(plateConfig(scene, b));
  }
  return out;
}

double RearWallState::holeRadius() const {
  for (const auto& h : holes)
    if (h.rInner <= 0.0) return h.rOuter;
  return 0.0;
}

namespace {

// The object index of the plate `cfg.name` and the velocity field; throws InputError naming
// what the snapshot lacks.
int plateObject(const Snapshot& s, const RearWallConfig& cfg) {
  const auto nameIt = std::find(s.objectNames.begin(), s.objectNames.end(), cfg.name);
  if (s.find("object") == nullptr || nameIt == s.objectNames.end())
    throw InputError(
        fmt::format("plate failure: the {} snapshot at t = {} us has no object "
                    "named '{}' (objects: {})",
                    s.solver, s.time, cfg.name, fmt::join(s.objectNames, ", ")));
  const Field* vel = s.find("velocity");
  if (vel == nullptr || vel->components != 2)
    throw InputError(fmt::format("plate failure: the {} snapshot at t = {} us has no velocity",
                                 s.solver, s.time));
  return static_cast<int>(nameIt - s.objectNames.begin());
}

double measureSpacing(const Snapshot& s, double spacing) {
  return spacing > 0.0                    ? spacing
         : s.kind == Snapshot::Kind::Grid ? std::max(s.grid.dx, s.grid.dz)
                                          : compare::nativeSpacing(s);
}

// One plate of `s`, on the grid `r` (of spacing h) resampled from it.
RearWallState measureOn(const Snapshot& s, const compare::Resampled& r, double h,
                        const RearWallConfig& cfg) {
  const int wall = plateObject(s, cfg);
  const Field* vel = s.find("velocity");
  const GridSpec& g = r.grid;
  const bool rz = s.geometry == Geometry::Axisymmetric;

  // Rear-wall cells of the resampled grid, split into 8-connected pieces.
  std::vector<char> in(static_cast<std::size_t>(g.cells()), 0);
  for (long c = 0; c < g.cells(); ++c) in[c] = r.object[c] == wall && r.density[c] > 0.0;
  std::vector<int> lab;
  const int n = label(in, g.nx, g.nz, lab);
  struct Acc {
    double mass = 0, mr = 0, mz = 0, pz = 0, zLow = 1e300, zHigh = -1e300, rOuter = 0;
    int cells = 0;
  };
  std::vector<Acc> acc(static_cast<std::size_t>(n));
  for (long c = 0; c < g.cells(); ++c) {
    if (lab[c] < 0) continue;
    Acc& a = acc[static_cast<std::size_t>(lab[c])];
    const int i = static_cast<int>(c % g.nx), k = static_cast<int>(c / g.nx);
    a.zLow = std::min(a.zLow, g.z0 + k * g.dz);
    a.zHigh = std::max(a.zHigh, g.z0 + (k + 1) * g.dz);
    a.rOuter = std::max(a.rOuter, g.x0 + (i + 1) * g.dx);
    ++a.cells;
  }
  // Mass, centroid and momentum of each piece from the source items (particles or cells) of the
  // rear wall, each given to the piece of its cell or, on a piece's smeared edge, of a
  // neighbouring cell: a thin piece's mass is then its particles', not the resampled field's
  // (which loses the part of a thin layer that falls below the material threshold).
  const Field* obj = s.find("object");
  const Field* m = s.find("mass");
  const Field* rho = s.find("density");
  for (long it = 0; it < s.count(); ++it) {
    if (std::lround(obj->data[it]) != wall) continue;
    double x, z, ma;
    if (s.kind == Snapshot::Kind::Particles) {
      x = s.positions[it].x;
      z = s.positions[it].z;
      ma = m ? m->data[it] : 0.0;
    } else {
      const int i = static_cast<int>(it % s.grid.nx), k = static_cast<int>(it / s.grid.nx);
      x = s.grid.x0 + (i + 0.5) * s.grid.dx;
      z = s.grid.z0 + (k + 0.5) * s.grid.dz;
      ma = (rho ? rho->data[it] : 0.0) * s.grid.dx * s.grid.dz * (rz ? kTwoPi * x : 1.0);
    }
    const int i = static_cast<int>(std::floor((x - g.x0) / g.dx));
    const int k = static_cast<int>(std::floor((z - g.z0) / g.dz));
    int piece = -1;
    for (int d = 0; d < 9 && piece < 0; ++d) {  // own cell first, then the 8 neighbours
      const int ii = i + (d == 0 ? 0 : (d - 1) % 3 - 1), kk = k + (d == 0 ? 0 : (d - 1) / 3 - 1);
      if (ii < 0 || kk < 0 || ii >= g.nx || kk >= g.nz) continue;
      piece = lab[static_cast<std::size_t>(kk) * g.nx + ii];
    }
    if (piece < 0) continue;  // dust of the wall that no piece holds
    Acc& a = acc[static_cast<std::size_t>(piece)];
    a.mass += ma;
    a.mr += ma * x;
    a.mz += ma * z;
    a.pz += ma * vel->data[2 * it + 1];
  }

  RearWallState st;
  st.time = s.time;
  st.cellSize = h;
  const double thickness = cfg.zMax - cfg.zMin;
  if (n == 0) {  // no rear-wall material left in the domain: the wall is gone
    st.holes.push_back({0.0, cfg.radius, (rz ? std::numbers::pi * cfg.radius : 2.0) * cfg.radius});
    st.thinnestFraction = 0.0;
    return st;
  }
  // The wall's main piece: the heaviest. Spall and fragments are the lighter ones.
  const int main = static_cast<int>(
      std::max_element(acc.begin(), acc.end(),
                       [](const Acc& a, const Acc& b) { return a.mass < b.mass; }) -
      acc.begin());
  const Acc& mainAcc = acc[static_cast<std::size_t>(main)];
  st.mainVelocityZ = mainAcc.mass > 0 ? mainAcc.pz / mainAcc.mass : 0.0;
  const double mainCentroidZ = mainAcc.mz / mainAcc.mass;

  // Through-holes: columns inside the plate radius where the main piece's areal mass is below
  // the threshold. A column's areal mass is sum(rho dz) over its main-piece cells.
  std::vector<double> areal(static_cast<std::size_t>(g.nx), 0.0);
  for (long c = 0; c < g.cells(); ++c)
    if (lab[c] == main) areal[static_cast<std::size_t>(c % g.nx)] += r.density[c] * g.dz;
  const double full = cfg.rho0 * thickness;
  int start = -1;
  const auto close = [&](int i0, int i1) {  // columns i0..i1-1 are open
    const double a = g.x0 + i0 * g.dx, b = g.x0 + i1 * g.dx;
    st.holes.push_back({a, b, rz ? std::numbers::pi * (b * b - a * a) : 2.0 * (b - a)});
  };
  int i = 0;
  for (; i < g.nx && r.xCentre(i) < cfg.radius; ++i) {
    const double f = areal[static_cast<std::size_t>(i)] / full;
    if (f < st.thinnestFraction) {
      st.thinnestFraction = f;
      st.thinnestRadius = r.xCentre(i);
    }
    const bool open = f < cfg.holeArealFraction;
    if (open && start < 0) start = i;
    if (!open && start >= 0) {
      close(start, i);
      start = -1;
    }
  }
  // An opening that reaches the plate's rim without reaching the axis is the free edge coming
  // loose (measured: the outermost ring of an intact SPH rear wall, r = 5.58-5.63 cm of 5.63,
  // read as open at 5 and 12 km/s), not a hole through the plate: only an opening that spans
  // the whole plate from the axis counts there.
  if (start == 0) close(start, i);

  // Detached spall: a lighter piece, downrange of the main piece's centroid, moving away from
  // it along the impact direction.
  for (int p = 0; p < n; ++p) {
    if (p == main) continue;
    const Acc& a = acc[static_cast<std::size_t>(p)];
    if (a.cells < cfg.minFragmentCells || !(a.mass > 0.0)) continue;
    const double cz = a.mz / a.mass;
    const double vz = a.pz / a.mass;
    const bool downrange = (cz - mainCentroidZ) * cfg.direction > 0.0;
    const bool away = (vz - st.mainVelocityZ) * cfg.direction > 0.0;
    if (!downrange || !away) continue;
    st.spall.push_back({a.mass, a.mr / a.mass, cz, a.zLow, a.zHigh, a.rOuter, vz, a.cells});
  }
  return st;
}

}  // namespace

RearWallState measureRearWall(const Snapshot& s, const RearWallConfig& cfg, double spacing) {
  (void)plateObject(s, cfg);  // refuse a snapshot without the plate before resampling it
  const double h = measureSpacing(s, spacing);
  return measureOn(s, compare::resample(s, compare::coveringGrid(s, h)), h, cfg);
}

std::vector<RearWallState> measurePlates(const Snapshot& s,
                                         const std::vector<RearWallConfig>& plates,
                                         double spacing) {
  std::vector<RearWallState> out;
  if (plates.empty()) return out;
  for (const auto& p : plates) (void)plateObject(s, p);
  const double h = measureSpacing(s, spacing);
  const compare::Resampled r = compare::resample(s, compare::coveringGrid(s, h));
  for (const auto& p : plates) out.push_back(measureOn(s, r, h, p));
  return out;
}

RearWallState measureRearWall(const std::filesystem::path& h5) {
  std::string toml;
  const Snapshot s = io::readHdf5(h5, &toml);
  const cases::Scene scene = cases::parseScene(toml, h5.string() + " (its scene)");
  const auto cfg = rearWallConfigFromScene(scene);
  if (!cfg)
    throw InputError(h5.string() +
                     ": its scene has no rect body named 'rear_wall'; allowed: a "
                     "shield scene (docs/shield.md)");
  return measureRearWall(s, *cfg);
}

nlohmann::json toJson(const RearWallState& s) {
  nlohmann::json holes = nlohmann::json::array(), spall = nlohmann::json::array();
  for (const auto& h : s.holes)
    holes.push_back({{"r_inner_cm", h.rInner}, {"r_outer_cm", h.rOuter}, {"area_cm2", h.area}});
  for (const auto& f : s.spall)
    spall.push_back({{"mass_g", f.mass},
                     {"centroid_r_cm", f.centroidR},
                     {"centroid_z_cm", f.centroidZ},
                     {"z_range_cm", {f.zLow, f.zHigh}},
                     {"r_outer_cm", f.rOuter},
                     {"velocity_z_cm_per_us", f.velocityZ},
                     {"cells", f.cells}});
  return {{"time_us", s.time},
          {"perforated", s.perforated()},
          {"mode", s.mode()},
          {"cell_size_cm", s.cellSize},
          {"holes", holes},
          {"spall", spall},
          {"thinnest_areal_fraction", s.thinnestFraction},
          {"thinnest_at_r_cm", s.thinnestRadius},
          {"main_velocity_z_cm_per_us", s.mainVelocityZ}};
}

nlohmann::json plateJson(const std::string& name, const RearWallState& s) {
  nlohmann::json j = toJson(s);
  j["name"] = name;
  j["hole_radius_cm"] = s.holeRadius();
  j["spalled"] = s.detachedSpall();
  return j;
}

nlohmann::json platesSummary(const nlohmann::json& perSnapshot) {
  // Each plate's states in time order, by name, in the order the plates first appear.
  std::vector<std::pair<std::string, nlohmann::json>> byName;
  for (const auto& plates : perSnapshot) {
    if (!plates.is_array()) continue;
    for (const auto& p : plates) {
      const std::string name = p.at("name");
      auto it = std::find_if(byName.begin(), byName.end(),
                             [&](const auto& e) { return e.first == name; });
      if (it == byName.end()) it = byName.insert(byName.end(), {name, nlohmann::json::array()});
      it->second.push_back(p);
    }
  }
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [name, states] : byName) {
    nlohmann::json v = failureVerdict(states);
    const nlohmann::json& last = states.back();
    nlohmann::json spallAt = nullptr;
    for (const auto& st : states)
      if (st.value("spalled", false)) {
        spallAt = st;
        break;
      }
    double maxHole = 0.0;
    for (const auto& st : states) maxHole = std::max(maxHole, st.value("hole_radius_cm", 0.0));
    out.push_back({{"name", name},
                   {"hole_radius_cm", last.value("hole_radius_cm", 0.0)},
                   {"hole_radius_time_us", last.at("time_us")},
                   {"max_hole_radius_cm", maxHole},
                   {"perforated", v.at("perforated")},
                   {"first_time_us", v.at("first_time_us")},
                   {"mode", v.at("mode")},
                   {"spalled", !spallAt.is_null()},
                   {"spall_first_time_us", spallAt.is_null() ? nlohmann::json(nullptr)
                                                              : spallAt.at("time_us")},
                   {"spall", spallAt.is_null() ? nlohmann::json::array() : spallAt.at("spall")},
                   {"evidence", v.at("evidence")}});
  }
  return out;
}

nlohmann::json failureVerdict(const nlohmann::json& states) {
  nlohmann::json last;
  for (const auto& st : states) {
    if (st.is_null()) continue;
    last = st;
    if (st.value("perforated", false))
      return {{"perforated", true},
              {"first_time_us", st.at("time_us")},
              {"mode", st.at("mode")},
              {"evidence", st}};
  }
  return {{"perforated", false},
          {"first_time_us", nullptr},
          {"mode", last.is_null() ? nlohmann::json("unknown") : last.at("mode")},
          {"evidence", last}};
}

}  // namespace hvi::shield
