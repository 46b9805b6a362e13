//! @file Runs one hard case with one solver step by step and measures what the checks assert.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/common/solver.hpp"

namespace hvi::hard {

//! Steps at the start that the time-step check leaves out: the first steps of an impact go from
//! the unshocked state (the first CFL step, the reference) to the peak shock state, and the
//! collapse the check looks for is a later, runaway one.
inline constexpr long kSettleSteps = 3;

//! What one run measured. Relative errors are against the initial totals.
struct RunResult {
  std::string caseName, solver;
  bool completed = false;  //!< reached time.end with every state check passed
  std::string failure;     //!< SimulationError message or the first failed state check
  long steps = 0;
  long items = 0;     //!< particles or cells at the start
  long itemsEnd = 0;  //!< particles left (SPH) or material cells (TVD) at the end
  double tEnd = 0.0, tReached = 0.0;
  double dt0 = 0.0;         //!< the first CFL step, us
  double minDtRatio = 1.0;  //!< min dt / dt0 over CFL steps after kSettleSteps
  long minDtStep = -1;
  //! SPH: max over the checks of |M + M_out - M0| / M0 (M_out: what left through outflow).
  //! TVD: max |M - M0 - (boundary flux)| / M0, i.e. mass made or lost by anything but the
  //! domain boundary (interfaces, owner changes, floors: the vacuum treatment).
  double massError = 0.0;
  //! TVD only (empty for SPH, which has no ledger): max |M - M0 - ledger.sum()| / M0, the
  //! ledger's closure (round-off).
  std::optional<double> massClosure;
  double energyError = 0.0;                         //!< as massError, for kinetic + internal energy
  double massDriftEnd = 0.0, energyDriftEnd = 0.0;  //!< the same, signed, at the end
  std::optional<double> energyClosure;              //!< as massClosure, for the energy
  //! TVD only: max |P - P0 - ledger momentum| / sqrt(2 M0 E0) over the components the ledger
  //! closes (z always, x in planar geometry: r-z radial momentum has the P/r source).
  std::optional<double> momentumClosure;
  double outflowMass = 0.0;    //!< fraction of M0 that left through outflow sides by the end
  //! SPH only (empty for TVD): every particle, found by its unique id, kept its initial mass bit
  //! for bit at every check. Set at the first check.
  std::optional<bool> massesBitwise;
  double maxSpeed = 0.0;       //!< cm/us, over the checks
  double minDensity = 0.0;     //!< g/cm^3, material only, over the checks
  double maxPressure = 0.0;    //!< Mbar
  double minEnergy = 0.0;      //!< specific internal energy, cm^2/us^2
  std::string minEnergyWhere;  //!< material, object and position of that minimum
  double wallSeconds = 0.0;
  //! TVD, at the end, signed, relative to M0 / E0: what each non-boundary mechanism of the
  //! ledger added (interfaces: ghost-fluid fluxes at object/object and object/vacuum faces;
  //! owner changes: cells re-initialised or emptied; floors: vacuum-density velocity reset and
  //! internal-energy floor).
  double massInterfaces = 0.0, massOwnerChanges = 0.0, massFloors = 0.0;
  double energyInterfaces = 0.0, energyOwnerChanges = 0.0, energyFloors = 0.0;
  double energyOutflow = 0.0;  //!< fraction of E0 that left through outflow sides
};

//! How to run one case with one solver.
struct RunSetup {
  std::string caseName;                //!< cases/scenes/hard/<caseName>.toml
  std::string solver;                  //!< "sph" or "tvd"
  std::string variant;                 //!< suffix for outputs ("" for the scene as written)
  std::vector<std::string> overrides;  //!< added to those that select the solver
  //! Builds the solver from the scene; empty: hvi::app::createSolver.
  std::function<std::unique_ptr<Solver>(const cases::Scene&)> make;
  int checkEvery = 5;  //!< full state check every this many steps (and at the end)
};

//! Loads the scene, runs it to time.end, checks the state every `checkEvery` steps (finite
//! fields, positive density in material), measures dt, mass and energy, writes
//! <build>/test_out/hard/<case>_<solver><variant>.json (and the state at failure as .h5), and
//! prints one line of results. Never throws for a SimulationError: it is reported in failure.
RunResult runHardCase(const RunSetup& setup);

//! The SPH variant of near_contact: the scene's particles with those of body `object` moved by
//! `dz` cm along z before the mass iteration (particles of two bodies almost on top of each other).
std::unique_ptr<Solver> makeShiftedSph(const cases::Scene& scene, int object, double dz);

}  // namespace hvi::hard
