#include "app/common/study_citation.hpp"
#include "app/incline/report_incline_series.hpp"

#include "numerics/units.hpp"
#include "incline/params.hpp"
#include "report/format.hpp"
#include "report/html.hpp"
#include "app/incline/report_incline_analysis.hpp"
#include "app/common/report_util.hpp"
#include "app/common/series_files.hpp"
#include "app/incline/incline_series.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;
using report::Figure;
using report::Series;
using report::Table;
using report::format_uncertain;
using report::format_value;

std::string opt_value(const std::optional<double>& v, int digits = 5) { return v ? format_value(*v, digits) : "—"; }

Figure series_figure(std::string title, std::string x, std::string y, int height = 360) {
  return make_figure(std::move(title), std::move(x), std::move(y), height);
}



/// Pull of point k (k-th analysed run) in the weighted mean, NaN when it has none.
double pull_of(const std::optional<analysis::WeightedMean>& m, const std::vector<int>& index, std::size_t k) {
  if (!m) return kNaN;
  for (std::size_t j = 0; j < index.size(); ++j)
    if (static_cast<std::size_t>(index[j]) == k) return m->pulls[j];
  return kNaN;
}

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

/// The weighted-mean rows of a summary table.
void add_mean_rows(Table& t, const std::string& what, const analysis::WeightedMean& m) {
  t.rows.push_back({"weighted " + what + " (inverse-variance)", format_uncertain(m.mean, m.sigma)});
  t.rows.push_back({"σ scaled by the Birge ratio", format_value(m.sigma_scaled, 3)});
  t.rows.push_back({"χ^2 / dof", format_value(m.chi2, 4) + " / " + std::to_string(m.dof)});
  t.rows.push_back({"p-value (χ^2)", std::isfinite(m.p_value) ? format_value(m.p_value, 3) : "—"});
  t.rows.push_back({"runs consistent at the 5 % level",
                    !std::isfinite(m.p_value) ? "— (one run)" : m.p_value >= 0.05 ? "yes" : "no"});
}

/// Values per run with error bars, the weighted mean and its ±sigma band (x = run number).
Figure per_run_figure(const std::string& title, const std::string& y_title, const std::vector<double>& y,
                      const std::vector<double>& sy, const std::vector<bool>& outlier, const analysis::WeightedMean& m,
                      double band_lo, double band_hi, const std::string& band_name) {
  Figure f = series_figure(title, "run", y_title, 380);
  Series pts = named("runs"), out = named("outliers (|pull| > 3)");
  out.color = "#d62728";
  for (std::size_t i = 0; i < y.size(); ++i) {
    Series& s = outlier[i] ? out : pts;
    s.x.push_back(static_cast<double>(i + 1));
    s.y.push_back(y[i]);
    s.y_error.push_back(sy[i]);
  }
  const double x0 = 0.5, x1 = static_cast<double>(y.size()) + 0.5;
  f.series = {std::move(pts), make_line("weighted mean", {x0, x1}, {m.mean, m.mean}, report::Dash::Solid, "black"),
              make_line(band_name, {x0, x1, kNaN, x0, x1}, {band_lo, band_lo, kNaN, band_hi, band_hi}, report::Dash::Dash,
                   "gray")};
  if (!out.x.empty()) f.series.push_back(std::move(out));
  f.caption = "Error bars: one standard uncertainty of each run. Runs without a value leave a gap.";
  return f;
}

std::string relation_title(analysis::StopRelation r) {
  switch (r) {
    case analysis::StopRelation::t_vs_v0: return "t_stop against v_0 (eq 7 (七))";
    case analysis::StopRelation::x_vs_v0sq: return "x_stop against v_0^2 (eq 8 (八))";
    case analysis::StopRelation::y_vs_v0sq: return "y_stop against v_0^2 (eq 9 (九))";
    case analysis::StopRelation::y_vs_x: return "y_stop against x_stop (eq 10 (十))";
  }
  return {};
}

std::pair<std::string, std::string> relation_axes(analysis::StopRelation r) {
  switch (r) {
    case analysis::StopRelation::t_vs_v0: return {"v_0 (m/s)", "t_{stop} (s)"};
    case analysis::StopRelation::x_vs_v0sq: return {"v_0^2 (m^2/s^2)", "x_{stop} (m)"};
    case analysis::StopRelation::y_vs_v0sq: return {"v_0^2 (m^2/s^2)", "y_{stop} (m)"};
    case analysis::StopRelation::y_vs_x: return {"x_{stop} (m)", "y_{stop} (m)"};
  }
  return {};
}

int add_scaling(report::Section& s, const std::string& title, const analysis::InclineSeriesSummary& sum) {
  if (sum.scaling.empty()) {
    s.add_paragraph("Not fitted: " + sum.scaling_note + ".");
    return 0;
  }
  s.add_paragraph("Each run's stop (time and point after the launch, from its model B fit) against its launch "
                  "speed, as the incline study's figure 8 (八): lines through the origin fitted over the runs at φ = " +
                  format_value(to_deg(*sum.common_phi), 5) +
                  " deg, and the μ each slope implies (eqs 7–10 (七–十) solved for μ at that angle; the interval is the "
                  "slope's 95 % interval mapped through the same relation, — where it leaves the range where the "
                  "disc stops)." + (sum.scaling_note.empty() ? std::string() : " " + sum.scaling_note + "."));
  Table t;
  t.caption = title + ": stop-point slopes (figure 8 (八))";
  t.header = {"relation", "slope", "95 % interval", "μ implied", "95 % interval of μ", "model B slope at the weighted μ"};
  for (const auto& sc : sum.scaling)
    t.rows.push_back({relation_title(sc.relation), format_uncertain(sc.fit.slope, sc.fit.sigma),
                      interval_cell(sc.fit.ci_low, sc.fit.ci_high), opt_value(sc.mu),
                      "[" + opt_value(sc.mu_ci_low) + ", " + opt_value(sc.mu_ci_high) + "]", opt_value(sc.slope_model)});
  s.add_table(std::move(t));
  s.add_equation("t_{stop}/v_0 = μ cos φ / (g(μ^2 cos^2 φ − sin^2 φ)),  x_{stop}/v_0^2 = 2μ cos φ / (g(4μ^2 cos^2 φ − sin^2 φ))",
                 "incline study, eqs 7, 8 (七, 八)");
  s.add_equation("y_{stop}/v_0^2 = −sin φ / (4g(μ^2 cos^2 φ − sin^2 φ)),  y_{stop}/x_{stop} = −k(4 − k^2)/(8(1 − k^2)), k = tan φ/μ",
                 "incline study, eqs 9, 10 (九, 十)");
  int n = 0;
  for (const auto& sc : sum.scaling) {
    const auto [xt, yt] = relation_axes(sc.relation);
    Figure f = series_figure(title + ": " + relation_title(sc.relation), xt, yt, 360);
    Series pts = named("runs");
    pts.x = sc.x;
    pts.y = sc.y;
    const double hi = *std::max_element(sc.x.begin(), sc.x.end()) * 1.1;
    f.series = {std::move(pts),
                make_line("fitted through the origin", {0, hi}, {0, sc.fit.slope * hi}, report::Dash::Solid, "#d62728")};
    if (sc.slope_model)
      f.series.push_back(make_line("model B at the weighted μ", {0, hi}, {0, *sc.slope_model * hi}, report::Dash::Dash, "black"));
    f.caption = "Slope " + format_uncertain(sc.fit.slope, sc.fit.sigma) + " over " + std::to_string(sc.fit.n) + " runs.";
    s.add_figure(std::move(f));
    ++n;
  }
  return n;
}


}  // namespace

int add_incline_series(report::Report& r, const std::string& title, const std::vector<InclineSeriesRun>& runs,
                       const analysis::InclineSeriesSummary& sum, const std::vector<std::string>& links) {
  int figures = 0;
  std::size_t n_failed = 0;
  for (const auto& run : runs) n_failed += run.analysis == nullptr;
  auto& s = r.add_section(title + ": friction coefficient over the runs");
  s.add_paragraph(std::to_string(runs.size()) + " runs, " + std::to_string(runs.size() - n_failed) + " analysed" +
                  (n_failed ? ", " + std::to_string(n_failed) + " failed (named in the table of runs)" : std::string()) +
                  ". μ of each run is its model B fit; the runs are combined with inverse-variance weights, and χ^2 "
                  "of the runs about the weighted mean tests whether they agree within their uncertainties "
                  "(docs/theory.md#series-of-runs).");
  Table st;
  st.caption = title + ": weighted μ";
  st.header = {"quantity", "value"};
  if (sum.mu) add_mean_rows(st, "μ", *sum.mu);
  else st.rows.push_back({"weighted μ (inverse-variance)", "— (no run analysed)"});
  st.rows.push_back({"outliers (|pull| > 3)", sum.outliers.empty() ? "none" : std::to_string(sum.outliers.size())});
  s.add_table(std::move(st));
  if (const auto w = series_warnings(sum.mu, sum.outliers); !w.empty()) {  // docs/theory.md#plausibility-checks
    std::vector<std::string> items;
    for (const auto& x : w) items.push_back("Warning: " + x);
    s.add_list(std::move(items));
  }
  s.add_equation("μ̄ = Σ w_i μ_i / Σ w_i,  w_i = 1/σ_i^2,  σ_{μ̄} = 1/√(Σ w_i),  χ^2 = Σ w_i (μ_i − μ̄)^2 (n − 1 dof)",
                 "docs/theory.md#series-of-runs", "pull of run i: (μ_i − μ̄)/√(σ_i² − σ² of the mean)");
  if (!sum.outliers.empty()) {
    std::vector<std::string> items;
    for (const auto& o : sum.outliers) items.push_back(o);
    s.add_paragraph("Runs more than 3 standard deviations from the weighted mean:");
    s.add_list(std::move(items));
  }

  // The table of runs, each linking to its own report.
  Table t;
  t.caption = title + ": runs";
  t.header = {"run", "φ (deg)", "μ", "pull", "v_0 (m/s)", "t_{stop} (s)", "x_{stop} (m)", "y_{stop} (m)", "f_N/m (m/s^2)",
              "verdict", "note"};
  std::vector<double> mu, smu, fn, sfn;
  std::vector<bool> outlier;
  std::size_t k = 0;  // index among the analysed runs
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& run = runs[i];
    const bool is_outlier = contains(sum.outliers, run.source);
    outlier.push_back(is_outlier);
    if (!run.analysis) {
      t.rows.push_back({run.source, format_value(to_deg(run.phi), 5), "—", "—", "—", "—", "—", "—", "—", "—",
                        "error: " + run.error});
      for (auto* v : {&mu, &smu, &fn, &sfn}) v->push_back(kNaN);
      t.links.push_back({});
      continue;
    }
    const analysis::InclineRunPoint p = analysis::incline_run_point(*run.analysis, run.source);
    const double pull = pull_of(sum.mu, sum.mu_index, k++);
    mu.push_back(p.mu);
    smu.push_back(p.sigma_mu);
    fn.push_back(p.normal_accel.value_or(kNaN));
    sfn.push_back(p.sigma_normal_accel.value_or(kNaN));
    t.rows.push_back({run.source, format_value(to_deg(run.phi), 5), format_uncertain(p.mu, p.sigma_mu),
                      std::isfinite(pull) ? format_value(pull, 3) : "—", format_uncertain(p.v0, p.sigma_v0),
                      opt_value(p.t_stop), opt_value(p.x_stop), opt_value(p.y_stop),
                      p.normal_accel ? format_uncertain(*p.normal_accel, *p.sigma_normal_accel) : "—", to_string(p.verdict),
                      is_outlier ? "outlier" : ""});
    t.links.push_back(i < links.size() ? links[i] : std::string());
  }
  if (std::all_of(t.links.begin(), t.links.end(), [](const std::string& l) { return l.empty(); })) t.links.clear();
  s.add_table(std::move(t));
  if (sum.mu) {
    s.add_figure(per_run_figure(title + ": μ per run", "μ", mu, smu, outlier, *sum.mu, sum.mu->mean - sum.mu->sigma,
                                sum.mu->mean + sum.mu->sigma, "± σ of the weighted mean"));
    ++figures;
  }

  auto& sc = r.add_section(title + ": stop point against launch speed (figure 8 (八))");
  figures += add_scaling(sc, title, sum);

  auto& tc = r.add_section(title + ": cos θ_c against tan φ (eq c')");
  if (sum.theta_c_test) figures += add_normal_friction_fit(tc, title, *sum.theta_c_test);
  else tc.add_paragraph("Not fitted: " + sum.theta_c_note + ".");

  auto& nf = r.add_section(title + ": normal friction pooled over the runs (model A)");
  if (sum.normal_friction) {
    const auto& p = *sum.normal_friction;
    nf.add_paragraph("Each run's model A fit gives f_N/m with a standard error; the weighted mean over the runs has "
                     "the interval mean ± z σ_scaled (σ scaled by the Birge ratio when the runs scatter more than "
                     "their errors allow), and the pooled verdict is \"present\" when it excludes 0.");
    Table pt;
    pt.caption = title + ": pooled f_N/m";
    pt.header = {"quantity", "value"};
    add_mean_rows(pt, "f_N/m (m/s^2)", p.mean);
    pt.rows.push_back({"95 % interval (m/s^2)", interval_cell(p.ci_low, p.ci_high)});
    pt.rows.push_back({"pooled verdict: normal friction", to_string(p.verdict)});
    pt.rows.push_back({"runs whose own verdict is present", std::to_string(p.n_present) + " of " + std::to_string(p.mean.n)});
    nf.add_table(std::move(pt));
    std::vector<bool> none(fn.size(), false);
    nf.add_figure(per_run_figure(title + ": f_N/m per run (model A)", "f_N/m (m/s^2)", fn, sfn, none, p.mean, p.ci_low,
                                 p.ci_high, "95 % interval of the pooled value"));
    ++figures;
  } else {
    nf.add_paragraph("Not pooled: " + sum.normal_friction_note + ".");
  }
  return figures;
}

report::Report incline_analyze_series_report(const std::vector<InclineSeriesRun>& runs,
                                             const analysis::InclineSeriesSummary& summary,
                                             const std::string& report_path, report::PlotlyMode plotly) {
  std::vector<std::string> sources;
  for (const auto& run : runs) sources.push_back(run.source);
  const std::vector<std::string> links =
      write_run_reports(sources, report_path, plotly, [&](std::size_t i) -> std::optional<report::Report> {
        if (!runs[i].analysis) return std::nullopt;
        return with_study_source(incline_analyze_report(runs[i].source, *runs[i].analysis), Study::incline);
      });
  report::Report r;
  r.title = "tribolab: incline analyze, a series of " + std::to_string(runs.size()) + " runs";
  r.subtitle = "Models B and A fitted to every run, and the series summarised as the incline study did (table 1, figures 5A–8 (五A–八))";
  add_incline_series(r, "Series", runs, summary, links);
  return r;
}

report::Report incline_slide_series_report(const std::vector<SlideSeriesRun>& runs,
                                           const analysis::SlideSeriesSummary& sum, const std::string& report_path,
                                           report::PlotlyMode plotly) {
  std::vector<std::string> sources;
  for (const auto& run : runs) sources.push_back(run.source);
  const std::vector<std::string> links =
      write_run_reports(sources, report_path, plotly, [&](std::size_t i) -> std::optional<report::Report> {
        if (!runs[i].result) return std::nullopt;
        return with_study_source(incline_slide_report(runs[i].source, *runs[i].result, runs[i].options), Study::incline);
      });
  report::Report r;
  r.title = "tribolab: incline mu-from-slide, a series of " + std::to_string(runs.size()) + " slides";
  r.subtitle = "μ from straight slides (incline study, eq a), combined with inverse-variance weights";
  auto& s = r.add_section("Series: friction coefficient over the slides");
  Table st;
  st.caption = "weighted μ";
  st.header = {"quantity", "value"};
  if (sum.mu) add_mean_rows(st, "μ", *sum.mu);
  else st.rows.push_back({"weighted μ (inverse-variance)", "— (" + sum.note + ")"});
  st.rows.push_back({"outliers (|pull| > 3)", sum.outliers.empty() ? "none" : std::to_string(sum.outliers.size())});
  s.add_table(std::move(st));
  if (const auto w = series_warnings(sum.mu, sum.outliers); !w.empty()) {  // docs/theory.md#plausibility-checks
    std::vector<std::string> items;
    for (const auto& x : w) items.push_back("Warning: " + x);
    s.add_list(std::move(items));
  }
  Table t;
  t.caption = "slides";
  t.header = {"run", "φ (deg)", "a (m/s^2)", "μ", "pull", "R^2", "note"};
  std::vector<double> mu, smu;
  std::vector<bool> outlier;
  std::size_t k = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& run = runs[i];
    const std::string phi = run.options.phi ? format_value(to_deg(*run.options.phi), 5) : "—";
    const bool is_outlier = contains(sum.outliers, run.source);
    outlier.push_back(is_outlier);
    t.links.push_back(links[i]);
    if (!run.result) {
      t.rows.push_back({run.source, phi, "—", "—", "—", "—", "error: " + run.error});
      mu.push_back(kNaN);
      smu.push_back(kNaN);
      continue;
    }
    const auto& res = *run.result;
    const double pull = pull_of(sum.mu, sum.mu_index, k++);
    mu.push_back(res.mu.value_or(kNaN));
    smu.push_back(res.sigma_mu.value_or(kNaN));
    t.rows.push_back({run.source, phi, format_uncertain(res.a, res.sigma_a),
                      res.mu ? format_uncertain(*res.mu, *res.sigma_mu) : "—",
                      std::isfinite(pull) ? format_value(pull, 3) : "—", format_value(res.r_squared, 6),
                      is_outlier ? "outlier" : ""});
  }
  if (std::all_of(t.links.begin(), t.links.end(), [](const std::string& l) { return l.empty(); })) t.links.clear();
  s.add_table(std::move(t));
  if (sum.mu)
    s.add_figure(per_run_figure("μ per slide", "μ", mu, smu, outlier, *sum.mu, sum.mu->mean - sum.mu->sigma,
                                sum.mu->mean + sum.mu->sigma, "± σ of the weighted mean"));
  return r;
}

}  // namespace tribolab::app
