// Where frames come from: a video file decoded by OpenCV's videoio (FFmpeg backend), or a
// Tracker project (.trk beside its video, .trz holding it), whose clip, time base and
// per-frame coordinate system are then used so that tracks land in exactly the world
// coordinates `track import` gives for the same project (docs/theory.md#video-tracking).
// Frames are streamed: memory is bounded by a few frames, never the whole video.
#pragma once

#include "io/tracker_trk.hpp"
#include "track/track.hpp"
#include "video/frame.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tribolab::video {

/// What the container says about a video.
struct VideoInfo {
  std::string path;      ///< the decoded file (a temporary copy for a video inside a .trz)
  int width = 0;         ///< px
  int height = 0;        ///< px
  int frame_count = 0;   ///< frames the container reports (may be approximate), e.g. 13
  double fps = 0;        ///< frames per second the container reports (0 when unknown: an image sequence)
  std::string codec;     ///< FourCC, e.g. "avc1"
};

/// The part of the video that is tracked (Tracker's VideoClip).
struct Clip {
  int start_frame = 0;   ///< first frame tracked
  int step_size = 1;     ///< frames between tracked steps, >= 1
  int step_count = 0;    ///< steps tracked; 0 = to the end of the video
  /// True when `frame` is one of the clip's steps.
  bool contains(int frame) const;
};

/// Frame index -> time: t = (start_time_s + (frame - start_frame) * frame_duration_s) * time_scale.
struct TimeBase {
  int start_frame = 0;
  double start_time_s = 0;      ///< time of start_frame, s (Tracker's starttime / 1000)
  double frame_duration_s = 0;  ///< s per frame as filmed or as Tracker says (delta_t / 1000)
  double time_scale = 1;        ///< real seconds per video second (slow motion 240->30: 0.125)
  double t(int frame) const;
  /// Real seconds between two consecutive frames (0 when unknown).
  double real_frame_s() const { return frame_duration_s * time_scale; }
};

/// Tracker's image position of a point minus OpenCV's (docs/theory.md#video-input-and-the-track-video-workflow):
/// Tracker puts the image's top-left corner at (0, 0), so the centre of pixel (column j, row i)
/// is at (j + 0.5, i + 0.5); tribolab's pixels (OpenCV's, every `_px` in `track video`) put it
/// at (j, i). A Tracker project's marks and coordinate origins are moved by -0.5 px when read
/// and by +0.5 px when written.
inline constexpr double kTrackerPixelOffset = 0.5;
/// A key frame in Tracker's image positions -> the same key frame in OpenCV's pixels.
io::TrkCoordFrame from_tracker_pixels(io::TrkCoordFrame c);
/// A key frame in OpenCV's pixels -> the same key frame in Tracker's image positions.
io::TrkCoordFrame to_tracker_pixels(io::TrkCoordFrame c);

/// Image pixels -> world metres, per frame (Tracker's ImageCoordSystem: key frames, each
/// holding until the next). An uncalibrated video has scale 1 px per unit and unit "px".
struct Calibration {
  std::vector<io::TrkCoordFrame> coords = {io::TrkCoordFrame{}};  ///< first key frame at 0
  double metres_per_unit = 1;   ///< the coordinate system's length unit in metres
  bool calibrated = false;      ///< false: world units are pixels (y up)
  const io::TrkCoordFrame& at(int frame) const;
  /// World position (m, or px when uncalibrated; y up) of image point (px, py) at `frame`.
  std::pair<double, double> to_world(int frame, double px, double py) const;
  /// Image position (px) of world point (x, y) at `frame` (inverse of to_world).
  std::pair<double, double> to_image(int frame, double x, double y) const;
};

/// Calibration and timing options for a plain video (a Tracker project brings its own; any
/// option given here overrides the project's, with a warning).
struct SourceOptions {
  double fps = 0;                 ///< override the container's frame rate (0 = keep), 1/s
  double time_scale = 1;          ///< real s per video s (slow motion), (0, 1e6]
  double scale_m_per_px = 0;      ///< metres per pixel (0 = not given)
  /// A stick of known length: two image points (px) and its length (m).
  std::optional<std::pair<cv::Point2d, cv::Point2d>> calibrate_points;
  double calibrate_length_m = 0;
  std::optional<cv::Point2d> origin_px;  ///< world origin in the image (default: bottom-left)
  double axes_deg = 0;            ///< world x-axis counter-clockwise from image x-axis, degrees
  std::string zip_entry;          ///< .trz: the .trk to use ("" = the first)
  std::string validate() const;   ///< empty when valid, else a message naming the field
};

/// A video ready to track: what to decode, which frames, their times and the calibration,
/// plus a Tracker project's own marks (in pixels) for `from_track`.
struct VideoInput {
  VideoInfo info;
  Clip clip;
  TimeBase time;
  Calibration calibration;
  std::string input;               ///< what the user named (video, .trk or .trz)
  std::string project_video;       ///< the video path as the project names it ("" for a plain video)
  /// The video as a file that outlives this run ("" when it lives only inside a .trz).
  std::string video_file;
  /// The project's tracks in image pixels (x right, y down, OpenCV's pixel centres: Tracker's
  /// image positions - kTrackerPixelOffset), by frame; empty for a plain video.
  std::vector<track::Track> marks_px;
  std::vector<std::string> warnings;  ///< e.g. "no scale: positions are in pixels"
  std::shared_ptr<void> temp_owner;   ///< keeps an extracted temporary video alive
  /// A plain video without `fps`: from the first frame whose timestamp (the container's
  /// presentation time) departs from time.t(frame) by more than a quarter frame, frames take
  /// their timestamps (variable frame rate; FrameReader::warnings() says so).
  bool frame_times_from_timestamps = false;
};

/// Opens `path` (video, .trk or .trz), reads the container's facts and the project's clip,
/// time base and coordinate system. Throws InputError naming the file for a missing,
/// truncated or undecodable video, a project without a video, bad options.
VideoInput open_input(const std::string& path, const SourceOptions& options);

/// Decodes the clip's frames in order, one at a time (frames outside the clip are skipped
/// without keeping them). Throws InputError when decoding fails mid-way.
class FrameReader {
 public:
  explicit FrameReader(const VideoInput& input);
  ~FrameReader();
  FrameReader(const FrameReader&) = delete;
  FrameReader& operator=(const FrameReader&) = delete;
  /// The next frame of the clip (bgr, index, t; gray left empty: gray_region converts the
  /// rectangles a tracker reads); false after the last one.
  bool next(Frame& frame);
  /// Steps the clip holds (an estimate from the container when step_count is 0).
  int expected_steps() const;
  /// What the decoding found out, e.g. a variable frame rate (after the frames are read).
  const std::vector<std::string>& warnings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribolab::video
