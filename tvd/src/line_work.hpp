//! @file Per-thread scratch of the 1-D sweeps and the description of one line.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/tvd/characteristics.hpp"
#include "hvi/tvd/state.hpp"

namespace hvi::tvd::detail {

//! What lies beyond one end of a loaded line.
enum class Side : unsigned char {
  Loaded,   //!< real cells (vacuum, in a marker run) were loaded as the two ghost cells
  Outflow,  //!< zero-gradient ghosts
  Reflect,  //!< mirror ghosts with the normal momentum negated (wall, axis)
};

//! How a face couples its two cells.
enum class FaceKind : signed char {
  Regular,      //!< same object (or no markers): Harten-Yee TVD flux
  Contact,      //!< two different objects: two-sided contact flux
  VacuumRight,  //!< material left, vacuum right: free-surface flux for the left cell only
  VacuumLeft,   //!< vacuum left, material right
  Void,         //!< vacuum on both sides: no flux
};

//! Components of a line's conserved vector (the first index of LineWork::u0, u1, w and of the
//! fluxes), in line coordinates: density, momentum along the line (normal to its faces),
//! momentum across it (tangential), total energy density.
enum Component : int { kRho = 0, kMn = 1, kMt = 2, kE = 3 };

//! What one line added to the domain, per unit of the line's cross-section (the sweep scales
//! it to the solver's units), in x/z components (SweepContext::axis).
struct LineBudget {
  Budget interfaces, floors;
  std::array<Budget, 2> edge;  //!< through the low / high domain edge (inflow positive)
  long relaxed = 0;            //!< cut-cell mode: cell-stages whose phases took one velocity
  long mixed = 0;              //!< cut-cell mode: deficits mixed with a neighbour (mixDeficits)
  long pooled = 0;             //!< cut-cell mode: cells below the vacuum density pooled (resetThin)
};

//! Buffers for one line of up to `capacity` cells plus two ghost cells at each end. Sized once,
//! reused for every line, so the sweeps do not allocate.
struct LineWork {
  explicit LineWork(int capacity);
  int capacity;
  // U^n (overwritten with U^{n+1}), the stage state, and the stage result.
  std::array<std::vector<double>, 4> u0, u1, w;
  std::vector<CellState> cs;                        // primitive state the fluxes are built from
  std::vector<double> sqrtRho;                      // sqrt(rho) per cell, for the Roe weights
  std::vector<std::array<double, 4>> F;             // physical flux per cell
  std::vector<FaceEigen> fe;                        // face f lies between cells f and f+1
  std::vector<std::array<double, kFields>> g;       // limited jumps per cell
  std::vector<std::array<double, 4>> fluxL, fluxR;  // flux seen by the left / right cell
  std::vector<unsigned char> fallback;              // face recomputed with the Rusanov flux
  // Markers: owner object and material per cell, interface normal per cell (line coords).
  std::vector<int> owner, mat;
  std::vector<double> nn, nt;
  std::vector<FaceKind> kind;
  // Geometry of the line: face area and inverse cell volume (line units), radial source 1/r.
  std::vector<double> area, invVol, invR;
  std::vector<double> pface;  // r-z radial lines: Riemann pressure at each face
  // Effect fracture (single material): the damage D per buffer cell at the sweep's start.
  std::vector<double> damage;
};

//! Constant for every line of one sweep.
struct SweepContext {
  const std::vector<cases::Material>* materials = nullptr;
  const double* rhoCut = nullptr;   //!< per material: vacuum density (velocity reset below)
  const double* rhoThin = nullptr;  //!< per material: nearly empty (may be reset to vacuum)
  int singleMaterial = 0;
  double entropyFix = 0.1;
  int contactIterations = 2;
  double dt = 0.0;
  double h = 0.0;  //!< cell size (cut-cell merging compares a cell's volume with its faces)
  int axis = 0;    //!< the lines run along x (0) or z (1): where the budgets book kMn and kMt
  bool keepColdStates = false;  //!< cut-cell mode: Options::keepColdStates
  //! Effect fracture, cut-cell mode (null without it): per phase its spall strength (Mbar; < 0
  //! for a phase without fracture, a fluid) and the density below which it is torn (no tension).
  const double* spall = nullptr;
  const double* rhoIntact = nullptr;
  bool closedOutflow = false;  //!< cut-cell mode: Options::closedOutflow
};

//! One line: `n` cells loaded at buffer positions 2..n+1.
struct LineSetup {
  int n = 0;
  Side left = Side::Outflow, right = Side::Outflow;
  bool leftEdge = false, rightEdge = false;  //!< faces 1 / n+1 are on the domain boundary
};

//! A cell that the scheme could not keep physical (buffer index, state).
struct LineFailure {
  int j = -1;
  double rho = 0.0, e = 0.0;
  std::string what;
};

}  // namespace hvi::tvd::detail
