#include "app/track/track_rotation.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"

#include "app/common/output_paths.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <ostream>

namespace tribolab::app {

namespace {

/// A CSV cell: shortest round-trip number, empty for NaN.

void write_csv(std::ostream& out, const track::PivotRotation& r) {
  out << "frame,t,x,y,theta,radius,omega,sigma_omega\n";
  for (const auto& p : r.rows) {
    out << p.frame << ',' << io::csv_number(p.t) << ',' << io::csv_number(p.x) << ',' << io::csv_number(p.y) << ',' << io::csv_number(p.theta) << ','
        << io::csv_number(p.radius) << ',' << io::csv_number(p.omega) << ',' << io::csv_number(p.sigma_omega) << '\n';
  }
}

/// What the data cannot carry, in words (docs/theory.md#rotation-about-a-pivot).
std::vector<std::string> rotation_warnings(const track::PivotRotation& r) {
  std::vector<std::string> w;
  if (r.max_turn > std::numbers::pi / 2) {
    w.push_back(fmt::format("the point turns by up to {:.2f} rad ({:.0f} deg) between frames: near pi the direction "
                            "of the turn is ambiguous and the spin may be aliased (a higher frame rate helps)",
                            r.max_turn, to_deg(r.max_turn)));
  }
  // A point on one rotating body keeps its distance to the pivot: residuals of 5 % of the
  // radius are far above tracking noise (a few px on a wheel of a hundred).
  if (r.rms_residual > 0.05 * r.radius) {
    w.push_back(fmt::format("the point strays from its circle by {:.2g} m rms ({:.1f} % of the radius {:.3g} m): it "
                            "does not turn about one {} pivot (a rolling wheel's axle moves: {}; a car "
                            "entering and leaving a loop is on a circle only part of the time: keep that part with "
                            "{}/{})",
                            r.rms_residual, 100 * r.rms_residual / r.radius, r.radius,
                            r.pivot_vx == 0 && r.pivot_vy == 0 ? "fixed" : "uniformly moving", field("moving_pivot"),
                            field("t_from"), field("t_to")));
  }
  // omega(t) = omega + alpha u is the model; local spins beyond 5 of their sigmas + 2 % in
  // more than a tenth of the frames mean it is not (a pendulum's spin swings back and forth)
  std::size_t n_local = 0, n_off = 0;
  for (const auto& p : r.rows) {
    if (!std::isfinite(p.omega) || !std::isfinite(p.sigma_omega)) continue;
    ++n_local;
    const double model = r.omega + r.alpha * (p.t - r.t_ref);
    n_off += std::abs(p.omega - model) > 5 * p.sigma_omega + 0.02 * std::abs(model);
  }
  if (n_local > 0 && n_off > n_local / 10) {
    w.push_back(fmt::format("the spin does not change uniformly: in {} of {} frames the local spin differs from "
                            "omega + alpha (t - t_ref) beyond its noise; omega and alpha summarise a spin that "
                            "swings or jumps (a pendulum, a push): read the local spins (--out)",
                            n_off, n_local));
  }
  return w;
}

}  // namespace

TrackRotationResult track_rotation(const TrackRotationOptions& options) {
  check_output_paths({options.input.file}, {{"out", options.out}});  // before any work (app/common/output_paths.hpp)
  track::PivotOptions po;
  po.pivot_x = options.pivot_x;
  po.pivot_y = options.pivot_y;
  po.moving_pivot = options.moving_pivot;
  po.window = options.window;
  if (const auto err = po.validate(); !err.empty()) throw InputError(err);
  std::vector<std::string> wanted;
  if (!options.track.empty()) wanted = {options.track};
  const track::TrackSet set = io::read_tracks(options.input.file, import_options(options.input, wanted));
  const track::Track tr = restrict_times(choose_track(set, options.track), options.t_from, options.t_to,
                                        options.moving_pivot ? 8 : 6, set.source);
  TrackRotationResult result;
  try {
    result.rotation = track::rotation_about_pivot(tr, po);
  } catch (const InputError& e) {
    throw InputError(set.source, e.message([](std::string_view f) { return field(f); }));
  }
  const track::PivotRotation& r = result.rotation;
  std::vector<std::string> warnings = set.warnings;
  for (auto& w : rotation_warnings(r)) warnings.push_back(std::move(w));

  nlohmann::json& j = result.json;
  j["source"] = set.source;
  j["track"] = tr.name;
  j["points"] = r.rows.size();
  j["frame_first"] = r.rows.front().frame;
  j["frame_last"] = r.rows.back().frame;
  j["t_first"] = r.rows.front().t;
  j["t_last"] = r.rows.back().t;
  j["time_scale"] = set.time_scale;
  j["pivot"] = po.pivot_given() ? "given" : (po.moving_pivot ? "moving" : "fitted");
  j["pivot_from_circle"] = r.pivot_from_circle;
  j["t_ref"] = r.t_ref;
  j["pivot_x"] = r.pivot_x;
  j["pivot_y"] = r.pivot_y;
  j["sigma_pivot_x"] = json_number(r.sigma_pivot_x);
  j["sigma_pivot_y"] = json_number(r.sigma_pivot_y);
  j["pivot_vx"] = r.pivot_vx;
  j["pivot_vy"] = r.pivot_vy;
  j["sigma_pivot_vx"] = json_number(r.sigma_pivot_vx);
  j["sigma_pivot_vy"] = json_number(r.sigma_pivot_vy);
  j["radius"] = r.radius;
  j["sigma_radius"] = json_number(r.sigma_radius);
  j["theta_ref"] = r.theta_ref;
  j["sigma_theta_ref"] = json_number(r.sigma_theta_ref);
  j["omega"] = r.omega;
  j["sigma_omega"] = json_number(r.sigma_omega);
  j["alpha"] = r.alpha;
  j["sigma_alpha"] = json_number(r.sigma_alpha);
  j["rms_residual"] = json_number(r.rms_residual);
  j["arc_deg"] = to_deg(r.arc);
  j["turns"] = r.arc / (2 * std::numbers::pi);
  j["max_turn_per_frame_deg"] = to_deg(r.max_turn);
  double wmin = NAN, wmax = NAN;
  for (const auto& p : r.rows) {
    if (!std::isfinite(p.omega)) continue;
    wmin = std::isfinite(wmin) ? std::min(wmin, p.omega) : p.omega;
    wmax = std::isfinite(wmax) ? std::max(wmax, p.omega) : p.omega;
  }
  j["omega_local_min"] = json_number(wmin);
  j["omega_local_max"] = json_number(wmax);
  j["t_from"] = json_number(options.t_from);  // null: not given
  j["t_to"] = json_number(options.t_to);
  j["kasa_circle"] = po.pivot_given() || po.moving_pivot ? nlohmann::json(nullptr)
                                      : nlohmann::json{{"x", r.kasa.x}, {"y", r.kasa.y}, {"r", r.kasa.r}};
  j["warnings"] = warnings;
  j["out"] = options.out.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.out);
  if (!options.out.empty()) {
    io::AtomicFile f(options.out);
    write_csv(f.stream(), r);
    f.commit();
  }
  return result;
}


const ResultKeys& track_rotation_result_keys() {
  static const ResultKeys k = {
      {"source", "", ""}, {"track", "", ""}, {"points", "", ""}, {"frame_first", "", ""}, {"frame_last", "", ""},
      {"t_first", "s", ""}, {"t_last", "s", ""}, {"time_scale", "", ""}, {"pivot", "", "given, fitted or moving"},
      {"pivot_from_circle", "", ""}, {"t_ref", "s", "time of theta_ref and of the pivot position"},
      {"pivot_x", "m", ""}, {"pivot_y", "m", ""}, {"pivot_vx", "m/s", ""}, {"pivot_vy", "m/s", ""},
      {"radius", "m", ""}, {"theta_ref", "rad", ""}, {"omega", "rad/s", ""}, {"alpha", "rad/s^2", ""},
      {"rms_residual", "m", "per coordinate"}, {"arc_deg", "deg", ""}, {"turns", "", ""},
      {"max_turn_per_frame_deg", "deg", ""}, {"omega_local_min", "rad/s", ""}, {"omega_local_max", "rad/s", ""},
      {"t_from", "s", ""}, {"t_to", "s", ""}, {"kasa_circle.x", "m", ""}, {"kasa_circle.y", "m", ""},
      {"kasa_circle.r", "m", ""}, {"kasa_circle", "", "null: pivot given or moving"}, {"warnings", "", ""}, {"out", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
