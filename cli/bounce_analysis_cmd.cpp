// `tribolab bounce analyze|fit|synth-video|synth-table`: seed 001's experiment 1 on tracked
// data, the contact-law fit to a table of bounces, and the synthetic data for both
// (docs/cli.md#bounce-analyze).
#include "bounce_analysis_cmd.hpp"

#include "app.hpp"
#include "bounce_options.hpp"
#include "report_bounce_analysis.hpp"
#include "report_option.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_synth.hpp"
#include "io/atomic_file.hpp"
#include "io/bounce_table.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using nlohmann::json;
using namespace tribolab::analysis;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

bounce::NormalModel parse_model(const std::string& name) {
  const auto m = bounce::parse_normal_model(name);
  if (!m) throw InputError("--model", "unknown model '" + name + "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
  return *m;
}

bounce::FrictionKind parse_friction(const std::string& name) {
  const auto k = bounce::parse_friction_kind(name);
  if (!k) throw InputError("--friction", "unknown friction model '" + name + "' (coulomb, regularized, spring)");
  return *k;
}

/// The contact law of the synthetic generators (truth).
struct TruthLaw {
  std::string model = "hunt-crossley", friction = "coulomb";
  double K = 101054, n = 1.51, D = 60423, mu = 0.5, slip_scale = 0.01;
  std::optional<double> restitution;
  void add(CLI::App* cmd) {
    cmd->add_option("--model", model, "normal law (default hunt-crossley)");
    cmd->add_option("--K", K, "stiffness, N/m^n (default 101054)");
    cmd->add_option("--n", n, "exponent (default 1.51)");
    cmd->add_option("--D", D, "damping, N s/m^(n+1) (default 60423)");
    cmd->add_option("--restitution", restitution, "target restitution instead of --D");
    cmd->add_option("--mu", mu, "friction coefficient (default 0.5)");
    cmd->add_option("--friction", friction, "coulomb|regularized|spring (default coulomb)");
    cmd->add_option("--slip-scale", slip_scale, "v_s of the regularized law, m/s (default 0.01)");
  }
  void apply(bounce::NormalLawSpec& s, bounce::FrictionModel& f) const {
    for (auto [v, name] : {std::pair{K, "--K"}, {n, "--n"}, {D, "--D"}, {mu, "--mu"}, {slip_scale, "--slip-scale"}})
      check_finite(v, name);
    s.model = parse_model(model);
    s.K = K;
    s.n = s.model == bounce::NormalModel::hooke ? 1.0 : n;
    s.D = s.model == bounce::NormalModel::hertz ? 0.0 : D;
    s.restitution = restitution;
    if (auto e = s.validate(); !e.empty()) invalid(e);
    f.kind = parse_friction(friction);
    f.mu = mu;
    f.slip_scale = slip_scale;
    if (auto e = f.validate(); !e.empty()) invalid(e);
  }
};

json segment_json(const SegmentFit& s) {
  return {{"vx", s.vx}, {"sigma_vx", num(s.sigma_vx)}, {"vy", s.vy}, {"sigma_vy", s.sigma_vy},
          {"omega", num(s.omega)}, {"sigma_omega", num(s.sigma_omega)},
          {"ay", s.acceleration_y}, {"sigma_ay", s.sigma_acceleration_y},
          {"r_squared", {{"x", s.x_line.r_squared}, {"y", s.y_parabola.r_squared}}},
          {"n_points", s.n_points}, {"apex_time", s.apex_time},
          {"apex_height", num(s.apex_height)}, {"sigma_apex_height", num(s.sigma_apex_height)},
          {"energy", {{"translational_x", s.energy.translational_x}, {"translational_y", s.energy.translational_y},
                      {"rotational", s.energy.rotational}, {"total", s.energy.total()}}}};
}

void add_analyze(CLI::App* area) {
  struct Opts {
    std::string file, a, b;
    double time_scale = 1;
    std::string length_unit;
    BounceAnalyzeOptions o;
    std::optional<double> floor_y, contact_duration;
    std::string report;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("analyze", "seed 001 experiment 1: v, omega, e and energies before/after one bounce from the two tracked tips");
  cmd->add_option("FILE", opts->file, "Tracker .trk/.trz, Export Data text or tidy CSV")->required();
  cmd->add_option("--track-a", opts->a, "name of the track of tip A")->required();
  cmd->add_option("--track-b", opts->b, "name of the track of tip B")->required();
  cmd->add_option("--time-scale", opts->time_scale, "real seconds per file second (240 fps shown at 30: 0.125; default 1)");
  cmd->add_option("--length-unit", opts->length_unit, "unit of the file's lengths, overriding the file (m, cm, mm, ...)");
  add_ball_options(cmd, opts->o.ball);
  cmd->add_option("--floor-y", opts->floor_y, "floor height in the file's frame, m (default: from the flights and --contact-duration; needed for e_height without it)");
  cmd->add_option("--sigma-floor-y", opts->o.sigma_floor_y, "standard uncertainty of --floor-y, m (default 0)");
  cmd->add_option("--contact-duration", opts->contact_duration, "contact duration, s (to half a frame): enables mean_normal_force, and locates the floor when --floor-y is not given");
  cmd->add_option("--exclude", opts->o.exclude, "points always dropped on each side of the impact (default 0; contact frames are dropped automatically)");
  cmd->add_option("--impact", opts->o.impact, "which detected impact to analyse (default 1)");
  add_report_option(*cmd, opts->report);
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    checked_ball(opts->o.ball);
    check_range(opts->time_scale, ranges::time_scale, "--time-scale");  // docs/cli.md#physical-ranges
    if (opts->floor_y) check_range(*opts->floor_y, ranges::position, "--floor-y");
    if (opts->contact_duration) check_range(*opts->contact_duration, PhysicalRange{0, 10, "s", true}, "--contact-duration");
    if (!std::isfinite(opts->time_scale) || !(opts->time_scale > 0)) throw InputError("--time-scale", "must be positive");
    if (opts->floor_y) check_finite(*opts->floor_y, "--floor-y");
    if (!(std::isfinite(opts->o.sigma_floor_y) && opts->o.sigma_floor_y >= 0 && opts->o.sigma_floor_y < 1))
      throw InputError("--sigma-floor-y", "must lie in [0, 1) m");
    if (opts->contact_duration && !(std::isfinite(*opts->contact_duration) && *opts->contact_duration > 0))
      throw InputError("--contact-duration", "must be a positive number of seconds");
    io::ImportOptions io;
    io.time_scale = opts->time_scale;
    io.length_unit = opts->length_unit;
    io.tracks = {opts->a, opts->b};
    if (opts->a == opts->b) throw InputError("--track-b", "must name a different track than --track-a");
    const auto set = io::read_tracks(opts->file, io);
    BounceAnalyzeOptions o = opts->o;
    o.floor_y = opts->floor_y;
    o.contact_duration = opts->contact_duration;
    const auto r = analyze_bounce(set.find(opts->a), set.find(opts->b), o);
    json j = {{"impact_time", r.impact_time},
              {"pre", segment_json(r.pre)},
              {"post", segment_json(r.post)},
              {"e_velocity", num(r.e_velocity)},
              {"sigma_e_velocity", num(r.sigma_e_velocity)},
              {"e_height", num(r.e_height)},
              {"sigma_e_height", num(r.sigma_e_height)},
              {"floor_y", r.floor_y},
              {"floor_given", r.floor_given},
              {"floor_half_width", r.floor_half_width},
              {"floor_method", r.floor_method},
              {"theta_impact_deg", r.theta_impact_deg},
              {"collision_angle_deg", num(r.collision_angle_deg)},
              {"sigma_collision_angle_deg", num(r.sigma_collision_angle_deg)},
              {"collision_angle_impact_deg", num(r.collision_angle_impact_deg)},
              {"t_touch", r.t_touch},
              {"sigma_t_touch", num(r.sigma_t_touch)},
              {"t_separation", r.t_separation},
              {"sigma_t_separation", num(r.sigma_t_separation)},
              {"contact_duration", r.contact_duration},
              {"sigma_contact_duration", num(r.sigma_contact_duration)},
              {"theta_touch_deg", r.theta_touch_deg},
              {"sigma_theta_touch_deg", num(r.sigma_theta_touch_deg)},
              {"vy_touch", r.vy_touch},
              {"sigma_vy_touch", num(r.sigma_vy_touch)},
              {"vy_separation", r.vy_separation},
              {"sigma_vy_separation", num(r.sigma_vy_separation)},
              {"e_velocity_common", num(r.e_velocity_common)},
              {"sigma_e_velocity_common", num(r.sigma_e_velocity_common)},
              {"contact_point_vx", num(r.contact_point_vx)},
              {"contact_point_vy", num(r.contact_point_vy)},
              {"contact_point_speed", num(r.contact_point_speed)},
              {"sigma_contact_point_vx", num(r.sigma_contact_point_vx)},
              {"sigma_contact_point_vy", num(r.sigma_contact_point_vy)},
              {"sigma_contact_point_speed", num(r.sigma_contact_point_speed)},
              {"energy_pre", r.pre.energy.total()},
              {"energy_post", r.post.energy.total()},
              {"n_impacts", r.impacts.impacts.size()},
              {"noise", r.impacts.noise_y},
              {"tip_distance_mean", r.body.length_mean},
              {"tip_distance_sd", r.body.length_sd},
              {"gravity", r.gravity},
              {"sigma_gravity", num(r.sigma_gravity)},
              {"gravity_tilt_deg", r.gravity_tilt_deg},
              {"sigma_gravity_tilt_deg", num(r.sigma_gravity_tilt_deg)},
              {"warnings", r.warnings}};
    if (r.mean_normal_force) {
      j["mean_normal_force"] = num(*r.mean_normal_force);
      j["sigma_mean_normal_force"] = num(*r.sigma_mean_normal_force);
      j["force_duration_method"] = r.force_duration_method;
    }
    write_report_if_requested(opts->report, [&] {
      return bounce_analyze_report("tribolab bounce analyze " + opts->file + " --track-a " + opts->a + " --track-b " +
                                       opts->b + " --time-scale " + io::format_number(opts->time_scale),
                                   o.ball, r);
    });
    print_result(j, opts->json);
  });
}

void add_fit(CLI::App* area) {
  struct Opts {
    std::string file, model = "hunt-crossley", friction = "coulomb", loss = "huber";
    std::vector<std::string> fix;
    std::string report;
    bool restitution = false, json = false;
    BounceFitOptions o;
  };
  auto opts = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("fit", "fit the contact law (K, n, D or e, mu) to a table of measured bounces");
  cmd->add_option("FILE", opts->file, "CSV with header theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out")->required();
  cmd->add_option("--model", opts->model, "normal law: hooke|hertz|hunt-crossley|flores|lankarani-nikravesh|gonthier (default hunt-crossley)");
  cmd->add_flag("--restitution", opts->restitution, "fit the target restitution e instead of D (restitution-based law)");
  cmd->add_option("--friction", opts->friction, "coulomb|regularized|spring (default coulomb)");
  cmd->add_option("--slip-scale", opts->o.friction.slip_scale, "v_s of the regularized law, m/s (default 0.01)");
  add_ball_options(cmd, opts->o.ball);
  cmd->add_option("--fix", opts->fix, "hold a parameter: NAME=VALUE with NAME in K, n, D, e, mu (repeatable)");
  cmd->add_option("--loss", opts->loss, "robust loss: huber|cauchy|none (default huber)");
  cmd->add_option("--loss-scale", opts->o.loss_scale, "residual where the robust loss bends, m/s (default 0.05)");
  cmd->add_option("--K0", opts->o.K0, "starting K, N/m^n (default 1e5)");
  cmd->add_option("--n0", opts->o.n0, "starting n (default 1.5)");
  cmd->add_option("--D0", opts->o.D0, "starting D (default 5e4)");
  cmd->add_option("--e0", opts->o.e0, "starting e (default 0.8)");
  cmd->add_option("--mu0", opts->o.mu0, "starting mu (default 0.5)");
  add_report_option(*cmd, opts->report);
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    BounceFitOptions o = opts->o;
    checked_ball(o.ball);
    o.model = parse_model(opts->model);
    o.restitution_model = opts->restitution;
    o.friction.kind = parse_friction(opts->friction);
    check_finite(o.friction.slip_scale, "--slip-scale");
    for (auto [v, name] : {std::pair{o.K0, "--K0"}, {o.n0, "--n0"}, {o.D0, "--D0"}, {o.e0, "--e0"}, {o.mu0, "--mu0"}, {o.loss_scale, "--loss-scale"}})
      check_finite(v, name);
    check_range(o.K0, ranges::stiffness, "--K0");  // docs/cli.md#physical-ranges
    check_range(o.D0, PhysicalRange{0, 1e12, "N s/m^(n+1)", true}, "--D0");
    check_range(o.loss_scale, PhysicalRange{0, 1e3, "m/s", true}, "--loss-scale");
    if (!(o.n0 >= 1 && o.n0 <= 3)) throw InputError("--n0", "must lie in [1, 3]");
    if (!(o.e0 > 0.02 && o.e0 <= 1)) throw InputError("--e0", "must lie in (0.02, 1]");
    if (!(o.mu0 >= 0 && o.mu0 <= 3)) throw InputError("--mu0", "must lie in [0, 3]");
    if (opts->loss == "huber") o.loss = numerics::RobustLoss::huber;
    else if (opts->loss == "cauchy") o.loss = numerics::RobustLoss::cauchy;
    else if (opts->loss == "none") o.loss = numerics::RobustLoss::none;
    else throw InputError("--loss", "unknown loss '" + opts->loss + "' (huber, cauchy, none)");
    for (const auto& f : opts->fix) {
      const auto eq = f.find('=');
      if (eq == std::string::npos) throw InputError("--fix", "expected NAME=VALUE, got '" + f + "'");
      const std::string name = f.substr(0, eq);
      if (name != "K" && name != "n" && name != "D" && name != "e" && name != "mu")
        throw InputError("--fix", "unknown parameter '" + name + "' (K, n, D, e, mu)");
      o.fixed[name] = io::parse_double(f.substr(eq + 1), "--fix " + name);
    }
    const auto rows = io::read_bounce_table(opts->file);
    const auto r = fit_bounces(rows, o);
    json res = json::array();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& p = r.rows[i];
      res.push_back({{"row", i + 1}, {"vx_pred", num(p.vx_pred)}, {"vy_pred", num(p.vy_pred)},
                     {"omega_pred", num(p.omega_pred)}, {"r_vx", num(p.r_vx)}, {"r_vy", num(p.r_vy)},
                     {"r_b_omega", num(p.r_b_omega)}});
    }
    json j = {{"K", r.K}, {"sigma_K", r.sigma_K}, {"n", r.n}, {"sigma_n", r.sigma_n},
              {"D", num(r.D)}, {"sigma_D", num(r.sigma_D)}, {"mu", r.mu}, {"sigma_mu", r.sigma_mu},
              {"rms", r.rms}, {"n_rows", rows.size()}, {"dof", r.fit.dof},
              {"iterations", r.fit.iterations}, {"free_parameters", r.free_parameters}};
    if (o.restitution_model) {
      j["e"] = r.e;
      j["sigma_e"] = r.sigma_e;
    }
    if (opts->json) j["residuals"] = res;
    write_report_if_requested(opts->report, [&] {
      std::string command = "tribolab bounce fit " + opts->file + " --model " + opts->model + " --friction " + opts->friction;
      if (o.restitution_model) command += " --restitution";
      for (const auto& f : opts->fix) command += " --fix " + f;
      return bounce_fit_report(command, rows, o, r);
    });
    print_result(j, opts->json);
  });
}

void add_synth_video(CLI::App* area) {
  struct Opts {
    SynthVideoOptions o;
    TruthLaw law;
    std::string out;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("synth-video", "write a synthetic Tracker export of one bounce (tips A and B) with known truth");
  cmd->add_option("--out", opts->out, "output file (Tracker Export Data text)")->required();
  add_ball_options(cmd, opts->o.ball);
  opts->law.add(cmd);
  cmd->add_option("--height", opts->o.height, "centre height at release, m (default 0.8)");
  cmd->add_option("--theta-deg", opts->o.theta_deg, "orientation at release, deg (default 20)");
  cmd->add_option("--omega", opts->o.omega, "spin at release, rad/s (default 45)");
  cmd->add_option("--vx", opts->o.vx, "horizontal speed, m/s (default 1.5)");
  cmd->add_option("--vy", opts->o.vy, "vertical speed at release, m/s (default 0)");
  cmd->add_option("--after", opts->o.after, "seconds of video after the separation (default 0.3)");
  cmd->add_option("--fps", opts->o.fps, "camera frame rate, 1/s (default 240)");
  cmd->add_option("--noise", opts->o.noise, "position noise sd of each tip coordinate, m (default 0.001)");
  cmd->add_option("--time-factor", opts->o.time_factor, "file time = real time x this (default 8: 240 fps shown at 30)");
  cmd->add_option("--seed", opts->o.seed, "random seed (default 1)");
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    SynthVideoOptions o = opts->o;
    checked_ball(o.ball);
    opts->law.apply(o.law, o.friction);
    const auto v = synth_video(o);
    io::AtomicFile file(opts->out);
    file.stream() << io::write_export_text({v.tip_a, v.tip_b});
    file.commit();
    const auto& t = v.truth;
    print_result({{"out", opts->out}, {"frames", v.tip_a.points.size()},
                  {"t_touch", t.t_touch}, {"t_separation", t.t_separation},
                  {"vx_in", t.touch.vx}, {"vy_in", t.touch.vy}, {"omega_in", t.touch.omega},
                  {"theta_touch_deg", bounce::wrap_angle(t.touch.theta) * 180 / M_PI},
                  {"vx_out", t.separation.vx}, {"vy_out", t.separation.vy}, {"omega_out", t.separation.omega},
                  {"release_apex", t.release_apex}, {"post_apex", t.post_apex},
                  {"e_height", std::sqrt(t.post_apex / t.release_apex)}},
                 opts->json);
  });
}

void add_synth_table(CLI::App* area) {
  struct Opts {
    SynthTableOptions o;
    TruthLaw law;
    std::string out;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto* cmd = area->add_subcommand("synth-table", "write a synthetic bounce table for `bounce fit` with known truth");
  cmd->add_option("--out", opts->out, "output CSV")->required();
  add_ball_options(cmd, opts->o.ball);
  opts->law.add(cmd);
  cmd->add_option("--rows", opts->o.rows, "bounces (default 40)");
  cmd->add_option("--speed-min", opts->o.speed_min, "smallest incoming |vy|, m/s (default 2)");
  cmd->add_option("--speed-max", opts->o.speed_max, "largest incoming |vy|, m/s (default 5)");
  cmd->add_option("--vx-max", opts->o.vx_max, "incoming vx in [-vx-max, vx-max], m/s (default 2)");
  cmd->add_option("--omega-max", opts->o.omega_max, "incoming omega in [-omega-max, omega-max], rad/s (default 50)");
  cmd->add_option("--noise-v", opts->o.noise_v, "noise sd of the outgoing vx, vy, m/s (default 0.02)");
  cmd->add_option("--noise-omega", opts->o.noise_omega, "noise sd of the outgoing omega, rad/s (default 0.5)");
  cmd->add_option("--outlier-fraction", opts->o.outlier_fraction,
                  "fraction of rows with a gross error on one outgoing value (default 0)");
  cmd->add_option("--outlier-v", opts->o.outlier_v,
                  "size of a gross error, m/s: uniform in [v, 2v], random sign; omega: v/b (default 0.3)");
  cmd->add_option("--seed", opts->o.seed, "random seed (default 1)");
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    SynthTableOptions o = opts->o;
    checked_ball(o.ball);
    opts->law.apply(o.law, o.friction);
    for (auto [v, name] : {std::pair{o.speed_min, "--speed-min"}, {o.speed_max, "--speed-max"}, {o.vx_max, "--vx-max"},
                           {o.omega_max, "--omega-max"}, {o.noise_v, "--noise-v"}, {o.noise_omega, "--noise-omega"},
                           {o.outlier_fraction, "--outlier-fraction"}, {o.outlier_v, "--outlier-v"}})
      check_finite(v, name);
    const auto rows = synth_table(o);
    io::AtomicFile file(opts->out);
    file.stream() << io::write_bounce_table(rows);
    file.commit();
    print_result({{"out", opts->out}, {"rows", rows.size()}}, opts->json);
  });
}

}  // namespace

void register_bounce_analysis(CLI::App* area) {
  add_analyze(area);
  add_fit(area);
  add_synth_video(area);
  add_synth_table(area);
}

}  // namespace tribolab::cli
