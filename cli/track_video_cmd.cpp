// `tribolab track video`: follow points and balls through a video or a Tracker project's
// video (docs/cli.md#track-video). Binds the options to app::TrackVideoOptions, shows progress
// on a terminal, prints the summary of app::track_video (src/app/track/track_video.hpp).
#include "track_video_cmd.hpp"
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"

#include "app.hpp"
#include "report_option.hpp"
#include "series_cmd.hpp"

#include "app/track/track_video.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace tribolab::cli {

namespace {

/// A progress line on stderr for people watching a terminal (never in pipes or tests),
/// rewritten in place and erased at the end.
class Progress {
 public:
  Progress() : enabled_(::isatty(STDERR_FILENO) == 1) {}
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%60s\r", "");
  }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void operator()(int done, int expected) {
    if (!enabled_ || expected < kLong) return;
    const int percent = static_cast<int>(100.0 * done / expected);
    if (percent == last_) return;
    last_ = percent;
    shown_ = true;
    std::fprintf(stderr, "\rtrack video: frame %d of %d (%d%%)", done, expected, percent);
    std::fflush(stderr);
  }

 private:
  static constexpr int kLong = 200;  ///< frames: shorter clips finish before a line helps
  bool enabled_, shown_ = false;
  int last_ = -1;
};

}  // namespace

void register_track_video(CLI::App& track_area) {
  auto* cmd = track_area.add_subcommand(
      "video", "Track points and balls in a video (or a Tracker .trk/.trz project's video) and "
               "write track,frame,t,x,y,x_px,y_px,score");
  auto o = std::make_shared<TrackVideoOptions>();
  auto as_json = std::make_shared<bool>(false);
  auto inputs = std::make_shared<std::vector<std::string>>();
  cmd->add_option("INPUT", *inputs,
                  "Video file (mp4, mov, avi, ...) or Tracker project .trk/.trz; several: each tracked with "
                  "the same options, its outputs named NN_<stem> in the --out (and --write-trk) folder")
      ->required();
  cmd->add_option("--out", o->out,
                  "Output CSV: track,frame,t,x,y,x_px,y_px,score (with several inputs: a folder, created "
                  "if missing, holding NN_<stem>.csv per video)")
      ->required();
  cmd->add_option("--start", o->start,
                  "Follow a textured point: NAME=X,Y[@FRAME] in image pixels (x right, y down), "
                  "from FRAME (when not given: the clip's first); repeatable");
  cmd->add_option("--ellipse", o->ellipse,
                  "Follow a ball or disc contrasting with its background as an ellipse: "
                  "NAME=X,Y[@FRAME] inside it; gives tracks NAME (centre), NAME.A and NAME.B "
                  "(ends of the major axis); repeatable");
  cmd->add_option("--from-track", o->from_track,
                  "Tracker project: follow this track from its first mark, and compare with its "
                  "further marks; repeatable");
  cmd->add_option("--mark", o->mark,
                  "Correct a track: NAME@FRAME=X,Y in image pixels; the track passes there (reported "
                  "manual, score 1) and is re-tracked from it forward and backward; repeatable");
  cmd->add_option("--scale", o->scale, "Plain video: metres per pixel");
  cmd->add_option("--calibrate", o->calibrate,
                  "Plain video: a stick of known length, X1,Y1,X2,Y2,LENGTH (px, px, px, px, m)");
  cmd->add_option("--origin", o->origin, "World origin in the image, X,Y px (when not given: the bottom-left pixel)");
  cmd->add_option("--axes-deg", o->axes_deg, "World x-axis counter-clockwise from the image x-axis, degrees");
  cmd->add_option("--fps", o->fps, "Frames per second of the video, overriding the container's (or the project's)");
  cmd->add_option("--time-scale", o->time_scale,
                  "Real seconds per video second: 240 fps slow motion played at 30 fps is 0.125");
  cmd->add_option("--entry", o->entry, "For a .trz: the .trk inside to use (when not given: the first)");
  cmd->add_option("--min-score", o->min_score, "Points: below this match score (0..1) a point is lost");
  cmd->add_option("--patch", o->patch,
                  "Points: template side, px, odd (when not given: the object's size with the path "
                  "tracker, 21 with the frame tracker)");
  cmd->add_option("--point-tracker", o->point_tracker,
                  "Points: path (offline: best path through candidates in every frame, default) or "
                  "frame (frame to frame, with rotation search)");
  cmd->add_option("--search", o->search,
                  "Points: search half-width around the prediction, px (when not given: automatic)");
  cmd->add_option("--max-turn-deg", o->max_turn_deg,
                  "Points: largest rotation of the pattern searched per frame, degrees");
  cmd->add_option("--ellipse-min-score", o->ellipse_min_score,
                  "Ellipses: below this edge-fit quality (0..1) the object is lost");
  cmd->add_option("--max-gap", o->max_gap, "Frames the motion model may bridge; beyond, an ellipse is given up and a point is searched for afresh");
  cmd->add_option("--write-trk", o->write_trk,
                  "Also write the tracks as a Tracker project (opens in Tracker with its video; with several "
                  "inputs: a folder holding NN_<stem>.trk per video)");
  add_json_flag(*cmd, *as_json);
  add_report_option(*cmd, o->report, o->plotly);
  declare_results(*cmd, track_video_result_keys());
  declare_series_results(*cmd, track_video_series_result_keys());
  cmd->callback([o, as_json, inputs] {
    if (inputs->size() == 1) {  // exactly the single-video command
      Progress progress;
      TrackVideoOptions options = *o;
      options.input = inputs->front();
      options.progress = [&progress](int done, int expected) { progress(done, expected); };
      print_result(track_video(options).json, *as_json, track_video_result_keys());
      return;
    }
    // Several videos (docs/cli.md#several-videos): one row each, in order; one that fails
    // never loses the others' files; the exit status says whether any failed.
    const TrackVideoSeries series = track_video_series(*o, *inputs, cli_series_options("videos"));
    print_series(series.rows, series.summary, *as_json, {"out", "frames", "track_names"}, track_video_result_keys(),
                 track_video_series_result_keys());
    // Field marks in the messages spelled as flags (--from-track), as for one video.
    for (const auto& row : spelled_for_cli(series.rows))
      if (row.contains("error")) std::cerr << "tribolab: error: " << row["error"].get<std::string>() << '\n';
    std::vector<std::string> errors;
    for (const auto& e : spelled_for_cli(nlohmann::json(series.errors))) errors.push_back(e.get<std::string>());
    finish_series(inputs->size(), errors);
  });
}

}  // namespace tribolab::cli
