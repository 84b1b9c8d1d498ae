// Order statistics shared by every layer: the median, the upper median and one MAD scale, so
// that a robust noise estimate means the same thing in the tracker, the impact finder and the
// fits.
#pragma once

#include "numerics/error.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace tribolab {

/// MAD -> standard deviation for normal data: 1 / Phi^-1(3/4) (Hampel 1974; Huber & Ronchetti,
/// Robust Statistics, 2nd ed., sec. 5.1). sd = kMadToSd * median(|x - median(x)|).
inline constexpr double kMadToSd = 1.482602218505602;

/// The sample median: the middle value, or the mean of the middle pair for an even count
/// (the convention of R's median() and numpy.median). NaN for an empty sample. O(n).
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  double m = *mid;
  if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), mid));
  return m;
}

/// The upper median: the element at index n/2 of the sorted sample, i.e. the middle value, or
/// the upper of the middle pair for an even count; always a value of the sample (a pixel
/// level, a score, a frame period), as the trackers and the robust scales of the fits take it.
/// The sample must not be empty (callers say what an empty one means). O(n).
template <class T>
T upper_median(std::vector<T> v) {
  TRIBOLAB_ASSERT(!v.empty(), std::string("upper_median of an empty sample"));
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Robust standard deviation of a sample about its median: kMadToSd * MAD. NaN when empty.
inline double mad_sd(const std::vector<double>& v) {
  const double m = median(v);
  std::vector<double> d;
  d.reserve(v.size());
  for (double x : v) d.push_back(x < m ? m - x : x - m);
  return kMadToSd * median(std::move(d));
}

}  // namespace tribolab
