//! @file The critical-diameter bisection on synthetic failure functions.
#include <gtest/gtest.h>

#include <cmath>

#include "hvi/shield/bisection.hpp"

namespace hvi::shield {
namespace {

// Runs the search against failed(d) = d >= dc, evaluating what it asks for in batches (as the
// parallel runner does); returns the number of evaluations.
int drive(CriticalDiameterSearch& s, double dc) {
  int runs = 0;
  while (!s.done()) {
    const auto want = s.pending();
    EXPECT_FALSE(want.empty());
    if (want.empty()) break;
    for (double d : want) {
      s.record(d, d >= dc);
      ++runs;
    }
    if (runs > 100) break;
  }
  return runs;
}

TEST(CriticalDiameterSearch, ConvergesToTheToleranceAroundATrueThreshold) {
  for (double dc : {0.3137, 0.5, 0.6934, 0.9}) {
    CriticalDiameterSearch s(0.25, 1.0, 0.02);
    const int runs = drive(s, dc);
    ASSERT_TRUE(s.bracketed()) << dc;
    // The bracket holds the threshold and is at most 2 % of its midpoint wide (plus the
    // 5-digit rounding of the diameters).
    EXPECT_LT(*s.survived(), dc);
    EXPECT_GE(*s.failed(), dc);
    EXPECT_LE(*s.failed() - *s.survived(), 0.02 * *s.estimate() + 1e-4);
    EXPECT_NEAR(*s.estimate(), dc, 0.01 * dc + 1e-4);
    // 2 bounds + the halvings of the width 0.75 cm down to 2 % of d_c (1 % slack for the
    // bracket's midpoint lying above d_c): 2 + ceil(log2(0.75 / (0.0198 d_c))).
    EXPECT_LE(runs, 2 + static_cast<int>(std::ceil(std::log2(0.75 / (0.0198 * dc))))) << dc;
  }
}

TEST(CriticalDiameterSearch, WidensAStartBracketThatDoesNotBracket) {
  CriticalDiameterSearch above(0.25, 1.0, 0.05);  // d_c = 1.7: the high bound doubles once
  drive(above, 1.7);
  ASSERT_TRUE(above.bracketed());
  EXPECT_NEAR(*above.estimate(), 1.7, 0.05 * 1.7);
  CriticalDiameterSearch below(0.25, 1.0, 0.05);  // d_c = 0.1: the low bound halves twice
  drive(below, 0.1);
  ASSERT_TRUE(below.bracketed());
  EXPECT_NEAR(*below.estimate(), 0.1, 0.05 * 0.1);
}

TEST(CriticalDiameterSearch, GivesUpAfterTheAllowedWidenings) {
  CriticalDiameterSearch s(0.25, 1.0, 0.05, 2);
  drive(s, 100.0);  // never fails
  EXPECT_TRUE(s.done());
  EXPECT_FALSE(s.bracketed());
  EXPECT_NE(s.note().find("every diameter survived"), std::string::npos) << s.note();
}

TEST(CriticalDiameterSearch, ResumedSearchAsksForTheSameRuns) {
  // A search that records earlier results (a resumed sweep) asks for the diameters a fresh one
  // would have asked for next: diameters are rounded to 5 digits.
  CriticalDiameterSearch a(0.25, 1.0, 0.02), b(0.25, 1.0, 0.02);
  for (int i = 0; i < 3; ++i)
    for (double d : a.pending()) a.record(d, d >= 0.6934);
  for (const auto& [d, f] : a.results()) b.record(d, f);
  EXPECT_EQ(a.pending(), b.pending());
  EXPECT_DOUBLE_EQ(CriticalDiameterSearch::round(0.123456789), 0.12346);
}

}  // namespace
}  // namespace hvi::shield
