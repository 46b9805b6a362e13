//! @file Bit-for-bit equality of doubles and of arrays: what the tests mean by "a restart (or
//! the batches, or another thread count) reproduces the run bit for bit". `==` is not that: it
//! calls -0.0 and 0.0 equal and a NaN unequal to itself.
#pragma once
#include <gtest/gtest.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hvi::test {

inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

//! Same size and every element the same bits; on failure the message names the first element
//! that differs and both values, so a failed restart test says where it went apart.
inline ::testing::AssertionResult sameBits(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << "sizes differ: " << a.size() << " and " << b.size();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!sameBits(a[i], b[i]))
      return ::testing::AssertionFailure()
             << "element " << i << " of " << a.size() << " differs: " << ::testing::PrintToString(a[i])
             << " and " << ::testing::PrintToString(b[i]);
  return ::testing::AssertionSuccess();
}
inline ::testing::AssertionResult sameBits(const std::vector<double>& a,
                                           const std::vector<double>& b) {
  return sameBits(std::span<const double>(a), std::span<const double>(b));
}

}  // namespace hvi::test
