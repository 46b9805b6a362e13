//! @file The lane kernels for AVX-512 (8 lanes). Compiled with -mavx512f etc. where the compiler
//! has them (sph/CMakeLists.txt); passes.cpp calls this only on a CPU that has them.
#include "detail/force_lanes.hpp"

#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__)
#define HVI_LANES 8
#define HVI_LANES_NS lanes_avx512
#include "detail/force_lanes_impl.hpp"

namespace hvi::sph::detail {
RowKernel rowKernelAvx512(bool rz, bool viscous, bool cached, bool compatible, bool half) {
  return lanes_avx512::pick(rz, viscous, cached, compatible, half);
}
ScanKernel scanKernelAvx512() { return &lanes_avx512::scan; }
DistanceWKernel distanceWKernelAvx512() { return &lanes_avx512::distanceW; }
RowWKernel rowWKernelAvx512() { return lanes_avx512::rowWKernel(); }
}  // namespace hvi::sph::detail
#else
namespace hvi::sph::detail {
RowKernel rowKernelAvx512(bool, bool, bool, bool, bool) { return nullptr; }
ScanKernel scanKernelAvx512() { return nullptr; }
DistanceWKernel distanceWKernelAvx512() { return nullptr; }
RowWKernel rowWKernelAvx512() { return nullptr; }
}  // namespace hvi::sph::detail
#endif
