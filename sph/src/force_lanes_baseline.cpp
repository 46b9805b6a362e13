//! @file The lane kernels for baseline x86-64 (2 lanes; any CPU the build targets).
#define HVI_LANES 2
#define HVI_LANES_NS lanes_baseline
#include "detail/force_lanes_impl.hpp"

namespace hvi::sph::detail {
RowKernel rowKernelBaseline(bool rz, bool viscous, bool cached, bool compatible, bool half) {
  return lanes_baseline::pick(rz, viscous, cached, compatible, half);
}
ScanKernel scanKernelBaseline() { return &lanes_baseline::scan; }
DistanceWKernel distanceWKernelBaseline() { return &lanes_baseline::distanceW; }
RowWKernel rowWKernelBaseline() { return lanes_baseline::rowWKernel(); }
}  // namespace hvi::sph::detail
