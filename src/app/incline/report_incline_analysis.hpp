// Report pages of the tracked-run analyses of seed 000 (`incline analyze`, `mu-from-slide`,
// `normal-friction-test`, `mu-from-stop`) and the building blocks the demo's "incline-runs"
// case study shares with them. Every number shown is the analysis result's own (the same
// values the command prints as JSON), formatted with report::format_uncertain.
#pragma once

#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/incline_slide.hpp"
#include "incline/inverse.hpp"
#include "report/report.hpp"

#include <optional>
#include <string>

namespace tribolab::app {

/// The parameters a synthetic run was made with, shown beside what the fit recovers.
struct InclineTruth {
  double mu = 0;            ///< kinetic friction coefficient
  double v0 = 0;            ///< launch speed, m/s
  double t0 = 0;            ///< launch instant in the file's time, s
  double x0 = 0, y0 = 0;    ///< launch point, m
  double normal_accel = 0;  ///< f_N/m of model A, m/s^2 (0 = model B)
};

/// The decision rule of the model A test, as stated in the report and docs/cli.md.
std::string incline_decision_rule();

/// Adds one run's analysis to `s`: fitted parameters with uncertainties and 95 % intervals
/// (and the truth, with whether each interval holds it, when `truth` is given), model A vs
/// B (F-test, A's interval, verdict and rule), the figures x–t, y–t, y–x, v_x–t, v_y–t,
/// a_x–t, a_y–t (data from the tracked points' Savitzky–Golay derivatives against the
/// fitted models), the residuals of each fit, a_N against sin(theta) with the fitted line and
/// its 95 % band (eq b), and v_y around theta_c (eq c). Figure titles start with `title`.
/// Returns the number of figures added: 7 + 1 per fitted model + 1 per diagnostic present.
int add_incline_run_analysis(report::Section& s, const std::string& title,
                             const analysis::InclineAnalysis& a,
                             const std::optional<InclineTruth>& truth = {});

/// The equations of the run analysis: model B (add_model_b_equations), model A, eqs b, c, c'.
void add_incline_analysis_equations(report::Section& s);

/// Adds the normal-friction test over runs (eq c, seed 圖三-2): a table of the runs, slope,
/// 1/mu, intercept with its interval and the verdict, and the figure cos(theta_c) against
/// tan(phi) with error bars, the fitted line and model B's line through the origin. Returns 1.
int add_normal_friction_fit(report::Section& s, const std::string& title,
                             const analysis::NormalFrictionTest& r,
                             const std::optional<double>& mu_truth = {});

/// Adds a straight slide's analysis (eq a): a and mu with uncertainties, the along-slope
/// distance s(t) with the fitted parabola, its residuals and the v–t line. Returns 3.
int add_slide_analysis(report::Section& s, const std::string& title, const analysis::SlideResult& r,
                       const analysis::SlideOptions& o, const std::optional<double>& mu_truth = {});

/// `incline analyze --report`.
report::Report incline_analyze_report(const std::string& source, const analysis::InclineAnalysis& a);

/// `incline mu-from-slide --report`.
report::Report incline_slide_report(const std::string& source, const analysis::SlideResult& r,
                                    const analysis::SlideOptions& o);

/// `incline normal-friction-test --report`.
report::Report incline_normal_test_report(const analysis::NormalFrictionTest& r);

/// `incline mu-from-stop --report`: the inputs, mu ± sigma (eq 十A), and model B's
/// trajectory with that mu and the implied v0 to the stop, with the measured stop point.
/// `has_sigma`: uncertainties were given (else sigma_mu is not shown); `advice`: the
/// best-angle advice of --plate-size, when asked for.
report::Report incline_stop_report(const incline::StopMeasurement& m, const incline::MuFromStopResult& r,
                                   bool has_sigma, const std::optional<incline::AngleAdvice>& advice = {});

}  // namespace tribolab::app
