#include "app/track/track_kinematics.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"

#include "app/track/report_track.hpp"
#include "io/atomic_file.hpp"
#include "io/track_csv.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

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

/// A track that keeps a constant distance from the one analysed over a flight segment: the
/// other end of a body the two are marked on (a rugby ball's tips), and the fit of their
/// midpoint's flight.
struct RigidPartner {
  std::string name;
  double distance = 0, distance_sd = 0;  ///< mean and sd of the distance between the two, m
  track::SegmentAcceleration midpoint;   ///< the midpoint's constant-acceleration fit
};

/// The first other track of `set` that has a point in at least 80 % of the frames of `seg`
/// and keeps its distance from `tr` there to the noise (sd <= 2 sqrt(2) noise + 1 mm, the
/// free-flight fit's own rule, with a mean at least 10 times that), or none. A point off the
/// centre of a turning body accelerates by omega^2 r towards it besides g, so its own flight
/// is no test of g; the midpoint of two tips is the body's centre (docs/theory.md#free-flight-check).
std::optional<RigidPartner> rigid_partner(const track::TrackSet& set, const track::Track& tr, const track::Segment& seg,
                                          double noise, const track::FreeFlightOptions& fo) {
  const double bar = 2 * std::sqrt(2.0) * noise + 1e-3;
  for (const track::Track& other : set.tracks) {
    if (other.name == tr.name) continue;
    std::map<int, const track::TrackPoint*> at;
    for (const auto& q : other.points) at[q.frame] = &q;
    track::Track mid;
    mid.name = tr.name + "+" + other.name;
    std::vector<double> d;
    for (std::size_t i = seg.begin; i < seg.end; ++i) {
      const auto& p = tr.points[i];
      const auto it = at.find(p.frame);
      if (it == at.end()) continue;
      const auto& q = *it->second;
      d.push_back(std::hypot(p.x - q.x, p.y - q.y));
      mid.points.push_back({p.frame, p.t, 0.5 * (p.x + q.x), 0.5 * (p.y + q.y)});
    }
    if (d.size() < static_cast<std::size_t>(fo.min_points) || 10 * d.size() < 8 * seg.size()) continue;
    double mean = 0, var = 0;
    for (double v : d) mean += v / static_cast<double>(d.size());
    for (double v : d) var += (v - mean) * (v - mean) / static_cast<double>(d.size() - 1);
    const double sd = std::sqrt(var);
    if (!(sd <= bar && mean >= 10 * bar)) continue;
    // Each coordinate of the midpoint carries the noise of one point over sqrt(2).
    const double n = noise / std::sqrt(2.0);
    auto fits = track::check_free_flight(mid, {{0, mid.points.size()}}, n, n, fo);
    return RigidPartner{other.name, mean, sd, fits.front()};
  }
  return std::nullopt;
}

/// The warning for segment `a` of `tr` that does not fall at g while `tr` keeps a constant
/// distance from `partner`: the midpoint falling at g says so; otherwise the midpoint's figures
/// are the ones to act on (its factor restores g; the point's own would not).
std::string turning_body_warning(const track::SegmentAcceleration& a, const std::string& name,
                                 const RigidPartner& partner, std::size_t index, std::size_t count, double g) {
  const auto& m = partner.midpoint;
  const auto sd = [](double v) { return fmt::format("{:.2g}", v); };
  const std::string keeps = fmt::format("it keeps {:.3g} m (sd {:.2g} mm) from track {} there", partner.distance,
                                        1e3 * partner.distance_sd, partner.name);
  if (m.checked() && m.plausible()) {
    return fmt::format("segment {} of {} (frames {}-{}): track {} itself accelerates at {} +- {} m/s^2 (tilted by {} "
                       "+- {} deg from the -y axis), not at g = {}; but {}, and their midpoint falls at {} +- {} "
                       "m/s^2: {} turns with the body (a point at r from the centre of a body spinning at omega "
                       "accelerates by omega^2 r towards it besides g), and the times and lengths agree with g; the "
                       "centre and the spin: track rigid-body",
                       index + 1, count, a.frame_first, a.frame_last, name, g3(a.magnitude), sd(a.sigma_magnitude),
                       g3(a.tilt_deg), sd(a.sigma_tilt_deg), g3(g), keeps, g3(m.magnitude), sd(m.sigma_magnitude),
                       name);
  }
  if (m.checked()) {
    return "track " + name + " is on one body with track " + partner.name + " (" + keeps +
           "), so their midpoint (the body's centre when they mark its two ends) is held against g instead of " + name +
           ", which turns with it: " + gravity_warning(m, index, count, g);
  }
  return gravity_warning(a, index, count, g) + "; but track " + name + " may be on a turning body: " + keeps +
         ", and a point off a turning body's centre does not fall at g (check their centre: track rigid-body)";
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
  std::optional<track::TrackSet> all;  // every track of the file, read only when a segment is warned
  for (std::size_t i = 0; i < result.segment_fits.size(); ++i) {
    const auto& a = result.segment_fits[i];
    if (!a.checked() || a.plausible()) continue;
    if (!all) {
      try {
        all = io::read_tracks(options.input.file, import_options(options.input));
      } catch (const InputError&) {  // another track the file holds does not read: no partner
        all = track::TrackSet{};
      }
    }
    const auto partner = rigid_partner(*all, tr, a.range, std::max(k.noise_x, k.noise_y), fo);
    result.warnings.push_back(partner ? turning_body_warning(a, tr.name, *partner, i, result.segment_fits.size(), options.g)
                                      : gravity_warning(a, i, result.segment_fits.size(), options.g));
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
