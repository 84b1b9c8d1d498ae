// `tribolab bounce analyze|fit|synth-video|synth-table`: seed 001's experiment 1 on tracked
// data, the contact-law fit to a table of bounces, and the synthetic data for both
// (docs/cli.md#bounce-analyze).
#include "bounce_analysis_cmd.hpp"

#include "app.hpp"
#include "bounce_options.hpp"
#include "app/bounce_series.hpp"
#include "bounce_truth_law.hpp"
#include "app/report_bounce_analysis.hpp"
#include "app/report_bounce_series.hpp"
#include "report_option.hpp"
#include "series_cmd.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_series.hpp"
#include "analysis/bounce_synth.hpp"
#include "io/atomic_file.hpp"
#include "io/bounce_table.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <cmath>
#include <filesystem>
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

}  // namespace

json bounce_analysis_json(const BounceAnalysis& r) {
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
            {"floor_method", to_string(r.floor_method)},
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
    j["force_duration_method"] = to_string(r.force_duration_method);
  }
  return j;
}

namespace {

struct AnalyzeOpts {
  std::vector<std::string> files;
  std::string a, b;
  double time_scale = 1;
  std::string length_unit;
  BounceAnalyzeOptions o;
  std::string floor_y, contact_duration;  ///< one value, or one per file (comma separated)
  std::string report, bounces_out;
  bool json = false;
};

/// Reads and analyses one file as the single-file command does.
BounceAnalysis analyze_file(const AnalyzeOpts& opts, const std::string& file, const BounceAnalyzeOptions& o) {
  io::ImportOptions io;
  io.time_scale = opts.time_scale;
  io.length_unit = opts.length_unit;
  io.tracks = {opts.a, opts.b};
  const auto set = io::read_tracks(file, io);
  return analyze_bounce(set.find(opts.a), set.find(opts.b), o);
}

/// The command line that analyses `file` alone with options `o` (shown in its report).
std::string analyze_command(const AnalyzeOpts& opts, const std::string& file, const BounceAnalyzeOptions& o) {
  std::string c = "tribolab bounce analyze " + file + " --track-a " + opts.a + " --track-b " + opts.b +
                  " --time-scale " + io::format_number(opts.time_scale);
  if (o.floor_y) c += " --floor-y " + io::format_number(*o.floor_y);
  if (o.sigma_floor_y > 0) c += " --sigma-floor-y " + io::format_number(o.sigma_floor_y);
  if (o.contact_duration) c += " --contact-duration " + io::format_number(*o.contact_duration);
  return c;
}

/// --bounces-out: the analysed runs as `bounce fit`'s table, one '#' line naming each row's file.
void write_bounces_out(const std::string& path, const std::vector<BounceSeriesPoint>& points,
                       const std::vector<std::string>& files) {
  std::string head = "# bounces measured by tribolab bounce analyze (fit them with: tribolab bounce fit FILE)\n";
  std::vector<BounceRow> rows;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string name = files[i];
    for (char& c : name)
      if (c == '\n' || c == '\r') c = '?';
    head += "# row " + std::to_string(i + 1) + ": " + name + "\n";
    rows.push_back(bounce_row_of(points[i]));
  }
  io::AtomicFile file(path);
  file.stream() << head << io::write_bounce_table(rows);
  file.commit();
}

/// The summary for people: the bins and outliers as dotted keys, the per-run points left out
/// (they are the table above it).
json summary_for_text(json summary) {
  json bins = json::object();
  for (const auto& b : summary["bins"])
    bins[io::format_number(b["low_deg"].get<double>()) + "-" + io::format_number(b["high_deg"].get<double>())] = b;
  summary["bins"] = bins;
  json outliers = json::object();
  for (const auto& o : summary["outliers"]) outliers[o["file"].get<std::string>()] = o["reason"];
  summary["outliers"] = outliers;
  summary.erase("points");
  return summary;
}

/// `bounce analyze` over several files (docs/cli.md#bounce-analyze).
void analyze_series(const AnalyzeOpts& opts, const std::vector<BounceAnalyzeOptions>& per) {
  const BounceAnalyzeOptions& o = per.front();  // the ball and what is shared
  struct Run {
    BounceAnalysis r;
    json j;
  };
  const auto runs = run_files<Run>(opts.files, [&](std::size_t i, const std::string& file) {
    Run run{analyze_file(opts, file, per[i]), {}};
    run.j = bounce_analysis_json(run.r);
    return run;
  });
  std::vector<BounceSeriesPoint> points;
  std::vector<std::string> files;
  for (const auto& run : runs) {
    if (!run.ok()) continue;
    points.push_back(point_of(run.result->r));
    files.push_back(run.source);
  }
  const BounceSeriesOptions so;
  json summary = series_counts(runs);
  std::optional<BounceSeriesSummary> sum;
  if (!points.empty()) {
    sum = summarize_bounce_series(points, so);
    summary.update(bounce_series_json(*sum, points, files, so));
    if (!opts.bounces_out.empty()) {
      write_bounces_out(opts.bounces_out, points, files);
      summary["bounces_out"] = opts.bounces_out;
    }
    write_report_if_requested(opts.report, [&] {
      std::vector<BounceSeriesRun> report_runs;
      for (const auto& run : runs)
        report_runs.push_back({run.source, run.ok() ? &run.result->r : nullptr, run.ok() ? std::string() : run.located_error()});
      std::string command = "tribolab bounce analyze";
      for (const auto& f : opts.files) command += " " + f;
      command += " --track-a " + opts.a + " --track-b " + opts.b + " --time-scale " + io::format_number(opts.time_scale);
      if (!opts.floor_y.empty()) command += " --floor-y " + opts.floor_y;
      if (o.sigma_floor_y > 0) command += " --sigma-floor-y " + io::format_number(o.sigma_floor_y);
      if (!opts.contact_duration.empty()) command += " --contact-duration " + opts.contact_duration;
      return bounce_analyze_series_report(command, o.ball, report_runs, points, *sum, so, opts.report,
                                          [&](std::size_t i) { return analyze_command(opts, runs[i].source, per[i]); });
    });
  }
  print_series(series_rows(runs, [](const Run& r) { return r.j; }), opts.json ? summary : summary_for_text(summary),
               opts.json, {"collision_angle_deg", "e_velocity", "sigma_e_velocity", "e_height", "energy_pre", "energy_post",
                           "mean_normal_force"});
  finish_series(runs);
}

void add_analyze(CLI::App* area) {
  auto opts = std::make_shared<AnalyzeOpts>();
  auto* cmd = area->add_subcommand("analyze", "seed 001 experiment 1: v, omega, e and energies before/after one bounce from the two tracked tips");
  cmd->add_option("FILE", opts->files, "Tracker .trk/.trz, Export Data text or tidy CSV; several files: a series with a summary (seed 001 experiment 2)")->required();
  cmd->add_option("--track-a", opts->a, "name of the track of tip A")->required();
  cmd->add_option("--track-b", opts->b, "name of the track of tip B")->required();
  cmd->add_option("--time-scale", opts->time_scale, "real seconds per file second (240 fps shown at 30: 0.125; default 1)");
  cmd->add_option("--length-unit", opts->length_unit, "unit of the file's lengths, overriding the file (m, cm, mm, ...)");
  add_ball_options(cmd, opts->o.ball);
  cmd->add_option("--floor-y", opts->floor_y, "floor height in the file's frame, m (default: from the flights and --contact-duration; needed for e_height without it); one, or one per file (comma separated)");
  cmd->add_option("--sigma-floor-y", opts->o.sigma_floor_y, "standard uncertainty of --floor-y, m (default 0; the same for every file)");
  cmd->add_option("--contact-duration", opts->contact_duration, "contact duration, s (to half a frame): enables mean_normal_force, and locates the floor when --floor-y is not given; one, or one per file (comma separated)");
  cmd->add_option("--exclude", opts->o.exclude, "points always dropped on each side of the impact (default 0; contact frames are dropped automatically)");
  cmd->add_option("--impact", opts->o.impact, "which detected impact to analyse (default 1)");
  cmd->add_option("--bounces-out", opts->bounces_out, "also write the analysed bounces as a `bounce fit` table (CSV)")->type_name("FILE.csv");
  add_report_option(*cmd, opts->report);
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    checked_ball(opts->o.ball);
    check_range(opts->time_scale, ranges::time_scale, "--time-scale");  // docs/cli.md#physical-ranges
    if (!std::isfinite(opts->time_scale) || !(opts->time_scale > 0)) throw InputError("--time-scale", "must be positive");
    if (!(std::isfinite(opts->o.sigma_floor_y) && opts->o.sigma_floor_y >= 0 && opts->o.sigma_floor_y < 1))
      throw InputError("--sigma-floor-y", "must lie in [0, 1) m");
    if (opts->a == opts->b) throw InputError("--track-b", "must name a different track than --track-a");
    if (!opts->bounces_out.empty()) {
      namespace fs = std::filesystem;
      const fs::path p(opts->bounces_out);
      std::error_code ec;
      if (fs::is_directory(p, ec)) throw InputError("--bounces-out", "'" + opts->bounces_out + "' is a directory");
      const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
      if (!fs::is_directory(dir, ec)) throw InputError("--bounces-out", "folder '" + dir.string() + "' does not exist");
    }
    const std::size_t n = opts->files.size();
    const auto floor_text = per_file_values(opts->floor_y, n, "--floor-y");
    const auto duration_text = per_file_values(opts->contact_duration, n, "--contact-duration");
    std::vector<BounceAnalyzeOptions> per(n, opts->o);
    for (std::size_t i = 0; i < n; ++i) {
      if (!floor_text[i].empty()) {
        per[i].floor_y = io::parse_double(floor_text[i], "--floor-y");
        check_range(*per[i].floor_y, ranges::position, "--floor-y");  // docs/cli.md#physical-ranges
        check_finite(*per[i].floor_y, "--floor-y");
      }
      if (!duration_text[i].empty()) {
        const double T = io::parse_double(duration_text[i], "--contact-duration");
        check_range(T, PhysicalRange{0, 10, "s", true}, "--contact-duration");
        if (!(std::isfinite(T) && T > 0)) throw InputError("--contact-duration", "must be a positive number of seconds");
        per[i].contact_duration = T;
      }
    }
    if (n > 1) return analyze_series(*opts, per);
    const BounceAnalyzeOptions& o = per.front();
    const std::string& file = opts->files.front();
    const auto r = analyze_file(*opts, file, o);
    json j = bounce_analysis_json(r);
    if (!opts->bounces_out.empty()) {
      write_bounces_out(opts->bounces_out, {point_of(r)}, {file});
      j["bounces_out"] = opts->bounces_out;
    }
    write_report_if_requested(opts->report, [&] { return bounce_analyze_report(analyze_command(*opts, file, o), o.ball, r); });
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
    // The truth `bounce fit` should recover, with the keys it prints (K, n, D, mu).
    json truth = {{"model", std::string(bounce::to_string(o.law.model))},
                  {"K", o.law.K},
                  {"n", o.law.n},
                  {"D", o.law.restitution ? json(nullptr) : json(o.law.D)},
                  {"restitution", o.law.restitution ? json(*o.law.restitution) : json(nullptr)},
                  {"friction", std::string(bounce::to_string(o.friction.kind))},
                  {"mu", o.friction.mu},
                  {"a", o.ball.a}, {"b", o.ball.b}, {"mass", o.ball.mass}, {"inertia", o.ball.inertia},
                  {"noise_v", o.noise_v}, {"noise_omega", o.noise_omega},
                  {"outlier_fraction", o.outlier_fraction}};
    if (o.friction.kind == bounce::FrictionKind::regularized) truth["slip_scale"] = o.friction.slip_scale;
    print_result({{"out", opts->out}, {"rows", rows.size()}, {"truth", truth}}, opts->json);
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
