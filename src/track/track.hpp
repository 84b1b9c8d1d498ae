// The in-memory model of tracked video data: named tracks of points (frame, t, x, y) in
// world units (s, m). Every importer (src/io/track_import.hpp) produces a TrackSet; every
// analysis of tracked data (kinematics, impacts, rigid body, the incline and bounce
// analyses) consumes one. See docs/theory.md#tracked-data.
//
// Invariants of a valid Track (checked by validate_track, guaranteed by the importers):
// points sorted by frame, frames strictly increasing, times strictly increasing, every
// t, x, y finite.
#pragma once

#include <string>
#include <vector>

namespace tribolab::track {

/// One marked position of a tracked point.
struct TrackPoint {
  int frame = 0;   ///< video frame number (Tracker's frame index; row index for plain tables)
  double t = 0;    ///< time, s (after any slow-motion time scaling), e.g. 0.0041667
  double x = 0;    ///< horizontal world position, m, e.g. 0.512
  double y = 0;    ///< vertical world position (up), m, e.g. 1.25
};

/// A named sequence of marked points (a Tracker point mass).
struct Track {
  std::string name;                ///< e.g. "ball", "tip A"
  std::vector<TrackPoint> points;  ///< sorted by frame, t strictly increasing
};

/// All tracks read from one file.
struct TrackSet {
  std::vector<Track> tracks;           ///< in file order
  std::string source;                  ///< the file (and zip entry) they came from
  std::string format;                  ///< "trk", "trz", "export" or "tidy_csv"
  std::string file_length_unit = "m";  ///< the length unit the file stated (converted to m)
  double time_scale = 1;               ///< the slow-motion factor applied to every t
  std::vector<std::string> warnings;   ///< things the importer dropped, for the user to see

  /// The track called `name`; throws InputError listing the available names if absent.
  const Track& find(const std::string& name) const;
  /// Names of all tracks, in file order.
  std::vector<std::string> names() const;
};

/// Throws InputError(where, ...) unless `track` satisfies the invariants above.
void validate_track(const Track& track, const std::string& where);

/// The usual frame step of a track: the most frequent positive difference between the frame
/// numbers of consecutive points (1 for a track with fewer than two points). Two points are
/// "consecutive steps" when their frames differ by exactly this step; a larger difference is
/// a gap (missing points).
int frame_step(const Track& track);

/// A track's times and positions as three columns, in point order (what the local fits and
/// filters take).
struct TrackColumns {
  std::vector<double> t, x, y;  ///< s, m, m
};
TrackColumns columns_of(const Track& track);

}  // namespace tribolab::track
