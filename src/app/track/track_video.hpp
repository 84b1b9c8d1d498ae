// `tribolab track video` (docs/cli.md#track-video): follow points and balls through a video or
// a Tracker project's video; write the table track,frame,t,x,y,x_px,y_px,score, optionally a
// Tracker project and a report. Options in the CLI's text form (NAME=X,Y[@FRAME], X1,Y1,...)
// are parsed here, so every front end accepts the same words.
#pragma once

#include "analysis/series.hpp"
#include "app/common/option_fields.hpp"
#include "video/track_video.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

struct TrackVideoOptions {
  std::string input;                   ///< video file or Tracker project .trk/.trz
  std::string out;                     ///< CSV track,frame,t,x,y,x_px,y_px,score; required
  std::vector<std::string> start;      ///< points: NAME=X,Y[@FRAME], image px (x right, y down)
  std::vector<std::string> ellipse;    ///< balls/discs: NAME=X,Y[@FRAME] inside the object, px
  std::vector<std::string> from_track; ///< Tracker project tracks to follow from their first mark
  std::vector<std::string> mark;       ///< corrections: NAME@FRAME=X,Y, image px; the track passes there (manual, score 1)
  std::optional<double> scale;         ///< plain video: metres per pixel
  std::string calibrate;               ///< plain video: X1,Y1,X2,Y2,LENGTH (px, px, px, px, m)
  std::string origin;                  ///< world origin in the image, X,Y px; empty: bottom-left pixel
  double axes_deg = video::SourceOptions{}.axes_deg;     ///< world x-axis from image x-axis, ccw, degrees
  std::optional<double> fps;           ///< frames per second, overriding the container's/project's, 1/s
  double time_scale = video::SourceOptions{}.time_scale;  ///< real s per video s (slow motion)
  std::string entry;                   ///< .trz: the .trk inside to use; empty: the first
  double min_score = video::PointTrackerOptions{}.min_score;  ///< points: lost below this match score (0..1)
  std::optional<int> patch;            ///< points: template side, px, odd; unset: 21 (frame), the object's size (path)
  std::string point_tracker = "path";  ///< points: "path" (offline, best path) or "frame" (frame to frame)
  std::optional<int> search;           ///< points: search half-width around the prediction, px; unset: automatic
  double max_turn_deg = video::PointTrackerOptions{}.max_turn_deg;  ///< points: largest rotation per frame, degrees
  double ellipse_min_score = video::EllipseTrackerOptions{}.min_score;  ///< ellipses: lost below this fit quality (0..1)
  int max_gap = video::PointTrackerOptions{}.max_gap_frames;  ///< frames the motion model may bridge
  std::string write_trk;               ///< also a Tracker project (.trk); empty: not written
  std::string report;                  ///< HTML report; empty: not written
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
  /// Called after each frame with (frames done, frames expected); may be empty.
  std::function<void(int, int)> progress;
  /// Kept between runs (the studio): a run whose options differ from the session's only in
  /// `mark` re-tracks from it (video::retrack: no decoding, no search) when it can; every run
  /// leaves its tracking there. Empty: track afresh.
  std::shared_ptr<video::TrackSession> session;
};

/// The declaration of every option of `track video` for one video (app/common/option_fields.hpp):
/// Python and the several-video command line (track_video_inputs_fields) bind from it.
inline const Fields<TrackVideoOptions>& track_video_fields() {
  using O = TrackVideoOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("input", &O::input, "", "video file (mp4, mov, avi, ...) or Tracker project .trk/.trz")
        .as(FieldRole::input_files)
        .needed();
    d.add("out", &O::out, "", "output CSV: track,frame,t,x,y,x_px,y_px,score").as(FieldRole::output_path).needed();
    d.add("start", &O::start, "",
          "follow a textured point: NAME=X,Y[@FRAME] in image pixels (x right, y down), from FRAME (when not given: "
          "the clip's first); repeatable");
    d.add("ellipse", &O::ellipse, "",
          "follow a ball or disc contrasting with its background as an ellipse: NAME=X,Y[@FRAME] inside it; gives "
          "tracks NAME (centre), NAME.A and NAME.B (ends of the major axis); repeatable");
    d.add("from_track", &O::from_track, "",
          "Tracker project: follow this track from its first mark, and compare with its further marks; repeatable");
    d.add("mark", &O::mark, "",
          "correct a track: NAME@FRAME=X,Y in image pixels; the track passes there (reported manual, score 1) and "
          "is re-tracked from it forward and backward (a point's look there searched for in the frames around it); "
          "repeatable");
    d.add("scale", &O::scale, "m/px", "plain video: metres per pixel");
    d.add("calibrate", &O::calibrate, "", "plain video: a stick of known length, X1,Y1,X2,Y2,LENGTH (px, px, px, px, m)");
    d.add("origin", &O::origin, "", "world origin in the image, X,Y px (when not given: the bottom-left pixel)");
    d.add("axes_deg", &O::axes_deg, "deg", "world x-axis counter-clockwise from the image x-axis");
    d.add("fps", &O::fps, "1/s", "frames per second of the video, overriding the container's (or the project's)");
    d.add("time_scale", &O::time_scale, "", "real seconds per video second: 240 fps slow motion played at 30 fps is 0.125");
    d.add("entry", &O::entry, "", "for a .trz: the .trk inside to use (when not given: the first)");
    d.add("min_score", &O::min_score, "", "points: below this match score (0..1) a point is lost");
    d.add("patch", &O::patch, "px",
          "points: template side, odd (when not given: the object's size with the path tracker, 21 with the frame "
          "tracker)");
    d.add("point_tracker", &O::point_tracker, "",
          "points: path (offline: best path through candidates in every frame, default) or frame (frame to frame, "
          "with rotation search)")
        .one_of({"path", "frame"});
    d.add("search", &O::search, "px", "points: search half-width around the prediction (when not given: automatic)");
    d.add("max_turn_deg", &O::max_turn_deg, "deg", "points: largest rotation of the pattern searched per frame");
    d.add("ellipse_min_score", &O::ellipse_min_score, "", "ellipses: below this edge-fit quality (0..1) the object is lost");
    d.add("max_gap", &O::max_gap, "",
          "frames the motion model may bridge; beyond, an ellipse is given up and a point is searched for afresh");
    d.add("write_trk", &O::write_trk, "",
          "also write the tracks as a Tracker project, which opens in Tracker with its video").as(FieldRole::output_path);
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

struct TrackVideoResult {
  nlohmann::json json;                 ///< what `track video --json` prints
  /// Per output track: name, kind and rows (frame, t (s), x, y (m, px uncalibrated), x_px,
  /// y_px (px), score, lost), the pattern/ellipse angle (rad), lost ranges.
  std::vector<video::TrackedSeries> series;
  /// Concluded from `session` without decoding (video::retrack): a new mark's look was not
  /// searched for (PathTracker::add_look); tracking afresh would.
  bool from_session = false;
};

/// Parses and validates the options (InputError naming --start, --calibrate, --origin,
/// --write-trk, --fps, ...), opens the outputs, tracks, writes CSV, project and report
/// (all or nothing) and summarises.
TrackVideoResult track_video(const TrackVideoOptions& options);

/// Several videos in one call (docs/cli.md#track-video, "Several videos").
struct TrackVideoSeries {
  nlohmann::json rows;      ///< per input, in order: {"file", ...the single-video object} or {"file", "error"}
  nlohmann::json summary;   ///< n_runs, n_ok, n_failed, failed, out_dir, write_trk_dir, report
  std::vector<std::string> errors;  ///< the failed inputs' located errors, in order
};

/// The file name of input `index` (0-based) of `n` inputs in a series' output folder:
/// "NN_<stem><extension>" (NN = index + 1 zero-padded to the width of n; characters other
/// than letters, digits, '.', '-', '_' in the stem replaced by '_'), as the runs' reports of
/// the other several-file commands are named.
std::string series_output_name(std::size_t index, const std::string& input, std::size_t n, const std::string& extension);

/// Tracks every input with the same options (`base.input` is ignored). `base.out` (and
/// `base.write_trk` when given) name folders, created when missing (their parent must exist);
/// input i writes series_output_name(i, input, n, ".csv") (".trk") there. `base.report`, when
/// given, is a series page linking each video's own report in <stem>_runs/ beside it. Inputs
/// run in parallel; one that fails (missing, corrupt, a start outside the image, a track lost
/// in every frame after its start) is a row with its error and leaves no file of its own,
/// never the others'. Throws InputError only for bad output folders or options (before any work).
/// `series`: threads and progress callback (analysis::SeriesOptions; default: all cores, none).
TrackVideoSeries track_video_series(const TrackVideoOptions& base, const std::vector<std::string>& inputs,
                                    const analysis::SeriesOptions& series = {});

/// `track video INPUT...` on the command line: one video, or several tracked with the same options.
struct TrackVideoInputsOptions {
  std::vector<std::string> input;  ///< videos or Tracker projects (required); several: a series
  TrackVideoOptions each;          ///< every option shared by the inputs (its `input` is not used)
};

/// The declaration of `track video INPUT...` (the command line binds from it): the one-video
/// fields (track_video_fields) in their order, `input` as a list, and `out`/`write_trk` saying
/// what they name with several inputs (a folder).
const Fields<TrackVideoInputsOptions>& track_video_inputs_fields();

}  // namespace tribolab::app
