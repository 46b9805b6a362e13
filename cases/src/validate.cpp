//! @file Checks across sections: bodies against the domain and geometry, overlaps, resolution,
//! and the layout the exact Riemann solution needs.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "detail/overlap.hpp"
#include "detail/parse.hpp"

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

// Memory per work item measured on the hard cases (peak RSS against items): ~1 KiB per SPH
// particle (state, step arrays and the Gaussian kernel's ~30-60 neighbours per particle), ~250 B
// per TVD cell (conserved state, predictor copy, fluxes, ownership). The caps keep a run near
// 10 GiB, under the 24 GiB of the machines this project targets, and keep item counts far from
// integer overflow; a scene beyond them is refused before anything is allocated.
constexpr double kMaxParticles = 1e7;
constexpr double kMaxCells = 5e7;

void checkSize(const TableReader& root, const Scene& scene, const std::string& section,
               const std::string& key, const std::string& what, double h) {
  const double cap = scene.solver == SolverKind::Sph ? kMaxParticles : kMaxCells;
  const double items = estimatedWorkItems(scene);
  if (items <= cap) return;
  const auto sec = root.subTable(section, false);
  fail(root.ctx(), sec && sec->find(key) ? sec->find(key) : nullptr, section + "." + key,
       fmt::format("{} cm gives about {:.3g} {}s, more than the {:.0e} hvi holds in memory "
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
  if (scene.solver == SolverKind::Riemann) checkRiemann(root, scene, src, tol);
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
  return 0.0;
}

}  // namespace hvi::cases
