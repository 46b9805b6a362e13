//! @file The SPH solver: scene to particles, stepping, snapshots.
#include "hvi/sph/sph.hpp"

#include <numbers>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

#include "hvi/cases/effects.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/snapshot.hpp"
#include "hvi/sph/fill.hpp"

#include "detail/axis_correction.hpp"

namespace hvi::sph {
namespace {

// docs/sph-rz.md, "Which form": the symmetric form where it is implemented (not with strength).
cases::RzForm resolvedRzForm(const cases::Scene& scene) {
  if (scene.sph.rzForm != cases::RzForm::Auto) return scene.sph.rzForm;
  return scene.has(cases::Effect::Strength) ? cases::RzForm::Ring : cases::RzForm::Symmetric;
}

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
  if (scene.geometry == Geometry::Axisymmetric && scene.sph.rzForm == cases::RzForm::Symmetric &&
      scene.has(cases::Effect::Strength))
    throw InputError(scene.path +
                     ": sph.rz_form = \"symmetric\" is not implemented with the effect strength "
                     "(docs/sph-rz.md); allowed with strength: \"auto\" or \"ring\"");
  if (scene.sph.viscositySwitch != cases::ViscositySwitch::Off) {
    // The switched viscosity is summed by the strength pass (docs/strength.md).
    if (!scene.has(cases::Effect::Strength) || !scene.has(cases::Effect::ArtificialViscosity))
      throw InputError(scene.path +
                       ": sph.viscosity_switch = \"morris_monaghan\" needs the effects strength "
                       "and artificial_viscosity; allowed without them: \"off\"");
    if (!(scene.sph.alpha > 0.0))
      throw InputError(fmt::format(
          "{}: sph.viscosity_switch = \"morris_monaghan\" needs sph.alpha > 0 (its maximum; "
          "got {})", scene.path, scene.sph.alpha));
    if (!(scene.sph.alphaMin <= scene.sph.alpha))
      throw InputError(fmt::format("{}: sph.alpha_min = {} must be <= sph.alpha = {}", scene.path,
                                   scene.sph.alphaMin, scene.sph.alpha));
  }
  // Options of the symmetric r-z form only.
  auto symmetricOnly = [&](double value, std::string_view key, std::string_view note) {
    if (scene.geometry == Geometry::Axisymmetric && value != 0.0 &&
        resolvedRzForm(scene) != cases::RzForm::Symmetric)
      throw InputError(fmt::format(
          "{}: sph.{} is implemented for the symmetric r-z form only (docs/sph-rz.md); set "
          "sph.{} = 0 or sph.rz_form = \"symmetric\"{}",
          scene.path, key, key, note));
  };
  symmetricOnly(scene.sph.rzViscousHoop, "rz_viscous_hoop",
                " (\"auto\" is the ring form with strength)");
  symmetricOnly(scene.sph.rzAxisCorrection, "rz_axis_correction", "");
  if (!(scene.sph.alpha >= 0.0) || !(scene.sph.beta >= 0.0))
    throw InputError(fmt::format("{}: sph.alpha = {} and sph.beta = {} must be >= 0", scene.path,
                                 scene.sph.alpha, scene.sph.beta));
}

// Validated before the fill, so that a scene SPH cannot run gets the solver's message.
ParticleSystem filledBodies(const cases::Scene& scene) {
  validate(scene);
  return fillBodies(scene);
}


}  // namespace

std::vector<eos::Eos> sceneMaterials(const cases::Scene& scene) {
  std::vector<eos::Eos> out;
  for (const auto& mat : cases::resolveMaterials(scene)) out.push_back(mat.eos);
  return out;
}

StepperConfig stepperConfig(const cases::Scene& scene) {
  StepperConfig cfg;
  cfg.geometry = scene.geometry;
  cfg.kernel = scene.sph.kernel;
  cfg.viscosity = scene.has(cases::Effect::ArtificialViscosity);
  cfg.visc = {scene.sph.alpha, scene.sph.beta};
  cfg.energy = scene.sph.energy;
  cfg.rzForm = resolvedRzForm(scene);
  cfg.rzViscousHoop = scene.sph.rzViscousHoop;
  cfg.rzAxisCorrection = scene.sph.rzAxisCorrection;
  cfg.cfl = scene.sph.cfl;
  cfg.domain = scene.domain;
  cfg.time = scene.tStart;
  for (const auto& body : scene.bodies) cfg.objectNames.push_back(body.name);
  if (scene.has(cases::Effect::Strength)) {
    for (const auto& mat : cases::resolveMaterials(scene)) {
      cfg.strength.push_back(mat.strength);
      cfg.strengthRho0.push_back(mat.rho0());
    }
    cfg.hFactor = scene.sph.hFactor;
    cfg.artificialStress = scene.sph.artificialStressEpsilon;
    cfg.artificialStressPower = scene.sph.artificialStressExponent;
    cfg.fracture = scene.has(cases::Effect::Fracture);
    cfg.plasticStrainRate = scene.sph.yieldStrainRate == cases::YieldStrainRate::Plastic;
    if (scene.sph.viscositySwitch == cases::ViscositySwitch::MorrisMonaghan) {
      cfg.viscositySwitch = true;
      cfg.alphaMin = scene.sph.alphaMin;
      cfg.switchDecay = scene.sph.switchDecay;
    }
  }
  return cfg;
}

MassAdjustOptions massAdjustOptions(const cases::Scene& scene) {
  MassAdjustOptions opt;
  opt.geometry = scene.geometry;
  opt.kernel = scene.sph.kernel;
  opt.rzForm = resolvedRzForm(scene);
  opt.domain = scene.domain;
  opt.tolerance = scene.sph.massTolerance;
  opt.deleteFraction = scene.sph.deleteFraction;
  opt.maxIterations = scene.sph.maxMassIterations;
  return opt;
}

SphSolver::SphSolver(const cases::Scene& scene) : SphSolver(scene, filledBodies(scene)) {}

SphSolver::SphSolver(const cases::Scene& scene, ParticleSystem ps) : scene_(scene) {
  validate(scene_);
  materials_ = sceneMaterials(scene_);
  // Set-up memory (docs/performance.md, "SPH memory"): rho, p and c are derived by the
  // stepper's corrector, so they are not held through the mass iteration; the filled arrays,
  // grown by push_back to up to twice their size, are cut to size.
  for (auto* v : {&ps.rho, &ps.p, &ps.c}) std::vector<double>().swap(*v);
  for (auto* v : {&ps.x, &ps.z, &ps.vx, &ps.vz, &ps.e, &ps.m, &ps.h, &ps.rhoRef}) v->shrink_to_fit();
  ps.material.shrink_to_fit();
  ps.object.shrink_to_fit();
  ps.id.shrink_to_fit();
  if (scene_.has(cases::Effect::MassAdjustment))
    massReport_ = adjustMasses(ps, massAdjustOptions(scene_));
  stepper_ = std::make_unique<Stepper>(std::move(ps), materials_, stepperConfig(scene_));
}

Snapshot SphSolver::snapshot() const {
  // The step's work space is dead between steps: freed before the copies are made, so that
  // an output does not raise the run's peak memory (docs/performance.md, "SPH memory").
  stepper_->releaseWork();
  ParticleSystem ps = stepper_->particles();
  const std::size_t np = ps.size();
  Snapshot s = makeSnapshot("sph", Snapshot::Kind::Particles, scene_.geometry, stepper_->time(),
                            stepper_->stepCount());
  // The copy's double arrays become fields (moved), the others are freed once their field
  // holds them: the output's peak memory is one copy of the state, not two.
  const auto release = [](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); };
  const bool phases = scene_.has(cases::Effect::PhaseBookkeeping);
  // r-z symmetric form: each particle's meridional area nu / (s rho) = m / (2 pi s(r)^2 rho), the
  // weight its own density sum gives it (docs/sph-rz.md, "The symmetric form"); finite at the
  // axis, which these particles may reach, where the ring area m / (2 pi r rho) diverges.
  // Readers (hvi compare, tools/study_measure.py) use a field `volume` as the area when present.
  std::vector<double> area;
  if (scene_.geometry == Geometry::Axisymmetric &&
      resolvedRzForm(scene_) == cases::RzForm::Symmetric) {
    const detail::RingScale& ring = detail::ringScale(scene_.sph.kernel);
    area.resize(np);
    for (std::size_t i = 0; i < np; ++i) {
      const double si = ring.value(std::abs(ps.x[i]), ps.h[i]);
      area[i] = ps.m[i] / (2.0 * std::numbers::pi * si * si * ps.rho[i]);
    }
  }
  s.positions.resize(np);
  for (std::size_t i = 0; i < np; ++i) s.positions[i] = {ps.x[i], ps.z[i]};
  release(ps.x);
  release(ps.z);
  release(ps.rhoRef);
  using Q = Quantity;
  addField(s, Q::Density, std::move(ps.rho));
  addField(s, Q::Pressure, std::move(ps.p));
  addField(s, Q::Velocity, ps.vx, ps.vz);
  release(ps.vx);
  release(ps.vz);
  if (phases)  // the phase fields below read e
    addField(s, Q::SpecificEnergy, ps.e);
  else
    addField(s, Q::SpecificEnergy, std::move(ps.e));
  addField(s, Q::SoundSpeed, std::move(ps.c));
  addField(s, Q::Mass, std::move(ps.m));
  addField(s, Q::Material, ps.material);
  addField(s, Q::Object, ps.object);
  release(ps.object);
  addField(s, Q::SmoothingLength, std::move(ps.h));
  addField(s, Q::Id, ps.id);
  release(ps.id);
  if (!area.empty()) s.fields.push_back({"volume", "cm^2", 1, std::move(area)});
  if (phases) {
    Field frac = makeField(Q::VapourFraction, s.geometry, np);
    Field phase = makeField(Q::Phase, s.geometry, np);
    for (std::size_t i = 0; i < np; ++i) {
      const eos::Eos& mat = materials_[static_cast<std::size_t>(ps.material[i])];
      const eos::PhaseState st = eos::phaseState(mat, ps.e[i]);
      frac.data[i] = st.vapourFraction;
      phase.data[i] = static_cast<double>(static_cast<int>(st.phase));
    }
    s.fields.push_back(std::move(frac));
    s.fields.push_back(std::move(phase));
  }
  if (scene_.has(cases::Effect::Strength)) {
    // docs/strength.md, "SPH": the deviator (stt = -(sxx + szz): the out-of-plane component in
    // plane strain), the equivalent plastic strain and the temperature model's T.
    const StrengthFields f = stepper_->strengthFields();
    const auto add = [&](const char* name, const char* unit, const std::vector<double>& v) {
      s.fields.push_back({name, unit, 1, v});
    };
    add("stress_deviator_xx", units::pressureName, f.sxx);
    add("stress_deviator_zz", units::pressureName, f.szz);
    add("stress_deviator_xz", units::pressureName, f.sxz);
    add("stress_deviator_tt", units::pressureName, f.stt);
    add("plastic_strain", "1", f.plasticStrain);
    if (scene_.has(cases::Effect::Fracture)) add("damage", "1", f.damage);
    add("temperature", "K", f.temperature);
  }
  for (const auto& mat : scene_.materials) s.materialNames.push_back(mat.name);
  for (const auto& body : scene_.bodies) s.objectNames.push_back(body.name);
  return s;
}

std::unique_ptr<Solver> createSolver(const cases::Scene& scene) {
  return std::make_unique<SphSolver>(scene);
}

}  // namespace hvi::sph
