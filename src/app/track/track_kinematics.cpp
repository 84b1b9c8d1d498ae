#include "app/track/track_kinematics.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"

#include "app/track/report_track.hpp"
#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tribolab::app {

namespace {

std::string g3(double v) { return fmt::format("{:.3g}", v); }

/// The plain-language warning for a free-flight segment that does not fall at g
/// (docs/theory.md#free-flight-check): what the data show, then what to check.
std::string gravity_warning(const track::SegmentAcceleration& a, std::size_t index, std::size_t count, double g) {
  std::string w = fmt::format("segment {} of {} (frames {}-{}, t = {:.4g}-{:.4g} s) moves like a free flight (one "
                              "constant acceleration along the y axis, rising and falling back) but ",
                              index + 1, count, a.frame_first, a.frame_last, a.t_first, a.t_last);
  const auto sd = [](double v) { return fmt::format("{:.2g}", v); };  // an uncertainty: 2 digits
  const std::string size = g3(a.magnitude) + " +- " + sd(a.sigma_magnitude) + " m/s^2";
  if (a.points_up) {
    w += "accelerates up the y axis (a_y = +" + g3(a.ay) + " +- " + sd(a.sigma_ay) + " m/s^2)";
    if (a.magnitude_off) w += " at " + size + ", not g = " + g3(g);
  } else if (a.magnitude_off) {
    w += "accelerates at " + size + ", not g = " + g3(g);
    if (a.tilted) w += ", tilted by " + g3(a.tilt_deg) + " +- " + sd(a.sigma_tilt_deg) + " deg from the -y axis";
  } else {
    w += "its acceleration (" + size + ") is tilted by " + g3(a.tilt_deg) + " +- " + sd(a.sigma_tilt_deg) +
         " deg from the -y axis";
  }
  w += ". ";
  if (a.points_up) w += "The file's y axis points down (image rows?): set the coordinate axes with y up. ";
  if (a.magnitude_off) {
    const double factor = std::sqrt(a.magnitude / g);  // times off by c scale every acceleration by 1/c^2
    w += "The times or the lengths are wrong: if the lengths are right, the file's times must be multiplied by " +
         g3(factor) + " (" + field("time_scale") + " " + g3(factor) +
         " times the one used; 240 fps slow motion played at 30 fps needs 0.125; an error of k % in the frame rate "
         "changes g by 2k %); else check the length calibration (the scale stick, the unit). ";
  }
  if (a.tilted) w += "The camera or the axes are turned by that angle: level them against a plumb line. ";
  w += "If the object was not in free flight (a puck on a tilted air table seen from above), this check does not apply";
  return w;
}

nlohmann::json segment_json(const track::SegmentAcceleration& a, std::size_t index) {
  const bool ff = a.checked();
  return {{"segment", index + 1},
          {"frame_first", a.frame_first},
          {"frame_last", a.frame_last},
          {"t_first", a.t_first},
          {"t_last", a.t_last},
          {"points", a.range.size()},
          {"ax", json_number(a.ax)},
          {"ay", json_number(a.ay)},
          {"sigma_ax", json_number(a.sigma_ax)},
          {"sigma_ay", json_number(a.sigma_ay)},
          {"acceleration", json_number(a.magnitude)},
          {"sigma_acceleration", json_number(a.sigma_magnitude)},
          {"tilt_deg", json_number(a.tilt_deg)},
          {"sigma_tilt_deg", json_number(a.sigma_tilt_deg)},
          {"rms_residual_x", json_number(a.rms_x)},
          {"rms_residual_y", json_number(a.rms_y)},
          {"free_flight", ff},
          {"not_free_flight_because", ff ? nlohmann::json(nullptr) : nlohmann::json(track::to_string(a.shape))},
          {"gravity_plausible", ff ? nlohmann::json(a.plausible()) : nlohmann::json(nullptr)}};
}

}  // namespace

TrackKinematicsResult track_kinematics(const TrackKinematicsOptions& options) {
  check_output_paths({options.input.file}, {{"out", options.out}, {"report", options.report}});  // before any work (app/common/output_paths.hpp)
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
  if (!(std::isfinite(options.g) && options.g > 0)) {
    throw InputError(field("g"), "must be a positive number of m/s^2, got " + fmt::format("{}", options.g));
  }
  if (options.out.empty()) throw MissingOptionError(field("out"), "the output CSV is required");
  o.window = options.window;
  o.order = options.order;
  o.split_at_impacts = options.impacts == "auto";
  if (const auto err = o.validate(); !err.empty()) throw InputError(err);
  std::vector<std::string> wanted;
  if (!options.track.empty()) wanted = {options.track};
  const track::TrackSet set = io::read_tracks(options.input.file, import_options(options.input, wanted));
  const track::Track tr = restrict_times(choose_track(set, options.track), options.t_from, options.t_to, 3, set.source);
  if (tr.points.size() < 3) {
    throw InputError(set.source, "track '" + tr.name + "' has " + std::to_string(tr.points.size()) +
                                     " point(s); at least 3 are needed for derivatives");
  }
  TrackKinematicsResult result;
  result.kinematics = track::differentiate(tr, o);
  const track::Kinematics& k = result.kinematics;
  const bool savgol = o.method == track::DerivativeMethod::savgol;
  // Free-flight segments held against g (docs/theory.md#free-flight-check).
  track::FreeFlightOptions fo;
  fo.g = options.g;
  result.segment_fits = track::check_free_flight(tr, track::flight_segments(tr.points.size(), k.impacts), k.noise_x,
                                                 k.noise_y, fo);
  result.warnings = set.warnings;  // what the importer left out (lost frames, marks off the clip's steps)
  for (std::size_t i = 0; i < result.segment_fits.size(); ++i) {
    const auto& a = result.segment_fits[i];
    if (a.checked() && !a.plausible()) {
      result.warnings.push_back(gravity_warning(a, i, result.segment_fits.size(), options.g));
    }
  }
  if (!options.report.empty()) {
    report::write_html(track_kinematics_report(k, o, set.source, result.segment_fits, result.warnings), options.report,
                       options.plotly);
  }
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
  j["t_from"] = json_number(options.t_from);  // null: not given
  j["t_to"] = json_number(options.t_to);
  j["g"] = options.g;
  nlohmann::json fits = nlohmann::json::array();
  for (std::size_t i = 0; i < result.segment_fits.size(); ++i) fits.push_back(segment_json(result.segment_fits[i], i));
  j["segment_fits"] = fits;
  j["warnings"] = result.warnings;
  j["out"] = options.out;
  return result;
}


const ResultKeys& track_kinematics_result_keys() {
  static const ResultKeys k = {
      {"track", "", ""}, {"method", "", ""}, {"points", "", ""}, {"window", "", ""}, {"order", "", ""},
      {"velocities_defined", "", "rows with a velocity"}, {"accelerations_defined", "", "rows with an acceleration"},
      {"segments", "", ""}, {"impacts.frame", "", ""}, {"impacts.t", "s", ""}, {"impacts.dvx", "m/s", ""},
      {"impacts.dvy", "m/s", ""}, {"impacts.significance", "", ""}, {"noise_x", "m", ""}, {"noise_y", "m", ""},
      {"residual_sigma_x", "m", ""}, {"residual_sigma_y", "m", ""}, {"time_scale", "", ""}, {"g", "m/s^2", ""},
      {"segment_fits.segment", "", ""}, {"segment_fits.frame_first", "", ""}, {"segment_fits.frame_last", "", ""},
      {"segment_fits.t_first", "s", ""}, {"segment_fits.t_last", "s", ""}, {"segment_fits.points", "", ""},
      {"segment_fits.ax", "m/s^2", ""}, {"segment_fits.ay", "m/s^2", ""}, {"segment_fits.acceleration", "m/s^2", ""},
      {"segment_fits.tilt_deg", "deg", ""}, {"segment_fits.rms_residual_x", "m", ""},
      {"segment_fits.rms_residual_y", "m", ""}, {"segment_fits.free_flight", "", ""},
      {"segment_fits.not_free_flight_because", "", ""}, {"segment_fits.gravity_plausible", "", ""},
      {"t_from", "s", "first time used (--from)"}, {"t_to", "s", "last time used (--to)"},
      {"warnings", "", ""}, {"out", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
