#include "app/track_kinematics.hpp"

#include "app/output_paths.hpp"

#include "app/report_track.hpp"
#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"

#include <cmath>

namespace tribolab::app {

TrackKinematicsResult track_kinematics(const TrackKinematicsOptions& options) {
  check_output_paths({options.input.file}, {{"out", options.out}, {"report", options.report}});  // before any work (app/output_paths.hpp)
  const TrackKinematicsOptions defaults;
  track::KinematicsOptions o;
  if (options.method == "tracker") {
    o.method = track::DerivativeMethod::tracker;
    if (options.window != defaults.window || options.order != defaults.order) {
      throw InputError(field("window") + "/" + field("order"), "apply to " + field("method") + " savgol only");
    }
  } else if (options.method == "savgol") {
    o.method = track::DerivativeMethod::savgol;
  } else {
    throw InputError(field("method"), "must be tracker or savgol, got '" + options.method + "'");
  }
  if (options.impacts != "auto" && options.impacts != "none") {
    throw InputError(field("impacts"), "must be auto or none, got '" + options.impacts + "'");
  }
  if (options.out.empty()) throw MissingOptionError(field("out"), "the output CSV is required");
  o.window = options.window;
  o.order = options.order;
  o.split_at_impacts = options.impacts == "auto";
  if (const auto err = o.validate(); !err.empty()) throw InputError(err);
  std::vector<std::string> wanted;
  if (!options.track.empty()) wanted = {options.track};
  const track::TrackSet set = io::read_tracks(options.input.file, import_options(options.input, wanted));
  const track::Track& tr = choose_track(set, options.track);
  if (tr.points.size() < 3) {
    throw InputError(set.source, "track '" + tr.name + "' has " + std::to_string(tr.points.size()) +
                                     " point(s); at least 3 are needed for derivatives");
  }
  TrackKinematicsResult result;
  result.kinematics = track::differentiate(tr, o);
  const track::Kinematics& k = result.kinematics;
  const bool savgol = o.method == track::DerivativeMethod::savgol;
  if (!options.report.empty()) report::write_html(track_kinematics_report(k, o, set.source), options.report, options.plotly);
  io::AtomicFile f(options.out);
  io::write_kinematics_csv(f.stream(), k, savgol);
  f.commit();
  nlohmann::json& j = result.json;
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
  j["noise_x"] = json_number(k.noise_x);
  j["noise_y"] = json_number(k.noise_y);
  j["residual_sigma_x"] = json_number(k.residual_sigma_x);
  j["residual_sigma_y"] = json_number(k.residual_sigma_y);
  j["time_scale"] = set.time_scale;
  j["warnings"] = set.warnings;  // what the importer left out (lost frames, marks off the clip's steps)
  j["out"] = options.out;
  return result;
}

}  // namespace tribolab::app
