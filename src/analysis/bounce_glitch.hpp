// Wild frames of a tracked throw that the impact detector takes for impacts: a hand in the
// picture, a shadow, the tracker jumping for a few frames. A real impact changes the flight;
// a glitch leaves it as it was: one free flight (x and y parabolas) fits the frames on both
// sides once the few wild ones are left out. docs/theory.md#plausibility-checks.
#pragma once

#include "track/impacts.hpp"
#include "track/track.hpp"

#include <vector>

namespace tribolab::analysis {

struct Glitches {
  std::vector<double> times;  ///< s, of the frames left out (file times)
  double worst = 0;           ///< m: largest distance of a left-out centre from the flight
};

/// Removes from tips `a` and `b` (the same frames from both) every glitch the impact detector
/// (`options`) sees on their centre track, until none is left (at most 10 rounds).
Glitches drop_glitches(track::Track& a, track::Track& b, const track::ImpactOptions& options);

}  // namespace tribolab::analysis
