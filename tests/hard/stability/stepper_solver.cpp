//! @file StepperSolver and the shifted-particle SPH variant of near_contact.
#include "stepper_solver.hpp"

#include "harness.hpp"
#include "hvi/common/units.hpp"
#include "hvi/sph/fill.hpp"
#include "hvi/sph/mass_adjust.hpp"
#include "hvi/sph/sph.hpp"

namespace hvi::hard {
namespace {

// The configuration sph::SphSolver derives from a scene (sph/src/solver.cpp).
sph::StepperConfig stepperConfig(const cases::Scene& scene) {
  sph::StepperConfig cfg;
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

StepperSolver::StepperSolver(const cases::Scene& scene, const sph::ParticleSystem& ps)
    : scene_(scene),
      stepper_(
          std::make_unique<sph::Stepper>(ps, sph::sceneMaterials(scene), stepperConfig(scene))) {}

Snapshot StepperSolver::snapshot() const {
  const sph::ParticleSystem ps = stepper_->particles();
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
  scalar("mass", "g/cm", ps.m);
  scalar("material", "1", ps.material);
  scalar("object", "1", ps.object);
  scalar("smoothing_length", units::lengthName, ps.h);
  scalar("id", "1", ps.id);
  for (const auto& mat : scene_.materials) s.materialNames.push_back(mat.name);
  for (const auto& body : scene_.bodies) s.objectNames.push_back(body.name);
  return s;
}

std::unique_ptr<Solver> makeShiftedSph(const cases::Scene& scene, int object, double dz) {
  sph::ParticleSystem ps = sph::fillBodies(scene);
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (ps.object[i] == object) ps.z[i] += dz;
  if (scene.has(cases::Effect::MassAdjustment)) {
    // Per object, as in sph::SphSolver: a rigid shift of one object leaves its masses as they
    // are without the shift.
    sph::MassAdjustOptions opt;
    opt.geometry = scene.geometry;
    opt.kernel = scene.sph.kernel;
    opt.domain = scene.domain;
    opt.tolerance = scene.sph.massTolerance;
    opt.deleteFraction = scene.sph.deleteFraction;
    opt.maxIterations = scene.sph.maxMassIterations;
    sph::adjustMasses(ps, opt);
  }
  return std::make_unique<StepperSolver>(scene, ps);
}

}  // namespace hvi::hard
