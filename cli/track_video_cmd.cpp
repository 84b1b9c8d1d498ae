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
  auto io = std::make_shared<TrackVideoInputsOptions>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *io, track_video_inputs_fields(), track_video_result_keys());
  add_json_flag(*cmd, *as_json);
  const std::shared_ptr<TrackVideoOptions> o(io, &io->each);
  const std::shared_ptr<std::vector<std::string>> inputs(io, &io->input);
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
      if (row.contains("error")) diagnostics() << "tribolab: error: " << row["error"].get<std::string>() << '\n';
    std::vector<std::string> errors;
    for (const auto& e : spelled_for_cli(nlohmann::json(series.errors))) errors.push_back(e.get<std::string>());
    finish_series(inputs->size(), errors);
  });
}

}  // namespace tribolab::cli
