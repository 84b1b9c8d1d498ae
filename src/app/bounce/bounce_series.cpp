#include "app/bounce/bounce_series.hpp"

#include "app/bounce/report_bounce_series.hpp"
#include "app/common/json_number.hpp"
#include "app/common/result_keys.hpp"
#include "app/common/series_json.hpp"
#include "analysis/series_plausibility.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"

#include <cmath>
#include <initializer_list>
#include <utility>

namespace tribolab::app {
namespace {

using nlohmann::json;
using namespace tribolab::analysis;

json mean_json(const WeightedMean& m) {
  return {{"n", m.n}, {"mean", json_number(m.mean)}, {"sigma", json_number(m.sigma)}, {"sigma_scaled", json_number(m.sigma_scaled)},
          {"chi2", json_number(m.chi2)}, {"dof", m.dof}, {"p_value", json_number(m.p_value)}};
}

json above_json(const AboveOne& a) { return {{"n", a.n}, {"above", a.above}, {"significant", a.significant}}; }

json energy_json(const bounce::KineticEnergy& e) {
  return {{"translational", e.translational_x + e.translational_y}, {"rotational", e.rotational}, {"total", e.total()}};
}

}  // namespace

json bounce_series_json(const BounceSeriesSummary& s, const std::vector<BounceSeriesPoint>& points,
                        const std::vector<std::string>& files, const BounceSeriesOptions& o) {
  json bins = json::array();
  for (const auto& b : s.bins) {
    bins.push_back({{"low_deg", b.low_deg}, {"high_deg", b.high_deg}, {"centre_deg", b.centre_deg}, {"n", b.n},
                    {"e_velocity", mean_json(b.e_velocity)}, {"e_min", b.e_min}, {"e_max", b.e_max},
                    {"n_above_one", b.n_above_one}});
  }
  json outliers = json::array();
  for (const auto& out : s.outliers) outliers.push_back({{"file", files[out.run]}, {"reason", out.reason}});
  json pts = json::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    pts.push_back({{"file", files[i]},
                   {"collision_angle_deg", json_number(p.collision_angle_deg)},
                   {"sigma_collision_angle_deg", json_number(p.sigma_collision_angle_deg)},
                   {"theta_deg", json_number(p.theta_deg)},
                   {"e_velocity", json_number(p.e_velocity)},
                   {"sigma_e_velocity", json_number(p.sigma_e_velocity)},
                   {"e_height", json_number(p.e_height)},
                   {"sigma_e_height", json_number(p.sigma_e_height)},
                   {"energy_pre", energy_json(p.energy_pre)},
                   {"energy_post", energy_json(p.energy_post)},
                   {"mean_normal_force", json_number(p.mean_normal_force)},
                   {"sigma_mean_normal_force", json_number(p.sigma_mean_normal_force)},
                   {"contact_point_vx", json_number(p.contact_point_vx)},
                   {"contact_point_vy", json_number(p.contact_point_vy)},
                   {"contact_point_speed", json_number(p.contact_point_speed)},
                   {"sigma_contact_point_speed", json_number(p.sigma_contact_point_speed)}});
  }
  auto named_run = [&](std::size_t i) {
    return json{{"file", files[i]}, {"contact_point_speed", json_number(points[i].contact_point_speed)},
                {"collision_angle_deg", json_number(points[i].collision_angle_deg)}};
  };
  return {{"e_velocity", mean_json(s.e_velocity)},
          {"e_height", mean_json(s.e_height)},
          // Restitutions at different angles are no one quantity: the headline is then the
          // relation with the angle, not the mean (analysis::e_velocity_headline).
          {"e_velocity_one_value", is_one_value(s.e_velocity)},
          {"e_height_one_value", is_one_value(s.e_height)},
          {"e_velocity_headline", e_velocity_headline(s)},
          {"above_one", {{"z", o.z_above_one}, {"velocity", above_json(s.above_one_velocity)},
                         {"height", above_json(s.above_one_height)}}},
          {"bin_width_deg", o.bin_width_deg},
          {"bins", bins},
          {"energy_ratio_mean", json_number(s.energy_ratio_mean)},
          {"n_energy_gain", s.n_energy_gain},
          {"mean_normal_force", {{"n", s.n_force}, {"mean", json_number(s.force_mean)}, {"sd", json_number(s.force_sd)},
                                 {"e_correlation", json_number(s.force_e_correlation)}}},
          {"contact_point", {{"fastest", named_run(s.fastest_contact_run)}, {"slowest", named_run(s.slowest_contact_run)}}},
          {"outliers", outliers},
          {"points", pts}};
}

}  // namespace tribolab::app

namespace tribolab::app {

const Fields<BounceAnalyzeSeriesOptions>& bounce_analyze_series_fields() {
  using S = BounceAnalyzeSeriesOptions;
  static const Fields<S> f = [] {
    Fields<S> d;
    for (const Field<BounceAnalyzeOptions>& g : bounce_analyze_fields()) {
      if (g.name == "file") {
        d.add("files", &S::files, "", g.help + "; several files: a series with a summary (the rugby-ball study's experiment 2)")
            .as(FieldRole::input_files)
            .needed();
      } else if (g.name == "floor_y" || g.name == "contact_duration") {
        FieldDecl& v = d.add(g.name, g.name == "floor_y" ? &S::floor_y : &S::contact_duration, g.unit,
                             g.help + "; one, or one per file (comma separated)");
        v.range = g.range;
      } else {
        d.add_from(&S::each, g);
      }
    }
    return d;
  }();
  return f;
}

std::vector<BounceAnalyzeOptions> BounceAnalyzeSeriesOptions::per_file() const {
  if (files.empty()) throw MissingOptionError("FILE", "is required");
  const std::size_t n = files.size();
  each.checked();  // the shared options first, as one file would check them
  const auto floor = app::per_file(floor_y, n, field("floor_y"));
  const auto duration = app::per_file(contact_duration, n, field("contact_duration"));
  std::vector<BounceAnalyzeOptions> per(n, each);
  for (std::size_t i = 0; i < n; ++i) {
    per[i].file = files[i];
    per[i].floor_y = floor[i];
    per[i].contact_duration = duration[i];
    per[i].checked();  // every file's values before any work
  }
  return per;
}

namespace {

/// The command line of the series (shown in its report), options as given.
std::string series_command(const BounceAnalyzeSeriesOptions& o) {
  const auto list = [](const std::vector<double>& v) {
    std::string s;
    for (double x : v) s += (s.empty() ? "" : ",") + io::format_number(x);
    return s;
  };
  const BounceAnalyzeOptions& e = o.each;
  std::string command = "tribolab bounce analyze";
  for (const auto& f : o.files) command += " " + f;
  command += " --track-a " + e.track_a + " --track-b " + e.track_b + " --time-scale " + io::format_number(e.time_scale);
  if (!o.floor_y.empty()) command += " --floor-y " + list(o.floor_y);
  if (e.sigma_floor_y > 0) command += " --sigma-floor-y " + io::format_number(e.sigma_floor_y);
  if (!o.contact_duration.empty()) command += " --contact-duration " + list(o.contact_duration);
  return command;
}

/// Runs that stand apart from the series (another time scale or length calibration).
template <class Runs>
std::vector<std::string> bounce_series_run_warnings(const Runs& runs) {
  std::vector<const analysis::BounceAnalysis*> analyses;
  std::vector<std::string> sources;
  for (const auto& run : runs) {
    analyses.push_back(run.ok() ? &run.result->analysis : nullptr);
    sources.push_back(run.source);
  }
  return analysis::bounce_series_warnings(analyses, sources);
}

}  // namespace

BounceAnalyzeSeriesResult bounce_analyze_series(const BounceAnalyzeSeriesOptions& o) {
  const std::vector<BounceAnalyzeOptions> per = o.per_file();
  BounceAnalyzeSeriesResult res;
  if (per.size() == 1) {
    BounceAnalyzeResult r = bounce_analyze(per.front());
    res.json = r.json;
    res.runs.push_back({per.front().file, std::move(r), {}});
    return res;
  }
  std::vector<analysis::BounceAnalyzeOptions> checked;
  for (const auto& p : per) checked.push_back(p.checked());
  const auto runs = analysis::run_series<BounceAnalyzeResult>(
      o.files, [&](std::size_t i, const std::string&) { return bounce_analyze_run(per[i], checked[i]); }, o.series);
  std::vector<analysis::BounceSeriesPoint> points;
  std::vector<std::string> files;
  for (const auto& run : runs) {
    if (!run.ok()) continue;
    points.push_back(analysis::point_of(run.result->analysis));
    files.push_back(run.source);
  }
  const analysis::BounceSeriesOptions so;
  json summary = series_counts(runs);
  if (!points.empty()) {
    const analysis::BounceSeriesSummary sum = analysis::summarize_bounce_series(points, so);
    summary.update(bounce_series_json(sum, points, files, so));
    summary["warnings"] = bounce_series_run_warnings(runs);  // docs/theory.md#plausibility-checks
    if (!o.each.bounces_out.empty()) {
      write_bounces_out(o.each.bounces_out, points, files);
      summary["bounces_out"] = o.each.bounces_out;
    }
    if (!o.each.report.empty()) {
      std::vector<BounceSeriesRun> report_runs;
      for (const auto& run : runs)
        report_runs.push_back({run.source, run.ok() ? &run.result->analysis : nullptr,
                               run.ok() ? std::string() : run.located_error()});
      report::write_html(bounce_analyze_series_report(series_command(o), checked.front().ball, report_runs, points,
                                                      sum, so, o.each.report,
                                                      [&](std::size_t i) { return bounce_analyze_command(per[i]); },
                                                      o.each.plotly),
                         o.each.report, o.each.plotly);
    }
  }
  res.json = {{"runs", series_rows(runs, [](const BounceAnalyzeResult& r) { return r.json; })}, {"summary", summary}};
  res.errors = series_errors(runs);
  for (const auto& r : runs) res.runs.push_back({r.source, r.result, r.located_error()});
  return res;
}

const ResultKeys& bounce_analyze_series_result_keys() {
  // The JSON gives bins and outliers as lists; the text listing keys them by their range
  // ("0-20") and file (cli/bounce_analysis_cmd.cpp): both spellings are declared.
  static const ResultKeys k = [] {
    ResultKeys keys = {
        {"e_velocity_one_value", "", "the runs agree with one e_velocity (chi2 test)"},
        {"e_height_one_value", "", ""}, {"e_velocity_headline", "", "the mean, or the relation with the angle"},
        {"above_one.z", "", "one-sided z of 'significantly above 1'"}, {"bin_width_deg", "deg", ""},
        {"energy_ratio_mean", "", "E_post/E_pre, mean over the runs"}, {"n_energy_gain", "", "runs with E_post > E_pre"},
        {"mean_normal_force.n", "", ""}, {"mean_normal_force.mean", "N", ""}, {"mean_normal_force.sd", "N", "over the runs"},
        {"mean_normal_force.e_correlation", "", "with e_velocity"}, {"outliers", "", ""}, {"outliers.file", "", ""}, {"outliers.reason", "", ""},
        {"outliers.*", "", "the reason, by file"}, {"points.file", "", ""}, {"points.collision_angle_deg", "deg", ""},
        {"points.theta_deg", "deg", ""}, {"points.e_velocity", "", ""}, {"points.e_height", "", ""},
        {"points.energy_pre.*", "J", ""}, {"points.energy_post.*", "J", ""}, {"points.mean_normal_force", "N", ""},
        {"points.contact_point_vx", "m/s", ""}, {"points.contact_point_vy", "m/s", ""},
        {"points.contact_point_speed", "m/s", ""}, {"warnings", "", ""}, {"bounces_out", "", "the table written"},
        {"n_runs", "", ""}, {"n_ok", "", ""}, {"n_failed", "", ""}, {"failed", "", "files that failed"},
    };
    for (const char* m : {"e_velocity", "e_height", "bins.e_velocity", "bins.*.e_velocity"})
      for (const char* f : {"n", "mean", "sigma", "sigma_scaled", "chi2", "dof", "p_value"})
        keys.push_back({std::string(m) + "." + f, "", ""});
    for (const char* m : {"above_one.velocity", "above_one.height"})
      for (const char* f : {"n", "above", "significant"}) keys.push_back({std::string(m) + "." + f, "", ""});
    for (const char* b : {"bins.", "bins.*."})
      for (const auto& [f, u] : std::initializer_list<std::pair<const char*, const char*>>{
               {"low_deg", "deg"}, {"high_deg", "deg"}, {"centre_deg", "deg"}, {"n", ""}, {"e_min", ""}, {"e_max", ""},
               {"n_above_one", ""}})
        keys.push_back({std::string(b) + f, u, ""});
    for (const char* c : {"contact_point.fastest.", "contact_point.slowest."})
      for (const auto& [f, u] : std::initializer_list<std::pair<const char*, const char*>>{
               {"file", ""}, {"contact_point_speed", "m/s"}, {"collision_angle_deg", "deg"}})
        keys.push_back({std::string(c) + f, u, ""});
    return keys;
  }();
  return k;
}

}  // namespace tribolab::app
