#include "app/common/study_citation.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"
#include "app/incline/incline_analyze.hpp"

#include "app/common/output_paths.hpp"

#include "app/incline/incline_launch.hpp"
#include "app/incline/incline_series.hpp"
#include "app/incline/report_incline_analysis.hpp"
#include "app/incline/report_incline_series.hpp"
#include "app/common/series_json.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tribolab::app {
namespace {

using nlohmann::json;

json interval(double lo, double hi) { return json::array({lo, hi}); }

analysis::SeriesOptions series_options(const InclineSeriesControl& c) {
  analysis::SeriesOptions o;
  o.threads = c.threads;
  o.progress = c.progress;
  return o;
}

json slide_json(const analysis::SlideResult& r, const track::Track& t) {
  json j;
  j["a"] = r.a;
  j["sigma_a"] = r.sigma_a;
  j["mu"] = json_number(r.mu);
  j["sigma_mu"] = json_number(r.sigma_mu);
  j["r_squared"] = r.r_squared;
  j["n_points"] = r.n_points;
  j["a_velocity_line"] = r.a_velocity_line;
  j["sigma_a_velocity_line"] = r.sigma_a_velocity_line;
  j["direction_deg"] = r.direction_deg;
  j["straightness_rms"] = r.straightness_rms;
  j["track"] = t.name;
  j["warnings"] = r.warnings;
  return j;
}

json estimate_ci(const analysis::Estimate& e) { return interval(e.ci_low, e.ci_high); }

}  // namespace

json incline_analysis_json(const analysis::InclineAnalysis& a) {
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
  j["frame_rotation_deg"] = to_deg(b.frame_rotation.value);
  j["sigma_frame_rotation_deg"] = to_deg(b.frame_rotation.sigma);
  j["frame_rotation_ci95_deg"] = interval(to_deg(b.frame_rotation.ci_low),
                                          to_deg(b.frame_rotation.ci_high));
  j["rms_residual"] = b.rms_residual;
  j["n_points"] = a.data.size();
  j["k"] = std::tan(a.phi) / b.mu.value;
  j["t_stop"] = json_number(b.t_stop);
  j["x_stop"] = json_number(b.x_stop);
  j["y_stop"] = json_number(b.y_stop);
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
                    {"frame_rotation_deg", to_deg(m.frame_rotation.value)},
                    {"frame_rotation_ci95_deg", interval(to_deg(m.frame_rotation.ci_low),
                                                         to_deg(m.frame_rotation.ci_high))},
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
                    {"cos_theta_c_model", a.cos_theta_c_model},
                    {"points", a.theta_c->points}};
  } else {
    j["theta_c"] = nullptr;
  }
  j["notes"] = a.notes;
  if (a.gravity && a.gravity->g_identifiable) {  // below 3 deg only the angle check's warning
    const auto& g = *a.gravity;
    auto deg_or_null = [](double rad) { return std::isfinite(rad) ? json(to_deg(rad)) : json(nullptr); };
    j["gravity"] = {{"g", g.g.value},
                    {"sigma_g", g.g.sigma},
                    {"g_ci95", estimate_ci(g.g)},
                    {"ratio", g.ratio},
                    {"time_factor", g.time_factor},
                    {"implausible", g.implausible},
                    {"phi_fit_deg", deg_or_null(g.phi.value)},
                    {"sigma_phi_fit_deg", deg_or_null(g.phi.sigma)}};
  } else {
    j["gravity"] = nullptr;
  }
  j["warnings"] = a.warnings;
  return j;
}


// ---- analyze --------------------------------------------------------------------------

const Fields<InclineAnalyzeOptions>& incline_analyze_fields() {
  using O = InclineAnalyzeOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("files", &O::files, "", "Tracker .trk/.trz, Export Data text, or CSV; several files: a series with a summary")
        .as(FieldRole::input_files)
        .needed();
    // Its range, [0, 90), is checked by check_incline_angle_deg (0 allowed: a level plane).
    d.add("phi_deg", &O::phi_deg, "deg", "incline angle, in [0, 90): one, or one per file (comma separated)").needed();
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.add("block", &O::block, "",
          "points per local fit of the a_N diagnostic (>= 5; unset or 0: about 8 blocks)");
    d.add("no_model_a", &O::no_model_a, "", "skip model A (the verdict then comes from the a_N intercept)");
    d.add("frame_rotation", &O::frame_rotation, "",
          "fit: fit the camera frame's rotation against the incline; none: frame known aligned")
        .one_of({"fit", "none"});
    d.group(&O::input, incline_track_input_fields());
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

InclineAnalyzeResult incline_analyze(const InclineAnalyzeOptions& s) {
  check_output_paths(s.files, {{"report", s.report}});  // before any work (app/common/output_paths.hpp)
  if (s.files.empty()) throw MissingOptionError("FILE", "is required");
  if (s.phi_deg.empty()) throw MissingOptionError(field("phi_deg"), "is required");
  const auto phi_given = per_file(s.phi_deg, s.files.size(), field("phi_deg"));
  if (s.frame_rotation != "fit" && s.frame_rotation != "none")
    throw InputError(field("frame_rotation"), "must be fit or none, got '" + s.frame_rotation + "'");
  std::vector<analysis::InclineFitOptions> per(s.files.size());
  std::vector<double> phi_deg(s.files.size());
  for (std::size_t i = 0; i < per.size(); ++i) {
    analysis::InclineFitOptions& o = per[i];
    phi_deg[i] = check_incline_angle_deg(*phi_given[i], field("phi_deg"), true);
    o.phi = to_rad(phi_deg[i]);
    o.g = check_range(s.g, ranges::gravity, field("g"));
    if (s.block && !(*s.block == 0 || (*s.block >= 5 && *s.block <= 1000)))  // 0: automatic, as unset
      throw InputError(field("block"), "must be 0 or an integer in [5, 1000], got " + std::to_string(*s.block));
    o.diagnostic_block = s.block.value_or(0);
    o.fit_model_a = !s.no_model_a;
    o.fit_frame_rotation = s.frame_rotation == "fit";
  }
  InclineAnalyzeResult res;
  if (s.files.size() == 1) {
    const track::Track t = read_incline_track(s.files.front(), s.input);
    analysis::InclineAnalysis a = analysis::analyze_incline_run(t, per.front());
    res.json = incline_analysis_json(a);
    res.json["track"] = t.name;
    if (!s.report.empty()) report::write_html(with_study_source(incline_analyze_report(s.files.front(), a), Study::incline), s.report, s.plotly);
    res.runs.push_back({s.files.front(), std::move(a), {}});
    return res;
  }
  // Several files: every run as the single-file command, then the series summary
  // (analysis/incline_series.hpp).
  struct Run {
    analysis::InclineAnalysis a;
    json j;
  };
  const auto runs = analysis::run_series<Run>(s.files, [&](std::size_t i, const std::string& file) {
    const track::Track t = read_incline_track(file, s.input);
    Run run{analysis::analyze_incline_run(t, per[i]), {}};
    run.j = incline_analysis_json(run.a);
    run.j["track"] = t.name;
    run.j["phi_deg"] = phi_deg[i];  // as given (deg -> rad -> deg need not round-trip)
    return run;
  }, series_options(s.series));
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
  if (!s.report.empty()) {
    std::vector<InclineSeriesRun> report_runs;
    for (std::size_t i = 0; i < runs.size(); ++i)
      report_runs.push_back({runs[i].source, runs[i].ok() ? &runs[i].result->a : nullptr, per[i].phi,
                             runs[i].ok() ? std::string() : runs[i].located_error()});
    report::write_html(with_study_source(incline_analyze_series_report(report_runs, sum, s.report, s.plotly), Study::incline), s.report, s.plotly);
  }
  res.json = {{"runs", series_rows(runs, [](const Run& r) { return r.j; })}, {"summary", summary}};
  res.errors = series_errors(runs);
  for (const auto& r : runs)
    res.runs.push_back({r.source, r.ok() ? std::optional(r.result->a) : std::nullopt, r.located_error()});
  return res;
}

// ---- mu-from-slide --------------------------------------------------------------------

const Fields<InclineMuFromSlideOptions>& incline_mu_from_slide_fields() {
  using O = InclineMuFromSlideOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("files", &O::files, "", "Tracker .trk/.trz, Export Data text, or CSV; several files: a series with a summary")
        .as(FieldRole::input_files)
        .needed();
    d.add("phi_deg", &O::phi_deg, "deg",
          "incline angle, in (0, 90): one, or one per file (comma separated); without it only a is reported");
    d.add("sigma_phi_deg", &O::sigma_phi_deg, "deg", "uncertainty of the angle (unset: exact): one, or one per file")
        .in(ranges::angle_sigma_deg);
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.group(&O::input, incline_track_input_fields());
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

InclineMuFromSlideResult incline_mu_from_slide(const InclineMuFromSlideOptions& s) {
  check_output_paths(s.files, {{"report", s.report}});  // before any work (app/common/output_paths.hpp)
  if (s.files.empty()) throw MissingOptionError("FILE", "is required");
  const auto phi = per_file(s.phi_deg, s.files.size(), field("phi_deg"));
  const auto sigma = per_file(s.sigma_phi_deg, s.files.size(), field("sigma_phi_deg"));
  std::vector<analysis::SlideOptions> per(s.files.size());
  for (std::size_t i = 0; i < per.size(); ++i) {
    analysis::SlideOptions& o = per[i];
    if (phi[i]) o.phi = to_rad(check_incline_angle_deg(*phi[i], field("phi_deg"), false));
    if (sigma[i]) {
      if (!o.phi) throw InputError(field("sigma_phi_deg"), "needs " + field("phi_deg"));
      o.sigma_phi = to_rad(check_range(*sigma[i], ranges::angle_sigma_deg, field("sigma_phi_deg")));
    }
    o.g = check_range(s.g, ranges::gravity, field("g"));
  }
  InclineMuFromSlideResult res;
  if (s.files.size() == 1) {
    const analysis::SlideOptions& o = per.front();
    const track::Track t = read_incline_track(s.files.front(), s.input);
    analysis::SlideResult r = analysis::mu_from_slide(t, o);
    res.json = slide_json(r, t);
    if (!s.report.empty()) report::write_html(with_study_source(incline_slide_report(s.files.front(), r, o), Study::incline), s.report, s.plotly);
    res.runs.push_back({s.files.front(), std::move(r), {}});
    return res;
  }
  struct Run {
    analysis::SlideResult r;
    json j;
  };
  const auto runs = analysis::run_series<Run>(s.files, [&](std::size_t i, const std::string& file) {
    const track::Track t = read_incline_track(file, s.input);
    Run run{analysis::mu_from_slide(t, per[i]), {}};
    run.j = slide_json(run.r, t);
    run.j["phi_deg"] = json_number(phi[i]);  // as given
    return run;
  }, series_options(s.series));
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
  if (!s.report.empty()) {
    std::vector<SlideSeriesRun> rows;
    for (std::size_t i = 0; i < runs.size(); ++i)
      rows.push_back({runs[i].source, runs[i].ok() ? &runs[i].result->r : nullptr, per[i],
                      runs[i].ok() ? std::string() : runs[i].located_error()});
    report::write_html(with_study_source(incline_slide_series_report(rows, sum, s.report, s.plotly), Study::incline), s.report, s.plotly);
  }
  res.json = {{"runs", series_rows(runs, [](const Run& r) { return r.j; })}, {"summary", summary}};
  res.errors = series_errors(runs);
  for (const auto& r : runs)
    res.runs.push_back({r.source, r.ok() ? std::optional(r.result->r) : std::nullopt, r.located_error()});
  return res;
}


const ResultKeys& incline_mu_from_slide_result_keys() {
  static const ResultKeys k = {
      {"a", "m/s^2", "acceleration along the slide (y-t parabola)"}, {"mu", "", ""}, {"r_squared", "", ""},
      {"n_points", "", ""}, {"a_velocity_line", "m/s^2", "acceleration from the v-t line"},
      {"direction_deg", "deg", ""}, {"straightness_rms", "m", ""}, {"track", "", ""},
      {"warnings", "", "what the data contradict (an angle in radians, times off by a factor)"},
      {"phi_deg", "deg", "as given (a run of several files)"}, {"file", "", "a run of several files"},
      {"error", "", "why the run failed"},
  };
  return k;
}

const ResultKeys& incline_analyze_result_keys() {
  static const ResultKeys k = {
      {"track", "", ""}, {"phi_deg", "deg", "as given"}, {"mu", "", "model B"}, {"v0", "m/s", ""},
      {"t0", "s", "launch time in the file's clock"}, {"x0", "m", ""}, {"y0", "m", ""},
      {"frame_rotation_deg", "deg", "camera frame against the incline"}, {"rms_residual", "m", ""},
      {"n_points", "", ""}, {"k", "", "tan(phi)/mu"}, {"t_stop", "s", ""}, {"x_stop", "m", ""}, {"y_stop", "m", ""},
      {"normal_friction.slope", "m/s^2", "of a_N against sin(theta) (eq b)"},
      {"normal_friction.slope_expected", "m/s^2", "g sin(phi)"}, {"normal_friction.intercept", "m/s^2", ""},
      {"normal_friction.intercept_excludes_zero", "", ""}, {"normal_friction.n_blocks", "", ""},
      {"normal_friction.block", "", "points per block"}, {"normal_friction.verdict", "", ""},
      {"normal_friction.verdict_source", "", ""}, {"normal_friction.p_value", "", ""},
      {"normal_friction.test_size", "", ""}, {"normal_friction.meaning", "", ""},
      {"model_a", "", "null: not fitted"}, {"model_a.mu", "", ""}, {"model_a.v0", "m/s", ""},
      {"model_a.normal_accel", "m/s^2", "f_N/m"}, {"model_a.frame_rotation_deg", "deg", ""},
      {"model_a.normal_accel_rotation_correlation", "", ""}, {"model_a.rms_residual", "m", ""},
      {"model_a.f_statistic", "", ""}, {"model_a.p_value", "", ""}, {"model_a.ci_excludes_zero", "", ""},
      {"model_a.significant", "", ""}, {"theta_c", "", "null: no v_y extremum"}, {"theta_c.cos_theta_c", "", ""},
      {"theta_c.theta_c_deg", "deg", ""}, {"theta_c.t_c", "s", ""}, {"theta_c.cos_theta_c_model", "", ""},
      {"theta_c.points", "", ""}, {"notes", "", ""}, {"gravity", "", "null: below 3 deg"},
      {"gravity.g", "m/s^2", "model B refitted with g free"}, {"gravity.ratio", "", "g / the g given"},
      {"gravity.time_factor", "", "sqrt(ratio)"}, {"gravity.implausible", "", ""}, {"gravity.phi_fit_deg", "deg", ""},
      {"warnings", "", ""}, {"file", "", ""}, {"error", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
