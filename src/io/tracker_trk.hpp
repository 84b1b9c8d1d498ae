// Tracker project files (Open Source Physics Tracker, physlets.org/tracker): .trk is the XML
// of a TrackerPanel; .trz is a zip holding one or more .trk files (and the video).
//
// What is read (docs/theory.md#tracker-files):
//   * PointMass tracks: property "framedata", entries "[n]" (n = video frame number) holding
//     the image position x, y in pixels (image x right, y down).
//   * ImageCoordSystem ("coords"): entries "[n]" at key frames holding xorigin, yorigin (px),
//     angle (degrees, world x-axis counter-clockwise from image x-axis), xscale, yscale
//     (pixels per world unit); each key frame holds until the next; a "fixed" flag makes the
//     last saved value hold for every frame (as Tracker's loader does).
//     world = R(-angle) * ((px - xorigin)/xscale, -(py - yorigin)/yscale).
//   * VideoClip ("videoclip"): startframe, stepsize, stepcount, starttime (ms); only points
//     on the clip's steps are kept, as in Tracker's tables.
//   * ClipControl ("clipcontrol"): delta_t, the frame duration in ms;
//     t(frame) = (starttime + (frame - startframe) * delta_t) / 1000 s.
//   * length_unit of the TrackerPanel (m if absent): the unit of the world coordinates.
//   * the video (videoclip/video/path, relative to the .trk's folder, and video_framecount),
//     for `track video`; pixel positions use OpenCV's convention (pixel j centred at x = j).
// Lengths are returned in the file's unit and times unscaled; read_tracks (track_import.hpp)
// converts. Numbers with a decimal comma are accepted. Errors name the element path.
#pragma once

#include "track/track.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tribolab::io {

/// One key frame of Tracker's image coordinate system.
struct TrkCoordFrame {
  int frame = 0;          ///< first video frame this key frame applies to
  double origin_x = 0;    ///< image position of the world origin, px, e.g. 131.3
  double origin_y = 0;    ///< px (image y grows downwards)
  double angle_deg = 0;   ///< world x-axis counter-clockwise from the image x-axis, degrees
  double xscale = 1;      ///< pixels per world length unit along x, e.g. 398.7 px/m
  double yscale = 1;      ///< pixels per world length unit along y
};

/// Image pixels -> world coordinates (in the file's length unit) for one key frame.
std::pair<double, double> image_to_world(const TrkCoordFrame& c, double px, double py);
/// World -> image pixels (inverse of image_to_world).
std::pair<double, double> world_to_image(const TrkCoordFrame& c, double x, double y);

/// The key frame in force at `frame`: the last one at or before it (the first before any).
/// `keys` must be non-empty and sorted by frame.
const TrkCoordFrame& coord_at(const std::vector<TrkCoordFrame>& keys, int frame);

/// A project's video clip and time base (Tracker's VideoClip and ClipControl).
struct TrkClip {
  int start_frame = 0;           ///< first video frame of the clip
  int step_size = 1;             ///< video frames per step, >= 1
  int step_count = 0;            ///< steps in the clip (0: not stated)
  double start_time_ms = 0;      ///< time of start_frame, ms
  double frame_duration_ms = 0;  ///< ms per video frame (delta_t, holds any slow motion), e.g. 66.0
  /// True when `frame` is one of the clip's steps.
  bool on_step(long long frame) const;
  /// Time of `frame`, s, unscaled: (start_time_ms + (frame - start_frame) * delta_t) / 1000.
  double t(long long frame) const;
};

/// Everything tribolab reads from a .trk: what parse_trk converts to world units and what
/// `track video` needs to decode the project's video in the same coordinates.
struct TrkProject {
  std::string source;                 ///< the file (and zip entry) it came from
  std::string video_path;             ///< videoclip/video/path as written ("" when none)
  int video_frame_count = 0;          ///< videoclip/video_framecount (0 when absent)
  TrkClip clip;
  std::vector<TrkCoordFrame> coords;  ///< key frames sorted by frame, "fixed" flags applied
  std::string length_unit = "m";      ///< unit of the world coordinates
  /// PointMass marks on the clip's steps: x, y in image pixels (x right, y down), t in s
  /// (unscaled). Marks off the clip's steps are left out with a warning, as in parse_trk.
  std::vector<track::Track> marks_px;
  std::vector<std::string> warnings;
};

/// Parses the XML of a .trk into the project (marks in pixels). `source` names the file in
/// messages. parse_trk is this followed by the coordinate conversion.
TrkProject parse_trk_project(std::string_view xml, const std::string& source);

/// Parses the XML of a .trk. `source` names the file in messages.
track::TrackSet parse_trk(std::string_view xml, const std::string& source);

/// A .trz read from disk: its project and the archive's entry names (the archive may hold
/// a large video, so it is never read whole).
struct TrzContents {
  TrkProject project;
  std::string trk_entry;              ///< the .trk entry read
  std::vector<std::string> entries;   ///< every entry name in the archive
};

/// Reads the .trk named `entry` (or the first .trk) from the .trz at `path`.
TrzContents read_trz_file(const std::string& path, const std::string& entry = "");

/// Streams zip entry `entry` of the archive at `zip_path` into the new file `out_path`
/// (at most max_bytes); throws InputError naming the archive and entry.
void extract_zip_entry(const std::string& zip_path, const std::string& entry,
                       const std::string& out_path, std::uint64_t max_bytes = 1ull << 34);

/// Reads a .trz (zip bytes): the .trk named `entry`, or the first .trk when entry is empty.
track::TrackSet read_trz(std::string_view zip_bytes, const std::string& source,
                         const std::string& entry = "");

/// What write_trk needs besides the tracks.
struct TrkWriteSpec {
  std::vector<TrkCoordFrame> coords = {TrkCoordFrame{}};  ///< key frames, first at frame 0
  int start_frame = 0;           ///< clip start frame
  int step_size = 1;             ///< clip step size, frames
  int step_count = 0;            ///< clip step count (0: enough for every point)
  double start_time_ms = 0;      ///< time of the start frame, ms
  double frame_duration_ms = 1000.0 / 30;  ///< ms per frame, e.g. 4.1667 at 240 fps
  std::string length_unit = "m"; ///< unit of the tracks' x, y
  /// The video as the project should name it, relative to the .trk's folder ("" = none):
  /// Tracker then opens the project with its video.
  std::string video_path;
  int video_frame_count = 0;     ///< frames of that video (0 = not written)
};

/// A .trk (Tracker 5/6 layout) holding `tracks` as PointMass tracks; each point's frame and
/// world x, y (in spec.length_unit) are stored, converted to pixels with spec.coords; the
/// points' t are ignored (the reader derives t from the frame and the clip).
std::string write_trk(const std::vector<track::Track>& tracks, const TrkWriteSpec& spec);

/// A .trz (zip) holding `trk_xml` as entry `entry_name`, and `files` (entry name, bytes),
/// e.g. the video at the path the project names.
std::string write_trz(const std::string& trk_xml, const std::string& entry_name,
                      const std::vector<std::pair<std::string, std::string>>& files = {});

}  // namespace tribolab::io
