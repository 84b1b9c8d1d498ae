// Tests of the incline run analysis on synthetic runs made by the project's simulators
// (src/analysis/incline_synthetic.hpp): recovery, interval coverage, model A detection.
#include "analysis/incline_fit.hpp"
#include "analysis/incline_synthetic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tribolab::analysis {
namespace {

InclineSynthOptions seed_run(std::uint64_t seed, double normal_accel = 0, double fps = 80) {
  InclineSynthOptions o;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(20.96);  // seed figure 五
  o.params.v0 = 2.62;
  o.params.normal_accel = normal_accel;
  o.fps = fps;
  o.noise = 0.001;
  o.t_launch = 0.1234;
  o.seed = seed;
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
  EXPECT_EQ(a.verdict, "absent");
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

TEST(InclineFit, IntervalsCoverTheTruthNinetyFivePercentOfTheTime) {
  const int runs = 200;
  int cover_mu = 0, cover_v0 = 0, cover_t0 = 0, cover_x0 = 0, cover_y0 = 0;
  int cover_mu_a = 0, cover_na = 0, present = 0, an_present = 0, an_runs = 0;
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
              "normal_accel %.3f | false positives: model A test %.3f, a_N intercept %.3f (%d runs)\n",
              runs, cover_mu / double(runs), cover_v0 / double(runs), cover_t0 / double(runs),
              cover_x0 / double(runs), cover_y0 / double(runs), cover_mu_a / double(runs),
              cover_na / double(runs), present / double(runs), an_present / double(an_runs), an_runs);
  for (int c : {cover_mu, cover_v0, cover_t0, cover_x0, cover_y0, cover_mu_a, cover_na})
    EXPECT_NEAR(c / double(runs), 0.95, tol);
  // False-positive rate of the verdict: near the 5 % size of the test.
  EXPECT_NEAR(present / double(runs), 0.05, binomial_tolerance(0.05, runs));
  EXPECT_EQ(an_runs, runs);
  EXPECT_NEAR(an_present / double(an_runs), 0.05, binomial_tolerance(0.05, an_runs));
}

TEST(InclineFit, DetectsANormalFrictionComponent) {
  // normal_accel = 0.3 m/s^2 (5 % of alpha): model A's interval is ~+-0.015, so the power is
  // essentially 1; every one of 50 runs must detect it and cover the truth at 99.9 %.
  const int runs = 50;
  int detected = 0, covered = 0;
  for (int i = 0; i < runs; ++i) {
    const auto s = seed_run(5000 + i, 0.3, i % 2 ? 80 : 240);
    const auto run = synthesize_incline_run(s);
    const InclineAnalysis a = analyze_incline_run(run.track, fit_options(s));
    ASSERT_TRUE(a.model_a && a.test);
    detected += a.verdict == "present";
    const auto& na = a.model_a->normal_accel;
    covered += std::abs(na.value - 0.3) < 3.3 * na.sigma;
  }
  std::printf("normal_accel = 0.3: detected in %d of %d runs\n", detected, runs);
  EXPECT_EQ(detected, runs);
  EXPECT_GE(covered, runs - 1);  // 99.9 % intervals: one miss in 50 is already unlikely
}

}  // namespace
}  // namespace tribolab::analysis
