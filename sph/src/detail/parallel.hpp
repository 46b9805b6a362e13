//! @file When a particle loop is worth an OpenMP team.
#pragma once

namespace hvi::sph::detail {

// Starting a team and its barrier costs microseconds, and far more when the machine is
// oversubscribed; small systems (tests, 1-D strips) run faster serially. Pair loops do ~1 us
// of work per particle, the element-wise loops ~1 ns.
inline constexpr long kParallelPairs = 2048;
inline constexpr long kParallelElements = 65536;

}  // namespace hvi::sph::detail
