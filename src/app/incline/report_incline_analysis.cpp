#include "app/incline/report_incline_analysis.hpp"

#include "numerics/units.hpp"
#include "incline/closed_form.hpp"
#include "incline/params.hpp"
#include "report/format.hpp"
#include "app/incline/report_incline.hpp"
#include "app/common/report_util.hpp"

#include <algorithm>
#include <cmath>

namespace tribolab::app {
namespace {

using report::Figure;
using report::Series;
using report::Table;
using report::format_uncertain;
using report::format_value;

Figure figure(std::string title, std::string x, std::string y, int height = 340) {
  return make_figure(std::move(title), std::move(x), std::move(y), height);
}


/// The tracked points with their Savitzky–Golay derivatives, as states for the kinematics figures.
std::vector<incline::State> data_states(const analysis::InclineAnalysis& a) {
  std::vector<incline::State> out;
  for (const auto& r : a.kinematics.rows) out.push_back({r.t, r.x, r.y, r.vx, r.vy, r.ax, r.ay});
  return out;
}

/// One row of a parameter table: value ± sigma, the interval, and (with truth) whether it holds it.
std::vector<std::string> estimate_row(const std::string& name, const analysis::Estimate& e,
                                      const std::optional<double>& truth) {
  std::vector<std::string> row{name, format_uncertain(e.value, e.sigma), interval_cell(e.ci_low, e.ci_high)};
  if (truth) {
    row.push_back(format_value(*truth, 5));
    row.push_back(yes_no(*truth >= e.ci_low && *truth <= e.ci_high));
  }
  return row;
}

Table estimate_table(std::string caption, bool with_truth) {
  Table t;
  t.caption = std::move(caption);
  t.header = {"parameter", "fit ± standard error", "95 % interval"};
  if (with_truth) {
    t.header.push_back("truth (the simulation's)");
    t.header.push_back("truth in the interval");
  }
  return t;
}

Figure residual_figure(const std::string& title, const analysis::InclineAnalysis& a,
                       const std::vector<double>& rx, const std::vector<double>& ry, double rms) {
  Figure f = figure(title, "t (s)", "data − model (m)", 300);
  f.caption = "rms residual " + format_value(rms, 3) + " m (about the position noise when the model fits).";
  Series sx = named("x residual"), sy = named("y residual");
  for (std::size_t i = 0; i < a.data.size() && i < rx.size(); ++i) {
    sx.x.push_back(a.data[i].t);
    sx.y.push_back(rx[i]);
    sy.x.push_back(a.data[i].t);
    sy.y.push_back(ry[i]);
  }
  f.series = {std::move(sx), std::move(sy)};
  return f;
}

/// a_N against sin(theta) (eq b): blocks, fitted line with its 95 % band, and g sin(phi) sin(theta).
Figure a_n_figure(const std::string& title, const analysis::NormalAccelDiagnostic& d) {
  Figure f = figure(title + ": a_N against sin θ (eq b)", "sin θ", "a_N (m/s^2)", 380);
  f.caption = "One point per block of " + std::to_string(d.block) +
              " points (independent local fits). The line's slope should be g sin φ; its intercept is −f_N/m.";
  Series pts = named("blocks");
  pts.x = d.sin_theta;
  pts.y = d.a_n;
  const auto [lo_it, hi_it] = std::minmax_element(d.sin_theta.begin(), d.sin_theta.end());
  const double lo = *lo_it, hi = *hi_it;
  // Band of the fitted line: t_q sqrt([1 s] C [1 s]^T), with the Student quantile t_q of the
  // fit's dof recovered from its coefficient interval (ci_half_width = t_q sigma).
  const double tq = d.line.sigma[0] > 0 ? d.line.ci_half_width(0, 0.95) / d.line.sigma[0] : 0;
  std::vector<double> xs, fit, up, down, expected;
  for (int i = 0; i <= 50; ++i) {
    const double x = lo + (hi - lo) * i / 50;
    const double var = d.line.covariance(0, 0) + 2 * x * d.line.covariance(0, 1) + x * x * d.line.covariance(1, 1);
    const double h = tq * std::sqrt(std::max(0.0, var));
    xs.push_back(x);
    fit.push_back(d.line(x));
    up.push_back(d.line(x) + h);
    down.push_back(d.line(x) - h);
    expected.push_back(d.slope_expected * x);
  }
  f.series = {std::move(pts), make_line("fitted line", xs, fit, report::Dash::Solid, "#d62728"),
              make_line("95 % band", xs, up, report::Dash::Dot, "#d62728"),
              make_line("95 % band (lower)", xs, down, report::Dash::Dot, "#d62728"),
              make_line("g sin φ sin θ (model B)", xs, expected, report::Dash::Dash, "black")};
  return f;
}

/// v_y around its extremum (eq c): data, the local fit's derivative, and the located theta_c.
Figure theta_c_figure(const std::string& title, const analysis::InclineAnalysis& a, const analysis::ThetaC& c) {
  Figure f = figure(title + ": v_y at its extremum, θ_c (eq c)", "t (s)", "v_y (m/s)", 340);
  f.caption = "a_y = 0 where v_y is extremal; there cos θ_c = |v_y|/|v|. Local polynomial fits (quartic or sextic) of x(t) and y(t) over the "
              "shaded window give v; model B predicts cos θ_c = k = tan φ/μ.";
  Series data = named("data (Savitzky–Golay)");
  for (const auto& r : a.kinematics.rows)
    if (r.t >= c.window_low && r.t <= c.window_high) {
      data.x.push_back(r.t);
      data.y.push_back(r.vy);
    }
  std::vector<double> ts, vy;
  const auto& k = c.fit_y.coef;
  for (int i = 0; i <= 80; ++i) {
    const double t = c.window_low + (c.window_high - c.window_low) * i / 80, tau = t - c.t_guess;
    double d = 0, p = 1;
    for (std::size_t j = 1; j < k.size(); ++j, p *= tau) d += static_cast<double>(j) * k[j] * p;
    ts.push_back(t);
    vy.push_back(d);
  }
  Series model = make_line("model B fit", {}, {}, report::Dash::Dash, "black");
  for (const auto& st : a.model_b_fine)
    if (st.t >= c.window_low && st.t <= c.window_high) {
      model.x.push_back(st.t);
      model.y.push_back(st.vy);
    }
  Series mark = named("θ_c = " + format_value(c.theta_c_deg, 4) + "°");
  mark.x = {c.t_c};
  mark.y = {c.vy};
  mark.x_error = {c.sigma_t_c};
  f.series = {std::move(data), make_line("local fit dy/dt", ts, vy, report::Dash::Solid, "#d62728"), std::move(model),
              std::move(mark)};
  return f;
}

}  // namespace

std::string incline_decision_rule() {
  return "Normal friction is declared present when model A's 95 % interval of f_N/m excludes 0 AND the "
         "F-test of A against B is significant (p < 0.05); otherwise absent. Without model A "
         "(--no-model-a) the a_N intercept's 95 % interval decides.";
}

void add_incline_analysis_equations(report::Section& s) {
  add_model_b_equations(s);
  s.add_equation("dv/dt = −g cos φ μ v̂ + (f_N/m) n̂ − g sin φ ŷ", "incline study, section 4-3 (肆-三); docs/theory.md#incline-analysis",
                 "model A: a friction component f_N normal to the path (n̂ = left normal of v̂); f_N = 0 is model B");
  s.add_equation("F = (RSS_B − RSS_A) / (RSS_A / (2n − 7))", "docs/theory.md#incline-analysis",
                 "A against B, nested models, both with the camera frame's rotation ψ fitted (2n − 6 without it); "
                 "p = the probability that an F(1, 2n − 7) variable exceeds F");
  s.add_equation("a_N = (a_x v_y − a_y v_x)/|v| = g sin φ sin θ − f_N/m,   sin θ = v_x/|v|", "incline study, eq b",
                 "sign corrected, see the errata");
  s.add_equation("cos θ_c = tan φ/μ − f_N sin θ_c/(m g μ cos φ)", "incline study, eq c",
                 "at the extremum of the velocity down the slope (zero acceleration there); cos θ_c = |v_y| / |v|");
  s.add_equation("cos θ_c = k = tan φ / μ", "incline study, eq c'", "model B (f_N = 0)");
}

int add_incline_run_analysis(report::Section& s, const std::string& title, const analysis::InclineAnalysis& a,
                             const std::optional<InclineTruth>& truth) {
  const auto& b = a.model_b;
  const auto tv = [&](double InclineTruth::*m) { return truth ? std::optional<double>((*truth).*m) : std::nullopt; };
  Table tb = estimate_table(title + ": model B fit (" + std::to_string(a.data.size()) + " points, " +
                                std::to_string(b.iterations) + " iterations)",
                            truth.has_value());
  tb.rows = {estimate_row("μ", b.mu, tv(&InclineTruth::mu)), estimate_row("v_0 (m/s)", b.v0, tv(&InclineTruth::v0)),
             estimate_row("t_0, launch (s)", b.t0, tv(&InclineTruth::t0)),
             estimate_row("x_0 (m)", b.x0, tv(&InclineTruth::x0)), estimate_row("y_0 (m)", b.y0, tv(&InclineTruth::y0))};
  s.add_table(std::move(tb));

  Table key;
  key.caption = title + ": derived numbers";
  key.header = {"quantity", "value"};
  key.rows = {{"φ (deg)", format_value(to_deg(a.phi), 5)},
              {"k = tan φ / μ", format_value(std::tan(a.phi) / b.mu.value, 5)},
              {"camera frame rotation ψ (deg)",
               b.frame_rotation.sigma > 0
                   ? format_uncertain(to_deg(b.frame_rotation.value),
                                      to_deg(b.frame_rotation.sigma))
                   : "0 (not fitted)"},
              {"rms residual, model B (m)", format_value(b.rms_residual, 4)},
              {"t_stop (s)", b.t_stop ? format_value(*b.t_stop, 5) : "—"},
              {"x_stop, y_stop (m)", b.x_stop ? format_value(*b.x_stop, 5) + ", " + format_value(*b.y_stop, 5) : "—"}};
  s.add_table(std::move(key));

  Table cmp;
  cmp.caption = title + ": model A against model B";
  cmp.header = {"quantity", "value"};
  if (a.model_a && a.test) {
    const auto& m = *a.model_a;
    const std::optional<double> fn = tv(&InclineTruth::normal_accel);
    cmp.rows = {{"f_N/m, model A (m/s^2)", format_uncertain(m.normal_accel.value, m.normal_accel.sigma)},
                {"95 % interval of f_N/m", interval_cell(m.normal_accel.ci_low, m.normal_accel.ci_high)},
                {"μ, model A", format_uncertain(m.mu.value, m.mu.sigma)},
                {"correlation of f_N/m with the frame rotation", format_value(m.rotation_correlation, 3)},
                {"rms residual A / B (m)", format_value(m.rms_residual, 4) + " / " + format_value(b.rms_residual, 4)},
                {"F statistic", format_value(a.test->f_statistic, 4)},
                {"p value", format_value(a.test->p_value, 3)},
                {"interval excludes 0", yes_no(a.test->ci_excludes_zero)},
                {"F-test significant (p < 0.05)", yes_no(a.test->significant)}};
    if (fn)
      cmp.rows.push_back({"truth f_N/m (make.sh)", format_value(*fn, 4) + (*fn >= m.normal_accel.ci_low &&
                                                                                       *fn <= m.normal_accel.ci_high
                                                                                   ? " (in the interval)"
                                                                                   : " (outside the interval)")});
  }
  cmp.rows.push_back({"verdict: normal friction", to_string(a.verdict)});
  cmp.rows.push_back({"decided by", a.verdict_source == analysis::VerdictSource::model_a_test ? "model A test" : "a_N intercept"});
  s.add_table(std::move(cmp));
  s.add_paragraph("Decision rule: " + incline_decision_rule());

  Table diag;
  diag.caption = title + ": the study's diagnostics (eqs b, c)";
  diag.header = {"quantity", "value"};
  if (a.a_n) {
    const auto& d = *a.a_n;
    diag.rows.push_back({"a_N slope (m/s^2)", format_uncertain(d.slope, d.sigma_slope)});
    diag.rows.push_back({"g sin φ (m/s^2)", format_value(d.slope_expected, 4)});
    diag.rows.push_back({"a_N intercept = −f_N/m (m/s^2)", format_uncertain(d.intercept, d.sigma_intercept)});
    diag.rows.push_back({"95 % interval of the intercept", interval_cell(d.intercept_ci_low, d.intercept_ci_high)});
  }
  if (a.theta_c) {
    const auto& c = *a.theta_c;
    diag.rows.push_back({"cos θ_c (data)", format_uncertain(c.cos_theta_c, c.sigma_cos_theta_c)});
    diag.rows.push_back({"θ_c (deg)", format_value(c.theta_c_deg, 4)});
    diag.rows.push_back({"t_c, the time of θ_c (s)", format_value(c.t_c, 4)});
    diag.rows.push_back({"cos θ_c = k, model B fit (eq c')", format_value(a.cos_theta_c_model, 4)});
  }
  if (!diag.rows.empty()) s.add_table(std::move(diag));
  if (!a.notes.empty()) s.add_list(a.notes);
  if (!a.warnings.empty()) {
    std::vector<std::string> w;
    for (const auto& x : a.warnings) w.push_back("Warning: " + x);
    s.add_list(w);
  }

  std::vector<InclineCurve> curves;
  curves.push_back({"data (Savitzky–Golay derivatives)", data_states(a), report::Mode::Markers, report::Dash::Solid, "#1f77b4"});
  curves.push_back(incline_curve("model B fit", a.model_b_fine, report::Dash::Solid, "#d62728"));
  if (a.model_a) curves.push_back(incline_curve("model A fit", a.model_a_fine, report::Dash::Dash, "#2ca02c"));
  int n = add_incline_kinematics(s, title, curves,
                                 "Points: the tracked positions and their local-fit derivatives; lines: the fitted models.");
  s.add_figure(residual_figure(title + ": residuals of model B", a, a.residual_x_b, a.residual_y_b, b.rms_residual));
  ++n;
  if (a.model_a) {
    s.add_figure(residual_figure(title + ": residuals of model A", a, a.residual_x_a, a.residual_y_a,
                                 a.model_a->rms_residual));
    ++n;
  }
  if (a.a_n) {
    s.add_figure(a_n_figure(title, *a.a_n));
    ++n;
  }
  if (a.theta_c) {
    s.add_figure(theta_c_figure(title, a, *a.theta_c));
    ++n;
  }
  return n;
}

int add_normal_friction_fit(report::Section& s, const std::string& title, const analysis::NormalFrictionTest& r,
                             const std::optional<double>& mu_truth) {
  Table runs;
  runs.caption = title + ": runs";
  runs.header = {"source", "φ (deg)", "tan φ", "cos θ_c"};
  for (const auto& p : r.points)
    runs.rows.push_back({p.source, format_value(to_deg(p.phi), 5), format_value(std::tan(p.phi), 5),
                         p.sigma_cos_theta_c > 0 ? format_uncertain(p.cos_theta_c, p.sigma_cos_theta_c)
                                                 : format_value(p.cos_theta_c, 5)});
  s.add_table(std::move(runs));
  Table fit;
  fit.caption = title + ": line cos θ_c = c_0 + c_1 tan φ";
  fit.header = {"quantity", "value"};
  fit.rows = {{"slope c_1 = 1/μ", format_uncertain(r.slope, r.sigma_slope)},
              {"μ = 1/c_1", format_uncertain(r.mu, r.sigma_mu)},
              {"intercept c_0", format_uncertain(r.intercept, r.sigma_intercept)},
              {"95 % interval of the intercept", interval_cell(r.intercept_ci_low, r.intercept_ci_high)},
              {"R^2", format_value(r.line.r_squared, 5)},
              {"verdict: normal friction", to_string(r.verdict)}};
  if (mu_truth) fit.rows.push_back({"truth μ (make.sh)", format_value(*mu_truth, 4)});
  s.add_table(std::move(fit));
  s.add_paragraph("Rule: with no normal friction (model B) the line passes through the origin with slope 1/μ "
                  "(eq c'); an intercept whose 95 % interval excludes 0 says a normal component is present.");

  Figure f = figure(title + ": cos θ_c against tan φ (eq c)", "tan φ", "cos θ_c", 400);
  f.caption = "Error bars: one standard uncertainty of each run's cos θ_c. Dashed: the line through the origin with "
              "the fitted μ (model B).";
  Series pts = named("runs");
  for (const auto& p : r.points) {
    pts.x.push_back(std::tan(p.phi));
    pts.y.push_back(p.cos_theta_c);
    pts.y_error.push_back(p.sigma_cos_theta_c > 0 ? p.sigma_cos_theta_c : NAN);
  }
  const double hi = *std::max_element(pts.x.begin(), pts.x.end()) * 1.1;
  f.series = {std::move(pts), make_line("fitted line", {0, hi}, {r.line(0), r.line(hi)}, report::Dash::Solid, "#d62728"),
              make_line("tan φ / μ", {0, hi}, {0, hi / r.mu}, report::Dash::Dash, "black")};
  s.add_figure(std::move(f));
  return 1;
}

int add_slide_analysis(report::Section& s, const std::string& title, const analysis::SlideResult& r,
                       const analysis::SlideOptions& o, const std::optional<double>& mu_truth) {
  Table t;
  t.caption = title + ": acceleration and friction";
  t.header = {"quantity", "value"};
  t.rows = {{"a along the path, parabola (m/s^2)", format_uncertain(r.a, r.sigma_a)},
            {"a from the v–t line, the study's method (m/s^2)", format_uncertain(r.a_velocity_line, r.sigma_a_velocity_line)},
            {"μ (eq a)", r.mu ? format_uncertain(*r.mu, *r.sigma_mu) : "— (needs --phi-deg)"},
            {"φ (deg)", !o.phi                ? "—"
                        : o.sigma_phi > 0 ? format_uncertain(to_deg(*o.phi), to_deg(o.sigma_phi))
                                          : format_value(to_deg(*o.phi), 6)},
            {"R^2 of the parabola", format_value(r.r_squared, 6)},
            {"moving points used", std::to_string(r.n_points)},
            {"direction of motion (deg)", format_value(r.direction_deg, 4)},
            {"rms distance from a straight path (m)", format_value(r.straightness_rms, 3)}};
  if (mu_truth) t.rows.push_back({"truth μ (make.sh)", format_value(*mu_truth, 4)});
  s.add_table(std::move(t));
  s.add_equation("μ = (g sin φ − a) / (g cos φ)", "incline study, eq a", "a = 2 c_2 of the parabola s = c_0 + c_1 t + c_2 t^2");

  Figure st = figure(title + ": distance along the slope s–t", "t (s)", "s (m), down the path", 360);
  st.caption = "The tracked points projected on their straight path, and the fitted parabola.";
  Series pts = named("data");
  pts.x = r.t;
  pts.y = r.s;
  std::vector<double> ft, fs, res;
  for (std::size_t i = 0; i < r.t.size(); ++i) res.push_back(r.s[i] - r.parabola(r.t[i]));
  if (!r.t.empty()) {
    for (int i = 0; i <= 100; ++i) {
      const double tt = r.t.front() + (r.t.back() - r.t.front()) * i / 100;
      ft.push_back(tt);
      fs.push_back(r.parabola(tt));
    }
  }
  st.series = {pts, make_line("parabola", ft, fs, report::Dash::Solid, "#d62728")};
  s.add_figure(std::move(st));
  Figure rf = figure(title + ": residuals of the parabola", "t (s)", "data − parabola (m)", 300);
  rf.caption = "rms " + format_value(r.parabola.rms, 3) + " m.";
  Series rs = named("residual");
  rs.x = r.t;
  rs.y = res;
  rf.series = {std::move(rs)};
  s.add_figure(std::move(rf));
  Figure vf = figure(title + ": speed v–t (the study's line)", "t (s)", "v (m/s)", 320);
  Series vs = named("central differences");
  vs.x = r.v_t;
  vs.y = r.v;
  std::vector<double> lv;
  for (double tt : r.v_t) lv.push_back(r.velocity_line(tt));
  vf.series = {std::move(vs), make_line("v–t line", r.v_t, lv, report::Dash::Solid, "#d62728")};
  s.add_figure(std::move(vf));
  return 3;
}

report::Report incline_analyze_report(const std::string& source, const analysis::InclineAnalysis& a) {
  report::Report r;
  r.title = "tribolab incline analyze";
  r.subtitle = "Models B and A fitted to " + source + " (incline study, section 4 (肆))";
  auto& eq = r.add_section("Models and equations");
  add_incline_analysis_equations(eq);
  auto& s = r.add_section("Analysis of " + source);
  add_incline_run_analysis(s, "Run", a);
  return r;
}

report::Report incline_slide_report(const std::string& source, const analysis::SlideResult& res,
                                    const analysis::SlideOptions& o) {
  report::Report r;
  r.title = "tribolab incline mu-from-slide";
  r.subtitle = "μ from a straight slide down the incline, " + source + " (incline study, eq a)";
  auto& s = r.add_section("Slide " + source);
  add_slide_analysis(s, "Slide", res, o);
  return r;
}

report::Report incline_normal_test_report(const analysis::NormalFrictionTest& res) {
  report::Report r;
  r.title = "tribolab incline normal-friction-test";
  r.subtitle = "cos θ_c against tan φ over " + std::to_string(res.points.size()) + " runs (incline study, eq c, figure 3-2 (圖三-2))";
  auto& s = r.add_section("Normal friction test");
  s.add_equation("cos θ_c = tan φ/μ − f_N sin θ_c/(m g μ cos φ)", "incline study, eq c");
  add_normal_friction_fit(s, "Test", res);
  return r;
}

report::Report incline_stop_report(const incline::StopMeasurement& m, const incline::MuFromStopResult& res,
                                   bool has_sigma, const std::optional<incline::AngleAdvice>& advice) {
  report::Report r;
  r.title = "tribolab incline mu-from-stop";
  r.subtitle = "μ from the stopping point alone (incline study, eq 10A (十A))";
  auto& s = r.add_section("Stop point");
  Table in;
  in.caption = "Inputs";
  in.header = {"quantity", "value"};
  in.rows = {{"φ (deg)", has_sigma ? format_uncertain(to_deg(m.phi), to_deg(m.sigma_phi))
                                   : format_value(to_deg(m.phi), 6)},
             {"x_stop (m)", has_sigma ? format_uncertain(m.x_stop, m.sigma_pos) : format_value(m.x_stop, 6)},
             {"y_stop (m)", has_sigma ? format_uncertain(m.y_stop, m.sigma_pos) : format_value(m.y_stop, 6)},
             {"g (m/s^2)", format_value(m.g, 5)}};
  s.add_table(std::move(in));
  Table out;
  out.caption = "Result";
  out.header = {"quantity", "value"};
  out.rows = {{"μ", has_sigma ? format_uncertain(res.mu, res.sigma_mu) : format_value(res.mu, 6)},
              {"k = tan φ / μ", format_value(res.k, 6)},
              {"r = |x_stop / y_stop|", format_value(res.r, 6)},
              {"v_0 implied by x_stop (m/s)", format_value(res.v0, 5)},
              {"∂μ/∂φ (1/rad), ∂μ/∂x, ∂μ/∂y (1/m)",
               format_value(res.dmu_dphi, 4) + ", " + format_value(res.dmu_dx, 4) + ", " + format_value(res.dmu_dy, 4)}};
  if (advice) {
    out.rows.push_back({"best angle for the same v_0 and uncertainties (deg)",
                        format_value(to_deg(advice->phi), 4) +
                            (advice->at_boundary ? " (the largest angle whose stop fits the plate)" : "")});
    out.rows.push_back({"σ_μ at the best angle", format_value(advice->sigma_mu, 3)});
  }
  s.add_table(std::move(out));
  s.add_equation("r k^3 − 8 k^2 − 4 r k + 8 = 0,   r = |x_{stop}/y_{stop}|,   μ = tan φ / k", "incline study, eq 10A (十A) (eq 10.3)",
                 "the unique root in (0, 1), by bracketing; eqs 8 and 9 (八, 九) divided");
  s.add_equation("x_{stop} = 2v_0^2/(α(4−k^2))", "incline study, eq 8 (八)", "gives the implied launch speed");
  incline::Parameters p;
  p.mu = res.mu;
  p.phi = m.phi;
  p.v0 = res.v0;
  p.g = m.g;
  const incline::ClosedForm cf(p);
  std::vector<double> x, y;
  for (int i = 0; i <= 200; ++i) {
    const auto st = cf.at(cf.t_stop() * i / 200);
    x.push_back(st.x);
    y.push_back(st.y);
  }
  Figure f = figure("Trajectory to the stop (model B with the solved μ and v_0)", "x (m)", "y (m)", 400);
  f.equal_aspect = true;
  f.caption = "The closed-form path from the launch to the stop; the marker is the measured stop point"
              + std::string(has_sigma ? " with one standard uncertainty." : ".");
  Series stop = named("measured stop");
  stop.x = {m.x_stop};
  stop.y = {m.y_stop};
  if (has_sigma && m.sigma_pos > 0) {
    stop.x_error = {m.sigma_pos};
    stop.y_error = {m.sigma_pos};
  }
  f.series = {make_line("model B, μ = " + format_value(res.mu, 4), x, y, report::Dash::Solid, "#d62728"), std::move(stop)};
  s.add_figure(std::move(f));
  return r;
}

}  // namespace tribolab::app
