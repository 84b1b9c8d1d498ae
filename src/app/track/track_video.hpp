// `tribolab track video` (docs/cli.md#track-video): follow points and balls through a video or
// a Tracker project's video; write the table track,frame,t,x,y,x_px,y_px,score, optionally a
// Tracker project and a report. Options in the CLI's text form (NAME=X,Y[@FRAME], X1,Y1,...)
// are parsed here, so every front end accepts the same words.
#pragma once

#include "analysis/series.hpp"
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

struct TrackVideoResult {
  nlohmann::json json;                 ///< what `track video --json` prints
  /// Per output track: name, kind and rows (frame, t (s), x, y (m, px uncalibrated), x_px,
  /// y_px (px), score, lost), the pattern/ellipse angle (rad), lost ranges.
  std::vector<video::TrackedSeries> series;
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

}  // namespace tribolab::app
