#include "track/track.hpp"

#include "numerics/error.hpp"

#include <cmath>
#include <map>

namespace tribolab::track {

const Track& TrackSet::find(const std::string& name) const {
  for (const Track& t : tracks) {
    if (t.name == name) return t;
  }
  std::string available;
  for (const Track& t : tracks) available += (available.empty() ? "'" : ", '") + t.name + "'";
  throw InputError(source, "no track named '" + name + "'; available tracks: " +
                               (available.empty() ? "(none)" : available));
}

std::vector<std::string> TrackSet::names() const {
  std::vector<std::string> out;
  for (const Track& t : tracks) out.push_back(t.name);
  return out;
}

void validate_track(const Track& track, const std::string& where) {
  const std::string w = where.empty() ? "track '" + track.name + "'" : where;
  for (std::size_t i = 0; i < track.points.size(); ++i) {
    const TrackPoint& p = track.points[i];
    if (!std::isfinite(p.t) || !std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw InputError(w, "track '" + track.name + "' has a non-finite value at frame " +
                              std::to_string(p.frame));
    }
    if (i == 0) continue;
    const TrackPoint& q = track.points[i - 1];
    if (p.frame <= q.frame) {
      throw InputError(w, "track '" + track.name + "': frame " + std::to_string(p.frame) +
                              " follows frame " + std::to_string(q.frame) +
                              " (frames must increase)");
    }
    if (!(p.t > q.t)) {
      throw InputError(w, "track '" + track.name + "': time does not increase at frame " +
                              std::to_string(p.frame));
    }
  }
}

int frame_step(const Track& track) {
  std::map<long long, int> counts;
  for (std::size_t i = 1; i < track.points.size(); ++i) {
    const long long d = static_cast<long long>(track.points[i].frame) - track.points[i - 1].frame;
    if (d > 0) ++counts[d];
  }
  long long best = 1;
  int best_count = 0;
  for (const auto& [d, c] : counts) {
    if (c > best_count) {  // ties go to the smaller step (map order)
      best = d;
      best_count = c;
    }
  }
  return static_cast<int>(best);
}

TrackColumns columns_of(const Track& track) {
  TrackColumns c;
  c.t.reserve(track.points.size());
  c.x.reserve(track.points.size());
  c.y.reserve(track.points.size());
  for (const TrackPoint& p : track.points) {
    c.t.push_back(p.t);
    c.x.push_back(p.x);
    c.y.push_back(p.y);
  }
  return c;
}

}  // namespace tribolab::track
