// `tribolab track video`: follow points and balls through a video or a Tracker project's
// video (docs/cli.md#track-video). Text -> TrackVideoOptions -> video::track_video -> CSV,
// JSON, Tracker project.
#include "track_video_cmd.hpp"

#include "app.hpp"
#include "report_option.hpp"
#include "app/report_track_video.hpp"

#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"
#include "video/track_video.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace tribolab::cli {

namespace {

struct Args {
  std::string input, out, write_trk, report;
  std::vector<std::string> start, ellipse, from_track;
  std::string calibrate, origin;
  video::TrackVideoOptions options;
  bool as_json = false;
};

std::vector<double> numbers(const std::string& text, std::size_t count, const std::string& where) {
  const auto parts = io::split(text, ',');
  if (parts.size() != count) {
    throw InputError(where, "expected " + std::to_string(count) + " comma-separated numbers, got '" +
                                text.substr(0, 60) + "'");
  }
  std::vector<double> v;
  for (const auto& p : parts) v.push_back(io::parse_double(p, where));
  return v;
}

/// NAME=X,Y[@FRAME]
video::Target parse_target(const std::string& text, video::Target::Kind kind, const std::string& opt) {
  const auto eq = text.find('=');
  const std::string where = opt + " " + text.substr(0, 60);
  if (eq == std::string::npos || eq == 0) {
    throw InputError(where, "expected NAME=X,Y or NAME=X,Y@FRAME (pixels: x right, y down)");
  }
  video::Target t;
  t.kind = kind;
  t.name = text.substr(0, eq);
  std::string pos = text.substr(eq + 1);
  if (const auto at = pos.find('@'); at != std::string::npos) {
    const double f = io::parse_double(pos.substr(at + 1), where + " (frame)");
    if (f != std::floor(f) || f < 0 || f > 1e8) {
      throw InputError(where, "the frame after @ must be a whole number from 0");
    }
    t.frame = static_cast<int>(f);
    pos = pos.substr(0, at);
  }
  const auto xy = numbers(pos, 2, where);
  t.x_px = xy[0];
  t.y_px = xy[1];
  return t;
}

bool ends_with_trk(const std::string& path) {
  if (path.size() < 4) return false;
  std::string e = path.substr(path.size() - 4);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == ".trk";
}

void build_options(Args& a) {
  auto& o = a.options;
  for (const auto& s : a.start) o.targets.push_back(parse_target(s, video::Target::Kind::point, "--start"));
  for (const auto& s : a.ellipse) o.targets.push_back(parse_target(s, video::Target::Kind::ellipse, "--ellipse"));
  for (const auto& name : a.from_track) {
    video::Target t;
    t.name = name;
    t.from_track = name;
    o.targets.push_back(t);
  }
  if (!a.calibrate.empty()) {
    const auto v = numbers(a.calibrate, 5, "--calibrate");
    o.source.calibrate_points = std::make_pair(cv::Point2d(v[0], v[1]), cv::Point2d(v[2], v[3]));
    o.source.calibrate_length_m = v[4];
  }
  if (!a.origin.empty()) {
    const auto v = numbers(a.origin, 2, "--origin");
    o.source.origin_px = cv::Point2d(v[0], v[1]);
  }
  if (!a.write_trk.empty() && !ends_with_trk(a.write_trk)) {
    throw InputError("--write-trk " + a.write_trk, "the project file must end in .trk");
  }
  if (const auto err = o.validate(); !err.empty()) throw InputError(err);
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json summary(const video::TrackVideoResult& r, const Args& a) {
  const video::VideoInput& in = r.input;
  nlohmann::json j;
  j["input"] = in.input;
  j["video"] = {{"path", in.project_video.empty() ? in.input : in.project_video},
                {"width", in.info.width},
                {"height", in.info.height},
                {"frame_count", in.info.frame_count},
                {"fps", number(in.info.fps)},
                {"codec", in.info.codec}};
  j["clip"] = {{"start_frame", in.clip.start_frame},
               {"step_size", in.clip.step_size},
               {"step_count", in.clip.step_count}};
  j["frames"] = r.frames;
  j["fps"] = 1 / in.time.frame_duration_s;
  j["time_base"] = {{"start_frame", in.time.start_frame},
                    {"start_time", in.time.start_time_s},
                    {"frame_duration", in.time.frame_duration_s},
                    {"time_scale", in.time.time_scale}};
  const io::TrkCoordFrame& c = in.calibration.coords.front();
  j["calibration"] = {
      {"calibrated", in.calibration.calibrated},
      {"unit", in.calibration.calibrated ? "m" : "px"},
      {"m_per_px", in.calibration.calibrated ? number(in.calibration.metres_per_unit / c.xscale)
                                             : nlohmann::json(nullptr)},
      {"origin_px", {c.origin_x, c.origin_y}},
      {"axes_deg", c.angle_deg},
      {"key_frames", in.calibration.coords.size()}};
  nlohmann::json tracks = nlohmann::json::object();
  nlohmann::json names = nlohmann::json::array();
  for (const auto& s : r.series) {
    names.push_back(s.name);
    nlohmann::json lost = nlohmann::json::array();
    int lost_rows = 0;
    for (const auto& [f0, f1] : s.lost_ranges) lost.push_back({f0, f1});
    for (const auto& row : s.rows) lost_rows += row.lost;
    nlohmann::json t = {{"kind", s.kind == video::Target::Kind::ellipse ? "ellipse" : "point"},
                        {"start_frame", s.rows.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.rows.front().frame)},
                        {"rows", s.rows.size()},
                        {"tracked", s.tracked},
                        {"lost", lost_rows},
                        {"lost_ranges", lost},
                        {"refound_frames", s.refound_frames},
                        {"median_score", s.median_score}};
    if (s.vs_human) {
      t["vs_human"] = {{"frames", s.vs_human->frames},
                       {"median_px", s.vs_human->median_px},
                       {"max_px", s.vs_human->max_px}};
    } else {
      t["vs_human"] = nullptr;
    }
    tracks[s.name] = t;
  }
  j["track_names"] = names;
  j["tracks"] = tracks;
  j["warnings"] = r.warnings;
  j["out"] = a.out;
  j["write_trk"] = a.write_trk.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.write_trk);
  j["report"] = a.report.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.report);
  return j;
}

/// A progress line on stderr for people watching a terminal (never in pipes or tests),
/// rewritten in place and erased at the end.
class Progress {
 public:
  Progress() : enabled_(::isatty(STDERR_FILENO) == 1) {}
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%60s\r", "");
  }
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

void run(Args& a) {
  build_options(a);
  Progress progress;
  a.options.progress = [&progress](int done, int expected) { progress(done, expected); };
  if (a.report.empty()) a.options.thumbnails = 0;
  // open the outputs first: a bad output path fails before minutes of decoding
  io::AtomicFile csv(a.out);
  std::unique_ptr<io::AtomicFile> trk;
  if (!a.write_trk.empty()) trk = std::make_unique<io::AtomicFile>(a.write_trk);
  video::TrackVideoResult r = video::track_video(a.input, a.options);
  video::write_csv(csv.stream(), r);
  if (trk) {
    const io::TrkWriteSpec spec = video::trk_spec(r, a.write_trk, r.warnings);
    trk->stream() << io::write_trk(video::to_track_set(r).tracks, spec);
  }
  write_report_if_requested(a.report, [&] { return track_video_report(r); });
  csv.commit();
  if (trk) trk->commit();
  print_result(summary(r, a), a.as_json);
}

}  // namespace

void register_track_video(CLI::App& track_area) {
  auto* cmd = track_area.add_subcommand(
      "video", "Track points and balls in a video (or a Tracker .trk/.trz project's video) and "
               "write track,frame,t,x,y,x_px,y_px,score");
  auto a = std::make_shared<Args>();
  cmd->add_option("INPUT", a->input, "Video file (mp4, mov, avi, ...) or Tracker project .trk/.trz")->required();
  cmd->add_option("--out", a->out, "Output CSV: track,frame,t,x,y,x_px,y_px,score")->required();
  cmd->add_option("--start", a->start,
                  "Follow a textured point: NAME=X,Y[@FRAME] in image pixels (x right, y down), "
                  "from FRAME (default the clip's first); repeatable");
  cmd->add_option("--ellipse", a->ellipse,
                  "Follow a ball or disc contrasting with its background as an ellipse: "
                  "NAME=X,Y[@FRAME] inside it; gives tracks NAME (centre), NAME.A and NAME.B "
                  "(ends of the major axis); repeatable");
  cmd->add_option("--from-track", a->from_track,
                  "Tracker project: follow this track from its first mark, and compare with its "
                  "further marks; repeatable");
  cmd->add_option("--scale", a->options.source.scale_m_per_px, "Plain video: metres per pixel");
  cmd->add_option("--calibrate", a->calibrate,
                  "Plain video: a stick of known length, X1,Y1,X2,Y2,LENGTH (px, px, px, px, m)");
  cmd->add_option("--origin", a->origin, "World origin in the image, X,Y px (default the bottom-left pixel)");
  cmd->add_option("--axes-deg", a->options.source.axes_deg,
                  "World x-axis counter-clockwise from the image x-axis, degrees (default 0)");
  cmd->add_option("--fps", a->options.source.fps,
                  "Frames per second of the video, overriding the container's (or the project's)");
  cmd->add_option("--time-scale", a->options.source.time_scale,
                  "Real seconds per video second: 240 fps slow motion played at 30 fps is 0.125 (default 1)");
  cmd->add_option("--entry", a->options.source.zip_entry, "For a .trz: the .trk inside to use (default the first)");
  cmd->add_option("--min-score", a->options.point.min_score,
                  "Points: below this match score (0..1) a point is lost (default 0.6)");
  cmd->add_option("--patch", a->options.point.patch_px, "Points: template side, px, odd (default 21)");
  cmd->add_option("--search", a->options.point.search_px,
                  "Points: search half-width around the prediction, px (default automatic)");
  cmd->add_option("--max-turn-deg", a->options.point.max_turn_deg,
                  "Points: largest rotation of the pattern searched per frame, degrees (default 40)");
  cmd->add_option("--ellipse-min-score", a->options.ellipse.min_score,
                  "Ellipses: below this edge-fit quality (0..1) the object is lost (default 0.6)");
  cmd->add_option("--max-gap", a->options.point.max_gap_frames,
                  "Frames the motion model may bridge; beyond, an ellipse is given up and a point is searched for afresh");
  cmd->add_option("--write-trk", a->write_trk,
                  "Also write the tracks as a Tracker project (opens in Tracker with its video)");
  add_json_flag(*cmd, a->as_json);
  add_report_option(*cmd, a->report);
  cmd->callback([a, cmd] {
    if (cmd->count("--max-gap") > 0) a->options.ellipse.max_gap_frames = a->options.point.max_gap_frames;
    run(*a);
  });
}

}  // namespace tribolab::cli
