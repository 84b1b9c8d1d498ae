// Sizes and bounds of the tests' statistical studies (coverage counts, false-alarm rates).
// The sanitizer tree (docs/design.md#build-and-ci) runs the same tests several times slower, so
// a long study has a short form there: fewer draws, from the same code paths, checked against a
// bound computed for that number of draws. The normal tree keeps its full study and its bounds.
#pragma once

#include "numerics/sanitizer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace tribolab {

/// Draws of a statistical study: `full` in the normal tree, `under_asan` in the sanitizer tree
/// (TRIBOLAB_ASAN); the environment variable TRIBOLAB_COVERAGE_RUNS, when set, overrides both
/// (a longer study on demand, e.g. the figures in docs/theory.md).
inline int study_draws(int full, [[maybe_unused]] int under_asan) {
  if (const char* e = std::getenv("TRIBOLAB_COVERAGE_RUNS"); e && *e) return std::max(1, std::atoi(e));
#if TRIBOLAB_ASAN
  return under_asan;
#else
  return full;
#endif
}

/// True when a study runs its full size `full` in the normal tree: there its recorded bounds
/// apply, bit for bit. Any other count (the sanitizer tree's short form, TRIBOLAB_COVERAGE_RUNS)
/// is checked against bounds computed for that count (binomial_floor, binomial_ceiling).
inline bool is_full_study(int draws, int full) { return !TRIBOLAB_ASAN && draws == full; }

/// P(X <= k) for X ~ Binomial(n, p), 0 < p < 1, summed in log space (n up to thousands).
inline double binomial_cdf(int k, int n, double p) {
  if (k < 0) return 0;
  if (k >= n) return 1;
  double sum = 0;
  for (int i = 0; i <= k; ++i)
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
                    (n - i) * std::log1p(-p));
  return std::min(sum, 1.0);
}

/// The lowest count of successes in n independent draws of probability p that is still
/// accepted: the largest k with P(X < k) <= alpha, X ~ Binomial(n, p). A correct method (true
/// rate >= p) passes `count >= binomial_floor(n, p)` with probability >= 1 - alpha.
/// E.g. n = 40, p = 0.95, alpha = 0.001: 33 (P(X < 33) = 7.1e-4).
inline int binomial_floor(int n, double p, double alpha = 1e-3) {
  int k = 0;
  while (k < n && binomial_cdf(k, n, p) <= alpha) ++k;
  return k;
}

/// The highest count still accepted: the smallest k with P(X > k) <= alpha. A method whose
/// true rate is <= p passes `count <= binomial_ceiling(n, p)` with probability >= 1 - alpha.
/// E.g. n = 40, p = 0.05, alpha = 0.001: 7 (P(X > 7) = 7.1e-4).
inline int binomial_ceiling(int n, double p, double alpha = 1e-3) {
  int k = n;
  while (k > 0 && 1 - binomial_cdf(k - 1, n, p) <= alpha) --k;
  return k;
}

}  // namespace tribolab
