//! @file A scene, parsed once from its file into typed structs; solvers never see the parser.
#pragma once
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "hvi/common/geometry.hpp"
#include "hvi/common/vec2.hpp"
#include "hvi/eos/eos.hpp"
#include "hvi/strength/strength.hpp"

namespace hvi::cases {

// All quantities are in the internal cm-g-us units of common/units.hpp.

//! A named material: its EOS (which carries the reference density rho0) and, for a solid, its
//! strength ([materials.<name>.strength]; used with the effects strength and fracture).
struct Material {
  std::string name;
  eos::Eos eos;
  std::optional<strength::Material> strength = std::nullopt;
  [[nodiscard]] double rho0() const { return eos::referenceDensity(eos); }
};

//! Disk in planar geometry, sphere in r-z (centre on the axis, x = 0).
struct Disk {
  Vec2 centre;
  double radius = 0.0;
};
//! Axis-aligned rectangle [xmin, xmax] x [zmin, zmax]; a plate in r-z when xmin = 0.
struct Rect {
  double xmin = 0.0, xmax = 0.0, zmin = 0.0, zmax = 0.0;
};
//! Simple polygon, vertices counter-clockwise (the parser reorders clockwise input).
struct Polygon {
  std::vector<Vec2> vertices;
};
using Shape = std::variant<Disk, Rect, Polygon>;

bool contains(const Shape& s, Vec2 p);
double area(const Shape& s);  //!< planar area of the section, cm^2
struct Box { double xmin, xmax, zmin, zmax; };
Box boundingBox(const Shape& s);

//! A body: a region of one material with a uniform initial state, except that its velocity may
//! be a radial field (the Noh problems: gas streaming onto an axis or a point).
struct Body {
  std::string name;
  int material = -1;        //!< index into Scene::materials
  Shape shape;
  Vec2 velocity;            //!< cm/us (uniform; unused when `radial` is set)
  double density = 0.0;     //!< g/cm^3 (defaults to the material's rho0)
  double specificEnergy = 0.0;  //!< cm^2/us^2 (from `pressure` if the file gives that)
  //! Radial velocity field v = radialSpeed * (p - radialCentre) / |p - radialCentre| (planar:
  //! about a point, i.e. cylindrical flow in x-z) or v = (radialSpeed, 0) (r-z: about the axis,
  //! cylindrical flow). Negative speeds converge. Zero where p is the centre (or on the axis).
  bool radial = false;
  double radialSpeed = 0.0;  //!< cm/us
  Vec2 radialCentre;         //!< cm, planar only
};

//! The initial velocity of `body` at point p (cm/us).
inline Vec2 initialVelocity(const Body& body, Geometry g, Vec2 p) {
  if (!body.radial) return body.velocity;
  if (g == Geometry::Axisymmetric) return {p.x > 0.0 ? body.radialSpeed : 0.0, 0.0};
  const Vec2 d{p.x - body.radialCentre.x, p.z - body.radialCentre.z};
  const double r = std::hypot(d.x, d.z);
  if (!(r > 0.0)) return {};
  return {body.radialSpeed * d.x / r, body.radialSpeed * d.z / r};
}

enum class Boundary { Outflow, Wall, Axis };
//! Domain of the simulation, cm. Boundaries are indexed xmin, xmax, zmin, zmax.
struct Domain {
  double xmin = 0.0, xmax = 1.0, zmin = 0.0, zmax = 1.0;
  std::array<Boundary, 4> boundary{Boundary::Outflow, Boundary::Outflow, Boundary::Outflow,
                                   Boundary::Outflow};
};

enum class SolverKind { Sph, Tvd, Riemann };

//! Effects a scene may name (docs/scenes.md, Effects; names, meanings and the solvers that
//! implement each: effects.hpp). A solver pays only for those named.
enum class Effect {
  ArtificialViscosity,  //!< Monaghan viscosity (SPH)
  TensionCutoff,        //!< P = 0 in tension for Tillotson / Mie-Gruneisen
  MassAdjustment,       //!< modified SPH mass iteration (absent: traditional SPH)
  PhaseBookkeeping,     //!< solid / partly vaporised / vapour fractions
  EnergyBudget,         //!< per-step kinetic / internal / total energy diagnostics
  MaterialInterfaces,   //!< marker lines (TVD); a single-material scene need not name it
  Features,             //!< debris-cloud features at each snapshot
  Strength,             //!< deviatoric stress, yield, plastic work (docs/strength.md)
  Fracture,             //!< spall strength instead of the zero cut-off, damage
};
std::string_view toString(Effect e);
std::optional<Effect> effectFromString(std::string_view s);
std::vector<std::string_view> allEffectNames();

enum class Kernel { Gaussian, CubicSpline };
enum class Lattice { Square, Hexagonal };
//! SPH energy equation (docs/sph.md, "Energy"): Owen's compatibly differenced form, whose pair
//! work is split by each side's own pressure work (exact total energy, no cooling of a particle
//! by its neighbours' pressure), or METHOD.md's symmetric form (the study's).
enum class EnergyForm { Compatible, Symmetric };
//! r-z SPH ring weights (docs/sph-rz.md): the ring form (neighbour radius r_j, hoop term with
//! the axis correction C) or the symmetric form (weight |r_j| / (s_i s_j), consistent at the
//! axis in the axial direction too). Auto: symmetric, ring with the effect strength (whose
//! stress terms exist for the ring form only).
enum class RzForm { Auto, Ring, Symmetric };

//! A per-particle switch of the Monaghan viscosity (docs/strength.md, "Viscosity switch"): off
//! (constant alpha, beta: the study's), or Morris and Monaghan's (1997) alpha_i.
enum class ViscositySwitch { Off, MorrisMonaghan };
//! The strain rate the SPH yield law sees (docs/strength.md, "SPH viscosity switch"): the
//! kernel velocity gradient's total equivalent rate, or the particle's plastic strain rate of
//! its last step.
enum class YieldStrainRate { Total, Plastic };

struct SphParams {
  double spacing = 0.01;   //!< particle spacing dx, cm
  double hFactor = 1.0;    //!< h = hFactor * spacing
  Kernel kernel = Kernel::Gaussian;
  Lattice lattice = Lattice::Square;
  EnergyForm energy = EnergyForm::Compatible;
  RzForm rzForm = RzForm::Auto;
  //! r-z symmetric form: the share kappa in [0, 1] of the viscous pair coefficient Pi_ij that
  //! enters the hoop term as the pressure's does (docs/sph-rz.md, "The viscous hoop"); 0 is the
  //! earlier scheme (Monaghan's Pi with no hoop stress), 1 makes a uniform Pi exert no radial
  //! force at the axis as a uniform pressure does.
  double rzViscousHoop = 0.0;
  //! r-z symmetric form: the axial pair gradient corrected by the z row of the Bonet-Lok
  //! matrix L_i = M_i^{-1} within this many h of the axis (blended out over one more h); 0 off
  //! (docs/sph-rz.md, "Corrected axial gradient").
  double rzAxisCorrection = 0.0;
  double alpha = 1.0;      //!< Monaghan alpha_Pi
  double beta = 2.0;       //!< Monaghan beta_Pi
  double cfl = 0.3;
  double massTolerance = 1e-9;     //!< |rho0/rho - 1| bound of the mass iteration
  double deleteFraction = 1e-4;    //!< delete if m_i / max m < this
  int maxMassIterations = 10000;
  //! Monaghan's (2000) artificial stress with strength (docs/strength.md): R = -epsilon sigma /
  //! rho^2 of the tensile principal stresses, weighted per pair by (W(r) / W(dp))^exponent.
  double artificialStressEpsilon = 0.3;
  int artificialStressExponent = 4;
  //! Viscosity switch (with strength only, docs/strength.md): alpha_i in [alphaMin, alpha],
  //! beta_i = beta alpha_i / alpha, decay time h / (switchDecay c).
  ViscositySwitch viscositySwitch = ViscositySwitch::Off;
  double alphaMin = 0.1;
  double switchDecay = 0.2;
  YieldStrainRate yieldStrainRate = YieldStrainRate::Total;  //!< with strength only
};

enum class Limiter { Minmod, VanLeer, Superbee };
//! How the TVD solver treats material interfaces (docs/tvd.md): the study's whole-cell owners
//! with ghost-fluid faces, or conservative cut cells (every material its own state on its part
//! of a cell, mass exact per material).
enum class InterfaceMode { WholeCell, Conservative };
//! TVD cut-cell mode at outflow sides: the zero-gradient ghost (material may re-enter) or no
//! re-entry (docs/tvd.md, "Outflow sides: no re-entry"); Auto (the default) is no re-entry where
//! the conservative interfaces run (the only mode it acts in) and open otherwise.
enum class OutflowMode { Open, NoReentry, NoReentryCut, Auto };

struct TvdParams {
  double cellSize = 0.015;  //!< dx = dz, cm
  InterfaceMode interfaces = InterfaceMode::Conservative;
  OutflowMode outflow = OutflowMode::Auto;
  Limiter limiter = Limiter::Minmod;
  double cfl = 0.4;
  double markerSpacing = 0.5;  //!< target marker spacing in cells
  //! Below this fraction of rho0 a cell (a phase of a cut cell) is vacuum: put at rest and cold,
  //! its mass kept. 0: the mode's default (TvdSolver::vacuumDensity(): 1e-6 without
  //! markers and in the whole-cell mode, 1e-9 in the conservative mode; docs/tvd.md).
  double vacuumDensity = 0.0;
};

//! Exact Riemann problem (the verification "solver"): the left and right bodies meet at
//! x = `interface`; the solution is sampled on `cells` cells across the domain in x.
struct RiemannParams {
  int cells = 400;
  double interface = 0.5;  //!< cm
};

struct Output {
  std::vector<double> times;  //!< us, ascending, within (tStart, tEnd]; tEnd is always written
  bool hdf5 = true;
  bool vtk = true;
  double checkpointEvery = 0.0;  //!< wall seconds between checkpoints (0: at snapshots only)
};

struct Scene {
  std::string path;          //!< file it came from
  std::string title;
  Geometry geometry = Geometry::Planar;
  Domain domain;
  std::vector<Material> materials;
  std::vector<Body> bodies;
  SolverKind solver = SolverKind::Sph;
  SphParams sph;
  TvdParams tvd;
  RiemannParams riemann;
  double tStart = 0.0, tEnd = 1.0;  //!< us
  Output output;
  std::set<Effect> effects;

  [[nodiscard]] bool has(Effect e) const { return effects.count(e) != 0; }
};

//! Work items the scene's solver will hold, estimated before anything is built: SPH particles
//! fill the bodies (their bounding boxes clipped to the domain, over spacing^2), TVD cells the
//! domain, the exact Riemann solver its riemann.cells. Validation caps it (docs/scenes.md).
double estimatedWorkItems(const Scene& scene);

}  // namespace hvi::cases
