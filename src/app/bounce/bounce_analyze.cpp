#include "app/common/study_citation.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"
#include "app/bounce/bounce_analyze.hpp"

#include "app/common/output_paths.hpp"

#include "app/bounce/report_bounce_analysis.hpp"

#include "io/atomic_file.hpp"
#include "io/bounce_table.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <cmath>
#include <filesystem>
#include <utility>

namespace tribolab::app {
namespace {

using nlohmann::json;
using analysis::BounceAnalysis;
using analysis::SegmentFit;

json segment_json(const SegmentFit& s) {
  return {{"vx", s.vx}, {"sigma_vx", json_number(s.sigma_vx)}, {"vy", s.vy}, {"sigma_vy", s.sigma_vy},
          {"omega", json_number(s.omega)}, {"sigma_omega", json_number(s.sigma_omega)},
          {"ay", s.acceleration_y}, {"sigma_ay", s.sigma_acceleration_y},
          {"r_squared", {{"x", s.x_line.r_squared}, {"y", s.y_parabola.r_squared}}},
          {"n_points", s.n_points}, {"apex_time", s.apex_time},
          {"apex_height", json_number(s.apex_height)}, {"sigma_apex_height", json_number(s.sigma_apex_height)},
          {"energy", {{"translational_x", s.energy.translational_x}, {"translational_y", s.energy.translational_y},
                      {"rotational", s.energy.rotational}, {"total", s.energy.total()}}}};
}

}  // namespace

json bounce_analysis_json(const BounceAnalysis& r) {
  json j = {{"impact_time", r.impact_time},
            {"pre", segment_json(r.pre)},
            {"post", segment_json(r.post)},
            {"e_velocity", json_number(r.e_velocity)},
            {"sigma_e_velocity", json_number(r.sigma_e_velocity)},
            {"e_height", json_number(r.e_height)},
            {"sigma_e_height", json_number(r.sigma_e_height)},
            {"floor_y", r.floor_y},
            {"floor_given", r.floor_given},
            {"floor_half_width", r.floor_half_width},
            {"floor_method", to_string(r.floor_method)},
            {"theta_impact_deg", r.theta_impact_deg},
            {"collision_angle_deg", json_number(r.collision_angle_deg)},
            {"sigma_collision_angle_deg", json_number(r.sigma_collision_angle_deg)},
            {"collision_angle_impact_deg", json_number(r.collision_angle_impact_deg)},
            {"t_touch", r.t_touch},
            {"sigma_t_touch", json_number(r.sigma_t_touch)},
            {"t_separation", r.t_separation},
            {"sigma_t_separation", json_number(r.sigma_t_separation)},
            {"contact_duration", r.contact_duration},
            {"sigma_contact_duration", json_number(r.sigma_contact_duration)},
            {"theta_touch_deg", r.theta_touch_deg},
            {"sigma_theta_touch_deg", json_number(r.sigma_theta_touch_deg)},
            {"vy_touch", r.vy_touch},
            {"sigma_vy_touch", json_number(r.sigma_vy_touch)},
            {"vy_separation", r.vy_separation},
            {"sigma_vy_separation", json_number(r.sigma_vy_separation)},
            {"e_velocity_common", json_number(r.e_velocity_common)},
            {"sigma_e_velocity_common", json_number(r.sigma_e_velocity_common)},
            {"contact_point_vx", json_number(r.contact_point_vx)},
            {"contact_point_vy", json_number(r.contact_point_vy)},
            {"contact_point_speed", json_number(r.contact_point_speed)},
            {"sigma_contact_point_vx", json_number(r.sigma_contact_point_vx)},
            {"sigma_contact_point_vy", json_number(r.sigma_contact_point_vy)},
            {"sigma_contact_point_speed", json_number(r.sigma_contact_point_speed)},
            {"energy_pre", r.pre.energy.total()},
            {"energy_post", r.post.energy.total()},
            {"n_impacts", r.impacts.impacts.size()},
            {"noise", r.impacts.noise_y},
            {"tip_distance_mean", r.body.length_mean},
            {"tip_distance_sd", r.body.length_sd},
            {"gravity", r.gravity},
            {"sigma_gravity", json_number(r.sigma_gravity)},
            {"gravity_tilt_deg", r.gravity_tilt_deg},
            {"sigma_gravity_tilt_deg", json_number(r.sigma_gravity_tilt_deg)},
            {"warnings", r.warnings}};
  if (r.mean_normal_force) {
    j["mean_normal_force"] = json_number(*r.mean_normal_force);
    j["sigma_mean_normal_force"] = json_number(*r.sigma_mean_normal_force);
    j["force_duration_method"] = to_string(r.force_duration_method);
  }
  return j;
}

void check_bounces_out_path(const std::string& path) { check_output_paths({}, {{"bounces_out", path}}); }

analysis::BounceAnalyzeOptions BounceAnalyzeOptions::checked() const {
  analysis::BounceAnalyzeOptions o;
  o.ball = ball.ball;
  checked_ball(o.ball);
  check_range(time_scale, ranges::time_scale, field("time_scale"));  // docs/cli.md#physical-ranges
  if (!std::isfinite(time_scale) || !(time_scale > 0)) throw InputError(field("time_scale"), "must be positive");
  if (!(std::isfinite(sigma_floor_y) && sigma_floor_y >= 0 && sigma_floor_y < 1))
    throw InputError(field("sigma_floor_y"), "must lie in [0, 1) m");
  if (track_a == track_b) throw InputError(field("track_b"), "must name a different track than " + field("track_a"));
  check_output_paths({file}, {{"bounces_out", bounces_out}, {"report", report}});  // before any work
  if (floor_y) {
    check_range(*floor_y, ranges::position, field("floor_y"));  // docs/cli.md#physical-ranges
    check_finite(*floor_y, field("floor_y"));
  }
  if (contact_duration) {
    const double T = *contact_duration;
    check_range(T, PhysicalRange{0, 10, "s", true}, field("contact_duration"));
    if (!(std::isfinite(T) && T > 0)) throw InputError(field("contact_duration"), "must be a positive number of seconds");
  }
  o.floor_y = floor_y;
  o.sigma_floor_y = sigma_floor_y;
  o.contact_duration = contact_duration;
  o.exclude = exclude;
  o.impact = impact;
  return o;
}

BounceAnalyzeResult bounce_analyze_run(const BounceAnalyzeOptions& opts, const analysis::BounceAnalyzeOptions& o) {
  io::ImportOptions io;
  io.time_scale = opts.time_scale;
  io.length_unit = opts.length_unit;
  io.tracks = {opts.track_a, opts.track_b};
  const auto set = io::read_tracks(opts.file, io);
  BounceAnalyzeResult res;
  res.tip_a = set.find(opts.track_a);
  res.tip_b = set.find(opts.track_b);
  res.analysis = analysis::analyze_bounce(res.tip_a, res.tip_b, o);
  // What the importer left out (lost frames, marks off the clip's steps) is said first.
  res.analysis.warnings.insert(res.analysis.warnings.begin(), set.warnings.begin(), set.warnings.end());
  res.json = bounce_analysis_json(res.analysis);
  return res;
}

std::string bounce_analyze_command(const BounceAnalyzeOptions& o) {
  std::string c = "tribolab bounce analyze " + o.file + " --track-a " + o.track_a + " --track-b " + o.track_b +
                  " --time-scale " + io::format_number(o.time_scale);
  if (o.floor_y) c += " --floor-y " + io::format_number(*o.floor_y);
  if (o.sigma_floor_y > 0) c += " --sigma-floor-y " + io::format_number(o.sigma_floor_y);
  if (o.contact_duration) c += " --contact-duration " + io::format_number(*o.contact_duration);
  return c;
}

void write_bounces_out(const std::string& path, const std::vector<analysis::BounceSeriesPoint>& points,
                       const std::vector<std::string>& files) {
  // A plain table (no comment line) that a spreadsheet and a naive CSV reader open: each row's
  // file is its last column, quoted where it holds a comma or a quote (docs/design.md#spreadsheets).
  // The reader is line-based, so a line break in a name is written as '?'.
  std::vector<analysis::BounceRow> rows;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string name = files[i];
    for (char& c : name)
      if (c == '\n' || c == '\r') c = '?';
    names.push_back(name);
    rows.push_back(analysis::bounce_row_of(points[i]));
  }
  io::AtomicFile file(path);
  file.stream() << io::write_bounce_table(rows, names);
  file.commit();
}

BounceAnalyzeResult bounce_analyze(const BounceAnalyzeOptions& opts) {
  const analysis::BounceAnalyzeOptions o = opts.checked();
  BounceAnalyzeResult res = bounce_analyze_run(opts, o);
  if (!opts.bounces_out.empty()) {
    write_bounces_out(opts.bounces_out, {analysis::point_of(res.analysis)}, {opts.file});
    res.json["bounces_out"] = opts.bounces_out;
  }
  if (!opts.report.empty())
    report::write_html(with_study_source(bounce_analyze_report(bounce_analyze_command(opts), o.ball, res.analysis), Study::rugby_ball), opts.report, opts.plotly);
  return res;
}

const Fields<BounceFitOptions>& bounce_fit_fields() {
  using O = BounceFitOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("file", &O::file, "", "CSV with header theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out")
        .as(FieldRole::input_files)
        .needed();
    d.add("model", &O::model, "", "normal law").one_of(bounce::normal_model_names());
    d.add("restitution", &O::restitution, "", "fit the target restitution e instead of D (restitution-based law)");
    d.add("friction", &O::friction, "", "friction model").one_of(bounce::friction_kind_names());
    d.add("slip_scale", &O::slip_scale, "m/s", "v_s of the regularized law");
    d.group(&O::ball, ball_fields());
    d.add("fix", &O::fix, "", "hold a parameter: NAME=VALUE with NAME in K, n, D, e, mu (repeatable)");
    d.add("loss", &O::loss, "", "robust loss").one_of({"huber", "cauchy", "none"});
    d.add("loss_scale", &O::loss_scale, "m/s", "residual where the robust loss bends").in(PhysicalRange{0, 1e3, "m/s", true});
    d.add("K0", &O::K0, "N/m^n", "starting K").in(ranges::stiffness);
    d.add("n0", &O::n0, "", "starting n").in(PhysicalRange{1, 3, ""});
    d.add("D0", &O::D0, "N s/m^(n+1)", "starting D").in(PhysicalRange{0, 1e12, "N s/m^(n+1)", true});
    d.add("e0", &O::e0, "", "starting e").in(PhysicalRange{0.02, 1, "", true});
    d.add("mu0", &O::mu0, "", "starting mu").in(PhysicalRange{0, 3, ""});
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

BounceFitResult bounce_fit(const BounceFitOptions& opts) {
  check_output_paths({opts.file}, {{"report", opts.report}});  // before any work (app/common/output_paths.hpp)
  analysis::BounceFitOptions o;
  o.ball = opts.ball.ball;
  checked_ball(o.ball);
  o.model = parsed_model(opts.model);
  o.restitution_model = opts.restitution;
  o.friction.kind = parsed_friction(opts.friction);
  o.friction.slip_scale = opts.slip_scale;
  check_finite(o.friction.slip_scale, field("slip_scale"));
  o.K0 = opts.K0;
  o.n0 = opts.n0;
  o.D0 = opts.D0;
  o.e0 = opts.e0;
  o.mu0 = opts.mu0;
  o.loss_scale = opts.loss_scale;
  for (auto [v, name] : {std::pair{o.K0, field("K0")}, {o.n0, field("n0")}, {o.D0, field("D0")}, {o.e0, field("e0")}, {o.mu0, field("mu0")}, {o.loss_scale, field("loss_scale")}})
    check_finite(v, name);
  // the starting values' bounds are the fit's own (the declared ranges say them for the schema)
  if (!(o.n0 >= 1 && o.n0 <= 3)) throw InputError(field("n0"), "must lie in [1, 3]");
  if (!(o.e0 > 0.02 && o.e0 <= 1)) throw InputError(field("e0"), "must lie in (0.02, 1]");
  if (!(o.mu0 >= 0 && o.mu0 <= 3)) throw InputError(field("mu0"), "must lie in [0, 3]");
  check_ranges(opts, bounce_fit_fields());  // K0, D0, loss_scale (docs/cli.md#physical-ranges)
  if (opts.loss == "huber") o.loss = numerics::RobustLoss::huber;
  else if (opts.loss == "cauchy") o.loss = numerics::RobustLoss::cauchy;
  else if (opts.loss == "none") o.loss = numerics::RobustLoss::none;
  else throw InputError(field("loss"), "unknown loss '" + opts.loss + "' (huber, cauchy, none)");
  for (const auto& f : opts.fix) {
    const auto eq = f.find('=');
    if (eq == std::string::npos) throw InputError(field("fix"), "expected NAME=VALUE, got '" + f + "'");
    const std::string name = f.substr(0, eq);
    if (name != "K" && name != "n" && name != "D" && name != "e" && name != "mu")
      throw InputError(field("fix"), "unknown parameter '" + name + "' (K, n, D, e, mu)");
    o.fixed[name] = io::parse_double(f.substr(eq + 1), field("fix") + " " + name);
  }
  BounceFitResult res;
  res.rows = io::read_bounce_table(opts.file);
  res.fit = analysis::fit_bounces(res.rows, o);
  const auto& r = res.fit;
  json residuals = json::array();
  for (std::size_t i = 0; i < res.rows.size(); ++i) {
    const auto& p = r.rows[i];
    residuals.push_back({{"row", i + 1}, {"vx_pred", json_number(p.vx_pred)}, {"vy_pred", json_number(p.vy_pred)},
                         {"omega_pred", json_number(p.omega_pred)}, {"r_vx", json_number(p.r_vx)}, {"r_vy", json_number(p.r_vy)},
                         {"r_b_omega", json_number(p.r_b_omega)}});
  }
  json j = {{"K", r.K}, {"sigma_K", r.sigma_K}, {"n", r.n}, {"sigma_n", r.sigma_n},
            {"D", json_number(r.D)}, {"sigma_D", json_number(r.sigma_D)}, {"mu", r.mu}, {"sigma_mu", r.sigma_mu},
            {"rms", r.rms}, {"n_rows", res.rows.size()}, {"dof", r.fit.dof},
            {"iterations", r.fit.iterations}, {"free_parameters", r.free_parameters},
            {"rows_touching_again", r.touching_again}, {"rows_left_out", r.left_out}};
  if (o.restitution_model) {
    j["e"] = r.e;
    j["sigma_e"] = r.sigma_e;
  }
  j["residuals"] = residuals;
  j["warnings"] = r.warnings;  // parameters at a bound (docs/theory.md#plausibility-checks)
  res.json = std::move(j);
  if (!opts.report.empty()) {
    std::string command = "tribolab bounce fit " + opts.file + " --model " + opts.model + " --friction " + opts.friction;
    if (o.restitution_model) command += " --restitution";
    for (const auto& f : opts.fix) command += " --fix " + f;
    report::write_html(with_study_source(bounce_fit_report(command, res.rows, o, res.fit), Study::rugby_ball), opts.report, opts.plotly);
  }
  return res;
}


const ResultKeys& bounce_analyze_result_keys() {
  static const ResultKeys k = {
      {"impact_time", "s", ""},
      {"pre.vx", "m/s", ""}, {"pre.vy", "m/s", ""}, {"pre.omega", "rad/s", ""},
      {"pre.ay", "m/s^2", "vertical acceleration of the fitted parabola"},
      {"pre.r_squared.x", "", "R^2 of the x-t line"}, {"pre.r_squared.y", "", "R^2 of the y-t parabola"},
      {"pre.n_points", "", ""}, {"pre.apex_time", "s", ""}, {"pre.apex_height", "m", ""},
      {"pre.energy.*", "J", "translational_x, translational_y, rotational, total"},
      {"post.vx", "m/s", ""}, {"post.vy", "m/s", ""}, {"post.omega", "rad/s", ""},
      {"post.ay", "m/s^2", "vertical acceleration of the fitted parabola"},
      {"post.r_squared.x", "", "R^2 of the x-t line"}, {"post.r_squared.y", "", "R^2 of the y-t parabola"},
      {"post.n_points", "", ""}, {"post.apex_time", "s", ""}, {"post.apex_height", "m", ""},
      {"post.energy.*", "J", "translational_x, translational_y, rotational, total"},
      {"e_velocity", "", "restitution from the velocities"},
      {"e_height", "", "restitution from the apex heights"},
      {"floor_y", "m", ""}, {"floor_given", "", ""}, {"floor_half_width", "m", ""}, {"floor_method", "", ""},
      {"theta_impact_deg", "deg", ""}, {"collision_angle_deg", "deg", ""}, {"collision_angle_impact_deg", "deg", ""},
      {"t_touch", "s", ""}, {"t_separation", "s", ""}, {"contact_duration", "s", ""}, {"theta_touch_deg", "deg", ""},
      {"vy_touch", "m/s", ""}, {"vy_separation", "m/s", ""}, {"e_velocity_common", "", ""},
      {"contact_point_vx", "m/s", ""}, {"contact_point_vy", "m/s", ""}, {"contact_point_speed", "m/s", ""},
      {"energy_pre", "J", ""}, {"energy_post", "J", ""}, {"n_impacts", "", ""}, {"noise", "m", "position noise"},
      {"tip_distance_mean", "m", ""}, {"tip_distance_sd", "m", ""}, {"gravity", "m/s^2", "fitted g"},
      {"gravity_tilt_deg", "deg", ""}, {"warnings", "", ""}, {"mean_normal_force", "N", ""},
      {"force_duration_method", "", ""}, {"bounces_out", "", ""},
      {"file", "", "a run of several files"}, {"error", "", "why the run failed"},
  };
  return k;
}

const ResultKeys& bounce_fit_result_keys() {
  static const ResultKeys k = {
      {"K", "N/m^n", "stiffness"}, {"n", "", "exponent"}, {"D", "N s/m^(n+1)", "damping (null with --restitution)"},
      {"e", "", "target restitution (--restitution)"}, {"mu", "", ""},
      {"rms", "m/s", "of the residuals vx, vy and b omega"}, {"n_rows", "", ""}, {"dof", "", ""},
      {"iterations", "", ""}, {"free_parameters", "", ""}, {"residuals.row", "", ""},
      {"residuals.vx_pred", "m/s", ""}, {"residuals.vy_pred", "m/s", ""}, {"residuals.omega_pred", "rad/s", ""},
      {"residuals.r_vx", "m/s", ""}, {"residuals.r_vy", "m/s", ""},
      {"residuals.r_b_omega", "m/s", "b times the omega residual"}, {"warnings", "", ""},
      {"rows_touching_again", "", "rows whose impact under the fitted law has a second contact (predicted whole)"},
      {"rows_left_out", "", "rows left out: their outcome jumps at the fitted law (a touch at the apex)"},
  };
  return k;
}
}  // namespace tribolab::app
