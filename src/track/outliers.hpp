// Isolated outliers of a tracked point: one value far off the motion of its neighbours on
// BOTH sides (a lost decimal point, a typo, one frame of the tracker on something else), so
// far that the fits downstream cannot carry it. A real impact or stop changes the motion on
// one side only, and a contact frame moves by far less than the track's extent, so neither is
// taken for one. docs/theory.md#plausibility-checks ("isolated outliers").
#pragma once

#include "track/track.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::track {

/// One point off its neighbours' motion.
struct Outlier {
  std::size_t index = 0;  ///< position in Track::points
  char axis = 'y';        ///< 'x' or 'y': the coordinate that is off (the larger offence)
  double value = 0;       ///< the point's coordinate, m
  double expected = 0;    ///< what the neighbours predict there (mean of the two sides), m
  double noise = 0;       ///< robust noise of the one-sided predictions on that axis, m
};

/// The isolated outliers of `track`: points whose x or y misses the quadratic through the 4
/// points before it AND the quadratic through the 4 points after it, on the same side, by more
/// than 10 robust noise sds of such predictions and by more than a quarter of the track's
/// extent on that axis (2nd to 98th percentile), the two predictions agreeing with each other
/// within half that miss. Points with fewer than 4 neighbours on one side are judged by the
/// other side alone. Empty for fewer than 12 points.
std::vector<Outlier> isolated_outliers(const Track& track);

/// `track` without the points `outliers` names.
Track without(const Track& track, const std::vector<Outlier>& outliers);

/// The warning for an outlier left out: its track, frame, time, value and what its neighbours
/// give (numbers with six significant digits).
std::string outlier_warning(const Track& track, const Outlier& o);

}  // namespace tribolab::track
