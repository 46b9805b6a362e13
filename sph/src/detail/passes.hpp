//! @file The pair loops of a step, one instantiation per (kernel, geometry, viscosity) policy.
#pragma once
#include <cstddef>

#include "detail/arrays.hpp"
#include "detail/axis_correction.hpp"
#include "hvi/cases/scene.hpp"
#include "hvi/sph/neighbours.hpp"
#include "hvi/sph/viscosity.hpp"

namespace hvi::sph::detail {

//! Rates of the real particles, written by a force pass.
struct Rates {
  double* ax;
  double* az;
  double* de;
  double* drho;  //!< continuity rate (cached pass only)
  double* phi;   //!< most negative viscosity phi_ij of the particle (cached pass only)
  // Compatible energy, half-state pass only (else null): per list entry (row i, slot k) the
  // pair acceleration summand of i times w_ij, before the division by r_i; per particle the
  // hoop acceleration (r-z).
  double* pairWx = nullptr;
  double* pairWz = nullptr;
  double* hoopAx = nullptr;
};

//! Momentum, energy (and, for the cached pass, continuity) rates of the real particles
//! [0, nReal) from the pair sums over their neighbour lists. The cached pass reuses the W_ij
//! stored by the list build (state at the list's positions); the other recomputes W_ij from
//! the current positions (the predictor's half state).
//! The continuity rate sums over the particle's own object only, as the summation density of
//! the corrector does (momentum and energy always sum over every pair).
//! `axis` (r-z ring form only, else null) corrects the hoop term near the axis; `ring` (r-z
//! symmetric form only, else null) gives s(r) and s'(r) of its hoop term (docs/sph-rz.md).
//! `compatible`: the energy rate is each particle's own share of its pairs' work (docs/sph.md,
//! "Energy"), and the half-state pass also fills out.pairWx, pairWz (and hoopAx in r-z).
using ForcePass = void (*)(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                           const MonaghanViscosity& visc, const AxisCorrection* axis,
                           const RingScale* ring, const Rates& out);
//! `half`: the pass for half rows (NeighbourList::half; planar Gaussian lanes only, see
//! halfListsAvailable; null otherwise): each pair evaluated once, both ends' terms added in a
//! fixed block order (passes.cpp), so the rates differ from the full rows' only by round-off
//! and do not depend on the thread count.
ForcePass selectForcePass(cases::Kernel kernel, bool rz, bool viscous, bool compatible,
                          bool cached, bool half = false);
//! The one-pair-at-a-time pass (pairTerms, no lanes): the pass that reads PairArrays' axis
//! correction columns lzx, lzz (sph.rz_axis_correction, docs/sph-rz.md).
ForcePass selectScalarForcePass(cases::Kernel kernel, bool rz, bool viscous, bool compatible,
                                bool cached);
//! Whether half rows have their passes: Gaussian kernel, planar, lanes of AVX2 or AVX-512.
bool halfListsAvailable(cases::Kernel kernel, bool rz);

//! The compatible energy's time-discrete remainder (docs/sph.md, "Energy"): with
//! da = a^{n+1/2} - a^n per point (ghosts mirrored), subtracts from de (the half-state rate)
//!   (dt/2) [ (1/r_i) sum_j w_ij a_ij . (da_i - da_j) + a_hoop,i da_x,i ]
//! so that the step's internal-energy change is exactly minus its kinetic-energy change.
//! `hoopAx` is null in planar geometry (rw = 1 there).
void compatibleEnergy(const NeighbourList& list, std::size_t nReal, const double* pairWx,
                      const double* pairWz, const double* dax, const double* daz, const double* rw,
                      const double* hoopAx, double halfDt, double* de);

//! compatibleEnergy with the pair data recomputed row by row from the half state (which must
//! be unchanged since the half-state pass) instead of stored: the same bits, no per-entry
//! storage (16 B per list slot), one more pair pass. Not with strength (its pass adds its own
//! pair data to the stored ones).
using RemainderPass = void (*)(const PairArrays& a, std::size_t nReal, const NeighbourList& list,
                               const MonaghanViscosity& visc, const double* dax,
                               const double* daz, const double* hoopAx, double halfDt,
                               double* de);
RemainderPass selectRemainderPass(cases::Kernel kernel, bool rz, bool viscous,
                                  bool half = false);
//! The remainder through pairTerms (as selectScalarForcePass).
RemainderPass selectScalarRemainderPass(cases::Kernel kernel, bool rz, bool viscous);

//! sph.rz_axis_correction (docs/sph-rz.md, "Corrected axial gradient"): for every real particle
//! within (zone + 1) h of the axis, M_i = (1/s_i) sum_j (nu_j / rho_j) (x_j - x_i) (x) grad_i W_ij
//! over its list (every object, ghosts included) at the current positions, and the z row of
//! L_i = M_i^{-1} blended with the identity from 1 at r = zone h to 0 at (zone + 1) h, into
//! a.lzx, a.lzz (sized a.size(); the others' identity). The ghosts' rows are the caller's.
void axisMatrix(PairArrays& a, std::size_t nReal, const NeighbourList& list, cases::Kernel kernel,
                double zone);

//! r-z predictor (docs/sph-rz.md, "Density"): adds to rho_i the change of the summation
//! density through the ring weights alone, sum_j dmu_j W_ij over i's own object (j = i
//! included), with dmu = mu^{n+1/2} - mu^n on every point (ghosts as their parents) and the
//! W_ij of the list build at x^n: cached by it, or recomputed from x0, z0 (the reals at x^n)
//! and xg, zg (the ghosts, indices >= nReal, still at x^n: refreshed after this).
void weightChange(const NeighbourList& list, std::size_t nReal, const double* x0,
                  const double* z0, const double* xg, const double* zg, const int* obj,
                  const double* h, const double* dmu, cases::Kernel kernel, double* rho);

//! Builds the neighbour lists of the real particles among the a.size() points and, if
//! `rhoOut` is not null, the summation density of the real particles into it (over the
//! particle's own object).
using ListPass = void (*)(const PairArrays& a, std::size_t nReal, double radiusFactor,
                          CellGrid& grid, NeighbourList& list, double* rhoOut);
ListPass selectListPass(cases::Kernel kernel);

double kernelSupport(cases::Kernel kernel);         //!< in units of h
double kernelSelf(cases::Kernel kernel, double h);  //!< W(0, h)

}  // namespace hvi::sph::detail
