//! @file The Gaussian pair terms of one particle's row, several pairs per vector register.
//!
//! The force passes (passes.cpp) sum per-pair terms over a particle's neighbour list. For the
//! Gaussian kernel the terms are computed here in vector lanes (L pairs at a time, every
//! condition a lane mask) and stored per pair; the pass then adds them up one by one in list
//! order, so the sums are bit for bit those of the one-pair-at-a-time loop (pairTerms in
//! pair_force.hpp), whatever the lane width: each lane does the same IEEE operations in the
//! same order (no contraction into FMA), and the exponential's range reduction is exact.
//! Three builds of the same code: baseline x86-64 (2 lanes) and, chosen at run time when the CPU
//! has them, AVX2 (4 lanes, force_lanes_avx2.cpp) and AVX-512 (8 lanes, force_lanes_avx512.cpp).
#pragma once
#include <cstddef>

namespace hvi::sph::detail {

//! What the pair terms read of every point (reals and ghosts), PairArrays' columns.
struct LaneArrays {
  const double *x, *z, *vx, *vz, *rho, *c, *h, *mu, *rw, *q;
  const int* obj;
  //! If not null (the 8-lane kernels; passes.cpp, PackRing): point j's x, z, vx, vz, h, q, mu,
  //! c in the 64-byte aligned row packed + 8 (j & packMask), for packBegin <= j < packEnd; a
  //! block of neighbours with one outside is gathered.
  const double* packed = nullptr;
  int packMask = 0, packBegin = 0, packEnd = 0;
};

//! What a row's force kernel computed of each pair, slot k for the k-th neighbour, for the
//! strength pass's kernel to read instead of computing it again (docs/strength.md, "Cost of
//! strength in SPH"): x_i - x_j, v_i - v_j, h_j, W_ij and grad W_ij / r_ij (f, grad_i W_ij =
//! f (dx, dz)). Whole blocks of lanes are stored (the lanes past the row included).
struct PairGeometry {
  double *dx, *dz, *dvx, *dvz, *hj, *w, *f;
};

//! Per-pair terms of one row, slot k for the k-th neighbour (capacity: the row's count rounded
//! up to 8). A pair with W_ij = 0 has all terms 0, as if skipped.
struct RowTerms {
  double *ax, *az, *de;
  double* drho;  //!< cached pass: mu_j v_ij . grad W over i's own object, else 0
  double* hoop;  //!< r-z: mu_j q_j W_ij
  double* phi;   //!< cached viscous pass: phi_ij (<= 0)
  double *pwx, *pwz;  //!< compatible half-state pass: w_ij times the pair acceleration (or null)
  double* hoopPi = nullptr;  //!< r-z viscous, if not null: mu_j Pi_ij W_ij (the viscous hoop)
  // Half lists (kernels picked with `half`): the same pair's terms of the other end j,
  // pairTerms(j, i) bit for bit (drho masked as drho, phi shared: phi_ji = phi_ij).
  double *axj = nullptr, *azj = nullptr, *dej = nullptr, *drhoj = nullptr;
  double *pwxj = nullptr, *pwzj = nullptr;
  // (A half kernel with pwx and a null ax writes the pair data pwx, pwz, pwxj, pwzj only.)
  const PairGeometry* geom = nullptr;  //!< if not null (full rows): each pair's geometry
};

//! Terms of row i: `nb` its cnt neighbours, `wc` their cached W (cached pass, when the list
//! holds them) or null (W from the positions: the same bits where the list was built there).
using RowKernel = void (*)(const LaneArrays& a, std::size_t i, const int* nb, const double* wc,
                           int cnt, double alpha, double beta, const RowTerms& out);

//! The list build's scan of the grid's sorted positions [s0, s1) around (xi, zi, hi): each
//! position s is written at slot[min(cnt, last)] and cnt advances if |x - x_s| < sqrt(rf2) h_is
//! (h_is = (hi + sh[s]) / 2, compared as rf2 h_is^2) and order[s] != self; with `r2` (not
//! null) its squared distance and h_is go to r2[min(cnt, last)] and hs[min(cnt, last)] (the
//! Gaussian's W follow from them: DistanceWKernel). Returns cnt. The same slots, values and count as that loop written one
//! position at a time (the distances in lanes).
using ScanKernel = int (*)(const double* sx, const double* sz, const double* sh, const int* order,
                           int s0, int s1, double xi, double zi, double hi, double rf2, int self,
                           int* slot, double* r2, double* hs, int cnt, int last);
ScanKernel scanKernel();  //!< AVX-512 where the CPU has it, else baseline

//! The Gaussian W of a scanned row's cnt kept pairs, in place: w holds their squared distances
//! (the scan's r2) and becomes W(r2, h_ij) with hs the scan's h_ij; nothing past cnt is written.
//! The bits of GaussianKernel::value (kernel.hpp) for every lane width.
using DistanceWKernel = void (*)(double* w, const double* hs, int cnt, double hi);
DistanceWKernel distanceWKernel();  //!< the scan's lane width

//! The Gaussian W_ij of row i's cnt neighbours nb into w (which has room for a lane width past
//! cnt), as the scan computed them: the same bits (the mass iteration recomputes them per
//! sweep instead of caching them).
using RowWKernel = void (*)(const double* x, const double* z, const double* h, std::size_t i,
                            const int* nb, int cnt, double* w);
RowWKernel rowWKernel();  //!< the widest the CPU has (laneWidth)
RowWKernel rowWKernelBaseline();
RowWKernel rowWKernelAvx512();  //!< null without compiler support
RowWKernel rowWKernelAvx2();    //!< null without compiler support

//! The kernel for the policy, for baseline x86-64 (2 lanes). `half` (planar only, else null):
//! the kernel also writes the j side's terms (RowTerms::axj ...) for half lists.
RowKernel rowKernelBaseline(bool rz, bool viscous, bool cached, bool compatible,
                            bool half = false);
//! The same compiled for AVX-512 (8 lanes), or null where the CPU (or compiler) lacks it.
RowKernel rowKernelAvx512(bool rz, bool viscous, bool cached, bool compatible, bool half = false);
//! The same compiled for AVX2 (4 lanes), or null without compiler support.
RowKernel rowKernelAvx2(bool rz, bool viscous, bool cached, bool compatible, bool half = false);
ScanKernel scanKernelBaseline();
ScanKernel scanKernelAvx512();  //!< null without compiler support
ScanKernel scanKernelAvx2();    //!< null without compiler support
DistanceWKernel distanceWKernelBaseline();
DistanceWKernel distanceWKernelAvx512();  //!< null without compiler support
DistanceWKernel distanceWKernelAvx2();    //!< null without compiler support
//! The widest of rowKernelAvx512, rowKernelAvx2 and rowKernelBaseline the CPU has (laneWidth),
//! full rows.
RowKernel rowKernel(bool rz, bool viscous, bool cached, bool compatible);
//! The lane width the passes use: the widest the CPU has (8 AVX-512, 4 AVX2, else 2), capped
//! by the environment variable HVI_SPH_LANES (2, 4 or 8) for side-by-side measurements.
int laneWidth();

}  // namespace hvi::sph::detail
