//! @file The stress lane kernels (detail/stress_lanes.hpp) for AVX2 (4 lanes), compiled with its
//! flags where the compiler has them (sph/CMakeLists.txt); the strength pass calls them only on
//! a CPU that has them (laneWidth()).
#include "detail/stress_lanes.hpp"

#if defined(__AVX2__)
#define HVI_LANES 4
#define HVI_LANES_NS stress_lanes_avx2
#include "detail/stress_lanes_impl.hpp"

namespace hvi::sph::detail {
StressRowKernel stressRowKernelAvx2(bool rz, bool viscositySwitch, bool fused) {
  return stress_lanes_avx2::pickStress(rz, viscositySwitch, fused);
}
}  // namespace hvi::sph::detail
#else
namespace hvi::sph::detail {
StressRowKernel stressRowKernelAvx2(bool, bool, bool) { return nullptr; }
}  // namespace hvi::sph::detail
#endif
