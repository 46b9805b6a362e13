//! @file State of the SPH stepper (shared by the step driver and the checkpoint code).
#pragma once
#include <string>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <type_traits>
#include <vector>

#include "detail/arrays.hpp"
#include "detail/boundary.hpp"
#include "detail/passes.hpp"
#include "detail/strength_pass.hpp"
#include "hvi/sph/stepper.hpp"

namespace hvi::sph {

struct Stepper::Impl {
  Impl(ParticleSystem ps, std::vector<eos::Eos> materials, StepperConfig config);

  void corrector();          // ghosts, list, summation density, EOS, derived values
  void deriveWeights();      // rw, mu of the reals from their positions and masses
  void deriveRates();        // q, lam of the reals from P, rho, v
  void checkState(const char* stage) const;
  //! sph.rz_axis_correction: the corrected-gradient rows a.lzx, a.lzz of the current state
  //! (reals and ghosts; nothing when off).
  void axisMatrix();
  //! Compatible energy: completes de1 (the half-state rate) with the step's remainder.
  void compatibleRemainder(double half);
  std::string objectName(std::size_t i) const;  // of real particle i, for diagnostics
  void removeOutflow();
  double timeStep() const;   // CFL limit from the rates of the cached pass
  double particleTimeStep(std::size_t i, bool* byAcceleration = nullptr) const;
  //! Throws SimulationError naming the particle that set a collapsed dt.
  [[noreturn]] void throwCollapse(double dt) const;

  // The one list of the per-particle state a step starts from, as f(ParticleSystem member,
  // stepper array): construction copies it in, outflow removal compacts it, particles() copies
  // it out and the checkpoint stores it, in this order (which is the checkpoint format).
  // rho, p and c are not in it: corrector() derives them from it.
  template <class Self, class F>
  static void forEachState(Self& s, F&& f) {
    using P = ParticleSystem;
    f(&P::x, s.a.x); f(&P::z, s.a.z); f(&P::vx, s.a.vx); f(&P::vz, s.a.vz); f(&P::h, s.a.h);
    f(&P::object, s.a.obj); f(&P::e, s.e); f(&P::m, s.m); f(&P::rhoRef, s.rhoRef);
    f(&P::material, s.mat); f(&P::id, s.id);
  }
  // What corrector() derives from the state, copied out by particles().
  template <class Self, class F>
  static void forEachDerived(Self& s, F&& f) {
    using P = ParticleSystem;
    f(&P::rho, s.a.rho); f(&P::p, s.a.p); f(&P::c, s.a.c);
  }
  // ParticleSystem has the 14 arrays of the two lists: one added there stops the build here
  // until it is listed.
  static_assert(sizeof(ParticleSystem) == 14 * sizeof(std::vector<double>));
  // Sizes the step work arrays to the n real particles (never stored: each step rewrites them).
  // hoopAx only in r-z (the planar passes do not write it).
  void resizeWork() {
    for (auto* v : {&x0, &z0, &vx0, &vz0, &e0, &ax0, &az0, &de0, &drho0, &phi0, &ax1, &az1, &de1})
      v->resize(n);
    hoopAx.resize(rz ? n : 0);
    keep.resize(n);
    workReleased = false;
  }
  // Lends the half passes the arrays `v` (each of at least n) for their spills, or none.
  void lendSpill(std::initializer_list<std::vector<double>*> v) {
    int k = 0;
    for (auto* a : v) list.lentSpill[k++] = a->data();
    list.lentSpillCount = k;
  }
  // Frees the work space that is dead between steps (the step arrays, the grid, the half
  // passes' spills, the stored pair data), for an output's peak memory (docs/performance.md,
  // "SPH memory"); the next step sizes it again. The state, the derived values and the list
  // (the next step's first pass reads it) stay.
  void releaseWork() {
    const auto release = [](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); };
    for (auto* v : {&x0, &z0, &vx0, &vz0, &e0, &ax0, &az0, &de0, &drho0, &phi0, &ax1, &az1, &de1,
                    &hoopAx, &pairWx, &pairWz, &dmu})
      release(*v);
    release(keep);
    grid.release();
    release(list.spill);
    release(list.spillSpan);
    release(list.farJ);
    release(list.farV);
    release(list.sums);
    workReleased = true;
  }

  StepperConfig cfg;
  std::vector<eos::Eos> materials;
  detail::ForcePass passCached = nullptr, passFresh = nullptr;
  detail::ListPass passList = nullptr;
  detail::RemainderPass passRemainder = nullptr;  // compatible, pair data not stored
  detail::Boundaries bounds;
  std::unique_ptr<detail::AxisCorrection> axis;  // r-z ring form only
  const detail::RingScale* ring = nullptr;       // r-z symmetric form only
  std::unique_ptr<detail::RingScale> ringOwn;    // its copy with a viscous hoop factor
  std::unique_ptr<detail::StrengthModel> strength;  // effect strength only
  double radiusFactor = 0.0;   // list radius / h_ij: kernel support + skin
  bool rz = false;
  bool compatible = false;     // cfg.energy == Compatible
  // Compatible: the half-state pass stores its pair data (16 B per list slot) for the
  // remainder, instead of the remainder recomputing them (with strength, whose pass adds to
  // them, always; else only with HVI_SPH_STORE_PAIRS=1: docs/performance.md, "SPH memory").
  bool storePairs = false;
  // With strength: the force passes run inside the strength pass (StrengthModel::passWithForces,
  // the same bits; HVI_SPH_FUSED=0 keeps them apart, for side-by-side runs).
  bool fused = false;
  bool viscous = false;  // the force passes' viscosity (off with the viscosity switch)

  std::size_t n = 0;           // real particles
  detail::PairArrays a;        // reals, then ghosts
  std::vector<double> e, m, rhoRef;
  std::vector<int> mat;
  std::vector<std::int64_t> id;

  // Step work arrays (reals only), sized once; the step loop allocates nothing (an output's
  // releaseWork() aside). Arrays dead in part of the step lend their storage there
  // (docs/performance.md, "SPH memory"): x0, z0 and vx0 hold the grid's sorted copies during
  // the list build, drho0 and phi0 the compatible remainder's a^{n+1/2} - a^n (then sized to
  // the reals and ghosts), de0 its per-particle sums; the half passes' spills lie in x0 ... e0
  // (state n), de0, drho0, phi0 (half state) and ax0 (remainder): lendSpill.
  std::vector<double> x0, z0, vx0, vz0, e0;
  std::vector<double> ax0, az0, de0, drho0, phi0, ax1, az1, de1;
  // Compatible energy: hoop acceleration (reals, r-z), and per list entry w_ij times the pair
  // acceleration summand (docs/sph.md, "Energy").
  std::vector<double> hoopAx, pairWx, pairWz;
  std::vector<double> dmu;  // r-z predictor: mu^{n+1/2} - mu^n (reals and ghosts)
  std::vector<unsigned char> keep;
  bool workReleased = false;  // releaseWork() since the last resizeWork()

  CellGrid grid;
  NeighbourList list;
  double t = 0.0;
  long steps = 0;
  double dt0 = 0.0;            // first CFL step: the reference of the dt-collapse check
  Totals out;                  // accumulated outflow
};

}  // namespace hvi::sph
