// The summary of a series of tracked incline runs (seed 000 launched many discs: table 1,
// figures 五A-八): the weighted friction coefficient and whether the runs agree, the stop
// point's scaling with the launch speed across runs (figure 八, eqs 七-十) and the mu each
// slope implies, the cos(theta_c)-tan(phi) test when the angles differ (eq c'), and model A's
// normal friction pooled over the runs. docs/theory.md#series-of-runs.
#pragma once

#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/series_stats.hpp"
#include "numerics/units.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// What the summary needs of one analysed run (incline_run_point makes it from an analysis;
/// tests build it by hand). Stop quantities are relative to the launch (t - t0, x - x0, y - y0).
struct InclineRunPoint {
  std::string source;          ///< file
  double phi = 0;              ///< incline angle, rad
  double mu = 0, sigma_mu = 0; ///< model B fit
  double v0 = 0, sigma_v0 = 0; ///< launch speed, m/s
  std::optional<double> t_stop;  ///< stop time after the launch, s (eq 七)
  std::optional<double> x_stop;  ///< stop point across the slope from the launch point, m (eq 八)
  std::optional<double> y_stop;  ///< and up the slope, m, < 0 (eq 九)
  std::optional<double> cos_theta_c, sigma_cos_theta_c;    ///< eq c diagnostic
  std::optional<double> normal_accel, sigma_normal_accel;  ///< model A's f_N/m, m/s^2
  Verdict verdict = Verdict::absent;  ///< the run's own normal-friction verdict
};

/// The point of one run's analysis.
InclineRunPoint incline_run_point(const InclineAnalysis& a, const std::string& source);

/// Which stop-point relation of figure 八.
enum class StopRelation {
  t_vs_v0,    ///< t_stop = v0 / (alpha (1 - k^2))                  (eq 七)
  x_vs_v0sq,  ///< x_stop = 2 v0^2 / (alpha (4 - k^2))              (eq 八)
  y_vs_v0sq,  ///< y_stop = -k v0^2 / (4 alpha (1 - k^2))           (eq 九)
  y_vs_x,     ///< y_stop / x_stop = -k (4 - k^2) / (8 (1 - k^2))   (eq 十)
};

/// Key of a relation in the JSON: "t_stop_v0", "x_stop_v0sq", "y_stop_v0sq", "y_stop_x_stop".
std::string stop_relation_key(StopRelation r);

/// The slope model B predicts for relation `r` (units s/(m/s), s^2/m, s^2/m, 1), or empty
/// when the disc does not stop (mu <= tan(phi)).
std::optional<double> stop_slope(StopRelation r, double mu, double phi, double g);

/// mu implied by a slope of relation `r` at angle phi (the inverse of stop_slope: each slope
/// is monotonic in mu on mu > tan(phi)); empty when no mu gives that slope (wrong sign, or
/// beyond the value at mu = tan(phi), or phi = 0 for the y relations, where y_stop = 0).
std::optional<double> mu_from_stop_slope(StopRelation r, double slope, double phi, double g);

/// One relation fitted across runs.
struct StopScaling {
  StopRelation relation = StopRelation::t_vs_v0;
  std::vector<double> x, y;   ///< the runs' points (v0, v0^2 or x_stop; t_stop, x_stop, y_stop)
  std::vector<std::string> sources;
  ProportionalFit fit;        ///< line through the origin
  /// mu implied by the slope, and by the ends of its interval (empty: unbounded there).
  std::optional<double> mu, mu_ci_low, mu_ci_high;
  std::optional<double> slope_model;  ///< the slope model B predicts at the weighted mu
};

/// Model A's normal friction pooled over runs.
struct PooledNormalFriction {
  WeightedMean mean;          ///< of f_N/m, m/s^2
  double ci_low = 0, ci_high = 0;  ///< mean -+ z sigma_scaled at `level`, m/s^2
  Verdict verdict = Verdict::absent;  ///< present when the interval excludes 0
  int n_present = 0;          ///< runs whose own verdict was present
};

struct InclineSeriesSummary {
  std::optional<WeightedMean> mu;  ///< weighted mean of the runs' mu (model B)
  std::vector<int> mu_index;       ///< run index of each value in mu (its pulls)
  /// Runs named by iterative rejection: the largest |pull| beyond outlier_pull is named and
  /// left out, the mean recomputed, until none is beyond (mu itself keeps every run).
  std::vector<std::string> outliers;
  std::optional<double> common_phi;   ///< rad, when every run has the same angle
  std::vector<StopScaling> scaling;   ///< figure 八's four relations (when the angle is common)
  std::string scaling_note;           ///< why scaling is empty or shorter
  std::optional<NormalFrictionTest> theta_c_test;  ///< eq c' over the angles
  std::string theta_c_note;           ///< why theta_c_test is empty
  std::optional<PooledNormalFriction> normal_friction;
  std::string normal_friction_note;
};

struct InclineSeriesOptions {
  double g = kDefaultG;       ///< m/s^2
  double level = 0.95;        ///< of every interval
  double outlier_pull = 3;    ///< |pull| beyond which a run is named an outlier
  std::string validate() const;
};

/// Summarises the runs (those that were analysed; failed runs are not passed). Parts the
/// runs cannot support are left empty with a note (never an exception for a thin series).
InclineSeriesSummary summarize_incline_series(const std::vector<InclineRunPoint>& runs,
                                              const InclineSeriesOptions& options = {});

/// Weighted mu of straight slides (`incline mu-from-slide` over several files).
struct SlideSeriesSummary {
  std::optional<WeightedMean> mu;
  std::vector<int> mu_index;
  std::vector<std::string> outliers;
  std::string note;
};

/// mu_i with sigma_i per run (empty: that run had no angle); sources name the runs.
SlideSeriesSummary summarize_slide_series(const std::vector<std::optional<double>>& mu,
                                          const std::vector<std::optional<double>>& sigma_mu,
                                          const std::vector<std::string>& sources, double outlier_pull = 3);

}  // namespace tribolab::analysis
