// Analysis of a tracked 2D run of the disc on the incline (seed 000; SPEC section 2.4):
// model B fitted to all x(t), y(t) by nonlinear least squares (unknowns mu, v0, launch
// point x0, y0 and launch time t0), model A (extra unknown: the normal-to-path friction
// acceleration f_N/m) fitted by the same least squares through the integrator, a test of
// A against B, and the seed's two diagnostics (a_N against sin(theta), eq b; theta_c at the
// v_y extremum, eq c). Result structs carry every point and curve a report draws.
//
// Model of the data (docs/theory.md#incline-analysis): for t <= t0 the disc rests at
// (x0, y0); for t > t0 it is at (x0, y0) + r(t - t0), with r the launch along +x from the
// origin (closed form for B, integrator for A) including the rest after a stop. Residuals are
// the x and y differences, all with one unknown noise level (estimated from the fit).
// The camera frame may be turned against the incline by a small unknown angle psi (a plumb
// line set off, a tripod not level): the model is rotated by psi about the launch point
// (analysis/frame_rotation.hpp) and psi is fitted as a nuisance parameter in both models
// (InclineFitOptions::fit_frame_rotation), so a turned frame is not mistaken for normal
// friction. The diagnostics run on the de-rotated points.
#pragma once

#include "analysis/incline_diagnostics.hpp"
#include "incline/closed_form.hpp"
#include "incline/params.hpp"
#include "numerics/least_squares.hpp"
#include "track/kinematics.hpp"
#include "track/track.hpp"
#include "numerics/units.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tribolab::analysis {

struct InclineFitOptions {
  double phi = 0;             ///< incline angle, rad, in [0, pi/2) (required input)
  double g = kDefaultG;       ///< m/s^2
  bool fit_model_a = true;    ///< also fit model A and test it against B
  double level = 0.95;        ///< confidence level of the intervals
  double significance = 0.05; ///< size of the A-vs-B test
  int min_points = 10;        ///< fewest points accepted
  /// Points per independent local fit of the a_N diagnostic; 0 = automatic (about eight
  /// blocks, 5 to 25 points each).
  int diagnostic_block = 0;
  double ode_tolerance = 1e-10;  ///< integrator tolerance inside the model A fit
  /// Fit the rotation psi of the camera frame against the incline (a nuisance parameter in
  /// models B and A); false holds psi = 0 (frame known to be aligned).
  bool fit_frame_rotation = true;

  std::string validate() const;
};

/// A fitted value with its standard error and confidence interval.
struct Estimate {
  double value = 0;    ///< best fit
  double sigma = 0;    ///< standard error (covariance, noise estimated from the residuals)
  double ci_low = 0;   ///< confidence interval at InclineFitOptions::level (Student t)
  double ci_high = 0;
};

/// Model B fit: unknowns mu, v0 (m/s), x0, y0 (m), t0 (s, in the file's time) and the frame
/// rotation psi (rad; value 0, sigma 0 when not fitted).
struct ModelBFit {
  Estimate mu, v0, x0, y0, t0, frame_rotation;
  double rms_residual = 0;   ///< sqrt(mean of the 2n squared residuals), m (~ the noise)
  double rss = 0;            ///< sum of squared residuals, m^2
  int dof = 0;               ///< 2n - 6 (2n - 5 without the frame rotation)
  int iterations = 0;
  std::optional<double> t_stop;          ///< stop instant in the file's time, s
  std::optional<double> x_stop, y_stop;  ///< stop point in the file's frame, m
  numerics::FitResult fit;   ///< the raw least-squares result (covariance, residuals)
};

/// Model A fit: model B's unknowns plus normal_accel = f_N/m (m/s^2, positive to the left
/// of the velocity: up the slope for a launch along +x).
struct ModelAFit {
  Estimate mu, v0, x0, y0, t0, normal_accel, frame_rotation;  ///< frame_rotation: psi, rad
  /// Correlation of normal_accel and frame_rotation in the fit's covariance (0 when the
  /// rotation is not fitted): how far one can stand in for the other.
  double rotation_correlation = 0;
  double rms_residual = 0, rss = 0;  ///< m, m^2
  int dof = 0;                       ///< 2n - 7 (2n - 6 without the frame rotation)
  int iterations = 0;
  numerics::FitResult fit;
};

/// Gravity as the data show it: model B refitted with g free (docs/theory.md#incline-gravity).
/// A slide fixes g sin(phi) (the pull down the slope) and mu g cos(phi) (the friction) apart,
/// so g is identifiable for phi >= 3 deg. Far from the g given means the times (slow motion
/// analysed as real time), the lengths or the incline angle are wrong.
struct GravityCheck {
  Estimate g;                  ///< fitted g, m/s^2
  double ratio = 1;            ///< g fitted / g given
  /// Factor the file's times would need to be multiplied by for the data to show the g
  /// given, sqrt(ratio): 0.125 for 240 fps slow motion played at 30 fps analysed as real time.
  double time_factor = 1;
  bool implausible = false;    ///< |ratio - 1| > 0.25 and more than 3 sigma from the g given
  /// The incline angle the data show with the g given, rad: model B depends on g and phi only
  /// through g sin(phi) and mu g cos(phi), so sin(phi_fit) = ratio sin(phi). NaN value when
  /// no angle fits (ratio sin(phi) > 1). Meaningful at every phi > 0, unlike g (phi >= 3 deg).
  Estimate phi;
  /// phi >= 3 deg: g itself is told apart from mu (below, only phi is: `implausible` is false).
  bool g_identifiable = true;
  double rms = 0;  ///< rms residual of the refit, m (at the noise level when it found the minimum)
};

/// Test of model A against B (nested: A with normal_accel = 0 is B).
struct ModelTest {
  double f_statistic = 0;   ///< (RSS_B - RSS_A) / (RSS_A / dof_A), 1 and dof_A degrees of freedom
  double p_value = 1;       ///< P(F > f_statistic) under model B
  bool ci_excludes_zero = false;  ///< the level-CI of normal_accel excludes 0
  bool significant = false;       ///< p_value < significance
  bool present = false;           ///< both: a normal friction component is present
  double size = 0.05;             ///< the test's size: how often a model-B run is called present
};

/// What decided InclineAnalysis::verdict.
enum class VerdictSource {
  none,           ///< no test could decide (the verdict defaults to absent)
  model_a_test,   ///< the model A test (ModelTest::present)
  a_n_intercept,  ///< the eq b diagnostic's intercept interval (NormalAccelDiagnostic)
};
/// "none", "model_a_test" or "a_n_intercept": the value of the JSON key "verdict_source".
const char* to_string(VerdictSource s);

struct InclineAnalysis {
  std::vector<track::TrackPoint> data;  ///< the points fitted (file time and frame)
  track::Kinematics kinematics;         ///< Savitzky-Golay velocities/accelerations (figures)
  double phi = 0, g = kDefaultG;        ///< rad, m/s^2
  ModelBFit model_b;
  std::optional<ModelAFit> model_a;
  std::optional<ModelTest> test;
  std::optional<NormalAccelDiagnostic> a_n;  ///< eq b diagnostic (absent: too few blocks)
  std::optional<ThetaC> theta_c;              ///< eq c diagnostic (absent: k >= 1 or no window)
  double cos_theta_c_model = 0;  ///< model B's cos(theta_c) = k = tan(phi)/mu (eq c'), when k < 1
  /// Decided by the model A test (ModelTest::present); when model A is not fitted, by the
  /// a_N intercept's interval (NormalAccelDiagnostic).
  Verdict verdict = Verdict::absent;
  VerdictSource verdict_source = VerdictSource::none;
  // Curves for figures: models at the data times and on a fine grid (400 times over the
  // data's span), states in the file's time and frame; residuals data - model, m.
  std::vector<incline::State> model_b_at_data, model_b_fine;
  std::vector<incline::State> model_a_at_data, model_a_fine;
  std::vector<double> residual_x_b, residual_y_b, residual_x_a, residual_y_a;
  std::vector<std::string> notes;  ///< what was skipped and why
  std::optional<GravityCheck> gravity;  ///< absent for phi < 3 deg or when the refit fails
  /// With the frame held aligned (fit_frame_rotation = false): psi, rad, refitted free (model A
  /// when it is fitted, else B) to check that assumption; absent when psi was fitted or the
  /// refit failed.
  std::optional<Estimate> frame_rotation_check;
  /// Plain-language warnings: data that contradict what the physics knows (gravity far from
  /// g, an impossible friction coefficient). Empty when none.
  std::vector<std::string> warnings;
};

/// Model B states at file times t for launch time t0 and point (x0, y0) (rest before t0),
/// turned by the frame rotation psi (rad) about the launch point.
std::vector<incline::State> model_b_states(const incline::Parameters& p, double t0, double x0,
                                           double y0, const std::vector<double>& t, double psi = 0);
/// Model A states likewise, by the integrator (Parameters::normal_accel); tolerance `tol`.
std::vector<incline::State> model_a_states(const incline::Parameters& p, double t0, double x0,
                                           double y0, const std::vector<double>& t,
                                           double tol = 1e-10, double psi = 0);
/// The track turned back by -psi about (x0, y0): the points in the incline's frame.
track::Track derotate_track(const track::Track& track, double psi, double x0, double y0);

/// Fits model B. Throws InputError when the data cannot support it (too few points, no
/// motion, motion toward -x, no convergence, parameters not identifiable).
ModelBFit fit_model_b(const track::Track& track, const InclineFitOptions& options);

/// Fits model A starting from a model B fit. Throws InputError like fit_model_b.
ModelAFit fit_model_a(const track::Track& track, const InclineFitOptions& options,
                      const ModelBFit& start);

/// Refits model B with g free, starting from `b` and from g scaled by the usual slow-motion
/// factors (4, 8, 16 in time). Empty when phi = 0 or no fit converges.
std::optional<GravityCheck> check_gravity(const track::Track& track, const InclineFitOptions& options,
                                          const ModelBFit& b);
/// The same refit from starting values read off the data, for when model B with the g given
/// cannot be fitted (a wrong time scale puts the data's g far from it).
std::optional<GravityCheck> check_gravity(const track::Track& track, const InclineFitOptions& options);

/// The warning of a gravity check that contradicts the g given (g in o.g, phi in o.phi):
/// implausible (times, lengths or angle wrong, with the time factor and the angle that fit),
/// significant, or an incline angle that looks like radians typed as degrees. Empty when the
/// data agree with g and phi (docs/theory.md#incline-gravity). `frame_turned`: a turned camera
/// frame was warned about, which also explains a g a little off.
std::string gravity_warning(const GravityCheck& c, const InclineFitOptions& o, bool frame_turned = false);

/// With psi held at 0 (options.fit_frame_rotation false): refits with psi free (model A from
/// `b` when options.fit_model_a, else model B) and returns psi, rad; empty when psi is fitted
/// anyway or the refit fails.
std::optional<Estimate> check_frame_rotation(const track::Track& track, const InclineFitOptions& options);

/// The whole analysis of `incline analyze`.
InclineAnalysis analyze_incline_run(const track::Track& track, const InclineFitOptions& options);

}  // namespace tribolab::analysis
