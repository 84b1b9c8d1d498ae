// --from/--to of the track commands (docs/cli.md#track-kinematics): only the points of a
// track within a time range, e.g. the free fall before a landing.
#pragma once

#include "track/track.hpp"

#include <cstddef>
#include <limits>
#include <string>

namespace tribolab::app {

/// Default of the --from/--to times (t_from = -kNoTimeLimit, t_to = +kNoTimeLimit): no limit.
inline constexpr double kNoTimeLimit = std::numeric_limits<double>::infinity();

/// The points of `track` with t_from <= t <= t_to (s; -inf/+inf: no limit). Throws InputError
/// naming t_from/t_to when t_from > t_to or either is NaN, and naming the file (`source`), the
/// track's time range and the least number `least` when fewer points remain.
track::Track restrict_times(const track::Track& track, double t_from, double t_to, std::size_t least,
                            const std::string& source);

}  // namespace tribolab::app
