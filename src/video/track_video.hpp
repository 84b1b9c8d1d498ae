// The `track video` workflow (docs/cli.md#track-video): open the input, start every target
// in its first frame, stream the clip through the point and ellipse trackers, convert to
// world coordinates, and summarise (lost frames, median score, agreement with any human
// marks of a Tracker project). Front ends (CLI, Python) call track_video() and print.
#pragma once

#include "track/track.hpp"
#include "video/ellipse_tracker.hpp"
#include "video/path_tracker.hpp"
#include "video/point_tracker.hpp"
#include "video/source.hpp"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::video {

/// One object to follow.
struct Target {
  enum class Kind { point, ellipse } kind = Kind::point;
  std::string name;        ///< output track name ("ball"; an ellipse also gives ball.A, ball.B)
  double x_px = 0, y_px = 0;  ///< start position in image pixels
  int frame = -1;          ///< start frame (-1: the clip's first frame)
  std::string from_track;  ///< non-empty: start from this project track's first mark
  /// The user's corrections (docs/cli.md#track-video, `mark`): frames after the start, each
  /// reported as marked (manual, score 1), the tracking restarting from each; an ellipse's
  /// marks are of its centre.
  std::vector<ManualMark> marks;
};

struct TrackVideoOptions {
  SourceOptions source;
  std::vector<Target> targets;
  PointTrackerOptions point;
  PathTrackerOptions path;
  /// Points: true follows them with the offline PathTracker, false with the frame-to-frame
  /// PointTracker (rotation search, see point_tracker.hpp).
  bool offline_points = true;
  EllipseTrackerOptions ellipse;
  int thumbnails = 6;      ///< frames kept (downscaled, tracks drawn) for the report
  /// Called after each frame with (frames done, frames expected); may be empty.
  std::function<void(int, int)> progress;
  std::string validate() const;
};

/// One row of the output: a tracked point in one frame.
struct TrackedRow {
  int frame = 0;
  double t = 0;            ///< s
  double x = 0, y = 0;     ///< world position, m (px when uncalibrated), y up
  double x_px = 0, y_px = 0;  ///< image position, px
  double score = 0;        ///< [0, 1]
  bool lost = false;       ///< no reliable position (x, y, x_px, y_px are NaN)
  bool manual = false;     ///< the user's mark (Target::marks), not tracked; score 1
};

struct TrackedSeries;

/// Distance between tribolab's track and the project's human marks on the same frames
/// (docs/theory.md#tracking-on-real-film: the figures a user correcting the track sees).
struct HumanComparison {
  int frames = 0;              ///< frames with both (the start mark excluded)
  double median_px = 0;        ///< median distance, px
  double max_px = 0;           ///< largest distance, px
  int marks = 0;               ///< human marks on the track's rows (the start mark excluded)
  double p90_px = 0;           ///< 90th percentile of the distance, px
  /// Distance beyond which a user would correct a frame: 4 px per 640 px of image width, px.
  double correct_px = 0;
  /// Marked frames a user must correct: no position, or farther than correct_px from the mark.
  int to_correct = 0;
  /// Marked frames with a position (score at or above the threshold) farther than 10 px from
  /// the mark: a confident wrong answer.
  int confidently_wrong = 0;
};

/// Compares a series with human marks (px) on the same frames, the mark of `start_frame`
/// left out; `image_width_px` sets the correction distance.
HumanComparison compare_with_human(const TrackedSeries& s, const track::Track& human, int start_frame,
                                   int image_width_px);

struct TrackedSeries {
  std::string name;
  Target::Kind kind = Target::Kind::point;
  std::vector<TrackedRow> rows;        ///< one per clip step from the start frame
  std::vector<double> angle_rad;       ///< per row: pattern rotation / ellipse orientation
  int tracked = 0;                     ///< rows with a position
  std::vector<std::pair<int, int>> lost_ranges;  ///< [first, last] frames lost, inclusive
  /// Frames where the point was found again after more than max_gap_frames lost in a row
  /// (its motion model restarted there); empty for an ellipse.
  std::vector<int> refound_frames;
  std::vector<int> manual_frames;      ///< frames of the user's marks (Target::marks)
  double median_score = 0;
  std::optional<HumanComparison> vs_human;
  /// Ellipse: the exposure read from the blurred edges, a fraction of the frame period, which
  /// put the frames at their time (EllipseTracker::at_frame_time); none when it was not read
  /// (the object moved under 8 px per frame, or is round) or for a point.
  std::optional<double> exposure;
};

/// A small image of one frame with every track drawn, for the report.
struct Thumbnail {
  int frame = 0;
  double t = 0;
  std::vector<unsigned char> jpeg;     ///< JPEG bytes (video::encode_image)
};

struct TrackVideoResult {
  VideoInput input;                    ///< what was decoded (info, clip, time base, calibration)
  std::vector<TrackedSeries> series;   ///< per output track (ellipse: NAME, NAME.A, NAME.B)
  std::vector<Thumbnail> thumbnails;
  int frames = 0;                      ///< clip frames decoded
  std::vector<std::string> warnings;
};

/// What a tracking keeps so that a correction re-tracks without decoding the video again
/// (retrack()): the trackers (the path trackers' candidates and background), the rows of the
/// frame-to-frame trackers, the thumbnails' frames.
class TrackSession {
 public:
  TrackSession();
  ~TrackSession();
  TrackSession(const TrackSession&) = delete;
  TrackSession& operator=(const TrackSession&) = delete;
  /// The caller's description of what was tracked (the app: every option but the marks), to
  /// tell whether a new run may re-track instead of tracking afresh.
  std::string key;
  bool empty() const;
  struct Impl;
  std::unique_ptr<Impl> impl;
};

/// Runs the whole workflow. Throws InputError for bad input (see source.hpp, the trackers).
/// With `keep`, what a re-tracking needs is left there.
TrackVideoResult track_video(const std::string& input, const TrackVideoOptions& options,
                             TrackSession* keep = nullptr);

/// The tracking of `session` again with `targets` (those tracked, in the same order, with the
/// same starts) whose marks may differ, without decoding (the studio's answer to a drag): a
/// path-tracked point's new marks choose its path anew among the candidates already found
/// (PathTracker::finish), every other track is as it was. A new mark's look is not searched for
/// (PathTracker::add_look needs the frames): where it would add candidates, track_video() with
/// these marks finds more. nullopt when it is not possible (no session, other targets, or new
/// marks of a frame-to-frame or ellipse track, which stream forward: track afresh). Throws
/// InputError for a bad mark, the session unchanged.
std::optional<TrackVideoResult> retrack(TrackSession& session, const std::vector<Target>& targets);

/// The tracked positions as a TrackSet (lost rows left out), for the analyses and `write_trk`.
track::TrackSet to_track_set(const TrackVideoResult& result);

/// Writes the table track,frame,t,x,y,x_px,y_px,score (docs/cli.md#track-video): one row per
/// series and clip step from its start, numbers in shortest round-trip form; a lost row has
/// empty x, y, x_px, y_px and score 0.
void write_csv(std::ostream& out, const TrackVideoResult& result);

/// The result as a Tracker project (PointMass tracks, the video relative to `trk_path`'s
/// folder, the clip, the time base with any time scale folded into the frame duration, and
/// the coordinate system), so that Tracker opens it with its video and `track import` reads
/// back the CSV's numbers. Adds a warning to `warnings` when the video cannot be named
/// (a video inside a .trz).
io::TrkWriteSpec trk_spec(const TrackVideoResult& result, const std::string& trk_path,
                          std::vector<std::string>& warnings);

}  // namespace tribolab::video
