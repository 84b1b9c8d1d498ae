// The seed's two diagnostics of a normal friction component (seed 000, 肆-二):
//
// (b) a_N against sin(theta): with theta the angle between the velocity and the -y axis
//     (sin theta = vx/|v|, cos theta = -vy/|v|, seed eq 1.3) and a_N the acceleration toward
//     the centre of curvature (the right normal of the velocity),
//       a_N = (ax vy - ay vx)/|v| = g sin(phi) sin(theta) - f_N/m           (eq b)
//     a straight line with slope g sin(phi) and intercept -f_N/m. (The seed prints
//     a_N = a_y sin(theta) - a_x cos(theta) with cos(theta) = v_y/|v|, which is -a_N: see the
//     errata in docs/theory.md.) Velocities and accelerations come from local quadratic fits
//     on NON-overlapping blocks of consecutive points, so the points of the line fit have
//     independent errors and the intercept's interval is honest.
// (c) theta_c at the extremum of v_y (a_y = 0): cos(theta_c) = |v_y|/|v| there, and
//       cos(theta_c) = tan(phi)/mu - f_N sin(theta_c)/(m g mu cos(phi))         (eq c)
//     so over runs at several angles cos(theta_c) against tan(phi) is a line through the
//     origin with slope 1/mu when f_N = 0 (eq c'). Located by a polynomial fit of y(t) around
//     the extremum (its inflection point), with the velocity from the fits of x(t) and y(t).
// See docs/theory.md#incline-analysis.
#pragma once

#include "numerics/polyfit.hpp"
#include "track/track.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// Eq b diagnostic of one run.
struct NormalAccelDiagnostic {
  std::vector<double> t, sin_theta, a_n;  ///< one point per block: s, 1, m/s^2
  numerics::PolyFit line;                 ///< a_n = c0 + c1 sin_theta
  double slope = 0;            ///< m/s^2 (expected g sin(phi))
  double sigma_slope = 0;      ///< m/s^2, from the line's scatter
  double slope_expected = 0;   ///< g sin(phi), m/s^2
  double intercept = 0;        ///< m/s^2 (expected 0 for model B, -f_N/m for model A)
  double sigma_intercept = 0;  ///< m/s^2, from the line's scatter (Student t, n - 2 dof)
  /// truncation bias of the local quadratics, measured on the model's noise-free path and
  /// already subtracted from intercept and slope (0 without a reference), m/s^2 (~1e-3..1e-2)
  double truncation_intercept = 0, truncation_slope = 0;
  double intercept_ci_low = 0, intercept_ci_high = 0;  ///< interval at `level`, m/s^2
  bool intercept_excludes_zero = false;
  int block = 0;               ///< points per block
  int degree = 2;              ///< degree of the local fits
};

/// A fitted model's noise-free path for the eq b diagnostic: the same blocks on it measure the
/// local quadratics' truncation bias (docs/theory.md#incline-analysis, "a_N truncation").
struct NormalAccelReference {
  track::Track path;       ///< the model's points at the data's times, same frame, m
  double intercept = 0;    ///< the model's own eq b intercept -f_N/m (0 for model B), m/s^2
};

/// Eq b over the points of `track` with t0 < t <= t_end (the moving part; choose t_end short
/// of the stop, where theta is undefined). `block` = points per local fit (0 = automatic).
/// With a `reference` the truncation bias is subtracted (without one it is not: raw use only).
/// Returns empty when fewer than 3 blocks fit.
std::optional<NormalAccelDiagnostic> normal_accel_diagnostic(const track::Track& track, double t0,
                                                             double t_end, double phi, double g,
                                                             int block, double level,
                                                             const NormalAccelReference* reference = nullptr);

/// Eq c diagnostic of one run.
struct ThetaC {
  double t_c = 0;            ///< instant of the v_y extremum, s (file time)
  double sigma_t_c = 0;      ///< s
  double vx = 0, vy = 0;     ///< velocity there, m/s
  double cos_theta_c = 0;    ///< |v_y|/|v| at the extremum
  /// propagated from the local fits' covariance, with the truncation error in quadrature
  double sigma_cos_theta_c = 0;
  /// the polynomial model's truncation error (automatic degree only; 0 otherwise), part of sigma
  double sigma_truncation = 0;
  int degree = 0;            ///< degree of the local fits of x(t) and y(t)
  double theta_c_deg = 0;    ///< deg
  double window_low = 0, window_high = 0;  ///< time window of the local polynomial fits, s
  numerics::PolyFit fit_x, fit_y;          ///< polynomials in (t - t_guess)
  double t_guess = 0;        ///< centre of the window (the model's prediction), s
  int points = 0;            ///< tracked points in the window (those the fits used)
};

/// Fewer points than this in the theta_c window and the stated sigma is too small: over a grid
/// of noisy model B runs the error was 1.42 stated sd rms below it (6 % beyond 3 sd, worst 5.2)
/// and 1.11 at or above it (docs/theory.md, "theta_c truncation"); `incline analyze` warns.
inline constexpr int kThetaCMinPoints = 50;

/// Locates the v_y extremum in [window_low, window_high] from polynomial fits of x(t) and
/// y(t) of `degree` (3..8) in t - t_guess: the inflection of y where y'' rises through zero
/// nearest t_guess. Empty when there is none in the window or the window has fewer than
/// degree + 4 points. `degree` = 0 (automatic): sextics (fewer with few points) and the
/// truncation error, from the fit two degrees higher, added to the sigma (docs/theory.md).
std::optional<ThetaC> theta_c_diagnostic(const track::Track& track, double t_guess,
                                         double window_low, double window_high, int degree = 0);

/// Whether a friction component normal to the path is present (docs/theory.md, model A):
/// present when the test's interval excludes 0.
enum class Verdict { absent, present };
/// "absent" or "present": the value of the JSON key "verdict".
const char* to_string(Verdict v);
/// present when `excludes_zero`, else absent.
constexpr Verdict verdict_from(bool excludes_zero) { return excludes_zero ? Verdict::present : Verdict::absent; }

/// One run of the cos(theta_c) - tan(phi) test.
struct ThetaCPoint {
  double phi = 0;              ///< rad
  double cos_theta_c = 0;
  double sigma_cos_theta_c = 0;  ///< 0 when unknown (a table without it)
  std::string source;          ///< file or table line it came from
};

/// Eq c over several runs (seed 000, 圖三-2): cos(theta_c) = c0 + c1 tan(phi).
struct NormalFrictionTest {
  std::vector<ThetaCPoint> points;
  numerics::PolyFit line;      ///< ordinary least squares (each run one point)
  double slope = 0, sigma_slope = 0;  ///< 1/mu when f_N = 0
  double mu = 0, sigma_mu = 0;        ///< 1/slope and sigma_slope/slope^2
  double intercept = 0, sigma_intercept = 0;
  double intercept_ci_low = 0, intercept_ci_high = 0;  ///< at `level`
  Verdict verdict = Verdict::absent;  ///< present when the interval excludes 0
};

/// Fits the line; throws InputError with fewer than 3 runs or a single angle.
NormalFrictionTest normal_friction_test(const std::vector<ThetaCPoint>& points, double level = 0.95);

}  // namespace tribolab::analysis
