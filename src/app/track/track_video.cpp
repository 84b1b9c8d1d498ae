#include "app/track/track_video.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"

#include "app/common/series_files.hpp"
#include "app/common/series_json.hpp"
#include "app/track/report_track_video.hpp"
#include "app/track/track_import.hpp"
#include "analysis/series.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <cmath>
#include <filesystem>
#include <memory>
#include <system_error>

namespace tribolab::app {

namespace {

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

/// NAME@FRAME=X,Y: the user's mark of track NAME in FRAME (an ellipse's: of its centre).
std::pair<std::string, video::ManualMark> parse_mark(const std::string& text) {
  const std::string where = field("mark") + " " + text.substr(0, 60);
  const auto at = text.find('@'), eq = text.find('=');
  if (at == std::string::npos || eq == std::string::npos || at == 0 || eq < at) {
    throw InputError(where, "expected NAME@FRAME=X,Y (pixels: x right, y down)");
  }
  const double f = io::parse_double(text.substr(at + 1, eq - at - 1), where + " (frame)");
  if (f != std::floor(f) || f < 0 || f > 1e8) throw InputError(where, "the frame after @ must be a whole number from 0");
  const auto xy = numbers(text.substr(eq + 1), 2, where);
  video::ManualMark m;
  m.frame = static_cast<int>(f);
  m.x_px = xy[0];
  m.y_px = xy[1];
  return {text.substr(0, at), m};
}

bool ends_with_trk(const std::string& path) {
  if (path.size() < 4) return false;
  std::string e = path.substr(path.size() - 4);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == ".trk";
}

/// The value of an optional option whose core field reads 0 as "unset": a value given is
/// checked here, so that 0 (or what rounds to it) is refused instead of taken for unset.
template <class T>
T given_or_unset(const std::optional<T>& v, const std::string& name) {
  if (v && !(*v > 0)) throw InputError(field(name), "must be > 0, got " + io::format_number(static_cast<double>(*v)) + " (leave it out for the default)");
  return v.value_or(T{0});
}

video::TrackVideoOptions build_options(const TrackVideoOptions& a) {
  video::TrackVideoOptions o;
  o.source.scale_m_per_px = given_or_unset(a.scale, "scale");
  o.source.axes_deg = a.axes_deg;
  o.source.fps = given_or_unset(a.fps, "fps");
  o.source.time_scale = a.time_scale;
  o.source.zip_entry = a.entry;
  o.point.min_score = a.min_score;
  const int search_px = given_or_unset(a.search, "search");
  const int patch_px = given_or_unset(a.patch, "patch");  // 0: the tracker's own choice
  o.point.patch_px = patch_px > 0 ? patch_px : video::PointTrackerOptions{}.patch_px;
  o.point.search_px = search_px;
  o.path.patch_px = patch_px;
  o.path.search_px = search_px;
  o.path.min_score = a.min_score;
  o.path.max_gap_frames = a.max_gap;
  if (a.point_tracker != "path" && a.point_tracker != "frame") {
    throw InputError(field("point_tracker") + " " + a.point_tracker.substr(0, 60), "expected path or frame");
  }
  o.offline_points = a.point_tracker == "path";
  o.point.max_turn_deg = a.max_turn_deg;
  o.point.max_gap_frames = a.max_gap;
  o.ellipse.min_score = a.ellipse_min_score;
  o.ellipse.max_gap_frames = a.max_gap;
  o.progress = a.progress;
  if (a.report.empty()) o.thumbnails = 0;
  for (const auto& s : a.start) o.targets.push_back(parse_target(s, video::Target::Kind::point, field("start")));
  for (const auto& s : a.ellipse) o.targets.push_back(parse_target(s, video::Target::Kind::ellipse, field("ellipse")));
  for (const auto& name : a.from_track) {
    video::Target t;
    t.name = name;
    t.from_track = name;
    o.targets.push_back(t);
  }
  for (const auto& text : a.mark) {
    auto [name, m] = parse_mark(text);
    const auto t = std::find_if(o.targets.begin(), o.targets.end(), [&name = name](const video::Target& x) { return x.name == name; });
    if (t == o.targets.end()) {
      std::string names;
      for (const auto& x : o.targets) names += (names.empty() ? "'" : ", '") + x.name + "'";
      throw InputError(field("mark") + " " + text.substr(0, 60),
                       "no track named '" + name.substr(0, 40) + "' is followed (" + names + ")");
    }
    t->marks.push_back(m);
  }
  if (!a.calibrate.empty()) {
    const auto v = numbers(a.calibrate, 5, field("calibrate"));
    o.source.calibrate_points = std::make_pair(cv::Point2d(v[0], v[1]), cv::Point2d(v[2], v[3]));
    o.source.calibrate_length_m = v[4];
  }
  if (!a.origin.empty()) {
    const auto v = numbers(a.origin, 2, field("origin"));
    o.source.origin_px = cv::Point2d(v[0], v[1]);
  }
  if (!a.write_trk.empty() && !ends_with_trk(a.write_trk)) {
    throw InputError(field("write_trk") + " " + a.write_trk, "the project file must end in .trk");
  }
  if (a.start.empty() && a.ellipse.empty() && a.from_track.empty())  // a missing required option
    throw MissingOptionError("nothing to track: give " + field("start") + ", " + field("ellipse") + " or " +
                             field("from_track"));
  if (const auto err = o.validate(); !err.empty()) throw InputError(err);
  return o;
}

nlohmann::json summary(const video::TrackVideoResult& r, const TrackVideoOptions& a) {
  const video::VideoInput& in = r.input;
  nlohmann::json j;
  j["input"] = in.input;
  j["video"] = {{"path", in.project_video.empty() ? in.input : in.project_video},
                {"width", in.info.width},
                {"height", in.info.height},
                {"frame_count", in.info.frame_count},
                {"fps", in.info.fps > 0 ? json_number(in.info.fps) : nlohmann::json(nullptr)},
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
      {"m_per_px", in.calibration.calibrated ? json_number(in.calibration.metres_per_unit / c.xscale)
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
                        {"manual_frames", s.manual_frames},
                        {"median_score", s.median_score},
                        {"exposure", s.exposure ? nlohmann::json(*s.exposure) : nlohmann::json(nullptr)}};
    if (s.vs_human) {
      // No marked frame with a position: no distance to state (0 px would read as a perfect track).
      const auto px = [&](double v) { return s.vs_human->frames > 0 ? nlohmann::json(v) : nlohmann::json(nullptr); };
      t["vs_human"] = {{"frames", s.vs_human->frames},
                       {"median_px", px(s.vs_human->median_px)},
                       {"max_px", px(s.vs_human->max_px)},
                       {"marks", s.vs_human->marks},
                       {"p90_px", px(s.vs_human->p90_px)},
                       {"correct_px", s.vs_human->correct_px},
                       {"to_correct", s.vs_human->to_correct},
                       {"confidently_wrong", s.vs_human->confidently_wrong}};
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

/// Everything a tracking depends on but the marks and the output paths (a session is re-used
/// only for the same): the input file (and its size and time), targets, calibration, trackers.
std::string session_key(const TrackVideoOptions& a) {
  std::string k;
  auto add = [&](const std::string& s) { k += std::to_string(s.size()) + ":" + s + ";"; };
  auto num = [&](const std::optional<double>& v) { add(v ? io::format_number(*v) : "-"); };
  add(a.input);
  std::error_code ec;
  const auto size = std::filesystem::file_size(a.input, ec);
  add(ec ? "?" : std::to_string(size));
  const auto time = std::filesystem::last_write_time(a.input, ec);
  add(ec ? "?" : std::to_string(time.time_since_epoch().count()));
  for (const auto* list : {&a.start, &a.ellipse, &a.from_track}) {
    add(std::to_string(list->size()));
    for (const auto& s : *list) add(s);
  }
  num(a.scale);
  add(a.calibrate);
  add(a.origin);
  num(a.axes_deg);
  num(a.fps);
  num(a.time_scale);
  add(a.entry);
  num(a.min_score);
  num(a.patch ? std::optional<double>(*a.patch) : std::nullopt);
  add(a.point_tracker);
  num(a.search ? std::optional<double>(*a.search) : std::nullopt);
  num(a.max_turn_deg);
  num(a.ellipse_min_score);
  num(a.max_gap);
  add(a.report.empty() ? "no report" : "report");  // thumbnails or none
  return k;
}

}  // namespace

TrackVideoResult track_video(const TrackVideoOptions& options) {
  check_output_paths({options.input}, {{"out", options.out}, {"write_trk", options.write_trk}, {"report", options.report}});  // before any work (app/common/output_paths.hpp)
  const video::TrackVideoOptions o = build_options(options);
  if (options.out.empty()) throw MissingOptionError(field("out"), "the output CSV is required");
  // open the outputs first: a bad output path fails before minutes of decoding
  io::AtomicFile csv(options.out);
  std::unique_ptr<io::AtomicFile> trk;
  if (!options.write_trk.empty()) trk = std::make_unique<io::AtomicFile>(options.write_trk);
  std::optional<video::TrackVideoResult> again;
  const std::string key = options.session ? session_key(options) : std::string();
  if (options.session && !options.session->empty() && options.session->key == key) {
    again = video::retrack(*options.session, o.targets);
  }
  video::TrackVideoResult r;
  const bool from_session = again.has_value();
  if (again) {
    r = std::move(*again);
  } else {
    r = video::track_video(options.input, o, options.session.get());
    if (options.session) options.session->key = key;
  }
  video::write_csv(csv.stream(), r);
  if (trk) {
    const io::TrkWriteSpec spec = video::trk_spec(r, options.write_trk, r.warnings);
    trk->stream() << io::write_trk(video::to_track_set(r).tracks, spec);
  }
  if (!options.report.empty()) report::write_html(track_video_report(r), options.report, options.plotly);
  csv.commit();
  if (trk) trk->commit();
  TrackVideoResult result;
  result.json = summary(r, options);
  result.series = std::move(r.series);
  result.from_session = from_session;
  return result;
}

namespace {

/// A series' output folder: an existing folder, or created (its parent must exist).
void ensure_folder(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) {
      throw InputError(field(option) + " " + path,
                       "with several inputs this names a folder (each video's file is written into it), "
                       "but it is a file");
    }
    return;
  }
  if (!fs::create_directory(path, ec) || ec) {
    throw InputError(field(option) + " " + path,
                     "cannot create the folder (" + (ec ? ec.message() : std::string("its parent is missing")) + ")");
  }
}

void remove_quietly(const std::string& path) {
  if (path.empty()) return;
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace

std::string series_output_name(std::size_t index, const std::string& input, std::size_t n, const std::string& extension) {
  std::string name = series_run_file(index, input, n);  // NN_<stem>.html
  return name.substr(0, name.size() - 5) + extension;
}

const Fields<TrackVideoInputsOptions>& track_video_inputs_fields() {
  using S = TrackVideoInputsOptions;
  static const Fields<S> f = [] {
    Fields<S> d;
    for (const Field<TrackVideoOptions>& g : track_video_fields()) {
      if (g.name == "input") {
        d.add("input", &S::input, "",
              g.help + "; several: each tracked with the same options, its outputs named NN_<stem> in the output "
                       "folder (and the write_trk folder)")
            .as(FieldRole::input_files)
            .needed();
      } else if (g.name == "out") {
        d.add_from(&S::each, g).help += " (with several inputs: a folder, created if missing, holding NN_<stem>.csv per video)";
      } else if (g.name == "write_trk") {
        d.add_from(&S::each, g).help += "; with several inputs: a folder holding NN_<stem>.trk per video";
      } else {
        d.add_from(&S::each, g);
      }
    }
    return d;
  }();
  return f;
}

TrackVideoSeries track_video_series(const TrackVideoOptions& base, const std::vector<std::string>& inputs,
                                    const analysis::SeriesOptions& series) {
  namespace fs = std::filesystem;
  if (base.out.empty()) throw MissingOptionError(field("out"), "the output folder is required");
  {
    TrackVideoOptions probe = base;  // the options' own checks, once, before any work
    probe.write_trk.clear();
    (void)build_options(probe);
  }
  ensure_folder(base.out, "out");
  if (!base.write_trk.empty()) ensure_folder(base.write_trk, "write_trk");
  std::string runs_folder;
  if (!base.report.empty()) {
    check_output_paths(inputs, {{"report", base.report}});
    runs_folder = series_runs_folder(base.report);
    std::error_code ec;
    fs::create_directories(runs_folder, ec);
    if (ec) throw InputError(field("report") + " " + base.report, "cannot create " + runs_folder + " (" + ec.message() + ")");
  }
  const std::size_t n = inputs.size();
  std::vector<std::string> reports(n);
  const auto runs = analysis::run_series<nlohmann::json>(
      inputs,
      [&](std::size_t i, const std::string& input) {
        TrackVideoOptions o = base;
        o.input = input;
        o.progress = nullptr;
        o.out = (fs::path(base.out) / series_output_name(i, input, n, ".csv")).string();
        if (!base.write_trk.empty()) o.write_trk = (fs::path(base.write_trk) / series_output_name(i, input, n, ".trk")).string();
        if (!base.report.empty()) o.report = (fs::path(runs_folder) / series_output_name(i, input, n, ".html")).string();
        TrackVideoResult r = track_video(o);
        // A track with no position after its start frame: nothing was tracked in this video.
        for (const auto& sr : r.series) {
          if (sr.rows.size() < 2 || sr.tracked > 1) continue;
          std::string why;
          for (const auto& w : r.json["warnings"])
            if (w.is_string() && w.get<std::string>().rfind("track '" + sr.name + "': lost", 0) == 0) why = w.get<std::string>();
          remove_quietly(o.out), remove_quietly(o.write_trk), remove_quietly(o.report);
          throw InputError(input, "track '" + sr.name + "' was lost in every frame after its start frame" +
                                      (why.empty() ? std::string() : " (" + why + ")") + "; no file written for this video");
        }
        if (!o.report.empty()) reports[i] = o.report;
        return r.json;
      },
      series);
  TrackVideoSeries out;
  out.rows = series_rows(runs, [](const nlohmann::json& j) { return j; });
  out.summary = series_counts(runs);
  out.summary["out_dir"] = base.out;
  out.summary["write_trk_dir"] = base.write_trk.empty() ? nlohmann::json(nullptr) : nlohmann::json(base.write_trk);
  out.summary["report"] = base.report.empty() ? nlohmann::json(nullptr) : nlohmann::json(base.report);
  out.errors = series_errors(runs);
  if (!base.report.empty()) {
    report::Report page;
    page.title = "tribolab: track video, " + std::to_string(n) + " videos";
    page.subtitle = "Each video's tracks, and its own report (linked from its row)";
    report::Table t;
    t.caption = "Videos in the order given; rows, tracked and lost per track; a failed video shows its error";
    t.header = {"video", "CSV", "tracks", "tracked / rows", "lost frames", "error"};
    const std::string folder = fs::path(runs_folder).filename().string();
    for (std::size_t i = 0; i < n; ++i) {
      const auto& row = out.rows[i];
      std::vector<std::string> cells{inputs[i]};
      if (row.contains("error")) {
        cells.insert(cells.end(), {"-", "-", "-", "-", row["error"].get<std::string>()});
        t.links.emplace_back();
      } else {
        std::string names, counts, lost;
        for (const auto& name : row["track_names"]) {
          const auto& tr = row["tracks"][name.get<std::string>()];
          names += (names.empty() ? "" : ", ") + name.get<std::string>();
          counts += (counts.empty() ? "" : ", ") + std::to_string(tr["tracked"].get<int>()) + "/" + std::to_string(tr["rows"].get<int>());
          lost += (lost.empty() ? "" : ", ") + std::to_string(tr["lost"].get<int>());
        }
        cells.insert(cells.end(), {row["out"].get<std::string>(), names, counts, lost, ""});
        const std::string link = folder + "/" + fs::path(reports[i]).filename().string();
        t.links.push_back(report::is_relative_link(link) ? link : std::string());
      }
      t.rows.push_back(std::move(cells));
    }
    page.add_section("Videos").add_table(std::move(t));
    if (out.summary["n_ok"].get<std::size_t>() > 0) report::write_html(page, base.report, base.plotly);
  }
  return out;
}


const ResultKeys& track_video_series_result_keys() {
  static const ResultKeys k = {
      {"n_runs", "", "videos given"}, {"n_ok", "", ""}, {"n_failed", "", ""}, {"failed", "", "videos that failed"},
      {"out_dir", "", "the folder of the CSV files"}, {"write_trk_dir", "", "the folder of the .trk files, null: none"},
      {"report", "", "the series page, null: none"},
  };
  return k;
}

const ResultKeys& track_video_result_keys() {
  static const ResultKeys k = {
      {"input", "", ""}, {"video.path", "", ""}, {"video.width", "px", ""}, {"video.height", "px", ""},
      {"video.frame_count", "", ""}, {"video.fps", "1/s", "as the container says"}, {"video.codec", "", ""},
      {"clip.start_frame", "", ""}, {"clip.step_size", "", ""}, {"clip.step_count", "", ""}, {"frames", "", ""},
      {"fps", "1/s", "frames per second of the time base"}, {"time_base.start_frame", "", ""},
      {"time_base.start_time", "s", ""}, {"time_base.frame_duration", "s", ""}, {"time_base.time_scale", "", ""},
      {"calibration.calibrated", "", ""}, {"calibration.unit", "", "m, or px without a scale"},
      {"calibration.m_per_px", "m/px", "length of a pixel"}, {"calibration.origin_px", "px", ""},
      {"calibration.axes_deg", "deg", ""}, {"calibration.key_frames", "", ""},
      {"track_names", "", ""}, {"tracks.*.kind", "", ""}, {"tracks.*.start_frame", "", ""}, {"tracks.*.rows", "", ""},
      {"tracks.*.tracked", "", ""}, {"tracks.*.lost", "", ""}, {"tracks.*.lost_ranges", "", "[first, last] frames"},
      {"tracks.*.refound_frames", "", ""}, {"tracks.*.manual_frames", "", "frames of the --mark corrections"}, {"tracks.*.median_score", "", ""},
      {"tracks.*.exposure", "", "ellipse: the shutter's fraction of the frame period, read from the blurred edges; null when not read"},
      {"tracks.*.vs_human.frames", "", ""}, {"tracks.*.vs_human.median_px", "px", ""},
      {"tracks.*.vs_human.max_px", "px", ""}, {"tracks.*.vs_human.p90_px", "px", ""},
      {"tracks.*.vs_human.correct_px", "px", "a user corrects a point farther than this"},
      {"tracks.*.vs_human", "", "null without human marks"},
      {"warnings", "", ""}, {"out", "", ""}, {"write_trk", "", ""}, {"report", "", ""},
      {"file", "", "a run of several videos"}, {"error", "", "why the video failed"},
  };
  return k;
}
}  // namespace tribolab::app
