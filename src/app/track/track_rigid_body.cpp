#include "app/track/track_rigid_body.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"

#include "app/track/report_track_rigid_body.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/polyfit.hpp"
#include "report/html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <ostream>

namespace tribolab::app {

namespace {

/// A CSV cell: shortest round-trip number, empty for NaN.

void write_csv(std::ostream& out, const track::RigidBody& body) {
  out << "frame,t,x,y,theta,omega,sigma_omega,length\n";
  for (const auto& r : body.rows) {
    out << r.frame << ',' << io::csv_number(r.t) << ',' << io::csv_number(r.xc) << ',' << io::csv_number(r.yc) << ',' << io::csv_number(r.theta) << ','
        << io::csv_number(r.omega) << ',' << io::csv_number(r.sigma_omega) << ',' << io::csv_number(r.length) << '\n';
  }
}

std::string percent(double fraction) { return fmt::format("{:.1f} %", 100 * fraction); }

void validate(const TrackRigidBodyOptions& o) {
  if (o.track_a.empty()) throw InputError(field("track_a"), "name the track of point A");
  if (o.track_b.empty()) throw InputError(field("track_b"), "name the track of point B");
  if (o.track_a == o.track_b) {
    throw InputError(field("track_b"), "must name another track than " + field("track_a") + " ('" + o.track_a + "')");
  }
  if (o.window < 3) throw InputError(field("window"), "must be at least 3 points, got " + std::to_string(o.window));
  if (!(o.max_drift > 0 && o.max_drift <= 1)) {
    throw InputError(field("max_drift"), "must lie in (0, 1] (a fraction of the A-B distance), got " +
                                        fmt::format("{}", o.max_drift));
  }
}

/// Frames where A and B coincide leave the orientation undefined.
void check_distinct(const track::RigidBody& body, const std::string& source) {
  for (const auto& r : body.rows) {
    if (!(r.length > 0)) {
      throw InputError(source, "points '" + body.point_a + "' and '" + body.point_b + "' coincide at frame " +
                                   std::to_string(r.frame) + ": the orientation is undefined there");
    }
  }
}

}  // namespace

LengthCheck check_length(const track::RigidBody& body) {
  std::vector<double> t, l;
  for (const auto& r : body.rows) {
    t.push_back(r.t);
    l.push_back(r.length);
  }
  LengthCheck c;
  c.mean = body.length_mean;
  c.sd = body.length_sd;
  c.min = *std::min_element(l.begin(), l.end());
  c.max = *std::max_element(l.begin(), l.end());
  const numerics::PolyFit fit = numerics::fit_polynomial(t, l, 1, "the A-B distance against time");
  const double span = t.back() - t.front();
  c.drift = fit.coef[1] * span;
  c.sigma_drift = fit.sigma[1] * span;
  return c;
}

TrackRigidBodyResult track_rigid_body(const TrackRigidBodyOptions& options) {
  check_output_paths({options.input.file}, {{"out", options.out}, {"report", options.report}});  // before any work (app/common/output_paths.hpp)
  validate(options);
  const track::TrackSet set =
      io::read_tracks(options.input.file, import_options(options.input, {options.track_a, options.track_b}));
  const track::Track& a = set.find(options.track_a);
  const track::Track& b = set.find(options.track_b);
  // Count the common frames first: the message names the file and the least number needed.
  std::size_t common = 0;
  for (std::size_t i = 0, j = 0; i < a.points.size(); ++i) {
    while (j < b.points.size() && b.points[j].frame < a.points[i].frame) ++j;
    if (j < b.points.size() && b.points[j].frame == a.points[i].frame) ++common;
  }
  if (common < static_cast<std::size_t>(kRigidBodyMinFrames)) {
    throw InputError(set.source, "tracks '" + a.name + "' and '" + b.name + "' share " + std::to_string(common) +
                                     " frame(s); at least " + std::to_string(kRigidBodyMinFrames) +
                                     " are needed (both points marked in the same frames)");
  }
  TrackRigidBodyResult result;
  track::RigidBodyOptions ro;
  ro.window = options.window;
  result.body = track::rigid_body_from_points(a, b, ro);
  const track::RigidBody& body = result.body;
  check_distinct(body, set.source);
  result.length = check_length(body);
  const LengthCheck& len = result.length;
  const auto& rows = body.rows;

  std::vector<std::string> warnings = set.warnings;
  const double drift_fraction = len.drift / len.mean, scatter_fraction = len.sd / len.mean;
  // A drift within 3 standard errors of zero is noise, however large (few noisy frames).
  if (std::abs(drift_fraction) > options.max_drift && std::abs(len.drift) > 3 * len.sigma_drift) {
    warnings.push_back("the distance between '" + a.name + "' and '" + b.name + "' changes by " +
                       percent(drift_fraction) + " over the record (more than " + field("max_drift") + " " + percent(options.max_drift) +
                       "): a rigid body keeps it; check the calibration (a tilted or moving scale) and that both "
                       "tracks follow points of the same body");
  }
  if (scatter_fraction > options.max_drift) {
    warnings.push_back("the distance between '" + a.name + "' and '" + b.name + "' scatters by " +
                       percent(scatter_fraction) + " of its mean from frame to frame (more than " + field("max_drift") + " " +
                       percent(options.max_drift) + "): check for mislabelled or swapped marks");
  }
  double max_turn = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) max_turn = std::max(max_turn, std::abs(rows[i].theta - rows[i - 1].theta));
  if (max_turn > std::numbers::pi / 2) {
    warnings.push_back(fmt::format("the body turns by up to {:.2f} rad between frames: near pi the direction of "
                                   "the turn is ambiguous and the spin may be aliased (a higher frame rate helps)",
                                   max_turn));
  }

  double wmin = NAN, wmax = NAN;
  for (const auto& r : rows) {
    if (!std::isfinite(r.omega)) continue;
    wmin = std::isfinite(wmin) ? std::min(wmin, r.omega) : r.omega;
    wmax = std::isfinite(wmax) ? std::max(wmax, r.omega) : r.omega;
  }
  // One spin for the whole record is meaningful only if the body turns steadily: local spins
  // that disagree with it beyond their noise (an impact, a torque, a hand) make it a mixture.
  std::size_t n_local = 0, n_off = 0;
  for (const auto& r : rows) {
    if (!std::isfinite(r.omega) || !std::isfinite(r.sigma_omega)) continue;
    ++n_local;
    // 5 standard errors of the local fit, and 2 % of the spin for noise-free records.
    n_off += std::abs(r.omega - body.spin.omega) > 5 * r.sigma_omega + 0.02 * std::abs(body.spin.omega);
  }
  if (n_local > 0 && n_off > n_local / 10) {
    warnings.push_back(fmt::format("the spin is not steady: in {} of {} frames the local spin (from {:.4g} to {:.4g} "
                                   "rad/s) differs from the one fitted to the whole record ({:.4g} rad/s) beyond its "
                                   "noise; that one spin mixes parts (an impact or a torque between them): analyse "
                                   "each part on its own (a bounce: bounce analyze)",
                                   n_off, n_local, wmin, wmax, body.spin.omega));
  }
  nlohmann::json j;
  j["source"] = set.source;
  j["track_a"] = a.name;
  j["track_b"] = b.name;
  j["frames"] = rows.size();
  j["frame_first"] = rows.front().frame;
  j["frame_last"] = rows.back().frame;
  j["t_first"] = rows.front().t;
  j["t_last"] = rows.back().t;
  j["time_scale"] = set.time_scale;
  j["window"] = std::min<int>(options.window, static_cast<int>(rows.size()));
  j["centre_first"] = {{"x", rows.front().xc}, {"y", rows.front().yc}};
  j["centre_last"] = {{"x", rows.back().xc}, {"y", rows.back().yc}};
  j["theta_first"] = rows.front().theta;
  j["theta_last"] = rows.back().theta;
  j["turns"] = (rows.back().theta - rows.front().theta) / (2 * std::numbers::pi);
  j["omega"] = json_number(body.spin.omega);
  j["sigma_omega"] = json_number(body.spin.sigma_omega);
  j["spin_rms_residual"] = json_number(body.spin.rms_residual);
  j["omega_local_min"] = json_number(wmin);
  j["omega_local_max"] = json_number(wmax);
  j["max_turn_per_frame"] = max_turn;
  j["length_mean"] = len.mean;
  j["length_sd"] = len.sd;
  j["length_min"] = len.min;
  j["length_max"] = len.max;
  j["length_drift"] = json_number(len.drift);
  j["sigma_length_drift"] = json_number(len.sigma_drift);
  j["length_drift_fraction"] = json_number(drift_fraction);
  j["length_scatter_fraction"] = json_number(scatter_fraction);
  j["warnings"] = warnings;
  j["out"] = options.out.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.out);
  j["report"] = options.report.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.report);
  result.json = std::move(j);
  // all or nothing: the CSV is committed only after the report is written
  std::unique_ptr<io::AtomicFile> csv;
  if (!options.out.empty()) {
    csv = std::make_unique<io::AtomicFile>(options.out);
    write_csv(csv->stream(), body);
  }
  if (!options.report.empty()) report::write_html(track_rigid_body_report(result, set.source), options.report, options.plotly);
  if (csv) csv->commit();
  return result;
}


const ResultKeys& track_rigid_body_result_keys() {
  static const ResultKeys k = {
      {"source", "", ""}, {"track_a", "", ""}, {"track_b", "", ""}, {"frames", "", ""}, {"frame_first", "", ""},
      {"frame_last", "", ""}, {"t_first", "s", ""}, {"t_last", "s", ""}, {"time_scale", "", ""},
      {"window", "", "points per local fit"}, {"centre_first.x", "m", ""}, {"centre_first.y", "m", ""},
      {"centre_last.x", "m", ""}, {"centre_last.y", "m", ""}, {"theta_first", "rad", ""}, {"theta_last", "rad", ""},
      {"turns", "", ""}, {"omega", "rad/s", ""}, {"spin_rms_residual", "rad", "of the orientation about the one-spin line"},
      {"omega_local_min", "rad/s", ""}, {"omega_local_max", "rad/s", ""}, {"max_turn_per_frame", "rad", ""},
      {"length_mean", "m", "A-B distance"}, {"length_sd", "m", ""}, {"length_min", "m", ""}, {"length_max", "m", ""},
      {"length_drift", "m", "end-to-end change of the A-B distance"}, {"length_drift_fraction", "", "of length_mean"},
      {"length_scatter_fraction", "", "length_sd / length_mean"}, {"warnings", "", ""}, {"out", "", ""},
      {"report", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
