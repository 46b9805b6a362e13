//! @file Exact Riemann solution sampled on a 1-D grid, behind the Solver interface.
#include "hvi/verify/riemann_solver.hpp"

#include <istream>
#include <ostream>
#include <variant>

#include "hvi/cases/effects.hpp"
#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"
#include "hvi/verify/riemann.hpp"

namespace hvi::verify {
namespace {

class RiemannSolver final : public Solver {
 public:
  explicit RiemannSolver(const cases::Scene& s) : scene_(s), t_(s.tStart) {
    if (s.bodies.size() != 2)
      throw InputError(s.path + ": solver \"riemann\" needs exactly two bodies (left, right)");
    // Validation lets the bodies come in either order (cases/src/validate.cpp, checkRiemann):
    // the left one is the one that starts further left.
    const auto* r0 = std::get_if<cases::Rect>(&s.bodies[0].shape);
    const auto* r1 = std::get_if<cases::Rect>(&s.bodies[1].shape);
    if (r0 && r1 && r1->xmin < r0->xmin) left_ = 1;
    const auto& l = s.bodies[left_];
    const auto& r = s.bodies[1 - left_];
    scene_.materials = cases::resolveMaterials(s);  // as every solver runs them
    const auto& m = scene_.materials;
    exact_ = std::make_unique<ExactRiemann>(
        m[l.material].eos, RiemannState{l.density, l.velocity.x, l.specificEnergy},
        m[r.material].eos, RiemannState{r.density, r.velocity.x, r.specificEnergy});
    grid_.nx = s.riemann.cells;
    grid_.nz = 1;
    grid_.x0 = s.domain.xmin;
    grid_.z0 = s.domain.zmin;
    grid_.dx = (s.domain.xmax - s.domain.xmin) / grid_.nx;
    grid_.dz = s.domain.zmax - s.domain.zmin;
  }

  std::string name() const override { return "riemann"; }
  double time() const override { return t_; }
  long step() const override { return step_; }
  long workItems() const override { return grid_.cells(); }

  double advance(double tStop) override {
    // Self-similar: the exact state at any time is one evaluation away, so a "step" goes
    // straight to the next stop.
    const double dt = tStop - t_;
    t_ = tStop;
    ++step_;
    return dt;
  }

  Snapshot snapshot() const override {
    Snapshot s = makeSnapshot("riemann", Snapshot::Kind::Grid, scene_.geometry, t_, step_);
    s.grid = grid_;
    const auto n = static_cast<std::size_t>(grid_.cells());
    const Geometry g = scene_.geometry;
    Field rho = makeField(Quantity::Density, g, n), p = makeField(Quantity::Pressure, g, n);
    Field v = makeField(Quantity::Velocity, g, n), e = makeField(Quantity::SpecificEnergy, g, n);
    Field mat = makeField(Quantity::Material, g, n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = cell(static_cast<long>(i));
      rho.data[i] = c.rho;
      p.data[i] = c.p;
      v.data[2 * i] = c.u;
      e.data[i] = c.e;
      mat.data[i] = c.material < 0 ? scene_.bodies[left_].material
                                   : (c.material > 0 ? scene_.bodies[1 - left_].material : -1);
    }
    s.fields = {rho, p, v, e, mat};
    for (const auto& m : scene_.materials) s.materialNames.push_back(m.name);
    for (const auto& b : scene_.bodies) s.objectNames.push_back(b.name);
    return s;
  }

  Totals totals() const override {
    Totals tot;
    const double vol = grid_.dx * grid_.dz;
    for (long i = 0; i < grid_.cells(); ++i) {
      const auto c = cell(i);
      tot.mass += c.rho * vol;
      tot.momentumX += c.rho * c.u * vol;
      tot.kinetic += 0.5 * c.rho * c.u * c.u * vol;
      tot.internal += c.rho * c.e * vol;
    }
    return tot;
  }

  void writeCheckpoint(std::ostream& out) const override {
    BinaryWriter w(out, "riemann checkpoint");
    w.value(t_);
    w.value(step_);
  }
  void readCheckpoint(std::istream& in) override {
    BinaryReader r(in, "riemann checkpoint");
    t_ = r.value<double>();
    step_ = r.value<long>();
  }

 private:
  RiemannSample cell(long i) const {
    const double x = grid_.x0 + (i + 0.5) * grid_.dx;
    const double dt = t_ - scene_.tStart;
    const double d = x - scene_.riemann.interface;
    if (dt <= 0.0) {
      const auto& b = scene_.bodies[d < 0.0 ? left_ : 1 - left_];
      const double pr = eos::pressure(scene_.materials[b.material].eos, b.density, b.specificEnergy);
      return {b.density, b.velocity.x, pr, b.specificEnergy, d < 0.0 ? -1 : 1};
    }
    return exact_->sample(d / dt);
  }

  cases::Scene scene_;
  std::size_t left_ = 0;  //!< index of the left body in scene_.bodies
  std::unique_ptr<ExactRiemann> exact_;
  GridSpec grid_;
  double t_;
  long step_ = 0;
};

}  // namespace

std::unique_ptr<Solver> createRiemannSolver(const cases::Scene& scene) {
  return std::make_unique<RiemannSolver>(scene);
}

}  // namespace hvi::verify
