#include "studio/workbench.hpp"

#include "app/bounce/bounce_analyze.hpp"
#include "app/bounce/bounce_series.hpp"
#include "app/incline/incline_analyze.hpp"
#include "app/common/result_keys.hpp"
#include "app/common/spelled_json.hpp"
#include "app/track/track_kinematics.hpp"
#include "app/track/track_rigid_body.hpp"
#include "app/track/track_video.hpp"
#include "io/atomic_file.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "studio/form_values.hpp"
#include "studio/guard.hpp"
#include "studio/upload.hpp"
#include "video/codec.hpp"
#include "video/source.hpp"

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>  // the cv::IMWRITE_* names; encoding is video/codec.hpp's

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

namespace tribolab::studio {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The series of a tracking as the page draws them: rows with image and world positions,
/// score and lost flag; NaN positions of lost rows become null.
json series_json(const std::vector<video::TrackedSeries>& series) {
  json a = json::array();
  for (const auto& s : series) {
    json rows = json::array();
    for (std::size_t i = 0; i < s.rows.size(); ++i) {
      const video::TrackedRow& r = s.rows[i];
      // An ellipse's orientation (centre to end A, counter-clockwise on the screen), deg; a
      // point tracked by the path tracker has no angle of its own (null).
      const double angle = s.kind == video::Target::Kind::ellipse && i < s.angle_rad.size() && !r.lost
                               ? s.angle_rad[i] * 180 / std::numbers::pi : std::nan("");
      rows.push_back({{"frame", r.frame}, {"t", r.t}, {"x", r.x}, {"y", r.y}, {"x_px", r.x_px}, {"y_px", r.y_px},
                      {"angle_deg", std::isfinite(angle) ? json(angle) : json(nullptr)},
                      {"score", r.score}, {"lost", r.lost}, {"manual", r.manual}});
    }
    a.push_back({{"name", s.name},
                 {"kind", s.kind == video::Target::Kind::point ? "point" : "ellipse"},
                 {"rows", rows},
                 {"lost_ranges", s.lost_ranges},
                 {"manual_frames", s.manual_frames},
                 {"tracked", s.tracked},
                 {"median_score", s.median_score}});
  }
  return a;
}

/// The input group's fields the form leaves out: the studio's tracks CSV is already in seconds
/// (after the time scale) and metres, and is not a .trz.
bool set_by_the_studio(const std::string& name) {
  return name == "time_scale" || name == "length_unit" || name == "entry";
}

}  // namespace

Workbench::Workbench(fs::path root) : root_(fs::canonical(root)) {}

class Workbench::Action {
 public:
  Action(Workbench& wb, const char* what) : wb_(wb) {
    wb_.cancel_ = false;
    wb_.done_ = 0;
    wb_.expected_ = 0;
    wb_.action_ = what;
    wb_.running_ = true;
  }
  ~Action() {
    wb_.running_ = false;
    wb_.cancel_ = false;
  }
  Action(const Action&) = delete;
  Action& operator=(const Action&) = delete;

 private:
  Workbench& wb_;
};

void Workbench::step(int done, int expected) {
  done_ = done;
  expected_ = expected;
  if (cancel_) throw InputError(std::string(action_.load()) + " cancelled: the project is as it was before");
}

json Workbench::progress() {
  const bool running = running_;
  return {{"running", running}, {"action", running ? action_.load() : ""}, {"done", done_.load()},
          {"expected", expected_.load()}};
}

json Workbench::cancel() {
  const bool running = running_;
  if (running) cancel_ = true;
  return {{"cancelling", running}};
}

fs::path Workbench::beside(const std::string& suffix) const {
  const fs::path p = file_.parent_path() / (file_.filename().string() + suffix);
  // The file is inside the folder; a symlink of this name pointing out of it is refused.
  const Confined c = confine(root_, relative(p));
  if (!c.problem.empty()) throw InputError(relative(p), "will not be written: " + c.problem);
  return p;
}

std::string Workbench::relative(const fs::path& p) const { return p.lexically_relative(root_).generic_string(); }

void Workbench::require_open() const {
  if (file_.empty()) throw InputError("open a video or a Tracker project first");
}

json Workbench::files() {
  json list = json::array();
  std::vector<std::string> names;
  std::error_code ec;
  // The folder's files, then those uploaded from the page (uploads/NAME).
  for (const std::string& folder : {std::string(), std::string(kUploadFolder) + "/"}) {
    std::vector<std::string> here;
    for (const auto& entry : fs::directory_iterator(root_ / folder, ec)) {
      const std::string name = folder + entry.path().filename().string();
      if (!studio_can_open(entry.path())) continue;
      const Confined c = confine(root_, name);  // a symlink out of the folder is not listed
      if (!c.problem.empty() || !fs::is_regular_file(c.path, ec)) continue;
      here.push_back(name);
    }
    std::sort(here.begin(), here.end());
    names.insert(names.end(), here.begin(), here.end());
  }
  // Those tracked in the studio (FILE.tracks.csv beside them): what a series can take.
  json tracked = json::array();
  for (const auto& n : names) {
    list.push_back(n);
    const Confined c = confine(root_, n + ".tracks.csv");
    if (c.problem.empty() && fs::is_regular_file(c.path, ec)) tracked.push_back(n);
  }
  return {{"folder", root_.filename().string()}, {"files", list}, {"tracked", tracked}};
}

json Workbench::open(const fs::path& file) {
  Action action(*this, "opening");
  video::VideoInput input = video::open_input(file.string(), video::SourceOptions{});
  video::FrameReader reader(input);
  const int expected = reader.expected_steps();
  std::vector<std::string> jpeg;
  json frames = json::array();
  std::size_t total = 0;
  video::Frame f;
  while (reader.next(f)) {
    const std::vector<unsigned char> buf = video::encode_image(".jpg", f.bgr, {cv::IMWRITE_JPEG_QUALITY, 90});
    if (buf.empty())
      throw InputError(file.string(), fmt::format("frame {} could not be encoded as JPEG", f.index));
    total += buf.size();
    if (total > kMaxFrameBytes)
      throw InputError(file.string(), fmt::format("the clip is too long for the studio (more than {} MB of frames at "
                                                  "frame {}); cut it, or track it with `track video`",
                                                  kMaxFrameBytes >> 20, f.index));
    jpeg.emplace_back(buf.begin(), buf.end());
    frames.push_back({{"frame", f.index}, {"t", f.t}});
    step(static_cast<int>(jpeg.size()), std::max(expected, static_cast<int>(jpeg.size())));
  }
  if (jpeg.empty()) throw InputError(file.string(), "the clip holds no frame");
  file_ = file;
  jpeg_ = std::move(jpeg);
  frames_ = std::move(frames);
  width_ = input.info.width;
  height_ = input.info.height;
  // (An image sequence states no frame rate: null.)
  const json fps = input.info.fps > 0 ? json(input.info.fps) : json(nullptr);
  video_ = {{"width", input.info.width}, {"height", input.info.height}, {"fps", fps},
            {"codec", input.info.codec}, {"calibrated", input.calibration.calibrated}};
  // The coordinate system the file brings (a Tracker project's, or a plain video's default:
  // origin at the bottom-left pixel, x right, y up), drawn by the page until one is set.
  const io::TrkCoordFrame& axes = input.calibration.coords.front();
  video_["axes"] = {{"origin_px", {axes.origin_x, axes.origin_y}}, {"axes_deg", axes.angle_deg}};
  calibration_ = {};
  session_ = std::make_shared<video::TrackSession>();
  looks_pending_ = false;
  decoded_marks_.clear();
  starts_.clear();
  tracks_ = json::object();
  analysis_ = nullptr;
  // The autosave of an earlier session, if any: the clicks, calibration, tracks and analysis.
  std::ifstream saved(beside(".studio.json"));
  if (saved) {
    std::stringstream text;
    text << saved.rdbuf();
    const json j = json::parse(text.str(), nullptr, false);
    const std::string where = relative(beside(".studio.json"));
    if (j.is_discarded() || !j.is_object()) throw InputError(where, "the autosave is not a JSON object: fix or delete it");
    try {
      if (j.contains("calibration")) calibration_ = calibration_from_json(j["calibration"]);
      for (const json& s : j.value("starts", json::array())) starts_.push_back(start_from_json(s));
    } catch (const InputError& e) {
      throw InputError(where, e.what());
    }
    tracks_ = j.value("tracks", json::object());
    analysis_ = j.value("analysis", json(nullptr));
  }
  return state();
}

std::string Workbench::frame_jpeg(int step) {
  require_open();
  if (step < 0 || step >= static_cast<int>(jpeg_.size()))
    throw InputError(fmt::format("frame step {} is outside the clip's {} steps", step, jpeg_.size()));
  return jpeg_[static_cast<std::size_t>(step)];
}

json Workbench::calibrate(const CalibrationInput& c) {
  require_open();
  Action action(*this, "calibrating");
  if (c.stick_px && !(c.stick_length_m > 0)) throw InputError("'length' of the stick must be positive, m");
  if (c.stick_px && std::hypot((*c.stick_px)[2] - (*c.stick_px)[0], (*c.stick_px)[3] - (*c.stick_px)[1]) < 1)
    throw InputError("the two ends of the stick are less than a pixel apart");
  if (c.fps && !(*c.fps > 0)) throw InputError("'fps' must be positive, 1/s");
  if (!(c.time_scale > 0)) throw InputError("'time_scale' must be positive");
  if (!(std::abs(c.axes_deg) <= ranges::angle_deg.hi))
    throw InputError(fmt::format("'axes_deg' must be an angle from {} to {} deg", ranges::angle_deg.lo, ranges::angle_deg.hi));
  const CalibrationInput before = calibration_;
  calibration_ = c;
  try {
    if (!starts_.empty()) run_tracks();  // the tracks in the new world units
  } catch (...) {
    calibration_ = before;
    throw;
  }
  autosave();
  return state();
}

json Workbench::track(const TrackStart& start) {
  require_open();
  Action action(*this, "tracking");
  const std::vector<TrackStart> before = starts_;
  auto same = std::find_if(starts_.begin(), starts_.end(), [&](const TrackStart& s) { return s.name == start.name; });
  if (same != starts_.end()) {
    // A new click on a track restarts it there; its marks after the new start are kept.
    std::vector<TrackMark> kept;
    for (const TrackMark& m : same->marks)
      if (m.frame > start.frame) kept.push_back(m);
    *same = start;
    if (same->marks.empty()) same->marks = kept;
  } else
    starts_.push_back(start);
  try {
    run_tracks();
  } catch (...) {
    starts_ = before;
    throw;
  }
  autosave();
  return state();
}

json Workbench::mark(const MarkInput& m) {
  require_open();
  Action action(*this, "re-tracking");
  auto start = std::find_if(starts_.begin(), starts_.end(), [&](const TrackStart& s) { return s.name == m.track; });
  if (start == starts_.end()) {
    std::string names;
    for (const auto& s : starts_) names += (names.empty() ? "'" : ", '") + s.name + "'";
    throw InputError(fmt::format("no track named '{}'{}", m.track,
                                 names.empty() ? ": start one by clicking the object" : "; the tracks: " + names));
  }
  const bool in_clip = std::any_of(frames_.begin(), frames_.end(), [&](const json& f) { return f["frame"] == m.frame; });
  if (!in_clip)
    throw InputError(fmt::format("frame {} is not one of the clip's frames ({} to {})", m.frame,
                                 frames_.front()["frame"].get<int>(), frames_.back()["frame"].get<int>()));
  if (!m.remove && !(m.x_px >= 0 && m.y_px >= 0 && m.x_px <= width_ - 1 && m.y_px <= height_ - 1))
    throw InputError(fmt::format("the mark ({}, {}) px is outside the {}x{} image", m.x_px, m.y_px, width_, height_));
  if (m.frame < start->frame)
    throw InputError(fmt::format("track '{}' starts at frame {}: a mark must come after its start (click the object "
                                 "in frame {} to start the track there)", m.track, start->frame, m.frame));
  const std::vector<TrackStart> before = starts_;
  auto& marks = start->marks;
  const auto at = std::find_if(marks.begin(), marks.end(), [&](const TrackMark& k) { return k.frame == m.frame; });
  if (m.remove) {
    if (m.frame == start->frame) throw InputError(fmt::format("frame {} is where track '{}' starts: its start cannot be removed", m.frame, m.track));
    if (at == marks.end()) throw InputError(fmt::format("track '{}' has no mark in frame {}", m.track, m.frame));
    marks.erase(at);
  } else if (m.frame == start->frame) {
    start->x_px = m.x_px;  // the start dragged: the track starts there
    start->y_px = m.y_px;
  } else if (at != marks.end()) {
    at->x_px = m.x_px;
    at->y_px = m.y_px;
  } else {
    marks.push_back({m.frame, m.x_px, m.y_px});
    std::sort(marks.begin(), marks.end(), [](const TrackMark& a, const TrackMark& b) { return a.frame < b.frame; });
  }
  try {
    run_tracks();
  } catch (...) {
    starts_ = before;
    throw;
  }
  autosave();
  return state();
}

json Workbench::retrack() {
  require_open();
  Action action(*this, "searching the frames around the marks");
  if (!starts_.empty()) {
    const std::shared_ptr<video::TrackSession> before = session_;
    session_ = std::make_shared<video::TrackSession>();  // nothing to conclude from: decode
    try {
      run_tracks();
    } catch (...) {
      session_ = before;
      throw;
    }
    autosave();
  }
  return state();
}

void Workbench::run_tracks() {
  app::TrackVideoOptions o;
  o.input = file_.string();
  o.out = beside(".tracks.csv").string();
  o.write_trk = beside(".tracks.trk").string();
  for (const TrackStart& s : starts_) {
    (s.kind == "ellipse" ? o.ellipse : o.start).push_back(fmt::format("{}={},{}@{}", s.name, s.x_px, s.y_px, s.frame));
    for (const TrackMark& m : s.marks) o.mark.push_back(fmt::format("{}@{}={},{}", s.name, m.frame, m.x_px, m.y_px));
  }
  const CalibrationInput& c = calibration_;
  if (c.stick_px)
    o.calibrate = fmt::format("{},{},{},{},{}", (*c.stick_px)[0], (*c.stick_px)[1], (*c.stick_px)[2], (*c.stick_px)[3],
                              c.stick_length_m);
  if (c.origin_px) o.origin = fmt::format("{},{}", (*c.origin_px)[0], (*c.origin_px)[1]);
  o.axes_deg = c.axes_deg;
  o.fps = c.fps;
  o.time_scale = c.time_scale;
  if (!session_) session_ = std::make_shared<video::TrackSession>();
  o.session = session_;
  o.progress = [this](int done, int expected) { step(done, expected); };
  const app::TrackVideoResult r = app::track_video(o);
  // A quick re-tracking with other marks than the last decoding's: their looks not searched for.
  if (!r.from_session) decoded_marks_ = o.mark;
  looks_pending_ = o.mark != decoded_marks_;
  tracks_ = {{"summary", app::plain_fields_json(r.json)}, {"series", series_json(r.series)}, {"csv", relative(o.out)}, {"trk", relative(o.write_trk)}};
  analysis_ = nullptr;  // it was of the tracks before
}

namespace {

/// A form: the command's declared fields but those the studio sets, and its declared result keys.
template <class O>
json form_of(const app::Fields<O>& declared, const app::ResultKeys& results) {
  json fields = json::array();
  for (const json& f : app::fields_schema(declared))
    if (!set_by_the_studio(f["name"])) fields.push_back(f);
  return {{"fields", fields}, {"results", app::result_keys_schema(results)}};
}

}  // namespace

namespace {

/// What an analysis run from the studio gives: its result and the files it wrote.
struct AnalysisRun {
  json result;         ///< the command's --json
  std::string out;     ///< its table (CSV), "" for none
  std::string report;  ///< its HTML report (Plotly.js embedded: a file to show as it is)
};

/// One analysis the studio offers: its form, and how it runs on the studio's tracks (`csvs`,
/// in s and m: the open file's, then those of the series' other videos) with a form's values,
/// its outputs named by `beside` (FILE + suffix).
struct OfferedAnalysis {
  const char* command;
  std::function<json()> form;
  app::ResultKeys (*results)();  ///< its declared result keys (one run's, and a series' summary's)
  bool series;                   ///< takes several videos' tracks (a series, as on the command line)
  std::function<AnalysisRun(const json& values, const std::vector<std::string>& csvs,
                            const std::function<std::string(const char*)>& beside)>
      run;
};

/// One run's result keys and those of a series' summary.
app::ResultKeys joined(const app::ResultKeys& run, const app::ResultKeys& summary) {
  app::ResultKeys keys = run;
  keys.insert(keys.end(), summary.begin(), summary.end());
  return keys;
}

/// Sets the form's `values` on `o` through `fields`, runs `analysis` and returns its JSON.
template <class O, class Run>
json run_form(O o, const app::Fields<O>& fields, const json& values, Run analysis) {
  apply_form_values(o, fields, values);
  return analysis(o).json;
}

/// The analyses of the studio's Analyse step (issue 25): every one from its declared fields.
const std::vector<OfferedAnalysis>& offered_analyses() {
  using Beside = std::function<std::string(const char*)>;
  static const std::vector<OfferedAnalysis> list = {
      {"track kinematics", [] { return form_of(app::track_kinematics_fields(), app::track_kinematics_result_keys()); },
       [] { return app::track_kinematics_result_keys(); }, false,
       [](const json& values, const std::vector<std::string>& csvs, const Beside& beside) {
         app::TrackKinematicsOptions o;
         o.input.file = csvs.front();
         o.out = beside(".kinematics.csv");
         o.report = beside(".kinematics.html");
         return AnalysisRun{run_form(o, app::track_kinematics_fields(), values, app::track_kinematics), o.out, o.report};
       }},
      {"track rigid-body", [] { return form_of(app::track_rigid_body_fields(), app::track_rigid_body_result_keys()); },
       [] { return app::track_rigid_body_result_keys(); }, false,
       [](const json& values, const std::vector<std::string>& csvs, const Beside& beside) {
         app::TrackRigidBodyOptions o;
         o.input.file = csvs.front();
         o.out = beside(".rigid_body.csv");
         o.report = beside(".rigid_body.html");
         return AnalysisRun{run_form(o, app::track_rigid_body_fields(), values, app::track_rigid_body), o.out, o.report};
       }},
      {"bounce analyze", [] { return form_of(app::bounce_analyze_series_fields(), app::bounce_analyze_result_keys()); },
       [] { return joined(app::bounce_analyze_result_keys(), app::bounce_analyze_series_result_keys()); }, true,
       [](const json& values, const std::vector<std::string>& csvs, const Beside& beside) {
         app::BounceAnalyzeSeriesOptions o;
         o.files = csvs;
         o.each.bounces_out = beside(".bounce.csv");
         o.each.report = beside(".bounce.html");
         return AnalysisRun{run_form(o, app::bounce_analyze_series_fields(), values, app::bounce_analyze_series),
                            o.each.bounces_out, o.each.report};
       }},
      {"incline analyze", [] { return form_of(app::incline_analyze_fields(), app::incline_analyze_result_keys()); },
       [] { return joined(app::incline_analyze_result_keys(), app::incline_analyze_series_result_keys()); }, true,
       [](const json& values, const std::vector<std::string>& csvs, const Beside& beside) {
         app::InclineAnalyzeOptions o;
         o.files = csvs;
         o.report = beside(".incline.html");
         return AnalysisRun{run_form(o, app::incline_analyze_fields(), values, app::incline_analyze), std::string(), o.report};
       }},
  };
  return list;
}

}  // namespace

json Workbench::forms() {
  json forms = json::object();
  for (const OfferedAnalysis& a : offered_analyses()) {
    forms[a.command] = a.form();
    forms[a.command]["series"] = a.series;  // takes other videos' tracks too
  }
  return forms;
}

/// `j` with the folder's own place on disk left out of its texts (a series' run files are the
/// tracks' CSVs by their full paths): the page names files relative to the folder.
json within_folder(json j, const std::string& root) {
  const std::string prefix = root.back() == '/' ? root : root + '/';
  if (j.is_string()) {
    std::string s = j.get<std::string>();
    for (std::size_t p = s.find(prefix); p != std::string::npos; p = s.find(prefix, p)) s.erase(p, prefix.size());
    return s;
  }
  if (j.is_structured())
    for (auto& e : j) e = within_folder(std::move(e), root);
  return j;
}

/// The unit of every number of an analysis's result, by its path in the result ("a.b", list
/// entries by index: "runs.0.mu"), from the command's declared keys through the rules the
/// command line's listing uses (app::find_result_key: sigma_X, X_ci95 and ci95.X take X's
/// unit); a series' runs are each a one-run result and its summary has the summary's keys.
void result_units(const json& v, const std::string& path, const std::string& key, const app::ResultKeys& keys,
                  json& units) {
  const auto join = [](const std::string& a, const std::string& b) { return a.empty() ? b : a + "." + b; };
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it) result_units(*it, join(path, it.key()), join(key, it.key()), keys, units);
    return;
  }
  if (v.is_array() && std::any_of(v.begin(), v.end(), [](const json& e) { return e.is_object(); })) {
    for (std::size_t i = 0; i < v.size(); ++i) result_units(v[i], join(path, std::to_string(i)), key, keys, units);
    return;
  }
  const app::ResultKey* k = app::find_result_key(keys, key);
  for (const char* part : {"runs.", "summary."})
    if (!k && key.rfind(part, 0) == 0) k = app::find_result_key(keys, key.substr(std::string(part).size()));
  if (k && !k->unit.empty()) units[path] = k->unit;
}

json Workbench::analyze(const std::string& command, const json& values, const std::vector<fs::path>& series) {
  require_open();
  Action action(*this, "analysing");
  const auto& list = offered_analyses();
  const auto offered = std::find_if(list.begin(), list.end(), [&](const OfferedAnalysis& a) { return a.command == command; });
  if (offered == list.end()) {
    std::string names;
    for (const OfferedAnalysis& a : list) names += (names.empty() ? "'" : ", '") + std::string(a.command) + "'";
    throw InputError("the studio offers the analyses " + names + ", not '" + command + "'");
  }
  if (!tracks_.contains("csv")) throw InputError("track an object first: the analysis reads its track");
  for (auto it = values.begin(); it != values.end(); ++it)
    if (set_by_the_studio(it.key())) throw InputError(field(it.key()), "is set by the studio: its tracks are in s and m");
  // A series: the open video's tracks first, then those of each other video named, as the
  // studio wrote them when that video was tracked (FILE.tracks.csv).
  std::vector<std::string> csvs = {(root_ / tracks_["csv"].get<std::string>()).string()};
  json series_names = json::array();
  if (!series.empty() && !offered->series)
    throw InputError(fmt::format("'{}' analyses one video; a series of videos is offered for bounce analyze and "
                                 "incline analyze", command));
  for (const fs::path& other : series) {
    if (other == file_) throw InputError(relative(other), "is the video open: it is the series' first run already");
    const fs::path csv = other.parent_path() / (other.filename().string() + ".tracks.csv");
    const Confined c = confine(root_, relative(csv));
    std::error_code ec;
    if (!c.problem.empty() || !fs::is_regular_file(c.path, ec))
      throw InputError(relative(other), "has no tracks yet: open it in the studio and track it, then add it to the series");
    if (std::find(csvs.begin(), csvs.end(), csv.string()) != csvs.end())
      throw InputError(relative(other), "is in the series twice");
    csvs.push_back(csv.string());
    series_names.push_back(relative(other));
  }
  const AnalysisRun run = offered->run(values, csvs, [this](const char* suffix) { return beside(suffix).string(); });
  const auto written = [this](const std::string& path) { return path.empty() ? json(nullptr) : json(relative(path)); };
  const json result = within_folder(app::plain_fields_json(run.result), root_.string());
  json units = json::object();
  result_units(result, "", "", offered->results(), units);
  analysis_ = {{"command", command}, {"values", values}, {"series", series_names}, {"result", result}, {"units", units},
               {"out", written(run.out)}, {"report", written(run.report)},
               {"results", app::result_keys_schema(offered->results())}};
  autosave();
  return state();
}

std::string Workbench::report_html() {
  require_open();
  if (!analysis_.is_object() || !analysis_.contains("report") || !analysis_["report"].is_string())
    throw InputError("run an analysis first: its report is shown here");
  const std::string name = analysis_["report"].get<std::string>();
  const Confined c = confine(root_, name);
  if (!c.problem.empty()) throw InputError(name, "will not be read: " + c.problem);
  std::ifstream in(c.path, std::ios::binary);
  if (!in) throw InputError(name, "the report is gone: run the analysis again");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

json Workbench::state() {
  json starts = json::array();
  for (const auto& s : starts_) starts.push_back(to_json(s));
  return {{"folder", root_.filename().string()},
          {"file", file_.empty() ? json(nullptr) : json(relative(file_))},
          {"video", video_},
          {"frames", frames_},
          {"calibration", to_json(calibration_)},
          {"starts", starts},
          {"tracks", tracks_},
          {"looks_pending", looks_pending_},
          {"analysis", analysis_},
          {"autosave", file_.empty() ? json(nullptr) : json(relative(beside(".studio.json")))}};
}

void Workbench::autosave() const {
  json starts = json::array();
  for (const auto& s : starts_) starts.push_back(to_json(s));
  const json j = {{"studio", 1}, {"file", relative(file_)}, {"calibration", to_json(calibration_)},
                  {"starts", starts}, {"tracks", tracks_}, {"analysis", analysis_}};
  io::AtomicFile out(beside(".studio.json").string());
  out.stream() << j.dump(1, ' ', false, json::error_handler_t::replace) << '\n';
  out.commit();
}

}  // namespace tribolab::studio
