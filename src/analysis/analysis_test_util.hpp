// Helpers shared by the analysis tests (bounce_analyze_test.cpp, bounce_touch_test.cpp,
// bounce_grid_test.cpp): one definition each, so that the test programs build in unity batches.
#pragma once

#include "track/track.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tribolab::analysis::testing {

/// Tracks in real time (undoes the synthetic slow-motion factor, as time_scale does).
inline track::Track real_time(track::Track t, double factor) {
  for (auto& p : t.points) p.t /= factor;
  return t;
}

/// A count of 95 % intervals that cover, out of n: within 3 binomial sds of 0.95 n.
inline void expect_binomial(int covered, int n, const char* what) {
  const double mean = 0.95 * n, sd = std::sqrt(n * 0.95 * 0.05);
  EXPECT_GE(covered, mean - 3 * sd) << what;
  EXPECT_LE(covered, std::min<double>(n, mean + 3 * sd)) << what;
}

}  // namespace tribolab::analysis::testing
