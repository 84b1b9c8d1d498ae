// Tests of the incline run analysis on synthetic runs made by the project's simulators
// (src/analysis/incline_synthetic.hpp): recovery, interval coverage, model A detection.
#include "analysis/incline_fit.hpp"
#include "analysis/incline_synthetic.hpp"
#include "numerics/coverage_test_util.hpp"
#include "numerics/error.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tribolab::analysis {
namespace {

InclineSynthOptions seed_run(std::uint64_t seed, double normal_accel = 0, double fps = 80,
                             double frame_rotation_deg = 0) {
  InclineSynthOptions o;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(20.96);  // seed figure 五
  o.params.v0 = 2.62;
  o.params.normal_accel = normal_accel;
  o.fps = fps;
  o.noise = 0.001;
  o.t_launch = 0.1234;
  o.seed = seed;
  o.frame_rotation = incline::deg_to_rad(frame_rotation_deg);
  return o;
}

InclineFitOptions fit_options(const InclineSynthOptions& s) {
  InclineFitOptions o;
  o.phi = s.params.phi;
  return o;
}

TEST(InclineFit, RecoversModelBParameters) {
  const auto s = seed_run(7);
  const auto run = synthesize_incline_run(s);
  const InclineAnalysis a = analyze_incline_run(run.track, fit_options(s));
  const auto& b = a.model_b;
  // Each truth within its own 99.9% interval (3.3 sigma): a failure here is a 1-in-1000 event
  // for a correct fit, and the seed is fixed.
  EXPECT_NEAR(b.mu.value, 0.634, 3.3 * b.mu.sigma);
  EXPECT_NEAR(b.v0.value, 2.62, 3.3 * b.v0.sigma);
  EXPECT_NEAR(b.t0.value, 0.1234, 3.3 * b.t0.sigma);
  EXPECT_NEAR(b.x0.value, 0.05, 3.3 * b.x0.sigma);
  EXPECT_NEAR(b.y0.value, 0.0, 3.3 * b.y0.sigma);
  // 1 mm noise, ~90 points: mu is determined to better than 1 %.
  EXPECT_LT(b.mu.sigma, 0.006);
  // The residual rms estimates the 1 mm noise (2n = 180 residuals: +-10 % is 3 sigma).
  EXPECT_NEAR(b.rms_residual, 0.001, 0.0001);
  ASSERT_TRUE(a.test.has_value());
  EXPECT_EQ(a.verdict, Verdict::absent);
  // Curves for figures: one state per data point and a 400-point grid.
  EXPECT_EQ(a.model_b_at_data.size(), run.track.points.size());
  EXPECT_EQ(a.model_b_fine.size(), 400u);
  EXPECT_EQ(a.residual_x_b.size(), run.track.points.size());
  EXPECT_EQ(a.model_a_at_data.size(), run.track.points.size());
  // Model B's stop (file time) near the truth: t0 + t_stop within 5 sigma of t0 and mu.
  ASSERT_TRUE(b.t_stop.has_value());
  EXPECT_NEAR(*b.t_stop, *run.t_stop, 0.005);
}


/// Truth inside [ci_low, ci_high].
bool covers(const Estimate& e, double truth) { return e.ci_low <= truth && truth <= e.ci_high; }

// Binomial tolerance of a rate p over N runs: +-3 sqrt(p(1-p)/N) (a correct interval fails
// the check with probability ~0.3 %; the seeds are fixed, so the outcome is reproducible).
double binomial_tolerance(double p, int n) { return 3 * std::sqrt(p * (1 - p) / n); }

// The sanitizer tree runs the first 40 seeds: each coverage count must reach
// binomial_floor(40, 0.95) = 33 (P(X < 33) = 7.1e-4; a sigma half the true one passes with
// probability 0.026) and each false-positive count stay at most binomial_ceiling(40, 0.05) = 7
// (P(X > 7) = 7.1e-4; a test whose sigma is half the true one says `present` 33 % of the time
// and passes with probability 0.026).
TEST(InclineFit, IntervalsCoverTheTruthNinetyFivePercentOfTheTime) {
  const int runs = study_draws(200, 40);
  int cover_mu = 0, cover_v0 = 0, cover_t0 = 0, cover_x0 = 0, cover_y0 = 0;
  int cover_mu_a = 0, cover_na = 0, present = 0, an_present = 0, an_runs = 0, cover_psi = 0;
  InclineFitOptions fo;
  for (int i = 0; i < runs; ++i) {
    // Vary the frame rate over the realistic 80-240 fps range.
    const double fps = i % 3 == 0 ? 80 : (i % 3 == 1 ? 120 : 240);
    const auto s = seed_run(1000 + i, 0, fps);
    const auto run = synthesize_incline_run(s);
    const InclineAnalysis a = analyze_incline_run(run.track, fit_options(s));
    cover_mu += covers(a.model_b.mu, 0.634);
    cover_v0 += covers(a.model_b.v0, 2.62);
    cover_t0 += covers(a.model_b.t0, 0.1234);
    cover_x0 += covers(a.model_b.x0, 0.05);
    cover_y0 += covers(a.model_b.y0, 0.0);
    cover_psi += covers(a.model_b.frame_rotation, 0.0);
    ASSERT_TRUE(a.model_a && a.test);
    cover_mu_a += covers(a.model_a->mu, 0.634);
    cover_na += covers(a.model_a->normal_accel, 0.0);
    present += a.test->present;
    if (a.a_n) {
      ++an_runs;
      an_present += a.a_n->intercept_excludes_zero;
    }
  }
  const double tol = binomial_tolerance(0.95, runs);  // 0.046
  std::printf("coverage over %d runs: mu %.3f v0 %.3f t0 %.3f x0 %.3f y0 %.3f | model A mu %.3f "
              "normal_accel %.3f | frame rotation %.3f | false positives: model A test %.3f, a_N intercept "
              "%.3f (%d runs)\n",
              runs, cover_mu / double(runs), cover_v0 / double(runs), cover_t0 / double(runs),
              cover_x0 / double(runs), cover_y0 / double(runs), cover_mu_a / double(runs),
              cover_na / double(runs), cover_psi / double(runs), present / double(runs),
              an_present / double(an_runs), an_runs);
  if (!is_full_study(runs, 200)) {
    for (int c : {cover_mu, cover_v0, cover_t0, cover_x0, cover_y0, cover_mu_a, cover_na, cover_psi})
      EXPECT_GE(c, binomial_floor(runs, 0.95));
    EXPECT_LE(present, binomial_ceiling(runs, 0.05));
    EXPECT_EQ(an_runs, runs);
    EXPECT_LE(an_present, binomial_ceiling(an_runs, 0.05));
    return;
  }
  for (int c : {cover_mu, cover_v0, cover_t0, cover_x0, cover_y0, cover_mu_a, cover_na, cover_psi})
    EXPECT_NEAR(c / double(runs), 0.95, tol);
  // False-positive rate of the verdict: near the 5 % size of the test.
  EXPECT_NEAR(present / double(runs), 0.05, binomial_tolerance(0.05, runs));
  EXPECT_EQ(an_runs, runs);
  EXPECT_NEAR(an_present / double(an_runs), 0.05, binomial_tolerance(0.05, an_runs));
}

TEST(InclineFit, DetectsANormalFrictionComponent) {
  // normal_accel = 0.3 m/s^2 (5 % of alpha): model A's interval is ~+-0.015, so the power is
  // essentially 1; every one of 50 runs must detect it and cover the truth at 99.9 %.
  // The sanitizer tree runs the first 20 seeds, with the same bounds: P(2 or more misses of 20
  // 99.9 % intervals) = 1.9e-4. (A sigma half the true one misses 9.9 % of the time: at most
  // one miss in 20 then has probability 0.40, in 50 0.035; the 95 % coverage studies above are
  // the sharper check of sigma.)
  const int runs = study_draws(50, 20);
  int detected = 0, covered = 0;
  for (int i = 0; i < runs; ++i) {
    const auto s = seed_run(5000 + i, 0.3, i % 2 ? 80 : 240);
    const auto run = synthesize_incline_run(s);
    const InclineAnalysis a = analyze_incline_run(run.track, fit_options(s));
    ASSERT_TRUE(a.model_a && a.test);
    detected += a.verdict == Verdict::present;
    const auto& na = a.model_a->normal_accel;
    covered += std::abs(na.value - 0.3) < 3.3 * na.sigma;
  }
  std::printf("normal_accel = 0.3: detected in %d of %d runs\n", detected, runs);
  EXPECT_EQ(detected, runs);
  EXPECT_GE(covered, runs - 1);  // 99.9 % intervals: one miss in 50 is already unlikely
}

// A camera frame turned against the incline (issue 11): model-B runs whose tracked points are
// rotated by psi about the launch point. With the rotation fitted as a nuisance parameter the
// verdict keeps its 5 % size; the rotation's interval covers the truth; the eq b diagnostic,
// run on the de-rotated points, keeps its size too. Before the fix (frame assumed aligned,
// which fit_frame_rotation = false reproduces) 0.5 deg gave `present` in every run.
struct TurnedFrameCounts {
  int runs = 0, present = 0, cover_psi = 0, cover_mu = 0, an_runs = 0, an_present = 0;
  double max_abs_correlation = 0, sum_abs_correlation = 0, sum_normal_accel = 0, sum_sigma_normal_accel = 0;
};

TurnedFrameCounts analyse_turned_runs(int runs, std::uint64_t first_seed, double psi_deg, double normal_accel,
                                      bool fit_rotation) {
  TurnedFrameCounts c;
  for (int i = 0; i < runs; ++i) {
    const double fps = i % 3 == 0 ? 80 : (i % 3 == 1 ? 120 : 240);
    const auto s = seed_run(first_seed + i, normal_accel, fps, psi_deg);
    const auto run = synthesize_incline_run(s);
    InclineFitOptions fo = fit_options(s);
    fo.fit_frame_rotation = fit_rotation;
    const InclineAnalysis a = analyze_incline_run(run.track, fo);
    EXPECT_TRUE(a.model_a && a.test);
    if (!a.model_a || !a.test) continue;
    ++c.runs;
    c.present += a.verdict == Verdict::present;
    c.cover_psi += covers(a.model_a->frame_rotation, s.frame_rotation);
    c.cover_mu += covers(a.model_b.mu, 0.634);
    c.max_abs_correlation = std::max(c.max_abs_correlation, std::abs(a.model_a->rotation_correlation));
    c.sum_abs_correlation += std::abs(a.model_a->rotation_correlation);
    c.sum_normal_accel += a.model_a->normal_accel.value;
    c.sum_sigma_normal_accel += a.model_a->normal_accel.sigma;
    if (a.a_n) {
      ++c.an_runs;
      c.an_present += a.a_n->intercept_excludes_zero;
    }
  }
  std::printf("frame turned %.2f deg, f_N/m %.2f, rotation %s: %d runs, present %d, psi covered %d, "
              "model B mu covered %d, a_N intercept present %d of %d, mean f_N/m %.4f (mean sigma %.4f), "
              "|corr(f_N, psi)| mean %.3f max %.3f\n",
              psi_deg, normal_accel, fit_rotation ? "fitted" : "not fitted", c.runs, c.present, c.cover_psi,
              c.cover_mu, c.an_present, c.an_runs, c.sum_normal_accel / std::max(1, c.runs),
              c.sum_sigma_normal_accel / std::max(1, c.runs), c.sum_abs_correlation / std::max(1, c.runs),
              c.max_abs_correlation);
  return c;
}

TEST(InclineFit, TurnedCameraFrameIsNotMistakenForNormalFriction) {
  // 150 runs at 0.5 deg and 60 at 1 deg (80/120/240 fps, 1 mm noise, seed figure 五's launch).
  // Binomial tolerance +-3 sqrt(p(1-p)/N): 0.053 at N = 150 (rate 5 %), 0.053 at N = 150
  // (coverage 95 %); at N = 60 the 5 % rate's tolerance is 0.084.
  // The sanitizer tree runs the first 40 and 20 seeds, with the exact binomial bounds for them:
  // coverage at least binomial_floor(40, 0.95) = 33 and (20, 0.95) = 15, `present` at most
  // binomial_ceiling(40, 0.05) = 7 and (20, 0.05) = 5 (each fails a correct method with
  // probability < 1e-3). A sigma half the true one (coverage 0.67, `present` 33 %) passes a
  // count of 40 with probability 0.026, one of 20 with 0.32.
  const int n_half = study_draws(150, 40), n_one = study_draws(60, 20);
  if (!is_full_study(n_half, 150)) {
    const TurnedFrameCounts half = analyse_turned_runs(n_half, 20000, 0.5, 0.0, true);
    ASSERT_EQ(half.runs, n_half);
    EXPECT_LE(half.present, binomial_ceiling(n_half, 0.05));
    EXPECT_GE(half.cover_psi, binomial_floor(n_half, 0.95));
    EXPECT_GE(half.cover_mu, binomial_floor(n_half, 0.95));
    ASSERT_EQ(half.an_runs, n_half);
    EXPECT_LE(half.an_present, binomial_ceiling(n_half, 0.05));
    const TurnedFrameCounts one = analyse_turned_runs(n_one, 21000, -1.0, 0.0, true);
    ASSERT_EQ(one.runs, n_one);
    EXPECT_LE(one.present, binomial_ceiling(n_one, 0.05));
    EXPECT_GE(one.cover_psi, binomial_floor(n_one, 0.95));
    EXPECT_LT(std::max(half.max_abs_correlation, one.max_abs_correlation), 0.95);  // as below
    return;
  }
  const TurnedFrameCounts half = analyse_turned_runs(150, 20000, 0.5, 0.0, true);
  ASSERT_EQ(half.runs, 150);
  EXPECT_NEAR(half.present / 150.0, 0.05, binomial_tolerance(0.05, 150));
  EXPECT_NEAR(half.cover_psi / 150.0, 0.95, binomial_tolerance(0.95, 150));
  EXPECT_NEAR(half.cover_mu / 150.0, 0.95, binomial_tolerance(0.95, 150));
  ASSERT_EQ(half.an_runs, 150);
  EXPECT_NEAR(half.an_present / 150.0, 0.05, binomial_tolerance(0.05, 150));
  const TurnedFrameCounts one = analyse_turned_runs(60, 21000, -1.0, 0.0, true);
  ASSERT_EQ(one.runs, 60);
  EXPECT_NEAR(one.present / 60.0, 0.05, binomial_tolerance(0.05, 60));
  EXPECT_NEAR(one.cover_psi / 60.0, 0.95, binomial_tolerance(0.95, 60));
  // The rotation and f_N/m are separately identifiable: a rotation turns the whole path
  // (launch direction and fall line together), f_N/m is a force that turns with the velocity.
  // Their correlation is high but not 1 (measured |corr| 0.855-0.856 over these runs;
  // sigma(f_N/m) grows from 0.0070 to 0.0092 m/s^2 when the rotation is fitted). The bound
  // 0.95 fails if the two became confounded, e.g. by a model change.
  EXPECT_LT(std::max(half.max_abs_correlation, one.max_abs_correlation), 0.95);
}

TEST(InclineFit, AnAlignedFrameAssumptionMistakesATurnedCameraForNormalFriction) {
  // The defect the rotation fit removes: holding psi = 0 on runs turned by 1 deg gives
  // `present` in (nearly) every run, with f_N/m ~0.1 m/s^2.
  const TurnedFrameCounts c = analyse_turned_runs(20, 22000, 1.0, 0.0, false);
  EXPECT_GE(c.present, 18);
  EXPECT_GT(std::abs(c.sum_normal_accel / c.runs), 0.05);
}

TEST(InclineFit, DetectsNormalFrictionThroughATurnedFrame) {
  // Power with the rotation fitted: f_N/m = 0.3 m/s^2 (5 % of alpha) and 0.1 m/s^2 filmed
  // with the frame turned 0.5 deg. sigma(f_N/m) is ~0.009 m/s^2 with the rotation fitted, so
  // 0.3 is 30 sigma and 0.1 is ~11 sigma: a 1.96-sigma test detects both in essentially every
  // run (the bound 27 of 30 for 0.1 leaves room for the F-test's part of the verdict). The mean
  // of the 30 fits must be unbiased within 3 standard errors of the mean.
  // The sanitizer tree runs the first 10 seeds of each: every strong run detected, psi covered
  // in at least binomial_floor(10, 0.95) = 6 (P(X < 6) = 6.4e-5), at most 2 weak runs missed
  // (P(3 or more) = 1.1e-4 even at a 1 % miss rate; an 11-sigma effect misses far less), the
  // means within 3 standard errors of 10 runs.
  const int runs = study_draws(30, 10);
  const bool full = is_full_study(runs, 30);
  const TurnedFrameCounts strong = analyse_turned_runs(runs, 23000, 0.5, 0.3, true);
  EXPECT_EQ(strong.present, strong.runs);
  if (full) {
    EXPECT_NEAR(strong.cover_psi / double(strong.runs), 0.95, binomial_tolerance(0.95, strong.runs));
  } else {
    EXPECT_GE(strong.cover_psi, binomial_floor(strong.runs, 0.95));
  }
  const TurnedFrameCounts weak = analyse_turned_runs(runs, 24000, 0.5, 0.1, true);
  EXPECT_GE(weak.present, full ? 27 : runs - 2);  // measured 30 of 30
  const double sqrt_runs = std::sqrt(double(runs));
  EXPECT_NEAR(strong.sum_normal_accel / strong.runs, 0.3, 3 * strong.sum_sigma_normal_accel / strong.runs / sqrt_runs);
  EXPECT_NEAR(weak.sum_normal_accel / weak.runs, 0.1, 3 * weak.sum_sigma_normal_accel / weak.runs / sqrt_runs);
}

TEST(InclineFit, DiagnosticsRunInTheDeRotatedFrame) {
  // Nearly noise-free run (10 um) filmed with the frame turned 3 deg, against the same run
  // filmed aligned: the eq b line (a_N against sin theta) and eq c (theta_c) of the turned run
  // must be those of the aligned one. a_N is invariant under a rotation but sin theta = vx/|v|
  // is not: on the points as filmed theta is off by psi, which bends the line (checked below
  // as the "before": intercept off by ~0.26 m/s^2, slope by 6 %). Tolerances: the two runs
  // differ only by the 10 um noise (not rotated) and psi's fitted error (~1e-6 rad), which
  // move the intercept by < 0.005 m/s^2 and cos theta_c by < 1e-4 (measured ~1e-4 and 1e-6).
  auto s = seed_run(31, 0, 240, 3.0);
  s.noise = 1e-5;
  auto s0 = s;
  s0.frame_rotation = 0;
  const auto run = synthesize_incline_run(s), run0 = synthesize_incline_run(s0);
  const InclineAnalysis a = analyze_incline_run(run.track, fit_options(s));
  const InclineAnalysis a0 = analyze_incline_run(run0.track, fit_options(s0));
  EXPECT_NEAR(a.model_b.frame_rotation.value, incline::deg_to_rad(3.0), 1e-5);
  ASSERT_TRUE(a.a_n && a0.a_n && a.theta_c && a0.theta_c);
  EXPECT_NEAR(a.a_n->intercept, a0.a_n->intercept, 0.005);
  EXPECT_NEAR(a.a_n->slope, a0.a_n->slope, 0.005);
  EXPECT_NEAR(a.theta_c->cos_theta_c, a0.theta_c->cos_theta_c, 1e-4);
  // Before: the same diagnostic on the points as filmed.
  const auto& b = a.model_b;
  const auto raw = normal_accel_diagnostic(run.track, b.t0.value, b.t0.value + 0.9 * (*b.t_stop - b.t0.value),
                                           s.params.phi, 9.8, 0, 0.95);
  ASSERT_TRUE(raw.has_value());
  std::printf("eq b, frame turned 3 deg: intercept %.4f de-rotated, %.4f as filmed, %.4f aligned run; "
              "slope %.4f / %.4f / %.4f; cos theta_c %.6f / %.6f aligned\n",
              a.a_n->intercept, raw->intercept, a0.a_n->intercept, a.a_n->slope, raw->slope, a0.a_n->slope,
              a.theta_c->cos_theta_c, a0.theta_c->cos_theta_c);
  EXPECT_GT(std::abs(raw->intercept - a0.a_n->intercept), 0.1);
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

TEST(InclineGravity, TheGravityTheDataShowIsTheTrueOneWithinItsInterval) {
  // 40 runs of the seed's disc at 80 fps, 1 mm noise: g refitted free must hold 9.8 in its
  // 95 % interval about 95 % of the time (binomial: 34..40 of 40 at the 0.1 % level), and
  // never be called implausible.
  int covered = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto s = seed_run(seed);
    const auto run = synthesize_incline_run(s);
    const InclineFitOptions o = fit_options(s);
    const auto gravity = check_gravity(run.track, o, fit_model_b(run.track, o));
    ASSERT_TRUE(gravity) << seed;
    if (gravity->g.ci_low <= 9.8 && 9.8 <= gravity->g.ci_high) ++covered;
    EXPECT_FALSE(gravity->implausible) << seed << ": g = " << gravity->g.value;
  }
  EXPECT_GE(covered, 34);
}

TEST(InclineGravity, SlowMotionAnalysedAsRealTimeIsCalledOutWithTheFactor) {
  // 240 fps slow motion played at 30 fps: the file's times are 8x the real ones. The fit with
  // g = 9.8 still "succeeds" (mu at its bound, a confident verdict); the check must say why.
  for (double factor : {8.0, 4.0, 0.5}) {
    auto s = seed_run(3);
    auto run = synthesize_incline_run(s);
    for (auto& p : run.track.points) p.t *= factor;
    InclineFitOptions o = fit_options(s);
    const auto gravity = check_gravity(run.track, o, fit_model_b(run.track, o));
    ASSERT_TRUE(gravity) << factor;
    EXPECT_TRUE(gravity->implausible) << factor;
    // g scales as 1/factor^2; the time factor that restores it is 1/factor (to 1 %: the fit's
    // sigma of g is ~0.3 % here).
    EXPECT_NEAR(gravity->time_factor, 1 / factor, 0.01 / factor) << factor;
    if (factor == 8.0) {  // the whole analysis carries the warning (model A skipped: speed)
      o.fit_model_a = false;
      const InclineAnalysis a = analyze_incline_run(run.track, o);
      ASSERT_FALSE(a.warnings.empty());
      EXPECT_NE(a.warnings.front().find("times must be multiplied by 0.125"), std::string::npos)
          << a.warnings.front();
    }
  }
}

TEST(InclineGravity, AFlatInclineHasNoGravityToCheckButItsAngle) {
  // At 1 deg, g sin(phi) is too small to tell g from mu: no g verdict. The angle the data show
  // (g given) is still measured: it must hold the truth (3.3 sigma: 99.9 %).
  auto s = seed_run(5);
  s.params.phi = incline::deg_to_rad(1.0);
  s.params.mu = 0.2;
  const auto run = synthesize_incline_run(s);
  const InclineFitOptions o = fit_options(s);
  const auto c = check_gravity(run.track, o, fit_model_b(run.track, o));
  ASSERT_TRUE(c);
  EXPECT_FALSE(c->g_identifiable);
  EXPECT_FALSE(c->implausible);
  EXPECT_NEAR(c->phi.value, s.params.phi, 3.3 * c->phi.sigma);
  EXPECT_TRUE(gravity_warning(*c, o).empty()) << gravity_warning(*c, o);
}

TEST(InclineGravity, RadiansTypedAsDegreesAreCalledOutWithTheAngleThatFits) {
  // Issue 27: the seed's run at 20.96 deg analysed with phi_deg = 0.3658 (the angle in radians)
  // gave mu 0.398 and "normal friction present" without a word. The data fix g sin(phi), so
  // they show the angle: the warning must say 0.3658 looks like radians and give ~20.96 deg.
  const auto s = seed_run(7);
  const auto run = synthesize_incline_run(s);
  InclineFitOptions o = fit_options(s);
  o.phi = incline::deg_to_rad(0.3658);
  o.fit_model_a = false;  // speed: the warning does not depend on model A
  const InclineAnalysis a = analyze_incline_run(run.track, o);
  ASSERT_TRUE(a.gravity);
  EXPECT_NEAR(a.gravity->phi.value, s.params.phi, 3.3 * a.gravity->phi.sigma);  // 99.9 %
  ASSERT_FALSE(a.warnings.empty());
  EXPECT_NE(a.warnings.front().find("looks like the angle in radians (0.3658 rad = 20.96 deg)"), std::string::npos)
      << a.warnings.front();
  EXPECT_NE(a.warnings.front().find("which show phi = 20.9"), std::string::npos) << a.warnings.front();
  // The same run with its angle right warns of nothing about the angle.
  o.phi = s.params.phi;
  for (const auto& w : analyze_incline_run(run.track, o).warnings) EXPECT_EQ(w.find("incline angle"), std::string::npos) << w;
}

TEST(InclineGravity, AnAngleFarOffIsCalledOutWithTheAngleThatFits) {
  // 12 deg typed for a 20.96 deg incline (not radians): the g warning names the angle that fits.
  const auto s = seed_run(8);
  const auto run = synthesize_incline_run(s);
  InclineFitOptions o = fit_options(s);
  o.phi = incline::deg_to_rad(12.0);
  o.fit_model_a = false;
  const InclineAnalysis a = analyze_incline_run(run.track, o);
  ASSERT_FALSE(a.warnings.empty());
  EXPECT_NE(a.warnings.front().find("the incline is at 20.9"), std::string::npos) << a.warnings.front();
  EXPECT_EQ(a.warnings.front().find("radians"), std::string::npos) << a.warnings.front();
}

TEST(InclineGravity, AWrongTimeScaleIsNamedWhereModelBCannotBeFitted) {
  // Issue 27: times 64x too long (--time-scale 8 given instead of 0.125 for 240 fps slow motion)
  // made the fit with g = 9.8 fail with "least squares did not converge"; the analysis must say
  // what the data show instead: their g, and the factor the times need.
  // 64 only (1/64 was checked too, when written: g = 40230 +- 159, the factor 64 named; 2 s more).
  for (double factor : {64.0}) {
    const auto s = seed_run(9);
    auto run = synthesize_incline_run(s);
    for (auto& p : run.track.points) p.t *= factor;
    InclineFitOptions o = fit_options(s);
    o.fit_model_a = false;
    try {
      const InclineAnalysis a = analyze_incline_run(run.track, o);
      ASSERT_FALSE(a.warnings.empty()) << factor;
      EXPECT_NE(a.warnings.front().find("times must be multiplied by"), std::string::npos) << a.warnings.front();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("times must be multiplied by 0.0156"),
                std::string::npos) << e.what();
    }
  }
}

TEST(InclineGravity, EveryWrongTimeScaleNamesItsFactorNeverTheSolver) {
  // Issue 27: times 8x too short made model B's fit fail and the message ended in the solver's
  // "least squares did not converge: Residual and Jacobian evaluation failed"; times 8x and 16x
  // too long must name their factor too (a warning: model B still fits). 64x long is
  // AWrongTimeScaleIsNamedWhereModelBCannotBeFitted's.
  const auto s = seed_run(9);
  const auto run0 = synthesize_incline_run(s);
  for (double factor : {0.125, 8.0, 16.0}) {
    auto run = run0;
    for (auto& p : run.track.points) p.t *= factor;
    InclineFitOptions o = fit_options(s);
    o.fit_model_a = false;
    // The factor the times need, as gravity_warning prints it (3 significant digits): 1/factor
    // within the fit's sigma of g (~0.4 %, half of that in sqrt(g)).
    std::string said;
    try {
      const InclineAnalysis a = analyze_incline_run(run.track, o);
      ASSERT_FALSE(a.warnings.empty()) << factor;
      said = a.warnings.front();
    } catch (const InputError& e) {
      said = e.what();
      EXPECT_EQ(said.find("least squares"), std::string::npos) << said;
      EXPECT_EQ(said.find("Jacobian"), std::string::npos) << said;
    }
    const auto at = said.find("times must be multiplied by ");
    ASSERT_NE(at, std::string::npos) << factor << ": " << said;
    const double named = std::stod(said.substr(at + 28));
    EXPECT_NEAR(named * factor, 1.0, 0.02) << factor << ": " << said;
  }
}

// The text of what decided the verdict is the JSON value of "verdict_source" (docs/cli.md).
TEST(VerdictSource, TextIsTheJsonValue) {
  EXPECT_STREQ(to_string(VerdictSource::model_a_test), "model_a_test");
  EXPECT_STREQ(to_string(VerdictSource::a_n_intercept), "a_n_intercept");
  EXPECT_STREQ(to_string(VerdictSource::none), "none");
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

bool warns(const InclineAnalysis& a, const std::string& text) {
  for (const auto& w : a.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// A frame rate off by 2 % (times 2 % short: g seen 4 % high) moves mu by several of its own
// sds with a confident verdict; the gross-error check (|g/9.8 - 1| > 25 %) is silent there.
// The significance warning must fire, and must not on the honest runs (3 sd + 0.03 m/s^2:
// ~4 sd here, a false alarm once in ~10^4 runs). Model A skipped: speed, and it does not
// enter the gravity check. Before this warning the 2 % runs printed mu off by ~3 sd silently.
TEST(InclineGravity, AFrameRateTwoPercentOffIsWarnedNotPrintedConfidently) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    auto s = seed_run(seed);
    auto run = synthesize_incline_run(s);
    InclineFitOptions o = fit_options(s);
    o.fit_model_a = false;
    const InclineAnalysis honest = analyze_incline_run(run.track, o);
    EXPECT_FALSE(warns(honest, "check the frame rate")) << seed << ": " << honest.gravity->g.value;
    for (auto& p : run.track.points) p.t /= 1.02;
    const InclineAnalysis off = analyze_incline_run(run.track, o);
    const double shift = std::abs(off.model_b.mu.value - s.params.mu);
    // Either the number is still right within its interval or the tool says why it is not.
    EXPECT_TRUE(shift <= 2 * off.model_b.mu.sigma || warns(off, "check the frame rate"))
        << seed << ": mu " << off.model_b.mu.value << " +- " << off.model_b.mu.sigma;
    EXPECT_TRUE(warns(off, "check the frame rate")) << seed << ": g " << off.gravity->g.value;
    std::printf("seed %d: mu shift %.4f = %.1f sd, g %.3f +- %.3f\n", static_cast<int>(seed), shift,
                shift / off.model_b.mu.sigma, off.gravity->g.value, off.gravity->g.sigma);
  }
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

bool warns_wild(const InclineAnalysis& a) {
  for (const auto& w : a.warnings)
    if (w.find("lie far from the fitted slide") != std::string::npos) return true;
  return false;
}

// A hand in the picture: three frames of the seed's slide 5 cm off (4 cm in x, 3 cm in y).
// Measured before this warning (seed 1 through the CLI): mu 0.6341 +- 0.0029 instead of
// 0.6346 +- 0.0005, and the normal-friction verdict "present" with no warning. Honest runs of
// model B and of model A (normal friction 0.3 m/s^2, which model B misses by centimetres but
// model A fits) are not called wild.
TEST(InclineWildFrames, AHandInThePictureIsNamedARealNormalFrictionIsNot) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    auto s = seed_run(seed);
    auto run = synthesize_incline_run(s);
    const InclineFitOptions o = fit_options(s);
    EXPECT_FALSE(warns_wild(analyze_incline_run(run.track, o))) << seed;
    for (std::size_t i = 40; i < 43; ++i) run.track.points[i].x += 0.04, run.track.points[i].y += 0.03;
    EXPECT_TRUE(warns_wild(analyze_incline_run(run.track, o))) << seed;
    auto sa = seed_run(seed, 0.3);
    EXPECT_FALSE(warns_wild(analyze_incline_run(synthesize_incline_run(sa).track, fit_options(sa)))) << seed;
  }
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

/// Runs of the coverage study at the demo's 20.96 deg settings (data/demo/incline/make.sh:
/// 80 fps, 1 mm, launch at t = 0.1 s from (0.05, 0)); TRIBOLAB_COVERAGE_RUNS raises the count
/// for the study recorded in docs/theory.md.
int coverage_runs(int fallback) {
  const char* e = std::getenv("TRIBOLAB_COVERAGE_RUNS");
  return e ? std::max(1, std::atoi(e)) : fallback;
}

/// Model B parameters of the demo's run (seed `seed`) whose 95 % interval misses the truth,
/// of mu, v0, x0, y0, t0.
int demo_run_misses(std::uint64_t seed) {
  InclineSynthOptions s = seed_run(seed, 0, 80);
  s.t_launch = 0.1;
  const ModelBFit b = fit_model_b(synthesize_incline_run(s).track, fit_options(s));
  return !covers(b.mu, 0.634) + !covers(b.v0, 2.62) + !covers(b.x0, 0.05) + !covers(b.y0, 0.0) + !covers(b.t0, 0.1);
}

// Issue 27: the demo's 20.96 deg run (make.sh: seed 21) has the truth outside the 95 %
// interval of 3 of its 5 model-B parameters (mu, t0, x0). Chance or calibration? At the run's
// own settings the intervals must cover 95 % each, and 3 misses of 5 must be about as rare as
// the study found (docs/theory.md#incline-analysis, "coverage at the demo's settings").
TEST(InclineFit, DemoRunSettingsIntervalsCoverTheTruth) {
  EXPECT_EQ(demo_run_misses(21), 3);  // the demo's run: the three misses reproduced
  const int runs = coverage_runs(60);
  int cover[6] = {0, 0, 0, 0, 0, 0};
  double pull2[6] = {0, 0, 0, 0, 0, 0};
  int three_misses = 0;
  for (int i = 0; i < runs; ++i) {
    InclineSynthOptions s = seed_run(5000 + i, 0, 80);
    s.t_launch = 0.1;  // make.sh: --t-offset default 0.1 s, on frame 8
    const auto run = synthesize_incline_run(s);
    const ModelBFit b = fit_model_b(run.track, fit_options(s));
    const Estimate* e[6] = {&b.mu, &b.v0, &b.x0, &b.y0, &b.t0, &b.frame_rotation};
    const double truth[6] = {0.634, 2.62, 0.05, 0.0, 0.1, 0.0};
    int misses = 0;
    for (int k = 0; k < 6; ++k) {
      cover[k] += covers(*e[k], truth[k]);
      if (k < 5) misses += !covers(*e[k], truth[k]);
      const double z = (e[k]->value - truth[k]) / e[k]->sigma;
      pull2[k] += z * z;
    }
    three_misses += misses >= 3;
  }
  std::printf("demo settings: %d of %d runs miss 3 or more of the 5 model-B parameters\n", three_misses, runs);
  std::printf("demo settings, %d runs: coverage mu %.3f v0 %.3f x0 %.3f y0 %.3f t0 %.3f psi %.3f; rms pull %.2f %.2f "
              "%.2f %.2f %.2f %.2f\n",
              runs, cover[0] / double(runs), cover[1] / double(runs), cover[2] / double(runs), cover[3] / double(runs),
              cover[4] / double(runs), cover[5] / double(runs), std::sqrt(pull2[0] / runs), std::sqrt(pull2[1] / runs),
              std::sqrt(pull2[2] / runs), std::sqrt(pull2[3] / runs), std::sqrt(pull2[4] / runs),
              std::sqrt(pull2[5] / runs));
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(cover[k] / double(runs), 0.95, binomial_tolerance(0.95, runs)) << k;
}

// Issue 27: the per-run sigma of f_N/m with the frame rotation fitted looked ~25 % conservative
// (chi2 8.6 on 15 dof: pull sd 0.76 +- 0.18). Calibrated by coverage at the demo's settings
// (data/demo/incline/make.sh: its five launches, 12-28 deg, v0 2.0-2.62 m/s, 80-240 fps, 1 mm;
// f_N/m 0 and 0.3 m/s^2; the frame turned -0.5, 0 and +0.5 deg, psi fitted): over 1000 runs
// (TRIBOLAB_COVERAGE_RUNS=1000) the pulls (f_N/m - truth) / sigma had rms 1.012 +- 0.022, chi2
// 1025 on 1000, the 95 % intervals covered 95.2 %: the sigma is right and the 16 runs' 0.76 was
// chance (docs/theory.md#incline-analysis, "Coverage study"). This test: 150 runs (measured
// chi2 142.5, 144 covering), the sum of squared pulls within the chi-square(150) quantiles at
// 5e-4 and 1 - 5e-4 (99.5 and 213.6: a correct sigma fails with probability 1e-3). That
// resolves pull sd outside 0.81-1.19: a sigma 25 % too large (pull sd 0.76: chi2 ~87 +- 10)
// fails with probability ~0.9, one 25 % too small (sd 1.33: chi2 ~267) almost surely. Coverage
// of the 95 % intervals at least binomial_floor(150, 0.95) = 133. The sanitizer tree runs 40
// runs with the bounds for 40 (chi2 ~16.8-76.2: resolves only pull sd outside 0.65-1.38).
// (12 s of CPU in the normal tree.)
TEST(InclineFit, NormalAccelSigmaWithTheFrameRotationFittedCoversTheTruth) {
  struct Launch {
    double phi_deg, v0, fps;
  };
  const Launch demo[] = {{12, 2.62, 120}, {16, 2.62, 240}, {20.96, 2.62, 80}, {25, 2.3, 120}, {28, 2.0, 120}};
  const int runs = study_draws(150, 40);
  double chi2 = 0;
  int covered = 0;
  for (int i = 0; i < runs; ++i) {
    const Launch& l = demo[i % 5];
    const double truth = (i / 5) % 2 ? 0.3 : 0.0;
    InclineSynthOptions s = seed_run(900000 + i, truth, l.fps, ((i / 10) % 3 - 1) * 0.5);
    s.params.phi = incline::deg_to_rad(l.phi_deg);
    s.params.v0 = l.v0;
    s.t_launch = 0.1;
    const InclineAnalysis a = analyze_incline_run(synthesize_incline_run(s).track, fit_options(s));
    ASSERT_TRUE(a.model_a.has_value()) << i;
    const Estimate& na = a.model_a->normal_accel;
    const double z = (na.value - truth) / na.sigma;
    chi2 += z * z;
    covered += covers(na, truth);
  }
  const boost::math::chi_squared dist(runs);
  const double lo = boost::math::quantile(dist, 5e-4), hi = boost::math::quantile(boost::math::complement(dist, 5e-4));
  std::printf("f_N/m with the rotation fitted, demo settings, %d runs: chi2 %.1f (accepted %.1f to %.1f), "
              "pull rms %.3f, 95 %% intervals covering %d (at least %d)\n",
              runs, chi2, lo, hi, std::sqrt(chi2 / runs), covered, binomial_floor(runs, 0.95));
  EXPECT_GE(chi2, lo);
  EXPECT_LE(chi2, hi);
  EXPECT_GE(covered, binomial_floor(runs, 0.95));
}

}  // namespace
}  // namespace tribolab::analysis
