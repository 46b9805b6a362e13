//! @file The lane kernels for AVX2 (4 lanes). Compiled with -mavx2 where the compiler
//! has them (sph/CMakeLists.txt); passes.cpp calls this only on a CPU that has them.
#include "detail/force_lanes.hpp"

#if defined(__AVX2__)
#define HVI_LANES 4
#define HVI_LANES_NS lanes_avx2
#include "detail/force_lanes_impl.hpp"

namespace hvi::sph::detail {
RowKernel rowKernelAvx2(bool rz, bool viscous, bool cached, bool compatible, bool half) {
  return lanes_avx2::pick(rz, viscous, cached, compatible, half);
}
ScanKernel scanKernelAvx2() { return &lanes_avx2::scan; }
DistanceWKernel distanceWKernelAvx2() { return &lanes_avx2::distanceW; }
RowWKernel rowWKernelAvx2() { return lanes_avx2::rowWKernel(); }
}  // namespace hvi::sph::detail
#else
namespace hvi::sph::detail {
RowKernel rowKernelAvx2(bool, bool, bool, bool, bool) { return nullptr; }
ScanKernel scanKernelAvx2() { return nullptr; }
DistanceWKernel distanceWKernelAvx2() { return nullptr; }
RowWKernel rowWKernelAvx2() { return nullptr; }
}  // namespace hvi::sph::detail
#endif
