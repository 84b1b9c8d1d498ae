// The impact of a filmed bounce when the impact detector (track::detect_impacts, a jump of
// velocity between two windows of `window` frames next to each other) sees none: a contact
// lasting several windows' worth of frames (the velocity turns smoothly inside it, no split
// shows a jump) or a noisy track (a window's velocity too uncertain for the threshold). The
// flights on both sides are compared across a gap of left-out frames, with wider windows.
// Internal to analyze_bounce; docs/theory.md#bounce-analysis ("impact search").
#pragma once

#include "track/impacts.hpp"
#include "track/track.hpp"

#include <cstddef>
#include <optional>

namespace tribolab::analysis::detail {

/// An impact found across a gap: points [0, last_pre] fly in, (last_pre, first_post) are in
/// contact (left out of both flights), [first_post, n) fly out.
struct GapImpact {
  track::Impact impact;        ///< index = last_pre; t = the gap's middle; jump and significance
  std::size_t first_post = 0;  ///< first point of the outgoing flight
};

/// Searches `centre` for the split (last_pre, first_post) whose flights, fitted by x and y
/// parabolas over w points on each side and extrapolated to the gap's middle, differ in
/// velocity most significantly (the noise of `found`, the threshold and min_jump of
/// `options`) with the centre falling before and rising after (a bounce); w doubles from options.window while none passes, gaps up to 0.1 s. Empty
/// when no split passes.
std::optional<GapImpact> find_impact_across_gap(const track::Track& centre, const track::ImpactResult& found,
                                                const track::ImpactOptions& options);

}  // namespace tribolab::analysis::detail
