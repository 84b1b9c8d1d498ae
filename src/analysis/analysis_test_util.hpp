// Helpers shared by the analysis tests (bounce_analyze_test.cpp, bounce_touch_test.cpp,
// bounce_grid_test.cpp): one definition each, so that the test programs build in unity batches.
#pragma once

#include "numerics/coverage_test_util.hpp"
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

/// A count of 95 % intervals that cover, out of n, in a study whose full size is `full`: within
/// 3 binomial sds of 0.95 n. A shorter study (the sanitizer tree's) has the exact lower bound
/// binomial_floor(n, 0.905) instead: 0.905 is the lowest rate the full study of 200 accepts
/// (181 of 200), so whatever it accepts the short form accepts with probability >= 0.999 (the
/// 80 fps vy interval covers 184 of 200 there: a bound at 0.95 would fail it ~1 % of the time).
/// n = 60: at least 46 (P(X < 46) = 3.9e-4); n = 64: at least 50 (P(X < 50) = 8.1e-4). An
/// interval of half the true sigma (coverage P(|Z| < 0.98) = 0.67) passes with probability
/// 0.077 and 0.040. 3 sds above the mean is more than n at such n: no upper bound there.
inline void expect_binomial(int covered, int n, int full, const char* what) {
  const double mean = 0.95 * n, sd = std::sqrt(n * 0.95 * 0.05);
  if (is_full_study(n, full)) {
    EXPECT_GE(covered, mean - 3 * sd) << what;
  } else {
    EXPECT_GE(covered, binomial_floor(n, 0.905)) << what;
  }
  EXPECT_LE(covered, std::min<double>(n, mean + 3 * sd)) << what;
}

}  // namespace tribolab::analysis::testing
