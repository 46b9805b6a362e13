//! @file Lane types and helpers of the SPH lane kernels, included by force_lanes_impl.hpp and
//! stress_lanes_impl.hpp inside their per-instruction-set anonymous namespace (HVI_LANES,
//! HVI_LANES_NS defined): each instruction set gets its own internal copy, so no AVX-512 copy
//! can stand in for baseline code at link time. No include guard on purpose.
#ifndef HVI_LANES
#error "lane_ops_impl.hpp is included by a lane kernel body with HVI_LANES defined"
#endif

constexpr int L = HVI_LANES;
using D = double __attribute__((vector_size(8 * L)));
using I = std::int64_t __attribute__((vector_size(8 * L)));

inline D splat(double v) { return D{} + v; }

// Element by element: measured faster than the AVX-512 gather instruction on this project's
// machines (microcoded since the 2023 gather-data-sampling mitigation).
inline D gather(const double* p, const int* idx) {
  D v;
  for (int l = 0; l < L; ++l) v[l] = p[idx[l]];
  return v;
}

inline D select(I m, D a, D b) { return m ? a : b; }
// (The including file includes <immintrin.h> for AVX2 / AVX-512 builds: one test instruction
// instead of a lane-by-lane OR, which compiled to ~15 extracts.)
inline bool anyLane(I m) {
#if HVI_LANES == 8 && defined(__AVX512F__)
  return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0;
#elif HVI_LANES == 4 && defined(__AVX2__)
  return _mm256_testz_si256((__m256i)m, (__m256i)m) == 0;
#else
  std::int64_t any = 0;
  for (int l = 0; l < L; ++l) any |= m[l];
  return any != 0;
#endif
}
inline void store(double* p, D v) { __builtin_memcpy(p, &v, sizeof v); }
inline D vabs(D v) { return (D)((I)v & (I{} + INT64_MAX)); }  // clears the sign bit

// kernel.hpp's expNegative lane by lane, same operations: truncation of y >= 0 is floor, done
// exactly as round-to-nearest through 2^52 minus one where that rounded up.
inline D expNegative(D x) {
  constexpr double ln2hi = 6.93147180369123816490e-01;
  constexpr double ln2lo = 1.90821492927058770002e-10;
  constexpr double invLn2 = 1.44269504088896338700e+00;
  constexpr double two52 = 4503599627370496.0;
  const D y = x * invLn2 + 0.5;
  D n = (y + two52) - two52;
  n = select(n > y, n - 1.0, n);
  const D r = (n * ln2hi - x) + n * ln2lo;
  const D r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const D a0 = 1.0 + r, a1 = 0.5 + r * (1.0 / 6.0);
  const D a2 = 1.0 / 24.0 + r * (1.0 / 120.0), a3 = 1.0 / 720.0 + r * (1.0 / 5040.0);
  const D a4 = 1.0 / 40320.0 + r * (1.0 / 362880.0);
  const D a5 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0);
  const D a6 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
  const D b0 = a0 + a1 * r2, b1 = a2 + a3 * r2, b2 = a4 + a5 * r2;
  const D d0 = b0 + b1 * r4, d1 = b2 + a6 * r4;
  const D p = d0 + d1 * r8;
  // 2^-n: n + 1.5 2^52 holds n in its low bits; (1023 - n) << 52 as a 64-bit difference.
  const I nbits = (I)(n + 6755399441055744.0);
  const I scale = (I{} + (std::int64_t{1023} << 52)) - (nbits << 52);
  return p * (D)scale;
}

inline D load(const double* p) {
  D v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
