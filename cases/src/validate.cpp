//! @file Checks across sections: bodies against the domain and geometry, overlaps, resolution,
//! and the layout the exact Riemann solution needs.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "detail/overlap.hpp"
#include "detail/parse.hpp"
#include "hvi/common/error.hpp"
#include "hvi/verify/riemann.hpp"

namespace hvi::cases::detail {
namespace {

// Six significant digits: enough to see why a check failed, short enough to read.
std::string g6(double v) { return fmt::format("{:.6g}", v); }

std::string range(double a, double b) { return fmt::format("[{}, {}]", g6(a), g6(b)); }

std::string bodyLabel(const Scene& scene, std::size_t i) {
  return "bodies[" + std::to_string(i) + "] (\"" + scene.bodies[i].name + "\")";
}

// In r-z, x is the radius: nothing left of the axis, disks are spheres on it, and a body on the
// axis cannot move radially as a whole.
void checkAxisymmetric(const TableReader& b, const Body& body, double tol) {
  if (const auto* d = std::get_if<Disk>(&body.shape))
    b.check(std::abs(d->centre.x) <= tol, "centre",
            "in rz geometry a disk is a sphere and must be centred on the axis",
            "centre = [\"0 cm\", z]");
  if (const auto* r = std::get_if<Rect>(&body.shape))
    b.check(r->xmin >= -tol, "x", "in rz geometry x is the radius and must be >= 0",
            "x = [min, max] with min >= 0");
  if (const auto* p = std::get_if<Polygon>(&body.shape))
    for (const Vec2 v : p->vertices)
      b.check(v.x >= -tol, "vertices", "in rz geometry x is the radius and must be >= 0",
              "vertices with x >= 0");
  if (boundingBox(body.shape).xmin <= tol && !body.radial)
    b.check(body.velocity.x == 0.0, "velocity",
            "a body on the axis cannot move radially in rz geometry",
            "velocity = [\"0 km/s\", vz], or radial_velocity for flow onto the axis");
}

// Memory per work item, peak RSS against items (docs/performance.md, tools/bench_effects.py
// --memory): ~380 B per SPH particle, the peak being the stepping (state and derived values
// ~150 B, step arrays ~100 B, the half-row list of indices ~120 B; the set-up and an output stay
// below it: docs/performance.md, "SPH memory"); ~1.3 KiB with strength, whose pass needs the compatible
// energy's pair data stored (16 B more per slot) and its own per-particle arrays; ~100 B per TVD cell
// (conserved state, 32 B, and a snapshot's fields, 56 B, at an output; the sweep buffers are per
// line and thread: issue 17, measured 89 B marginal and 94-100 B per cell on 2-4 million cells),
// ~340 B per TVD cell with marker lines and two bodies, ~450 B with three (about 80 B per body:
// its state, fraction, working fraction, four apertures; issue 17 goal 3, docs/tvd.md
// "Threading and memory"; ~710 B with strength), so the cap below holds ~11 GiB for three
// bodies without strength. The
// caps keep a run near 12 GiB, under the 24 GiB of the machines this project targets, and keep
// item counts far from integer overflow; a scene beyond them is refused before anything is
// allocated.
constexpr double kMaxParticles = 3e7;
constexpr double kMaxParticlesWithStrength = 8e6;
constexpr double kMaxCells = 1.2e8;
constexpr double kMaxCellsWithMarkers = 2.5e7;

void checkSize(const TableReader& root, const Scene& scene, const std::string& section,
               const std::string& key, const std::string& what, double h) {
  const double cap = scene.solver == SolverKind::Sph
                         ? (scene.has(Effect::Strength) ? kMaxParticlesWithStrength : kMaxParticles)
                     : scene.has(Effect::MaterialInterfaces) ? kMaxCellsWithMarkers
                                                             : kMaxCells;
  const double items = estimatedWorkItems(scene);
  if (items <= cap) return;
  const auto sec = root.subTable(section, false);
  fail(root.ctx(), sec && sec->find(key) ? sec->find(key) : nullptr, section + "." + key,
       fmt::format("{} cm gives about {:.3g} {}s, more than the {:.2g} hvi holds in memory "
                   "(docs/scenes.md)",
                   g6(h), items, what, cap),
       section + "." + key + " >= " + g6(h * std::sqrt(items / cap)) + " cm, or a smaller " +
           (scene.solver == SolverKind::Sph ? "body" : "domain"));
}

void checkResolution(const TableReader& root, const Scene& scene, const Sources& src) {
  std::string section, key, what;
  double h = 0.0;
  if (scene.solver == SolverKind::Sph) {
    section = "sph", key = "spacing", what = "particle", h = scene.sph.spacing;
  } else if (scene.solver == SolverKind::Tvd) {
    section = "tvd", key = "cell_size", what = "cell", h = scene.tvd.cellSize;
  } else {
    return;
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Box bb = boundingBox(scene.bodies[i].shape);
    double thickness = std::min(bb.xmax - bb.xmin, bb.zmax - bb.zmin);
    if (h <= thickness) continue;
    const auto sec = root.subTable(section, false);
    const toml::node* where = sec && sec->find(key) ? sec->find(key) : src.bodies[i];
    fail(root.ctx(), where, section + "." + key,
         g6(h) + " cm is coarser than " + bodyLabel(scene, i) + ", which is " + g6(thickness) +
             " cm thick: it would get no " + what + " across",
         section + "." + key + " <= " + g6(thickness) + " cm");
  }
  checkSize(root, scene, section, key, what, h);
}

// Whether the SPH fill (sph/src/fill.cpp, fillBodies) puts a particle into bodies[b]: the same
// lattice (square, or hexagonal with odd rows shifted), the same site positions and the same
// rule that the first body in scene order owns a site two bodies share. The thickness check
// passes bodies whose bounding box is wide enough but that still catch no site (a thin diagonal
// strip, a small disk between rows); without this, `check` accepts what `run` refuses.
// Stops at the first site; the sites scanned are at most the bounding box over spacing^2, which
// checkSize has capped.
bool holdsLatticeSite(const Scene& scene, std::size_t b) {
  const SphParams& sp = scene.sph;
  double ax = sp.spacing, az = sp.spacing;
  const bool shiftOdd = sp.lattice == Lattice::Hexagonal;
  if (shiftOdd) {
    ax = sp.spacing * std::sqrt(2.0 / std::sqrt(3.0));
    az = 0.5 * std::sqrt(3.0) * ax;
  }
  const Domain& dom = scene.domain;
  const Box box = boundingBox(scene.bodies[b].shape);
  const double zlo = std::max(box.zmin, dom.zmin), zhi = std::min(box.zmax, dom.zmax);
  const double xlo = std::max(box.xmin, dom.xmin), xhi = std::min(box.xmax, dom.xmax);
  const long k0 = std::max(0L, static_cast<long>(std::floor((zlo - dom.zmin) / az - 0.5)));
  const long k1 = static_cast<long>(std::ceil((zhi - dom.zmin) / az));
  for (long k = k0; k <= k1; ++k) {
    const double z = dom.zmin + (static_cast<double>(k) + 0.5) * az;
    if (z < zlo || z > zhi || z > dom.zmax) continue;
    const double shift = (shiftOdd && (k & 1)) ? 0.5 : 0.0;
    const long i0 = std::max(0L, static_cast<long>(std::floor((xlo - dom.xmin) / ax - 0.5 - shift)));
    const long i1 = static_cast<long>(std::ceil((xhi - dom.xmin) / ax));
    for (long i = i0; i <= i1; ++i) {
      const double x = dom.xmin + (static_cast<double>(i) + 0.5 + shift) * ax;
      if (x < xlo || x > xhi || x > dom.xmax) continue;
      const Vec2 pt{x, z};
      if (!contains(scene.bodies[b].shape, pt)) continue;
      bool claimed = false;
      for (std::size_t o = 0; o < b && !claimed; ++o) claimed = contains(scene.bodies[o].shape, pt);
      if (!claimed) return true;
    }
  }
  return false;
}

void checkSphFill(const TableReader& root, const Scene& scene, const Sources& src) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (holdsLatticeSite(scene, i)) continue;
    fail(root.ctx(), src.bodies[i], "bodies[" + std::to_string(i) + "]",
         "\"" + scene.bodies[i].name + "\" holds no SPH particle: no site of the " +
             g6(scene.sph.spacing) + " cm particle lattice lies inside it",
         "a smaller sph.spacing, or a larger body");
  }
}

// tvd.outflow = "no_reentry" (and "no_reentry_cut") is a rule of the cut cells' phase faces
// (docs/tvd.md, "Outflow sides: no re-entry"): the conservative interface mode only.
void checkTvdOutflow(const TableReader& root, const Scene& scene) {
  if (scene.tvd.outflow != OutflowMode::Open && scene.tvd.outflow != OutflowMode::Auto &&
      !(scene.has(Effect::MaterialInterfaces) &&
        scene.tvd.interfaces == InterfaceMode::Conservative))
    root.subTable("tvd", true)
        ->fail("outflow",
               "\"no_reentry\" and \"no_reentry_cut\" act on the phases of the conservative "
               "interface mode, which this "
               "scene does not run",
               "tvd.outflow = \"open\", or effects with \"material_interfaces\" and "
               "tvd.interfaces = \"conservative\"");
}

// Without marker lines the TVD solver keeps one material (its cells hold no material index).
void checkTvdMaterials(const TableReader& root, const Scene& scene, const Sources& src) {
  if (scene.has(Effect::MaterialInterfaces)) return;
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].material == scene.bodies[0].material) continue;
    const auto& mats = scene.materials;
    const toml::node* where = src.bodies[i]->get("material");
    fail(root.ctx(), where ? where : src.bodies[i], "bodies[" + std::to_string(i) + "].material",
         "is \"" + mats[static_cast<std::size_t>(scene.bodies[i].material)].name + "\" but " +
             bodyLabel(scene, 0) + " is \"" +
             mats[static_cast<std::size_t>(scene.bodies[0].material)].name +
             "\": the TVD solver needs the effect \"material_interfaces\" (marker lines) for "
             "several materials",
         "effects = [..., \"material_interfaces\"], or one material for every body");
  }
}

// Strength and fracture (docs/strength.md): solids only, and with fracture every solid's spall
// strength stands in for the zero cut-off, so the two cannot both be named.
void checkStrength(const TableReader& root, const Scene& scene) {
  const bool fracture = scene.has(Effect::Fracture);
  if (fracture && scene.has(Effect::TensionCutoff))
    root.fail("effects",
              "\"fracture\" replaces the zero cut-off of \"tension_cutoff\" by each material's "
              "spall_strength: name one of them",
              "effects without \"tension_cutoff\" (spall_strength = 0 is the zero cut-off)");
  const auto mats = root.subTable("materials", true);
  bool any = false;
  for (const Material& m : scene.materials) {
    const bool gas = std::holds_alternative<eos::IdealGas>(m.eos);
    const auto t = mats->subTable(m.name, true);
    if (m.strength && gas)
      t->fail("strength", "an ideal gas carries no shear stress and no tension",
              "a strength table for Tillotson and Mie-Gruneisen materials only");
    if (!m.strength && !gas && fracture)
      t->fail("strength",
              "missing: the effect \"fracture\" needs the spall strength of every solid",
              "[" + t->path() + ".strength] with spall_strength (a preset, or model and its keys)");
    any = any || m.strength.has_value();
  }
  if (fracture && !scene.has(Effect::Strength))
    root.fail("effects",
              "\"fracture\" removes tensile and shear strength that \"strength\" gives: name both",
              "effects = [..., \"strength\", \"fracture\"]");
  if (scene.has(Effect::Strength) && !any)
    root.fail("effects", "\"strength\" is named but no material has a strength table",
              "[materials.<name>.strength] for the solids");
  // TVD carries the deviator per phase in the conservative interface mode; the study's
  // whole-cell mode has none (docs/strength.md, "TVD with interfaces").
  if (scene.solver == SolverKind::Tvd && scene.has(Effect::Strength) &&
      scene.has(Effect::MaterialInterfaces) && scene.tvd.interfaces == InterfaceMode::WholeCell)
    root.fail("effects",
              "the TVD solver runs \"strength\" with \"material_interfaces\" in the "
              "conservative interface mode only (the deviator is carried per phase; the "
              "study's whole-cell interfaces have no strength)",
              "tvd.interfaces = \"conservative\" (the default), or effects without "
              "\"strength\"");
}

// The SPH viscosity switch (docs/strength.md, "Viscosity switch") is summed by the strength
// pass: with the effects strength and artificial_viscosity only; alpha is its maximum.
void checkViscositySwitch(const TableReader& root, const Scene& scene) {
  if (scene.sph.yieldStrainRate == YieldStrainRate::Plastic &&
      (scene.solver != SolverKind::Sph || !scene.has(Effect::Strength)))
    root.subTable("sph", true)
        ->fail("yield_strain_rate",
               "\"plastic\" is the SPH yield law's strain rate with the effect \"strength\"",
               "\"total\", or solver = \"sph\" with effects = [..., \"strength\"]");
  if (scene.sph.viscositySwitch == ViscositySwitch::Off) return;
  const auto sph = root.subTable("sph", true);
  if (scene.solver != SolverKind::Sph || !scene.has(Effect::Strength) ||
      !scene.has(Effect::ArtificialViscosity))
    sph->fail("viscosity_switch",
              "\"morris_monaghan\" switches the SPH viscosity per particle with the effects "
              "\"strength\" and \"artificial_viscosity\" (the strength pass sums it)",
              "\"off\", or solver = \"sph\" with effects = [..., \"artificial_viscosity\", "
              "\"strength\"]");
  if (!(scene.sph.alpha > 0.0))
    sph->fail("viscosity_switch", "needs sph.alpha > 0: alpha is the switch's maximum",
              "sph.alpha > 0, or \"off\"");
  if (scene.sph.alphaMin > scene.sph.alpha)
    sph->fail("alpha_min",
              "is " + g6(scene.sph.alphaMin) + ", above sph.alpha = " + g6(scene.sph.alpha) +
                  " (the switch's maximum)",
              "0 <= alpha_min <= alpha");
}

void checkRiemann(const TableReader& root, const Scene& scene, const Sources& src, double tol) {
  const std::string need = "planar geometry and exactly two rect bodies meeting at x = interface";
  if (scene.geometry != Geometry::Planar)
    root.fail("geometry", "the exact Riemann solution is one-dimensional", need);
  if (scene.bodies.size() != 2)
    root.fail("bodies",
              "the Riemann solver needs 2 bodies, got " + std::to_string(scene.bodies.size()),
              need);
  for (std::size_t i = 0; i < 2; ++i)
    if (!std::holds_alternative<Rect>(scene.bodies[i].shape))
      fail(root.ctx(), src.bodies[i], "bodies[" + std::to_string(i) + "].shape",
           "the Riemann solver needs rect bodies", need);
  for (std::size_t i = 0; i < 2; ++i)
    if (scene.bodies[i].radial)
      fail(root.ctx(), src.bodies[i], "bodies[" + std::to_string(i) + "].radial_velocity",
           "the Riemann solver needs uniform states", "velocity = [vx, 0]");
  const Rect& a = std::get<Rect>(scene.bodies[0].shape);
  const Rect& b = std::get<Rect>(scene.bodies[1].shape);
  const Rect& left = a.xmin <= b.xmin ? a : b;
  const Rect& right = a.xmin <= b.xmin ? b : a;
  if (std::abs(left.xmax - right.xmin) > tol)
    fail(root.ctx(), src.bodies[1], "bodies",
         "the two bodies must meet along x: the left ends at x = " + g6(left.xmax) +
             " cm, the right starts at x = " + g6(right.xmin) + " cm",
         need);
  if (std::abs(scene.riemann.interface - left.xmax) > tol) {
    const auto sec = root.subTable("riemann", false);
    fail(root.ctx(), sec && sec->find("interface") ? sec->find("interface") : nullptr,
         "riemann.interface",
         "is " + g6(scene.riemann.interface) + " cm but the bodies meet at x = " + g6(left.xmax) +
             " cm",
         "the x where the bodies meet (or leave it out)");
  }
}

// A step dt at time t is kept only to within ulp(t) (t + dt rounds to a double): when dt falls
// below half an ulp, t stops advancing and the run spins (time.start = 1e20 us: ulp = 16384 us).
// The first step is estimated before anything is built, as cfl h / max(|v| + c) over the bodies'
// initial states (h: the SPH smoothing length or the TVD cell). Impacts shorten the step as they
// compress and heat, typically 10 to 100 fold, so the estimate must exceed ulp(t) by a wide
// margin: 2^20 ulps keeps each step exact to 1e-6 and still advancing after a 1e6-fold drop.
// Shipped scenes end by 7.2 us; the tightest bound among them (noh_planar) is 4e6 us.
constexpr double kMinStepUlps = 1048576.0;

void checkTimeResolution(const TableReader& root, const Scene& scene) {
  double h = 0.0, cfl = 0.0;
  if (scene.solver == SolverKind::Sph) {
    h = scene.sph.hFactor * scene.sph.spacing, cfl = scene.sph.cfl;
  } else if (scene.solver == SolverKind::Tvd) {
    h = scene.tvd.cellSize, cfl = scene.tvd.cfl;
  } else {
    return;  // the exact solution goes from output time to output time in one step
  }
  double speed = 0.0;
  for (const Body& b : scene.bodies) {
    const Material& m = scene.materials[static_cast<std::size_t>(b.material)];
    const double rho = b.density > 0.0 ? b.density : m.rho0();
    const double c = eos::state(m.eos, rho, b.specificEnergy).soundSpeed;
    const double v = b.radial ? std::abs(b.radialSpeed) : norm(b.velocity);
    if (std::isfinite(c + v)) speed = std::max(speed, c + v);
  }
  if (!(speed > 0.0)) return;  // nothing moves or sounds: the solvers step to the output times
  const double dt = cfl * h / speed;
  const bool startIsLarger = std::abs(scene.tStart) >= std::abs(scene.tEnd);
  const double t = startIsLarger ? std::abs(scene.tStart) : std::abs(scene.tEnd);
  const double ulp = std::nextafter(t, HUGE_VAL) - t;
  if (dt >= kMinStepUlps * ulp) return;
  // The largest |t| whose ulp is dt / kMinStepUlps (ulp(t) <= 2^-52 t).
  const double tMax = dt / kMinStepUlps / std::ldexp(1.0, -52);
  const std::string key = startIsLarger ? "start" : "end";
  const auto sec = root.subTable("time", false);
  fail(root.ctx(), sec && sec->find(key) ? sec->find(key) : nullptr, "time." + key,
       fmt::format("at t = {} us doubles are {} us apart, while the first time step is about "
                   "{} us (cfl h / (|v| + c) of the initial state): the steps would be lost to "
                   "round-off and t would not advance",
                   g6(t), g6(ulp), g6(dt)),
       fmt::format("|time.start| and |time.end| below {} us at this resolution (shift the times "
                   "towards 0)",
                   g6(tMax)));
}

// The exact solution does not exist for every pair of states (two Tillotson bodies separating
// faster than their tension holds, an isentrope leaving the EOS's hyperbolic region): the
// solver would refuse it at set-up, so `check` builds it here (milliseconds) to name the file.
void checkRiemannSolution(const TableReader& root, const Scene& scene, const Sources& src) {
  const Rect& a = std::get<Rect>(scene.bodies[0].shape);
  const Rect& b = std::get<Rect>(scene.bodies[1].shape);
  const std::size_t l = b.xmin < a.xmin ? 1 : 0, r = 1 - l;
  auto state = [&](std::size_t i) {
    const Body& body = scene.bodies[i];
    return verify::RiemannState{body.density, body.velocity.x, body.specificEnergy};
  };
  try {
    (void)verify::ExactRiemann(scene.materials[static_cast<std::size_t>(scene.bodies[l].material)].eos,
                               state(l),
                               scene.materials[static_cast<std::size_t>(scene.bodies[r].material)].eos,
                               state(r));
  } catch (const SimulationError& e) {
    fail(root.ctx(), src.bodies[r], "bodies",
         std::string("the exact Riemann solution does not exist for these two states: ") +
             e.what(),
         "left and right states (density, velocity, pressure or specific_energy) that the "
         "exact solver can join, e.g. a lower separation speed");
  }
}

// The debris-cloud features measure a striker against a shield (compare::featureConfigFromScene:
// bodies so named, else the first body strikes the second); with one body every feature would
// be null at every snapshot.
void checkFeatures(const TableReader& root, const Scene& scene) {
  if (!scene.has(Effect::Features) || scene.bodies.size() >= 2) return;
  const toml::array* arr = root.find("effects") ? root.find("effects")->as_array() : nullptr;
  std::size_t i = 0;
  while (arr && i < arr->size() && arr->get(i)->value_or(std::string_view{}) != "features") ++i;
  fail(root.ctx(), arr && i < arr->size() ? arr->get(i) : nullptr,
       "effects[" + std::to_string(i) + "]",
       "effect \"features\" needs a striker and a shield, but the scene has " +
           std::to_string(scene.bodies.size()) + " body",
       "two bodies or more (named \"striker\" and \"shield\", else the first strikes the "
       "second), or no \"features\"");
}

}  // namespace

void validateScene(const TableReader& root, const Scene& scene, const Sources& src) {
  const Domain& d = scene.domain;
  // Touching bodies computed from unit conversions differ by round-off; 1e-9 of the domain is far
  // below any resolution a solver can use.
  const double tol = 1e-9 * std::max(d.xmax - d.xmin, d.zmax - d.zmin);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    const TableReader b(root.ctx(), *src.bodies[i], "bodies[" + std::to_string(i) + "]");
    if (scene.geometry == Geometry::Axisymmetric) checkAxisymmetric(b, body, tol);
    Box bb = boundingBox(body.shape);
    if (scene.geometry == Geometry::Axisymmetric) bb.xmin = std::max(bb.xmin, 0.0);
    if (bb.xmin < d.xmin - tol || bb.xmax > d.xmax + tol || bb.zmin < d.zmin - tol ||
        bb.zmax > d.zmax + tol)
      fail(root.ctx(), src.bodies[i], "bodies[" + std::to_string(i) + "]",
           "\"" + body.name + "\" spans x " + range(bb.xmin, bb.xmax) + ", z " +
               range(bb.zmin, bb.zmax) + " cm, outside the domain x " + range(d.xmin, d.xmax) +
               ", z " + range(d.zmin, d.zmax) + " cm",
           "bodies inside [domain] (touching its edges is fine)");
  }
  for (std::size_t j = 1; j < scene.bodies.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (overlaps(scene.bodies[i].shape, scene.bodies[j].shape, tol))
        fail(root.ctx(), src.bodies[j], "bodies[" + std::to_string(j) + "]",
             "\"" + scene.bodies[j].name + "\" overlaps " + bodyLabel(scene, i),
             "bodies that touch but do not overlap");
  checkResolution(root, scene, src);
  if (scene.solver == SolverKind::Sph) checkSphFill(root, scene, src);
  if (scene.solver == SolverKind::Tvd) {
    checkTvdMaterials(root, scene, src);
    checkTvdOutflow(root, scene);
  }
  checkTimeResolution(root, scene);
  checkFeatures(root, scene);
  checkStrength(root, scene);
  checkViscositySwitch(root, scene);
  if (scene.solver == SolverKind::Riemann) {
    checkRiemann(root, scene, src, tol);
    checkRiemannSolution(root, scene, src);
  }
}

}  // namespace hvi::cases::detail

namespace hvi::cases {

double estimatedWorkItems(const Scene& scene) {
  const Domain& d = scene.domain;
  if (scene.solver == SolverKind::Sph) {
    double area = 0.0;
    for (const Body& body : scene.bodies) {
      const Box bb = boundingBox(body.shape);
      area += std::max(0.0, std::min(bb.xmax, d.xmax) - std::max(bb.xmin, d.xmin)) *
              std::max(0.0, std::min(bb.zmax, d.zmax) - std::max(bb.zmin, d.zmin));
    }
    return area / (scene.sph.spacing * scene.sph.spacing);
  }
  if (scene.solver == SolverKind::Tvd)
    return (d.xmax - d.xmin) * (d.zmax - d.zmin) / (scene.tvd.cellSize * scene.tvd.cellSize);
  return static_cast<double>(scene.riemann.cells);
}

}  // namespace hvi::cases
