// Tests of the incline series summary (analysis/incline_series.hpp): the stop-point slopes of
// figure 八 against the closed form, their inversion for mu, recovery of the truth's mu from
// synthetic series (by hand-built stop points and by whole synthetic tracked runs), the
// cos(theta_c)-tan(phi) test over angles, and model A's normal friction pooled.
#include "analysis/incline_series.hpp"

#include "analysis/incline_synthetic.hpp"
#include "incline/closed_form.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tribolab::analysis {
namespace {

constexpr StopRelation kAll[] = {StopRelation::t_vs_v0, StopRelation::x_vs_v0sq, StopRelation::y_vs_v0sq,
                                 StopRelation::y_vs_x};

// Two independent methods: the slopes in factored form against the closed form's own stop
// (incline::ClosedForm::predict, eqs 七-九) divided by v0 or v0^2.
TEST(StopSlope, AgreesWithTheClosedFormStop) {
  for (double mu : {0.3, 0.585, 0.634, 1.2}) {
    for (double phi_deg : {0.0, 4.82, 10.37, 20.96}) {
      incline::Parameters p;
      p.mu = mu;
      p.phi = incline::deg_to_rad(phi_deg);
      p.v0 = 2.0;
      if (std::tan(p.phi) >= mu) continue;
      const incline::Prediction pr = incline::ClosedForm(p).predict();
      ASSERT_TRUE(pr.t_stop && pr.x_stop && pr.y_stop);
      // 1e-12 relative: both are a few rounding errors from the exact value.
      EXPECT_NEAR(*stop_slope(StopRelation::t_vs_v0, mu, p.phi, 9.8), *pr.t_stop / 2.0, 1e-12 * *pr.t_stop);
      EXPECT_NEAR(*stop_slope(StopRelation::x_vs_v0sq, mu, p.phi, 9.8), *pr.x_stop / 4.0, 1e-12 * *pr.x_stop);
      EXPECT_NEAR(*stop_slope(StopRelation::y_vs_v0sq, mu, p.phi, 9.8), *pr.y_stop / 4.0, 1e-12 + 1e-12 * -*pr.y_stop);
      if (phi_deg > 0) {
        EXPECT_NEAR(*stop_slope(StopRelation::y_vs_x, mu, p.phi, 9.8), *pr.y_stop / *pr.x_stop, 1e-12);
      }
    }
  }
  // No stop for mu <= tan(phi).
  EXPECT_FALSE(stop_slope(StopRelation::t_vs_v0, 0.3, incline::deg_to_rad(20), 9.8));
}

TEST(StopSlope, InvertsToMu) {
  for (double mu : {0.2, 0.585, 0.634, 1.5}) {
    for (double phi_deg : {0.0, 4.82, 10.37, 23.2}) {
      const double phi = incline::deg_to_rad(phi_deg);
      if (std::tan(phi) >= mu) continue;
      for (StopRelation r : kAll) {
        if (phi_deg == 0 && (r == StopRelation::y_vs_v0sq || r == StopRelation::y_vs_x)) {
          EXPECT_FALSE(mu_from_stop_slope(r, -0.01, phi, 9.8));  // y_stop = 0 on a level plane
          continue;
        }
        const auto m = mu_from_stop_slope(r, *stop_slope(r, mu, phi, 9.8), phi, 9.8);
        ASSERT_TRUE(m) << stop_relation_key(r);
        // The inversions are closed forms (or TOMS 748 to full precision for eq 十): 1e-10.
        EXPECT_NEAR(*m, mu, 1e-10) << stop_relation_key(r) << " phi " << phi_deg;
      }
    }
  }
  // Slopes no mu can give: wrong sign, or an x slope beyond its value at mu = tan(phi).
  const double phi = incline::deg_to_rad(10);
  EXPECT_FALSE(mu_from_stop_slope(StopRelation::t_vs_v0, -0.1, phi, 9.8));
  EXPECT_FALSE(mu_from_stop_slope(StopRelation::y_vs_v0sq, 0.1, phi, 9.8));
  EXPECT_FALSE(mu_from_stop_slope(StopRelation::x_vs_v0sq, 1.01 * 2 / (3 * 9.8 * std::sin(phi)), phi, 9.8));
}

/// A run's stop point from the closed form (eqs 七-九) measured with noise: 2 ms on t_stop,
/// noise_pos on x_stop and y_stop; mu and sigma_mu as a fit would report them.
InclineRunPoint stop_point(double mu, double phi, double v0, PortableNormal& z, double noise_pos, const std::string& name) {
  incline::Parameters p;
  p.mu = mu;
  p.phi = phi;
  p.v0 = v0;
  const incline::Prediction pr = incline::ClosedForm(p).predict();
  InclineRunPoint r;
  r.source = name;
  r.phi = phi;
  r.mu = mu;
  r.sigma_mu = 0.003;
  r.v0 = v0;
  r.t_stop = *pr.t_stop + 0.002 * z();
  r.x_stop = *pr.x_stop + noise_pos * z();
  r.y_stop = *pr.y_stop + noise_pos * z();
  return r;
}

// Figure 八 recovered: stop points of 7 runs (v0 1.5..3 m/s, 2 mm and 2 ms noise) at the seed's
// 10.37 deg; every slope's mu interval covers the truth in about 95 % of 400 series.
TEST(InclineSeries, StopSlopesRecoverMuAndTheirIntervalsCover) {
  PortableNormal z(11);
  const double mu = 0.585, phi = incline::deg_to_rad(10.37);
  const int series = 400;
  int covered[4] = {0, 0, 0, 0};
  for (int k = 0; k < series; ++k) {
    std::vector<InclineRunPoint> runs;
    for (int i = 0; i < 7; ++i) runs.push_back(stop_point(mu, phi, 1.5 + 0.25 * i, z, 0.002, "r" + std::to_string(i)));
    const InclineSeriesSummary s = summarize_incline_series(runs);
    ASSERT_EQ(s.scaling.size(), 4u) << s.scaling_note;
    for (int j = 0; j < 4; ++j) {
      const auto& sc = s.scaling[static_cast<std::size_t>(j)];
      ASSERT_TRUE(sc.mu);
      const double lo = sc.mu_ci_low.value_or(0), hi = sc.mu_ci_high.value_or(INFINITY);
      covered[j] += lo <= mu && mu <= hi;
    }
  }
  std::printf("stop-slope mu intervals cover the truth: t %.3f x %.3f y %.3f y/x %.3f (%d series)\n",
              covered[0] / double(series), covered[1] / double(series), covered[2] / double(series),
              covered[3] / double(series), series);
  // Binomial 3-sigma tolerance around 0.95 over 400 series: +-0.033.
  for (int j = 0; j < 4; ++j)
    EXPECT_NEAR(covered[j] / double(series), 0.95, 3 * std::sqrt(0.95 * 0.05 / series))
        << stop_relation_key(kAll[j]);
}

TEST(InclineSeries, ExactStopPointsGiveTheTruthsMuFromEverySlope) {
  PortableNormal z(3);
  const double mu = 0.634, phi = incline::deg_to_rad(20.96);
  std::vector<InclineRunPoint> runs;
  for (double v0 : {1.8, 2.2, 2.62, 3.0}) runs.push_back(stop_point(mu, phi, v0, z, 0.0, "run"));
  const InclineSeriesSummary s = summarize_incline_series(runs);
  ASSERT_EQ(s.scaling.size(), 4u);
  // x and y exact: their slopes give mu to rounding (1e-9 leaves room for the fit's sums).
  EXPECT_NEAR(*s.scaling[1].mu, mu, 1e-9);
  EXPECT_NEAR(*s.scaling[2].mu, mu, 1e-9);
  EXPECT_NEAR(*s.scaling[3].mu, mu, 1e-9);
  EXPECT_NEAR(*s.scaling[0].mu, mu, 0.01);  // t has 2 ms noise: ~0.3 % of t_stop, mu to ~0.5 %
  EXPECT_NEAR(s.mu->mean, mu, 1e-12);
  EXPECT_NEAR(*s.scaling[1].slope_model, s.scaling[1].fit.slope, 1e-9);
  ASSERT_TRUE(s.common_phi);
  EXPECT_FALSE(s.theta_c_test);  // one angle
  EXPECT_FALSE(s.theta_c_note.empty());
}

TEST(InclineSeries, SeveralAnglesSkipTheSlopesAndRunTheThetaCTest) {
  const double mu = 0.634;
  std::vector<InclineRunPoint> runs;
  for (double phi_deg : {10.0, 14.0, 18.0, 22.0}) {
    InclineRunPoint r;
    r.source = "phi" + std::to_string(phi_deg);
    r.phi = incline::deg_to_rad(phi_deg);
    r.mu = mu;
    r.sigma_mu = 0.004;
    r.v0 = 2.5;
    r.t_stop = 1.0;
    r.x_stop = 0.5;
    r.y_stop = -0.1;
    r.cos_theta_c = std::tan(r.phi) / mu;  // eq c' exactly
    r.sigma_cos_theta_c = 0.01;
    runs.push_back(r);
  }
  const InclineSeriesSummary s = summarize_incline_series(runs);
  EXPECT_FALSE(s.common_phi);
  EXPECT_TRUE(s.scaling.empty());
  EXPECT_NE(s.scaling_note.find("4 different angles"), std::string::npos) << s.scaling_note;
  ASSERT_TRUE(s.theta_c_test) << s.theta_c_note;
  EXPECT_NEAR(s.theta_c_test->mu, mu, 1e-9);  // exact points: slope 1/mu through the origin
  EXPECT_EQ(s.theta_c_test->verdict, Verdict::absent);
}

TEST(InclineSeries, OutliersAreNamedAndPullsFollowTheRuns) {
  std::vector<InclineRunPoint> runs;
  for (int i = 0; i < 6; ++i) {
    InclineRunPoint r;
    r.source = "r" + std::to_string(i);
    r.phi = 0.2;
    r.mu = i == 3 ? 0.70 : 0.60 + 0.001 * (i % 2);
    r.sigma_mu = 0.005;
    runs.push_back(r);
  }
  const InclineSeriesSummary s = summarize_incline_series(runs);
  ASSERT_TRUE(s.mu);
  // r3 is 20 sigma off and drags the mean of six so far that every pull about it exceeds 3:
  // only the culprit may be named.
  ASSERT_EQ(s.outliers.size(), 1u);
  EXPECT_EQ(s.outliers[0], "r3");
  EXPECT_LT(s.mu->p_value, 1e-10);
  EXPECT_EQ(s.mu_index.size(), 6u);
  EXPECT_GT(s.mu->pulls[3], 3);
  EXPECT_NE(s.scaling_note.find("0 run(s) stopped"), std::string::npos);
}

// Whole synthetic tracked runs made by `incline synth`'s generator and analysed as the CLI does:
// model B (no normal friction) at one angle, then model A with f_N/m = 0.3 m/s^2.
std::vector<InclineRunPoint> analysed_series(double normal_accel, int n, std::uint64_t seed0) {
  std::vector<InclineRunPoint> out;
  for (int i = 0; i < n; ++i) {
    InclineSynthOptions o;
    o.params.mu = 0.634;
    o.params.phi = incline::deg_to_rad(20.96);
    o.params.v0 = 1.8 + 0.2 * i;
    o.params.normal_accel = normal_accel;
    o.fps = 120;
    o.seed = seed0 + static_cast<std::uint64_t>(i);
    const InclineSynthRun run = synthesize_incline_run(o);
    InclineFitOptions f;
    f.phi = o.params.phi;
    out.push_back(incline_run_point(analyze_incline_run(run.track, f), "run" + std::to_string(i)));
  }
  return out;
}

TEST(InclineSeries, SyntheticRunsGiveTheTruthAndPoolNormalFriction) {
  const auto b = summarize_incline_series(analysed_series(0, 6, 500));
  ASSERT_TRUE(b.mu);
  // Truth within the weighted mean's 99.9 % interval (3.3 sigma), fixed seeds.
  EXPECT_NEAR(b.mu->mean, 0.634, 3.3 * b.mu->sigma);
  EXPECT_GT(b.mu->p_value, 0.001);  // consistent runs
  ASSERT_EQ(b.scaling.size(), 4u);
  for (const auto& sc : b.scaling) {
    ASSERT_TRUE(sc.mu_ci_low && sc.mu_ci_high) << stop_relation_key(sc.relation);
    // The 95 % interval of each slope's mu holds the truth (a fixed-seed 1-in-20 event otherwise).
    EXPECT_LE(*sc.mu_ci_low, 0.634) << stop_relation_key(sc.relation);
    EXPECT_GE(*sc.mu_ci_high, 0.634) << stop_relation_key(sc.relation);
  }
  ASSERT_TRUE(b.normal_friction);
  // Model B: the pooled f_N/m within 3.3 sigma (99.9 %) of 0 (the 95 % verdict itself would
  // fail for 1 seed in 20; the interval's coverage is WeightedMean.SigmaCovers...).
  EXPECT_NEAR(b.normal_friction->mean.mean, 0, 3.3 * b.normal_friction->mean.sigma_scaled);

  const auto a = summarize_incline_series(analysed_series(0.3, 4, 600));
  ASSERT_TRUE(a.normal_friction);
  EXPECT_EQ(a.normal_friction->verdict, Verdict::present);
  EXPECT_NEAR(a.normal_friction->mean.mean, 0.3, 3.3 * a.normal_friction->mean.sigma_scaled);
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

TEST(SlideSeries, WeightedMuSkipsRunsWithoutAnAngle) {
  const SlideSeriesSummary s = summarize_slide_series({0.63, std::nullopt, 0.64}, {0.01, std::nullopt, 0.01},
                                                      {"a", "b", "c"});
  ASSERT_TRUE(s.mu);
  EXPECT_NEAR(s.mu->mean, 0.635, 1e-15);
  EXPECT_NEAR(s.mu->sigma, 0.01 / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(s.mu_index, (std::vector<int>{0, 2}));
  EXPECT_NEAR(s.mu->chi2, 0.5, 1e-12);  // each 0.5 sigma off
  const SlideSeriesSummary none = summarize_slide_series({std::nullopt}, {std::nullopt}, {"a"});
  EXPECT_FALSE(none.mu);
  EXPECT_FALSE(none.note.empty());
}

TEST(InclineSeries, NoRunsGiveNotesNotExceptions) {
  const InclineSeriesSummary s = summarize_incline_series({});
  EXPECT_FALSE(s.mu);
  EXPECT_EQ(s.scaling_note, "no runs were analysed");
  EXPECT_EQ(s.theta_c_note, "no runs were analysed");
  EXPECT_FALSE(s.normal_friction);
}

}  // namespace
}  // namespace tribolab::analysis
