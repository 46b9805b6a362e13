//! @file The SPH solver: scene to particles, stepping, snapshots.
#include "hvi/sph/sph.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/units.hpp"
#include "hvi/sph/fill.hpp"

namespace hvi::sph {
namespace {

void validate(const cases::Scene& scene) {
  const auto& b = scene.domain.boundary;
  for (int s = 1; s < 4; ++s)
    if (b[s] == cases::Boundary::Axis)
      throw InputError(fmt::format(
          "{}: SPH: boundary {} is 'axis'; only the xmin side (x = 0 in r-z) can be the axis",
          scene.path, s));
  if (scene.geometry == Geometry::Axisymmetric &&
      (scene.domain.xmin != 0.0 || b[0] != cases::Boundary::Axis))
    throw InputError(fmt::format(
        "{}: SPH in rz geometry needs domain xmin = 0 with boundary 'axis' (got xmin = {})",
        scene.path, scene.domain.xmin));
  if (scene.bodies.empty()) throw InputError(scene.path + ": SPH: the scene has no bodies");
  if (!(scene.sph.alpha >= 0.0) || !(scene.sph.beta >= 0.0))
    throw InputError(fmt::format("{}: sph.alpha = {} and sph.beta = {} must be >= 0",
                                 scene.path, scene.sph.alpha, scene.sph.beta));
}

StepperConfig stepperConfig(const cases::Scene& scene) {
  StepperConfig cfg;
  cfg.geometry = scene.geometry;
  cfg.kernel = scene.sph.kernel;
  cfg.viscosity = scene.has(cases::Effect::ArtificialViscosity);
  cfg.visc = {scene.sph.alpha, scene.sph.beta};
  cfg.cfl = scene.sph.cfl;
  cfg.domain = scene.domain;
  cfg.time = scene.tStart;
  for (const auto& body : scene.bodies) cfg.objectNames.push_back(body.name);
  return cfg;
}

}  // namespace

std::vector<eos::Eos> sceneMaterials(const cases::Scene& scene) {
  std::vector<eos::Eos> out;
  for (const auto& mat : cases::resolveMaterials(scene)) out.push_back(mat.eos);
  return out;
}

SphSolver::SphSolver(const cases::Scene& scene) : scene_(scene) {
  validate(scene_);
  materials_ = sceneMaterials(scene_);
  ParticleSystem ps = fillBodies(scene_);
  if (scene_.has(cases::Effect::MassAdjustment)) {
    MassAdjustOptions opt;
    opt.geometry = scene_.geometry;
    opt.kernel = scene_.sph.kernel;
    opt.domain = scene_.domain;
    opt.tolerance = scene_.sph.massTolerance;
    opt.deleteFraction = scene_.sph.deleteFraction;
    opt.maxIterations = scene_.sph.maxMassIterations;
    massReport_ = adjustMasses(ps, opt);
  }
  stepper_ = std::make_unique<Stepper>(ps, materials_, stepperConfig(scene_));
}

Snapshot SphSolver::snapshot() const {
  const ParticleSystem ps = stepper_->particles();
  const std::size_t n = ps.size();
  Snapshot s;
  s.time = stepper_->time();
  s.step = stepper_->stepCount();
  s.solver = "sph";
  s.geometry = scene_.geometry;
  s.kind = Snapshot::Kind::Particles;
  s.positions.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.positions[i] = {ps.x[i], ps.z[i]};
  auto scalar = [&](const char* name, const char* unit, const auto& v) {
    Field f{name, unit, 1, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) f.data[i] = static_cast<double>(v[i]);
    s.fields.push_back(std::move(f));
  };
  const bool rz = scene_.geometry == Geometry::Axisymmetric;
  scalar("density", units::densityName, ps.rho);
  scalar("pressure", units::pressureName, ps.p);
  Field vel{"velocity", units::velocityName, 2, std::vector<double>(2 * n)};
  for (std::size_t i = 0; i < n; ++i) {
    vel.data[2 * i] = ps.vx[i];
    vel.data[2 * i + 1] = ps.vz[i];
  }
  s.fields.push_back(std::move(vel));
  scalar("specific_energy", units::energyName, ps.e);
  scalar("sound_speed", units::velocityName, ps.c);
  scalar("mass", rz ? "g" : "g/cm", ps.m);
  scalar("material", "1", ps.material);
  scalar("object", "1", ps.object);
  scalar("smoothing_length", units::lengthName, ps.h);
  scalar("id", "1", ps.id);
  if (scene_.has(cases::Effect::PhaseBookkeeping)) {
    Field frac{"vapour_fraction", "1", 1, std::vector<double>(n, 0.0)};
    Field phase{"phase", "1", 1, std::vector<double>(n, 0.0)};
    for (std::size_t i = 0; i < n; ++i) {
      const auto* t = std::get_if<eos::Tillotson>(&materials_[static_cast<std::size_t>(ps.material[i])]);
      if (!t) continue;
      frac.data[i] = std::clamp((ps.e[i] - t->e1) / (t->e2 - t->e1), 0.0, 1.0);
      phase.data[i] = static_cast<double>(static_cast<int>(t->phase(ps.e[i])));
    }
    s.fields.push_back(std::move(frac));
    s.fields.push_back(std::move(phase));
  }
  for (const auto& mat : scene_.materials) s.materialNames.push_back(mat.name);
  for (const auto& body : scene_.bodies) s.objectNames.push_back(body.name);
  return s;
}

std::unique_ptr<Solver> createSolver(const cases::Scene& scene) {
  return std::make_unique<SphSolver>(scene);
}

}  // namespace hvi::sph
