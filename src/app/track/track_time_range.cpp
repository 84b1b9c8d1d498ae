#include "app/track/track_time_range.hpp"

#include "numerics/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tribolab::app {

track::Track restrict_times(const track::Track& track, double t_from, double t_to, std::size_t least,
                            const std::string& source) {
  if (std::isnan(t_from) || std::isnan(t_to) || t_from > t_to) {
    throw InputError(field("t_from") + "/" + field("t_to"), "must be times in s with " + field("t_from") + " <= " +
                                                             field("t_to") + ", got " + fmt::format("{}", t_from) +
                                                             " and " + fmt::format("{}", t_to));
  }
  track::Track kept{track.name, {}};
  for (const auto& p : track.points) {
    if (p.t >= t_from && p.t <= t_to) kept.points.push_back(p);
  }
  if (kept.points.size() < least && (std::isfinite(t_from) || std::isfinite(t_to))) {
    const std::string range = track.points.empty() ? std::string("has no points")
                                                   : fmt::format("runs from t = {:.6g} to {:.6g} s",
                                                                 track.points.front().t, track.points.back().t);
    throw InputError(source, fmt::format("{}/{} keep {} point(s) of track '{}' (at least {} are needed); the track {}",
                                         field("t_from"), field("t_to"), kept.points.size(), track.name, least, range));
  }
  return kept;
}

}  // namespace tribolab::app
