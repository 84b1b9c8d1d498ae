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
// Lengths are returned in the file's unit and times unscaled; read_tracks (track_import.hpp)
// converts. Numbers with a decimal comma are accepted. Errors name the element path.
#pragma once

#include "track/track.hpp"

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

/// Parses the XML of a .trk. `source` names the file in messages.
track::TrackSet parse_trk(std::string_view xml, const std::string& source);

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
};

/// A .trk (Tracker 5/6 layout) holding `tracks` as PointMass tracks; each point's frame and
/// world x, y (in spec.length_unit) are stored, converted to pixels with spec.coords; the
/// points' t are ignored (the reader derives t from the frame and the clip).
std::string write_trk(const std::vector<track::Track>& tracks, const TrkWriteSpec& spec);

/// A .trz (zip) holding `trk_xml` as entry `entry_name`.
std::string write_trz(const std::string& trk_xml, const std::string& entry_name);

}  // namespace tribolab::io
