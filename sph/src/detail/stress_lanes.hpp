//! @file The strength pass's pair terms of one particle's row, several pairs per vector register
//! (docs/strength.md, "Cost of strength"), as force_lanes.hpp does for the force pass: the terms
//! of strength_pass.cpp's one-pair-at-a-time loop computed in lanes (every condition a lane
//! mask) and stored per pair, then added up by the pass one by one in list order: the same
//! sums bit for bit, since each lane does that loop's IEEE operations in its order (no FMA
//! contraction) and the exponential's range reduction is exact. Gaussian kernel only; AVX2
//! (4 lanes) and AVX-512 (8 lanes) builds, chosen at run time (laneWidth()); below 4 lanes the
//! pass keeps its scalar loop.
#pragma once
#include <cstddef>

#include "detail/force_lanes.hpp"  // PairGeometry

namespace hvi::sph::detail {

//! What the stress pair terms read of every point (reals and ghosts).
struct StressLaneArrays {
  const double *x, *z, *vx, *vz, *h, *mu, *rho, *c, *rw;
  const double *txx, *tzz, *txz, *rxx, *rzz, *rxz, *htt;  //!< StressPoints' columns
  const double* alpha;  //!< viscosity switch: alpha_i (else unused)
  const double* vol;    //!< mu / rho
  //! Per point, 8 doubles: txx, tzz, txz, rxx, rzz, rxz, mu / rho, mu (StressPoints::rec)
  const double* rec;
};

//! Per-pair terms of one row, slot k for the k-th neighbour (capacity: the row's count rounded
//! up to 8). A pair with W_ij = 0 has all terms 0, as if skipped.
struct StressRowTerms {
  double *gxx, *gxz, *gzx, *gzz;  //!< the velocity gradient's summands
  double *ax, *az, *de;           //!< stressPairTerm's
  double* hoop;                   //!< r-z: mu_j htt_j W_ij
  double* phi;                    //!< viscosity switch: phi_ij (<= 0)
  //! If not null, 3 doubles the kernel keeps W(dp) of the last row's h_i in (h_i, q2dp, W(dp);
  //! start with a NaN h_i), for the next row of the same h_i (the same value).
  double* wdpMemo = nullptr;
  //! If not null (the fused half-state pass with compatible energy): the row's pair data, to
  //! which the kernel adds 0.5 ax, 0.5 az of each of the cnt slots (the stress power's even
  //! share, as the pass would add them).
  double *pwx = nullptr, *pwz = nullptr;
};

struct StressRowParams {
  double q2dp;          //!< (dp / h)^2: W(dp) of the artificial stress
  int power;            //!< its exponent (0: off)
  double betaPerAlpha;  //!< viscosity switch: beta_ij = betaPerAlpha alpha_ij
};

//! Terms of row i: `nb` its cnt neighbours, `wc` their cached W or null (W from positions).
//! `geom`: the row's pair geometry as the force kernel of the same state stored it (the kernels
//! picked with `fused`: read instead of computed, the same values), else null.
using StressRowKernel = void (*)(const StressLaneArrays& a, std::size_t i, const int* nb,
                                 const double* wc, int cnt, const StressRowParams& p,
                                 const StressRowTerms& out, const PairGeometry* geom);

//! The kernel for (r-z, viscosity switch, fused) compiled for AVX-512 / AVX2, or null without
//! compiler support (the caller checks the CPU with laneWidth()).
StressRowKernel stressRowKernelAvx512(bool rz, bool viscositySwitch, bool fused = false);
StressRowKernel stressRowKernelAvx2(bool rz, bool viscositySwitch, bool fused = false);

}  // namespace hvi::sph::detail
