//! @file Per-thread buffers of the conservative cut-cell sweeps: every phase of one grid line.
#pragma once
#include <array>
#include <vector>

#include "hvi/tvd/characteristics.hpp"
#include "line_work.hpp"

namespace hvi::tvd::detail {

//! One phase (material) of a loaded line, buffer layout as LineWork (cells 0..n+3, face f
//! between cells f and f+1). q is the phase's conserved state per unit CELL volume, in line
//! components (kRho, kMn, kMt, kE); U = q / alpha its own state per unit phase volume.
struct PhaseLine {
  explicit PhaseLine(int capacity);
  bool active = false;  // the phase occupies some cell of the loaded line (else it is skipped)
  int lo = 0, hi = -1;  // first and last buffer cell the phase occupies (prepare)
  std::array<std::vector<double>, 4> q0, q1, w, ex;  // start, stage input, stage result, exchange
  std::array<std::vector<double>, 4> U;              // state of the stage input, per phase volume
  std::vector<double> alpha;  // volume fraction per cell from the marker lines (step start)
  // Working volume fraction: moved by the phase's own velocity through its interface area
  // within the step (start, stage input, stage result), so that U = q / vol stays consistent
  // while mass crosses the faces of a cut cell.
  std::vector<double> vol0, vol1, volW;
  std::vector<double> gm, gp;  // face apertures seen from the lower / upper cell (one-sided)
  std::vector<double> ap;      // paired aperture: the phase on both sides of the face
  std::vector<double> uL, uR;  // unpaired wet part of a face seen from its lower / upper cell
  std::vector<double> It;      // in-cell interface area across the line (planar form)
  std::vector<unsigned char> present;
  // An empty cell beyond a face the phase wets from one side only, with no other phase in it
  // (the interface lies on the face, against vacuum): -1 if its donor is the lower neighbour,
  // +1 if the upper one, else 0. Until it holds some of the phase, the face between them
  // carries the donor's own state at the donor's velocity (vflux, per unit aperture).
  std::vector<signed char> virt;
  std::vector<double> vflux;
  std::vector<unsigned char> dry;  // faces a trailing edge crossed in this stage
  std::vector<int> into;  // the cell absorbFading handed this cell's content to, or -1
  std::vector<CellState> cs;
  std::vector<double> sqrtRho;
  std::vector<std::array<double, 4>> F, flux;
  std::vector<FaceEigen> fe;
  std::vector<std::array<double, kFields>> g;
  std::vector<unsigned char> fallback;
  std::vector<double> pface;
  // Effect strength: the phase's mass per unit cell volume before the sweep (buffer positions
  // 2..n+1), and the mass that came in through face 1 when it is the domain's low edge; the
  // strength state's advection takes the phase's mass fluxes from them (strength_step.hpp).
  std::vector<double> massOld;
  double edgeMass = 0.0;
  // Effect fracture: the phase's damage D per buffer cell at the sweep's start (ghosts
  // included), which scales its tension in every EOS call of the sweep (limitTension).
  std::vector<double> damage;
};

//! All phases of one line, plus the line's geometry (as LineWork).
struct CutLineWork {
  CutLineWork(int capacity, int phases);
  int capacity;
  std::vector<PhaseLine> phase;
  std::vector<double> area, invVol, invR;
  std::vector<double> relax;  // one cell's phases for the velocity relaxation (7 per phase)
  //! The cells (2..n+1, in order) that two or more phases hold in this step (prepare): the only
  //! ones where phases exchange momentum inside a cell or relax together.
  std::vector<int> shared;
  int sharedCount = 0;
  //! Mass of phase p through the line's low (2 p) and high (2 p + 1) end face, inflow positive,
  //! in line units (the kernel's ledgerFaces; the sweep books what crosses an outflow side).
  std::vector<double> edgeMass;
};

}  // namespace hvi::tvd::detail
