//! @file The interface the command line drives: both solvers implement it.
#pragma once
#include <iosfwd>
#include <string>

#include "hvi/common/snapshot.hpp"

namespace hvi {

//! Integrals of the state; the driver reports their drift in summary.json (docs/output.md).
struct Totals {
  double mass = 0.0;       //!< g (planar: g per cm of depth; r-z: whole body, 2 pi r included)
  double momentumX = 0.0;  //!< g cm/us (planar x; zero by symmetry in r-z)
  double momentumZ = 0.0;
  double kinetic = 0.0;    //!< g cm^2/us^2
  double internal = 0.0;
  [[nodiscard]] double energy() const { return kinetic + internal; }
};

//! A step this much smaller than a solver's first (CFL) step means the run has collapsed: an
//! item driven to a singular state. Each solver checks it in advance() and names the particle or
//! cell that set the step; going on would only burn time.
inline constexpr double kDtCollapseFraction = 1e-6;

//! A time-marching solver. Calls are per step, never per particle or cell, so this virtual
//! interface costs nothing measurable.
class Solver {
 public:
  virtual ~Solver() = default;

  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual double time() const = 0;
  [[nodiscard]] virtual long step() const = 0;
  //! Number of particles or cells updated per step (for throughput).
  [[nodiscard]] virtual long workItems() const = 0;

  //! Advances one stable step, never past `tStop`. Returns the step taken.
  //! Throws SimulationError if the new state is unphysical (NaN, negative density, dt collapse).
  virtual double advance(double tStop) = 0;

  [[nodiscard]] virtual Snapshot snapshot() const = 0;
  //! What the domain holds plus what has left it through outflow sides (outflow()), so that
  //! the drift from the initial totals measures the scheme, not the boundary. Walls and axes
  //! are not outflow: what a wall pushes back is a change of the totals.
  [[nodiscard]] virtual Totals totals() const = 0;
  //! What has left through outflow sides since the start (mass, momentum, energy carried out;
  //! negative where more came in). Zero for a solver without outflow sides.
  [[nodiscard]] virtual Totals outflow() const { return {}; }

  //! Exact binary state, so that a restart continues bit for bit.
  virtual void writeCheckpoint(std::ostream& out) const = 0;
  virtual void readCheckpoint(std::istream& in) = 0;
};

}  // namespace hvi
