// `tribolab track`: read tracked video data (Tracker .trk/.trz, Export Data text, CSV) and
// differentiate it. Options are documented in docs/cli.md#track.
#include "app.hpp"
#include "report_option.hpp"
#include "app/report_track.hpp"
#include "track_video_cmd.hpp"

#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "io/track_import.hpp"
#include "numerics/error.hpp"
#include "track/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::cli {

namespace {

struct ImportArgs {
  std::string file;
  io::ImportOptions options;
};

void add_import_options(CLI::App& cmd, ImportArgs& a, bool many_tracks) {
  cmd.add_option("FILE", a.file, "Tracker .trk/.trz, Tracker Export Data text, or CSV")->required();
  cmd.add_option("--time-scale", a.options.time_scale,
                 "Real seconds per file second: slow motion recorded at 240 fps and played at "
                 "30 fps is 0.125 (default 1)");
  if (many_tracks) {
    cmd.add_option("--track", a.options.tracks, "Keep only this track (repeatable; default all)");
  }
  cmd.add_option("--length-unit", a.options.length_unit,
                 "Unit of the file's lengths, overriding what the file says: m, cm, mm, km, um, "
                 "in, ft (default: the file's unit, else m)");
  cmd.add_option("--entry", a.options.zip_entry, "For a .trz: the .trk inside to read (default the first)");
}

double finite_or_nan(double v) { return std::isfinite(v) ? v : std::numeric_limits<double>::quiet_NaN(); }

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json summary(const track::Track& t) {
  nlohmann::json j;
  j["points"] = t.points.size();
  if (t.points.empty()) return j;
  double x0 = t.points[0].x, x1 = x0, y0 = t.points[0].y, y1 = y0;
  for (const auto& p : t.points) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  j["frame_first"] = t.points.front().frame;
  j["frame_last"] = t.points.back().frame;
  j["t_min"] = t.points.front().t;
  j["t_max"] = t.points.back().t;
  j["x_min"] = x0;
  j["x_max"] = x1;
  j["y_min"] = y0;
  j["y_max"] = y1;
  return j;
}

void run_import(const ImportArgs& a, const std::string& out, bool as_json) {
  const track::TrackSet set = io::read_tracks(a.file, a.options);
  nlohmann::json j;
  j["source"] = set.source;
  j["format"] = set.format;
  j["length_unit_in_file"] = set.file_length_unit;
  j["time_scale"] = set.time_scale;
  j["track_names"] = set.names();
  nlohmann::json tracks = nlohmann::json::object();
  for (const auto& t : set.tracks) tracks[t.name] = summary(t);
  j["tracks"] = tracks;
  j["warnings"] = set.warnings;
  j["out"] = out.empty() ? nlohmann::json(nullptr) : nlohmann::json(out);
  if (!out.empty()) {
    io::AtomicFile f(out);
    io::write_tidy_csv(f.stream(), set);
    f.commit();
  }
  print_result(j, as_json);
}

const track::Track& choose_track(const track::TrackSet& set, const std::vector<std::string>& wanted) {
  if (!wanted.empty()) return set.find(wanted.front());
  std::vector<const track::Track*> with_points;
  for (const auto& t : set.tracks) {
    if (!t.points.empty()) with_points.push_back(&t);
  }
  if (with_points.size() == 1) return *with_points.front();
  std::string names;
  for (const auto* t : with_points) names += (names.empty() ? "'" : ", '") + t->name + "'";
  throw InputError(set.source, "the file holds " + std::to_string(with_points.size()) +
                                   " tracks (" + names + "); choose one with --track");
}

}  // namespace

void register_track(CLI::App& root) {
  auto* area = root.add_subcommand(
      "track", "Tracked video data: track points and balls in video, read Tracker files and exports, velocities and accelerations");
  area->require_subcommand(1);

  // track video (cli/track_video_cmd.cpp)
  register_track_video(*area);

  // track import
  {
    auto* cmd = area->add_subcommand(
        "import", "Read tracked points into a tidy table track,frame,t,x,y (s, m) and summarise them");
    auto args = std::make_shared<ImportArgs>();
    auto out = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    add_import_options(*cmd, *args, true);
    cmd->add_option("--out", *out, "Write the tidy CSV here (columns track,frame,t,x,y)");
    add_json_flag(*cmd, *as_json);
    cmd->callback([args, out, as_json] { run_import(*args, *out, *as_json); });
  }

  // track kinematics
  {
    auto* cmd = area->add_subcommand(
        "kinematics", "Velocities and accelerations of one track (Tracker's stencils or "
                      "Savitzky-Golay with standard errors), never across impacts");
    struct Args {
      ImportArgs in;
      std::string track, method = "tracker", impacts = "auto", out, report;
      int window = 7, order = 2;
      bool as_json = false;
    };
    auto a = std::make_shared<Args>();
    add_import_options(*cmd, a->in, false);
    cmd->add_option("--track", a->track, "Track to differentiate (required when the file has several)");
    cmd->add_option("--method", a->method, "tracker (Tracker's finite differences) or savgol (default tracker)");
    cmd->add_option("--window", a->window, "savgol: points per local fit (default 7)");
    cmd->add_option("--order", a->order, "savgol: polynomial degree 1..6 (default 2)");
    cmd->add_option("--impacts", a->impacts,
                    "auto: detect impacts and never difference across them; none: differentiate "
                    "straight through, exactly as Tracker does (default auto)");
    cmd->add_option("--out", a->out, "Output CSV: t,x,y,vx,vy,ax,ay (+ sigma columns for savgol)")->required();
    add_json_flag(*cmd, a->as_json);
    add_report_option(*cmd, a->report);
    cmd->callback([a, cmd] {
      track::KinematicsOptions o;
      if (a->method == "tracker") {
        o.method = track::DerivativeMethod::tracker;
        if (cmd->count("--window") > 0 || cmd->count("--order") > 0) {
          throw InputError("--window/--order", "apply to --method savgol only");
        }
      } else if (a->method == "savgol") {
        o.method = track::DerivativeMethod::savgol;
      } else {
        throw InputError("--method", "must be tracker or savgol, got '" + a->method + "'");
      }
      if (a->impacts != "auto" && a->impacts != "none") {
        throw InputError("--impacts", "must be auto or none, got '" + a->impacts + "'");
      }
      o.window = a->window;
      o.order = a->order;
      o.split_at_impacts = a->impacts == "auto";
      if (const auto err = o.validate(); !err.empty()) throw InputError(err);
      if (!a->track.empty()) a->in.options.tracks = {a->track};
      const track::TrackSet set = io::read_tracks(a->in.file, a->in.options);
      const track::Track& tr = choose_track(set, a->in.options.tracks);
      if (tr.points.size() < 3) {
        throw InputError(set.source, "track '" + tr.name + "' has " + std::to_string(tr.points.size()) +
                                         " point(s); at least 3 are needed for derivatives");
      }
      const track::Kinematics k = track::differentiate(tr, o);
      const bool savgol = o.method == track::DerivativeMethod::savgol;
      write_report_if_requested(a->report, [&] { return track_kinematics_report(k, o, set.source); });
      io::AtomicFile f(a->out);
      io::write_kinematics_csv(f.stream(), k, savgol);
      f.commit();
      nlohmann::json j;
      j["track"] = tr.name;
      j["method"] = track::to_string(o.method);
      j["points"] = k.rows.size();
      j["window"] = savgol ? nlohmann::json(o.window) : nlohmann::json(nullptr);
      j["order"] = savgol ? nlohmann::json(o.order) : nlohmann::json(nullptr);
      int dv = 0, da = 0;
      for (const auto& r : k.rows) {
        dv += std::isfinite(r.vx);
        da += std::isfinite(r.ax);
      }
      j["velocities_defined"] = dv;
      j["accelerations_defined"] = da;
      j["segments"] = k.segments;
      nlohmann::json impacts = nlohmann::json::array();
      for (const auto& im : k.impacts) {
        impacts.push_back({{"frame", im.frame},
                           {"t", im.t},
                           {"dvx", im.dvx},
                           {"dvy", im.dvy},
                           {"significance", im.significance}});
      }
      j["impacts"] = impacts;
      j["noise_x"] = number(finite_or_nan(k.noise_x));
      j["noise_y"] = number(finite_or_nan(k.noise_y));
      j["residual_sigma_x"] = number(k.residual_sigma_x);
      j["residual_sigma_y"] = number(k.residual_sigma_y);
      j["time_scale"] = set.time_scale;
      j["out"] = a->out;
      print_result(j, a->as_json);
    });
  }
}

}  // namespace tribolab::cli
