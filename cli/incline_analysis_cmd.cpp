// The analyses of tracked incline runs (seed 000; SPEC sections 2.3-2.5 and 5): parse options
// as text (every error names its option), read the tracks through io::read_tracks, call
// src/analysis, print JSON. docs/cli.md#incline-analyze.
#include "incline_analysis_cmd.hpp"

#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/incline_slide.hpp"
#include "analysis/incline_synthetic.hpp"
#include "app.hpp"
#include "incline/params.hpp"
#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "io/track_csv.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "app/report_incline_analysis.hpp"
#include "report_option.hpp"
#include "app/incline_series.hpp"
#include "app/report_incline_series.hpp"
#include "series_cmd.hpp"

#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using nlohmann::json;

double number(const std::string& text, const std::string& option) { return io::parse_double(text, option); }

json opt(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

void set_types(CLI::App* cmd) {
  for (CLI::Option* o : cmd->get_options()) {
    if (o->get_lnames().empty()) {
      if (o->get_positional()) o->type_name("FILE");
      continue;
    }
    const std::string n = o->get_lnames().front();
    if (n == "help" || n == "json" || n == "no-model-a") continue;
    if (n == "out" || n == "table") o->type_name("FILE");
    else if (n == "track" || n == "track-name") o->type_name("NAME");
    else if (n == "format") o->type_name("export|csv");
    else o->type_name("NUM");
  }
}

double parse_angle_deg(const std::string& text, const std::string& option, bool allow_zero) {
  const double v = number(text, option);
  if (!(v >= 0 && v < 90) || (!allow_zero && v == 0))
    throw InputError(option, std::string("must be in ") + (allow_zero ? "[0, 90)" : "(0, 90)") +
                                 " degrees, got " + text);
  return v;
}

double parse_g(const std::string& text) { return check_range(number(text, "--g"), ranges::gravity, "--g"); }

/// File, track and time-scale options shared by the commands that read tracked data.
struct TrackInput {
  std::string track, time_scale = "1";
};

void add_track_input(CLI::App* cmd, TrackInput& in) {
  cmd->add_option("--track", in.track, "Track to analyse (required when the file holds several)");
  cmd->add_option("--time-scale", in.time_scale,
                  "Real seconds per file second (slow motion 240 fps shown at 30 fps: 0.125; default 1)");
}

track::Track read_one_track(const std::string& file, const TrackInput& in) {
  io::ImportOptions o;
  o.time_scale = check_range(number(in.time_scale, "--time-scale"), ranges::time_scale, "--time-scale");
  if (!in.track.empty()) o.tracks = {in.track};
  const track::TrackSet set = io::read_tracks(file, o);
  if (!in.track.empty()) return set.find(in.track);
  std::vector<const track::Track*> with_points;
  for (const auto& t : set.tracks)
    if (!t.points.empty()) with_points.push_back(&t);
  if (with_points.size() == 1) return *with_points.front();
  std::string names;
  for (const auto* t : with_points) names += (names.empty() ? "'" : ", '") + t->name + "'";
  throw InputError(set.source, "the file holds " + std::to_string(with_points.size()) + " tracks (" +
                                   names + "); choose one with --track");
}

json interval(double lo, double hi) { return json::array({lo, hi}); }

// ---- synth ---------------------------------------------------------------------------

struct SynthText {
  std::string mu, phi_deg, v0, g = "9.8", normal_accel = "0", fps = "80", noise = "0.001",
                                      seed = "1", t_offset = "0.1", x0 = "0.05", y0 = "0",
                                      duration = "0", format = "export", track_name = "disc", out,
                                      frame_rotation_deg = "0";
  bool json = false;
};

void add_synth(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "synth", "Synthetic tracked run from the simulators, with noise (test and demo data)");
  auto s = std::make_shared<SynthText>();
  cmd->add_option("--mu", s->mu, "Kinetic friction coefficient (> 0)")->required();
  cmd->add_option("--phi-deg", s->phi_deg, "Incline angle, degrees, in [0, 90)")->required();
  cmd->add_option("--v0", s->v0,
                  "Launch speed along +x, m/s (>= 0; 0 = released from rest: a straight slide down the slope)")
      ->required();
  cmd->add_option("--g", s->g, "Gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--normal-accel", s->normal_accel,
                  "Model A: normal friction / mass, m/s^2, positive left of the velocity (default 0 = model B)");
  cmd->add_option("--fps", s->fps, "Frame rate, 1/s (default 80)");
  cmd->add_option("--noise", s->noise, "Standard deviation of the position noise, m (default 0.001)");
  cmd->add_option("--seed", s->seed, "Noise seed, integer >= 0 (default 1)");
  cmd->add_option("--t-offset", s->t_offset, "Launch instant in the file's time, s (default 0.1)");
  cmd->add_option("--x0", s->x0, "Launch point x, m (default 0.05)");
  cmd->add_option("--y0", s->y0, "Launch point y, m (default 0)");
  cmd->add_option("--duration", s->duration,
                  "Recording length, s (default 0: until 0.3 s after the stop, or 1.5 s after the launch)");
  cmd->add_option("--format", s->format,
                  "export (Tracker Export Data text, tab delimited; default) or csv (track,frame,t,x,y)");
  cmd->add_option("--track-name", s->track_name, "Name of the track (default disc)");
  cmd->add_option("--frame-rotation-deg", s->frame_rotation_deg,
                  "Camera axes turned against the incline: points rotated CCW about the launch point, deg "
                  "(default 0, within +-20)");
  cmd->add_option("--out", s->out, "Output file")->required();
  add_json_flag(*cmd, s->json);
  set_types(cmd);
  cmd->callback([s] {
    analysis::InclineSynthOptions o;
    // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
    o.params.mu = check_range(number(s->mu, "--mu"), ranges::friction, "--mu");
    if (!(o.params.mu > 0)) throw InputError("--mu", "must be > 0, got " + s->mu);
    o.params.phi = incline::deg_to_rad(parse_angle_deg(s->phi_deg, "--phi-deg", true));
    o.params.v0 = check_range(number(s->v0, "--v0"), ranges::speed, "--v0");
    o.params.g = parse_g(s->g);
    o.params.normal_accel = check_range(number(s->normal_accel, "--normal-accel"), ranges::accel, "--normal-accel");
    o.fps = check_range(number(s->fps, "--fps"), ranges::frame_rate, "--fps");
    o.noise = check_range(number(s->noise, "--noise"), ranges::noise, "--noise");
    const double turn = number(s->frame_rotation_deg, "--frame-rotation-deg");
    if (!(std::abs(turn) <= 20))
      throw InputError("--frame-rotation-deg", "must be within [-20, 20] deg, got " + s->frame_rotation_deg);
    o.frame_rotation = incline::deg_to_rad(turn);
    const double seed = number(s->seed, "--seed");
    if (!(seed >= 0 && seed <= 9.007199254740992e15 && seed == std::floor(seed)))
      throw InputError("--seed", "must be an integer >= 0, got " + s->seed);
    o.seed = static_cast<std::uint64_t>(seed);
    o.t_launch = check_range(number(s->t_offset, "--t-offset"), ranges::duration, "--t-offset");
    o.x0 = check_range(number(s->x0, "--x0"), ranges::position, "--x0");
    o.y0 = check_range(number(s->y0, "--y0"), ranges::position, "--y0");
    o.duration = check_range(number(s->duration, "--duration"), ranges::duration, "--duration");
    if (s->format != "export" && s->format != "csv")
      throw InputError("--format", "must be export or csv, got '" + s->format + "'");
    if (s->track_name.empty() || s->track_name.find_first_of(",\t;\n\"") != std::string::npos)
      throw InputError("--track-name", "must be a non-empty name without , ; tab or quotes");
    o.track_name = s->track_name;
    if (const std::string e = o.validate(); !e.empty()) throw InputError("incline synth", e);
    const analysis::InclineSynthRun run = analysis::synthesize_incline_run(o);

    io::AtomicFile file(s->out);
    if (s->format == "csv") {
      track::TrackSet set;
      set.tracks.push_back(run.track);
      io::write_tidy_csv(file.stream(), set);
    } else {
      file.stream() << io::write_export_text({run.track});
    }
    file.commit();
    json j;
    j["points"] = run.track.points.size();
    j["t_launch"] = o.t_launch;
    j["t_stop"] = opt(run.t_stop);
    if (run.t_stop) {
      const auto& last = run.truth.back();
      j["x_stop"] = last.x;
      j["y_stop"] = last.y;
    } else {
      j["x_stop"] = nullptr;
      j["y_stop"] = nullptr;
    }
    j["model"] = o.params.normal_accel != 0 ? "A" : "B";
    j["format"] = s->format;
    j["track"] = o.track_name;
    j["out"] = s->out;
    print_result(j, s->json);
  });
}

// ---- mu-from-slide -------------------------------------------------------------------

struct SlideText {
  std::vector<std::string> files;
  std::string phi_deg, sigma_phi_deg, g = "9.8", report;
  TrackInput in;
  bool json = false;
};

json slide_json(const analysis::SlideResult& r, const track::Track& t);
void slide_series(const SlideText& s, const std::vector<analysis::SlideOptions>& per,
                  const std::vector<std::string>& phi_text);

void add_mu_from_slide(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "mu-from-slide", "Friction coefficient from a straight slide down the incline (seed 000, eq a)");
  auto s = std::make_shared<SlideText>();
  cmd->add_option("FILE", s->files,
                  "Tracker .trk/.trz, Export Data text, or CSV; several files: a series with a summary")
      ->required();
  cmd->add_option("--phi-deg", s->phi_deg,
                  "Incline angle, degrees, in (0, 90): one, or one per file (comma separated); without it only a is reported");
  cmd->add_option("--sigma-phi-deg", s->sigma_phi_deg, "Uncertainty of the angle, degrees (default 0): one, or one per file");
  cmd->add_option("--g", s->g, "Gravitational acceleration, m/s^2 (default 9.8)");
  add_track_input(cmd, s->in);
  add_json_flag(*cmd, s->json);
  set_types(cmd);
  add_report_option(*cmd, s->report);
  cmd->callback([s] {
    const auto phi_text = per_file_values(s->phi_deg, s->files.size(), "--phi-deg");
    const auto sigma_text = per_file_values(s->sigma_phi_deg, s->files.size(), "--sigma-phi-deg");
    std::vector<analysis::SlideOptions> per(s->files.size());
    for (std::size_t i = 0; i < per.size(); ++i) {
      analysis::SlideOptions& o = per[i];
      if (!phi_text[i].empty()) o.phi = incline::deg_to_rad(parse_angle_deg(phi_text[i], "--phi-deg", false));
      if (!sigma_text[i].empty()) {
        if (!o.phi) throw InputError("--sigma-phi-deg", "needs --phi-deg");
        const double v = check_range(number(sigma_text[i], "--sigma-phi-deg"), ranges::angle_sigma_deg,
                                     "--sigma-phi-deg");
        o.sigma_phi = incline::deg_to_rad(v);
      }
      o.g = parse_g(s->g);
    }
    if (s->files.size() > 1) return slide_series(*s, per, phi_text);
    const analysis::SlideOptions& o = per.front();
    const track::Track t = read_one_track(s->files.front(), s->in);
    const analysis::SlideResult r = analysis::mu_from_slide(t, o);
    const json j = slide_json(r, t);
    write_report_if_requested(s->report, [&] { return incline_slide_report(s->files.front(), r, o); });
    print_result(j, s->json);
  });
}

json slide_json(const analysis::SlideResult& r, const track::Track& t) {
    json j;
    j["a"] = r.a;
    j["sigma_a"] = r.sigma_a;
    j["mu"] = opt(r.mu);
    j["sigma_mu"] = opt(r.sigma_mu);
    j["r_squared"] = r.r_squared;
    j["n_points"] = r.n_points;
    j["a_velocity_line"] = r.a_velocity_line;
    j["sigma_a_velocity_line"] = r.sigma_a_velocity_line;
    j["direction_deg"] = r.direction_deg;
    j["straightness_rms"] = r.straightness_rms;
    j["track"] = t.name;
    return j;
}

void slide_series(const SlideText& s, const std::vector<analysis::SlideOptions>& per,
                  const std::vector<std::string>& phi_text) {
  struct Run {
    analysis::SlideResult r;
    json j;
  };
  const auto runs = run_files<Run>(s.files, [&](std::size_t i, const std::string& file) {
    const track::Track t = read_one_track(file, s.in);
    Run run{analysis::mu_from_slide(t, per[i]), {}};
    run.j = slide_json(run.r, t);
    run.j["phi_deg"] = per[i].phi ? json(number(phi_text[i], "--phi-deg")) : json(nullptr);  // as given
    return run;
  });
  std::vector<std::optional<double>> mu, sigma_mu;
  std::vector<std::string> sources;
  std::vector<std::size_t> run_of_point;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].ok()) continue;
    mu.push_back(runs[i].result->r.mu);
    sigma_mu.push_back(runs[i].result->r.sigma_mu);
    sources.push_back(runs[i].source);
    run_of_point.push_back(i);
  }
  const analysis::SlideSeriesSummary sum = analysis::summarize_slide_series(mu, sigma_mu, sources);
  json summary = series_counts(runs);
  summary.update(slide_series_json(sum, runs.size(), run_of_point));
  write_report_if_requested(s.report, [&] {
    std::vector<SlideSeriesRun> rows;
    for (std::size_t i = 0; i < runs.size(); ++i)
      rows.push_back({runs[i].source, runs[i].ok() ? &runs[i].result->r : nullptr, per[i],
                      runs[i].ok() ? std::string() : runs[i].located_error()});
    return incline_slide_series_report(rows, sum, s.report);
  });
  print_series(series_rows(runs, [](const Run& r) { return r.j; }), summary, s.json,
               {"phi_deg", "a", "sigma_a", "mu", "sigma_mu", "r_squared"});
  finish_series(runs);
}

// ---- analyze -------------------------------------------------------------------------

struct AnalyzeText {
  std::vector<std::string> files;
  std::string phi_deg, g = "9.8", block = "0", report, frame_rotation = "fit";
  TrackInput in;
  bool no_model_a = false, json = false;
};

json estimate_ci(const analysis::Estimate& e) { return interval(e.ci_low, e.ci_high); }

json analysis_json(const analysis::InclineAnalysis& a) {
  const auto& b = a.model_b;
  json j;
  j["mu"] = b.mu.value;
  j["sigma_mu"] = b.mu.sigma;
  j["v0"] = b.v0.value;
  j["sigma_v0"] = b.v0.sigma;
  j["t0"] = b.t0.value;
  j["sigma_t0"] = b.t0.sigma;
  j["x0"] = b.x0.value;
  j["sigma_x0"] = b.x0.sigma;
  j["y0"] = b.y0.value;
  j["sigma_y0"] = b.y0.sigma;
  j["ci95"] = {{"mu", estimate_ci(b.mu)}, {"v0", estimate_ci(b.v0)}, {"t0", estimate_ci(b.t0)},
               {"x0", estimate_ci(b.x0)}, {"y0", estimate_ci(b.y0)}};
  // Frame rotation psi (docs/theory.md#incline-analysis): the launch direction's angle in the
  // file's frame; 0 with a zero-width interval under --frame-rotation none.
  j["frame_rotation_deg"] = incline::rad_to_deg(b.frame_rotation.value);
  j["sigma_frame_rotation_deg"] = incline::rad_to_deg(b.frame_rotation.sigma);
  j["frame_rotation_ci95_deg"] = interval(incline::rad_to_deg(b.frame_rotation.ci_low),
                                          incline::rad_to_deg(b.frame_rotation.ci_high));
  j["rms_residual"] = b.rms_residual;
  j["n_points"] = a.data.size();
  j["k"] = std::tan(a.phi) / b.mu.value;
  j["t_stop"] = opt(b.t_stop);
  j["x_stop"] = opt(b.x_stop);
  j["y_stop"] = opt(b.y_stop);
  json nf;
  if (a.a_n) {
    nf["slope"] = a.a_n->slope;
    nf["sigma_slope"] = a.a_n->sigma_slope;
    nf["slope_expected"] = a.a_n->slope_expected;
    nf["intercept"] = a.a_n->intercept;
    nf["intercept_ci95"] = interval(a.a_n->intercept_ci_low, a.a_n->intercept_ci_high);
    nf["intercept_excludes_zero"] = a.a_n->intercept_excludes_zero;
    nf["n_blocks"] = a.a_n->t.size();
    nf["block"] = a.a_n->block;
  } else {
    for (const char* k : {"slope", "sigma_slope", "intercept", "intercept_ci95", "intercept_excludes_zero",
                          "n_blocks", "block"})
      nf[k] = nullptr;
    nf["slope_expected"] = a.g * std::sin(a.phi);
  }
  nf["verdict"] = to_string(a.verdict);
  nf["verdict_source"] = to_string(a.verdict_source);
  // What the verdict is: a test with a size, so a reader knows how often it errs.
  if (a.test) {
    const int in = static_cast<int>(std::lround(1 / a.test->size));
    nf["p_value"] = a.test->p_value;
    nf["test_size"] = a.test->size;
    nf["meaning"] = fmt::format(
        "present when model A's f_N/m interval excludes 0 and the F-test of A against B gives p < {:g} "
        "(here p = {:.2g}): at this {:g} % size, about one run in {} without normal friction is called present",
        a.test->size, a.test->p_value, 100 * a.test->size, in);
  } else {
    nf["p_value"] = nullptr;
    nf["test_size"] = a.a_n ? json(0.05) : json(nullptr);
    nf["meaning"] = a.a_n ? "present when the 95 % interval of the a_N intercept (eq b) excludes 0: about one "
                            "run in twenty without normal friction is called present"
                          : "no test could decide; absent by default";
  }
  j["normal_friction"] = nf;
  if (a.model_a && a.test) {
    const auto& m = *a.model_a;
    j["model_a"] = {{"mu", m.mu.value},
                    {"sigma_mu", m.mu.sigma},
                    {"v0", m.v0.value},
                    {"normal_accel", m.normal_accel.value},
                    {"sigma_normal_accel", m.normal_accel.sigma},
                    {"normal_accel_ci95", estimate_ci(m.normal_accel)},
                    {"frame_rotation_deg", incline::rad_to_deg(m.frame_rotation.value)},
                    {"frame_rotation_ci95_deg", interval(incline::rad_to_deg(m.frame_rotation.ci_low),
                                                         incline::rad_to_deg(m.frame_rotation.ci_high))},
                    {"normal_accel_rotation_correlation", m.rotation_correlation},
                    {"rms_residual", m.rms_residual},
                    {"f_statistic", a.test->f_statistic},
                    {"p_value", a.test->p_value},
                    {"ci_excludes_zero", a.test->ci_excludes_zero},
                    {"significant", a.test->significant}};
  } else {
    j["model_a"] = nullptr;
  }
  if (a.theta_c) {
    j["theta_c"] = {{"cos_theta_c", a.theta_c->cos_theta_c},
                    {"sigma_cos_theta_c", a.theta_c->sigma_cos_theta_c},
                    {"theta_c_deg", a.theta_c->theta_c_deg},
                    {"t_c", a.theta_c->t_c},
                    {"cos_theta_c_model", a.cos_theta_c_model}};
  } else {
    j["theta_c"] = nullptr;
  }
  j["notes"] = a.notes;
  if (a.gravity) {
    const auto& g = *a.gravity;
    j["gravity"] = {{"g", g.g.value},
                    {"sigma_g", g.g.sigma},
                    {"g_ci95", estimate_ci(g.g)},
                    {"ratio", g.ratio},
                    {"time_factor", g.time_factor},
                    {"implausible", g.implausible}};
  } else {
    j["gravity"] = nullptr;
  }
  j["warnings"] = a.warnings;
  return j;
}

/// `incline analyze` over several files: every run as the single-file command, the series
/// summary (analysis/incline_series.hpp), and with --report the series report.
void analyze_series(const AnalyzeText& s, const std::vector<analysis::InclineFitOptions>& per,
                    const std::vector<double>& phi_deg) {
  struct Run {
    analysis::InclineAnalysis a;
    json j;
  };
  const auto runs = run_files<Run>(s.files, [&](std::size_t i, const std::string& file) {
    const track::Track t = read_one_track(file, s.in);
    Run run{analysis::analyze_incline_run(t, per[i]), {}};
    run.j = analysis_json(run.a);
    run.j["track"] = t.name;
    run.j["phi_deg"] = phi_deg[i];  // as given (deg -> rad -> deg need not round-trip)
    return run;
  });
  std::vector<analysis::InclineRunPoint> points;
  std::vector<std::size_t> run_of_point;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].ok()) continue;
    points.push_back(analysis::incline_run_point(runs[i].result->a, runs[i].source));
    run_of_point.push_back(i);
  }
  analysis::InclineSeriesOptions so;
  so.g = per.front().g;
  const analysis::InclineSeriesSummary sum = analysis::summarize_incline_series(points, so);
  json summary = series_counts(runs);
  summary.update(incline_series_json(sum, runs.size(), run_of_point));
  if (sum.common_phi) summary["phi_deg"] = phi_deg.front();
  const json rows = series_rows(runs, [](const Run& r) { return r.j; });
  write_report_if_requested(s.report, [&] {
    std::vector<InclineSeriesRun> report_runs;
    for (std::size_t i = 0; i < runs.size(); ++i)
      report_runs.push_back({runs[i].source, runs[i].ok() ? &runs[i].result->a : nullptr, per[i].phi,
                             runs[i].ok() ? std::string() : runs[i].located_error()});
    return incline_analyze_series_report(report_runs, sum, s.report);
  });
  print_series(rows, summary, s.json,
               {"phi_deg", "mu", "sigma_mu", "v0", "rms_residual", "/normal_friction/verdict"});
  finish_series(runs);
}

void add_analyze(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "analyze", "Fit models B and A to a tracked 2D run; test for a normal friction component");
  auto s = std::make_shared<AnalyzeText>();
  cmd->add_option("FILE", s->files,
                  "Tracker .trk/.trz, Export Data text, or CSV; several files: a series with a summary")
      ->required();
  cmd->add_option("--phi-deg", s->phi_deg,
                  "Incline angle, degrees, in [0, 90): one, or one per file (comma separated)")
      ->required();
  cmd->add_option("--g", s->g, "Gravitational acceleration, m/s^2 (default 9.8)");
  cmd->add_option("--block", s->block,
                  "Points per local fit of the a_N diagnostic (>= 5; default 0 = about 8 blocks)");
  cmd->add_flag("--no-model-a", s->no_model_a, "Skip model A (the verdict then comes from the a_N intercept)");
  cmd->add_option("--frame-rotation", s->frame_rotation,
                  "fit: fit the camera frame's rotation against the incline (default); none: frame known aligned");
  add_track_input(cmd, s->in);
  add_json_flag(*cmd, s->json);
  set_types(cmd);
  cmd->get_option("--frame-rotation")->type_name("fit|none");
  add_report_option(*cmd, s->report);
  cmd->callback([s] {
    const auto phi_text = per_file_values(s->phi_deg, s->files.size(), "--phi-deg");
    if (s->frame_rotation != "fit" && s->frame_rotation != "none")
      throw InputError("--frame-rotation", "must be fit or none, got '" + s->frame_rotation + "'");
    std::vector<analysis::InclineFitOptions> per(s->files.size());
    std::vector<double> phi_deg(s->files.size());
    for (std::size_t i = 0; i < per.size(); ++i) {
      analysis::InclineFitOptions& o = per[i];
      phi_deg[i] = parse_angle_deg(phi_text[i], "--phi-deg", true);
      o.phi = incline::deg_to_rad(phi_deg[i]);
      o.g = parse_g(s->g);
      const double block = number(s->block, "--block");
      if (!(block == 0 || (block >= 5 && block <= 1000 && block == std::floor(block))))
        throw InputError("--block", "must be 0 or an integer in [5, 1000], got " + s->block);
      o.diagnostic_block = static_cast<int>(block);
      o.fit_model_a = !s->no_model_a;
      o.fit_frame_rotation = s->frame_rotation == "fit";
    }
    if (s->files.size() > 1) return analyze_series(*s, per, phi_deg);
    const analysis::InclineFitOptions& o = per.front();
    const track::Track t = read_one_track(s->files.front(), s->in);
    const analysis::InclineAnalysis a = analysis::analyze_incline_run(t, o);
    json j = analysis_json(a);
    j["track"] = t.name;
    write_report_if_requested(s->report, [&] { return incline_analyze_report(s->files.front(), a); });
    print_result(j, s->json);
  });
}

// ---- normal-friction-test ------------------------------------------------------------

struct NormalTestText {
  std::vector<std::string> files;
  std::string phi_deg, table, g = "9.8", report;
  TrackInput in;
  bool json = false;
};

std::vector<analysis::ThetaCPoint> read_table(const std::string& path) {
  const std::string text = io::read_file(path);
  std::vector<analysis::ThetaCPoint> pts;
  int line_no = 0, col_phi = -1, col_cos = -1, col_sigma = -1;
  std::size_t pos = 0;
  bool header = false;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string line(io::trim(std::string_view(text).substr(pos, end - pos)));
    pos = end + 1;
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no);
    if (line.empty() || line[0] == '#') {
      if (end == text.size()) break;
      continue;
    }
    const auto cells = io::split(line, ',');
    if (!header) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const std::string c(io::trim(cells[i]));
        if (c == "phi_deg") col_phi = static_cast<int>(i);
        else if (c == "cos_theta_c") col_cos = static_cast<int>(i);
        else if (c == "sigma_cos_theta_c") col_sigma = static_cast<int>(i);
      }
      if (col_phi < 0 || col_cos < 0)
        throw InputError(where, "header must name the columns phi_deg and cos_theta_c (comma separated)");
      header = true;
    } else {
      const int need = std::max({col_phi, col_cos, col_sigma});
      if (static_cast<int>(cells.size()) <= need)
        throw InputError(where, "expected " + std::to_string(need + 1) + " cells, got " + std::to_string(cells.size()));
      analysis::ThetaCPoint p;
      const double phi_deg = io::parse_double(io::trim(cells[col_phi]), where);
      if (!(phi_deg > 0 && phi_deg < 90)) throw InputError(where, "phi_deg must be in (0, 90)");
      p.phi = incline::deg_to_rad(phi_deg);
      p.cos_theta_c = io::parse_double(io::trim(cells[col_cos]), where);
      if (col_sigma >= 0) p.sigma_cos_theta_c = io::parse_double(io::trim(cells[col_sigma]), where);
      p.source = where;
      pts.push_back(p);
    }
    if (end == text.size()) break;
  }
  if (!header) throw InputError(path, "is empty; expected a header phi_deg,cos_theta_c");
  return pts;
}

void add_normal_friction_test(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "normal-friction-test",
      "cos(theta_c) against tan(phi) over runs at several angles (seed 000, eq c): slope 1/mu");
  auto s = std::make_shared<NormalTestText>();
  cmd->add_option("FILES", s->files, "Tracked runs, one per angle (with --phi-deg)");
  cmd->add_option("--phi-deg", s->phi_deg, "Comma-separated incline angles, degrees, one per file");
  cmd->add_option("--table", s->table, "CSV with columns phi_deg,cos_theta_c[,sigma_cos_theta_c] instead of files");
  cmd->add_option("--g", s->g, "Gravitational acceleration, m/s^2 (default 9.8)");
  add_track_input(cmd, s->in);
  add_json_flag(*cmd, s->json);
  set_types(cmd);
  add_report_option(*cmd, s->report);
  cmd->get_option("--phi-deg")->type_name("NUM[,NUM...]");
  cmd->callback([s] {
    std::vector<analysis::ThetaCPoint> pts;
    if (!s->table.empty()) {
      if (!s->files.empty() || !s->phi_deg.empty())
        throw InputError("--table", "give either --table or tracked files with --phi-deg, not both");
      pts = read_table(s->table);
    } else {
      if (s->files.empty()) throw InputError("normal-friction-test", "give tracked files with --phi-deg, or --table");
      if (s->phi_deg.empty()) throw InputError("--phi-deg", "is required with tracked files (one angle per file)");
      const auto angles = io::split(s->phi_deg, ',');
      if (angles.size() != s->files.size())
        throw InputError("--phi-deg", "gives " + std::to_string(angles.size()) + " angles for " +
                                          std::to_string(s->files.size()) + " files");
      const double g = parse_g(s->g);
      for (std::size_t i = 0; i < s->files.size(); ++i) {
        analysis::InclineFitOptions o;
        o.phi = incline::deg_to_rad(parse_angle_deg(std::string(io::trim(angles[i])), "--phi-deg", false));
        o.g = g;
        o.fit_model_a = false;
        const track::Track t = read_one_track(s->files[i], s->in);
        const analysis::InclineAnalysis a = analysis::analyze_incline_run(t, o);
        if (!a.theta_c)
          throw InputError(s->files[i], "no v_y extremum found (" +
                                            (a.notes.empty() ? std::string("the disc does not stop") : a.notes.back()) + ")");
        pts.push_back({o.phi, a.theta_c->cos_theta_c, a.theta_c->sigma_cos_theta_c, s->files[i]});
      }
    }
    const analysis::NormalFrictionTest r = analysis::normal_friction_test(pts);
    json runs = json::array();
    for (const auto& p : r.points)
      runs.push_back({{"source", p.source},
                      {"phi_deg", incline::rad_to_deg(p.phi)},
                      {"tan_phi", std::tan(p.phi)},
                      {"cos_theta_c", p.cos_theta_c},
                      {"sigma_cos_theta_c", p.sigma_cos_theta_c > 0 ? json(p.sigma_cos_theta_c) : json(nullptr)}});
    json j;
    j["mu"] = r.mu;
    j["sigma_mu"] = r.sigma_mu;
    j["slope"] = r.slope;
    j["sigma_slope"] = r.sigma_slope;
    j["intercept"] = r.intercept;
    j["sigma_intercept"] = r.sigma_intercept;
    j["intercept_ci95"] = interval(r.intercept_ci_low, r.intercept_ci_high);
    j["r_squared"] = r.line.r_squared;
    j["verdict"] = to_string(r.verdict);
    j["test_size"] = 0.05;
    j["meaning"] = "present when the 95 % interval of the intercept of cos(theta_c) against tan(phi) excludes 0 "
                   "(eq c): about one series in twenty without normal friction is called present";
    j["n_runs"] = r.points.size();
    j["runs"] = runs;
    write_report_if_requested(s->report, [&] { return incline_normal_test_report(r); });
    print_result(j, s->json);
  });
}

}  // namespace

void add_incline_analysis_commands(CLI::App* incline) {
  add_synth(incline);
  add_mu_from_slide(incline);
  add_analyze(incline);
  add_normal_friction_test(incline);
}

}  // namespace tribolab::cli
