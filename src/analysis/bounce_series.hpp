// A series of analysed bounces (seed 001's experiments 1 and 2: 120 throws, six data sets):
// restitution against the collision angle with error bars and a binned trend (its figure 32),
// energies before/after and the mean normal force per run (figures 49, 50), the contact-point
// speed at touch against the angle (figure 52), runs with e > 1 and whether significantly so,
// outliers named, and the runs as rows of `bounce fit`'s table (`bounces_out`).
// docs/theory.md#bounce-series.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/series_stats.hpp"
#include "bounce/contact.hpp"
#include "bounce/geometry.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// What the series reads from one analysed bounce. NaN marks a value the run does not have
/// (e_height without a trusted floor, the force without a contact duration).
struct BounceSeriesPoint {
  double collision_angle_deg = 0;        ///< seed 001 figure 30, at first touch, deg in [0, 180]
  double sigma_collision_angle_deg = 0;  ///< deg; NaN when the analysis has none (floor bracketed)
  double theta_deg = 0;                  ///< orientation of the major axis at first touch, deg
  double e_velocity = 0, sigma_e_velocity = 0;  ///< restitution from velocities (typ. 0.4-1.3)
  double e_height = 0, sigma_e_height = 0;      ///< sqrt(H'/H); NaN when not reported
  double vx_in = 0, vy_in = 0, omega_in = 0;    ///< at first touch, m/s, m/s (< 0), rad/s
  double vx_out = 0, vy_out = 0, omega_out = 0; ///< at separation, m/s, m/s, rad/s
  /// Their standard uncertainties (deg, m/s, rad/s; NaN with a bracketed floor): the fit's
  /// weights (bounce_row_of, fit_bounces).
  double sigma_theta_deg = NAN, sigma_vx_in = NAN, sigma_vy_in = NAN, sigma_omega_in = NAN;
  double sigma_vx_out = NAN, sigma_vy_out = NAN, sigma_omega_out = NAN;
  bounce::KineticEnergy energy_pre, energy_post;  ///< J at touch / separation (seed 001, 討論 (一))
  double mean_normal_force = 0, sigma_mean_normal_force = 0;  ///< N (typ. 100-300); NaN without T
  /// Velocity of the material point at the support point at first touch, m/s (seed 001
  /// figure 51-c, 討論 三; typ. 1-6 m/s), and its speed with its sigma (the analysis's own).
  double contact_point_vx = 0, contact_point_vy = 0;
  double contact_point_speed = 0, sigma_contact_point_speed = 0;
};

/// The adapter: the ONE place that reads a BounceAnalysis for the series (so a change of the
/// single-run fields is a change here only). Everything is the touch / separation state.
BounceSeriesPoint point_of(const BounceAnalysis& r);

/// The run as a row of `bounce fit`'s table: orientation and velocities at first touch, and
/// the velocities at separation (what bounce fit's simulated contact starts from and ends at).
BounceRow bounce_row_of(const BounceSeriesPoint& p);

struct BounceSeriesOptions {
  double bin_width_deg = 20;   ///< width of the collision-angle bins of the trend, deg (1..180)
  /// One-sided normal quantile for "e > 1 significantly": (e - 1)/sigma_e > z (1.645: 95%).
  double z_above_one = 1.6448536269514722;
  /// Modified z-score (Iglewicz & Hoaglin 1993: 0.6745 |x - median| / MAD) above which a run
  /// is named an outlier of its angle bin; 3.5 is their recommendation.
  double outlier_z = 3.5;
  int outlier_min_bin = 4;     ///< runs a bin needs before its outliers are named
  std::string validate() const;
};

/// The weighted mean (analysis/series_stats.hpp) of the values that have one: a NaN value or
/// a sigma that is not finite and positive is left out; none left gives n = 0, NaN mean and
/// sigma.
WeightedMean weighted_mean_of_finite(const std::vector<double>& x, const std::vector<double>& sigma);

/// One bin of collision angle [low, high) (the last bin includes 180).
struct AngleBin {
  double low_deg = 0, high_deg = 0;   ///< deg
  double centre_deg = 0;              ///< weighted mean angle of its runs, deg (NaN if empty)
  int n = 0;                          ///< runs in the bin
  WeightedMean e_velocity;            ///< of the runs' e_velocity
  double e_min = 0, e_max = 0;        ///< range of e_velocity in the bin
  int n_above_one = 0;                ///< runs with e_velocity > 1
};

/// Restitution of the runs above 1: counts (e_velocity and e_height separately).
struct AboveOne {
  int n = 0;               ///< runs with the value
  int above = 0;           ///< value > 1
  int significant = 0;     ///< (value - 1)/sigma > z_above_one
};

struct BounceOutlier {
  std::size_t run = 0;     ///< index into the points
  std::string reason;      ///< plain text naming the value and the comparison
};

struct BounceSeriesSummary {
  int n_runs = 0;                       ///< points summarised
  WeightedMean e_velocity, e_height;    ///< over all runs (chi2: one e for every angle?)
  AboveOne above_one_velocity, above_one_height;
  std::vector<AngleBin> bins;           ///< the binned trend of figure 32 (non-empty bins)
  double energy_ratio_mean = 0;         ///< mean of E_post/E_pre over the runs
  int n_energy_gain = 0;                ///< runs whose total kinetic energy grew
  /// Mean normal force over the runs that have it (unweighted mean and sd, N), and Pearson's
  /// r between it and e_velocity (the seed's "higher mean force, higher rebound"); NaN with
  /// fewer than 3 runs.
  int n_force = 0;
  double force_mean = 0, force_sd = 0, force_e_correlation = 0;
  /// The runs where the contact point moved fastest / slowest (figure 52), index and angle.
  std::size_t fastest_contact_run = 0, slowest_contact_run = 0;
  std::vector<BounceOutlier> outliers;
};

/// Whether the runs can be one quantity: the weighted mean's chi-square test does not reject a
/// common value (p >= kContradictionP, analysis/series_plausibility.hpp), or there is one run.
/// Restitutions at different collision angles are not: e depends on the angle (seed 001's
/// figure 32), and their mean describes no bounce.
bool is_one_value(const WeightedMean& m);

/// The series' headline for e_velocity: the weighted mean when the runs are one value, else the
/// relation with the collision angle from the binned trend ("depends on the collision angle:
/// e_v = 0.42 +- 0.01 at 12 deg (bin 0-20) to 1.18 +- 0.02 at 95 deg (bin 80-100) over 7 bins;
/// one common e is rejected, chi2 = ... on ... dof"). docs/theory.md#bounce-series.
std::string e_velocity_headline(const BounceSeriesSummary& s);

/// Summarises points (at least 1). Throws InputError for invalid options or no points.
BounceSeriesSummary summarize_bounce_series(const std::vector<BounceSeriesPoint>& points,
                                            const BounceSeriesOptions& options = {});

}  // namespace tribolab::analysis
