// Tests of the series statistics (analysis/series_stats.hpp) against hand-computed cases and
// by coverage over many synthetic series.
#include "analysis/series_stats.hpp"

#include "analysis/incline_synthetic.hpp"  // PortableNormal
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace tribolab::analysis {
namespace {

TEST(WeightedMean, HandComputedCase) {
  // x = 1, 2, 4 with s = 1, 1, 2: w = 1, 1, 1/4; sum w = 2.25; sum w x = 1 + 2 + 1 = 4.
  const std::vector<double> x{1, 2, 4}, s{1, 1, 2};
  const WeightedMean m = weighted_mean(x, s);
  EXPECT_DOUBLE_EQ(m.mean, 4.0 / 2.25);
  EXPECT_DOUBLE_EQ(m.sigma, 1.0 / 1.5);
  // chi2 = (1 - 16/9)^2 + (2 - 16/9)^2 + (4 - 16/9)^2 / 4 = 49/81 + 4/81 + 400/324 = 153/81.
  EXPECT_NEAR(m.chi2, 153.0 / 81.0, 1e-14);
  EXPECT_EQ(m.dof, 2);
  // chi-square with 2 dof: P(X > c) = exp(-c/2) exactly.
  EXPECT_NEAR(m.p_value, std::exp(-m.chi2 / 2), 1e-14);
  EXPECT_NEAR(m.birge_ratio, std::sqrt(m.chi2 / 2), 1e-14);
  EXPECT_DOUBLE_EQ(m.sigma_scaled, m.sigma);  // Birge ratio < 1: not scaled down
  // pull_1 = (1 - 16/9)/sqrt(1 - 4/9) = (-7/9)/sqrt(5/9).
  EXPECT_NEAR(m.pulls[0], (-7.0 / 9) / std::sqrt(5.0 / 9), 1e-14);
}

TEST(WeightedMean, EqualUncertaintiesGiveTheArithmeticMean) {
  const std::vector<double> x{0.61, 0.63, 0.65, 0.62}, s(4, 0.01);
  const WeightedMean m = weighted_mean(x, s);
  EXPECT_NEAR(m.mean, 0.6275, 1e-15);
  EXPECT_NEAR(m.sigma, 0.005, 1e-15);  // s / sqrt(n)
}

TEST(WeightedMean, ConsistentRunsHaveALargePValueAndInconsistentOnesATinyOne) {
  // Consistent: the values differ by about their error. chi2 = 4 * (0.5)^2... computed: x =
  // 0.60 +- 0.01 alternating, mean 0.605, each 0.5 sigma off: chi2 = 6 * 0.25 = 1.5, 5 dof.
  const std::vector<double> s(6, 0.01);
  const WeightedMean ok = weighted_mean(std::vector<double>{0.60, 0.61, 0.60, 0.61, 0.60, 0.61}, s);
  EXPECT_NEAR(ok.chi2, 1.5, 1e-10);
  EXPECT_NEAR(ok.p_value, 0.9131, 1e-4);  // tables: P(chi2_5 > 1.5) = 0.9131
  // Inconsistent: two groups 0.10 apart with 0.01 errors: each 5 sigma off, chi2 = 150.
  const WeightedMean bad = weighted_mean(std::vector<double>{0.55, 0.65, 0.55, 0.65, 0.55, 0.65}, s);
  EXPECT_NEAR(bad.chi2, 150, 1e-9);
  EXPECT_LT(bad.p_value, 1e-29);
  EXPECT_NEAR(bad.sigma_scaled, bad.sigma * std::sqrt(30.0), 1e-15);
}

TEST(WeightedMean, OneValueHasNoChiSquare) {
  const WeightedMean m = weighted_mean(std::vector<double>{0.6}, std::vector<double>{0.02});
  EXPECT_EQ(m.mean, 0.6);
  EXPECT_EQ(m.sigma, 0.02);
  EXPECT_EQ(m.dof, 0);
  EXPECT_TRUE(std::isnan(m.p_value));
  EXPECT_TRUE(std::isnan(m.pulls[0]));
}

TEST(WeightedMean, RejectsBadInput) {
  EXPECT_THROW(weighted_mean(std::vector<double>{}, std::vector<double>{}), InputError);
  EXPECT_THROW(weighted_mean(std::vector<double>{1, 2}, std::vector<double>{1}), InputError);
  EXPECT_THROW(weighted_mean(std::vector<double>{1, 2}, std::vector<double>{1, 0}), InputError);
  EXPECT_THROW(weighted_mean(std::vector<double>{1, NAN}, std::vector<double>{1, 1}), InputError);
}

// Over many synthetic series with known truth and unequal errors: the mean's +-sigma covers
// the truth 68.3 % of the time, chi2 averages dof, and p < 0.05 in 5 % of the series.
TEST(WeightedMean, SigmaCoversAndTheChiSquareTestHasItsSize) {
  PortableNormal z(2026);
  const int series = 4000, n = 7;
  const double truth = 0.634;
  int covered = 0, rejected = 0;
  double chi2_sum = 0;
  for (int k = 0; k < series; ++k) {
    std::vector<double> x, s;
    for (int i = 0; i < n; ++i) {
      s.push_back(0.005 * (1 + i));  // 5 to 35 mm-level errors: weights differ 49-fold
      x.push_back(truth + s.back() * z());
    }
    const WeightedMean m = weighted_mean(x, s);
    covered += std::abs(m.mean - truth) <= m.sigma;
    rejected += m.p_value < 0.05;
    chi2_sum += m.chi2;
  }
  std::printf("weighted mean over %d series of %d: +-sigma covers %.4f, p < 0.05 in %.4f, mean chi2 %.3f\n", series, n,
              covered / double(series), rejected / double(series), chi2_sum / series);
  // Binomial 3-sigma tolerances over 4000 series: 0.683 +- 0.022, 0.05 +- 0.010; the mean chi2
  // has sd sqrt(2 dof / series) = 0.055: +-0.17 is 3 sd.
  EXPECT_NEAR(covered / double(series), 0.6827, 3 * std::sqrt(0.683 * 0.317 / series));
  EXPECT_NEAR(rejected / double(series), 0.05, 3 * std::sqrt(0.05 * 0.95 / series));
  EXPECT_NEAR(chi2_sum / series, n - 1, 3 * std::sqrt(2.0 * (n - 1) / series));
}

TEST(ProportionalFit, HandComputedCase) {
  // y = 2x exactly at x = 1, 2, 3 plus residuals (+0.1, -0.1, +0.1/3) chosen orthogonal to x:
  // 0.1 - 0.2 + 0.1 = 0, so the slope stays 2.
  const std::vector<double> x{1, 2, 3}, y{2.1, 3.9, 6.0 + 0.1 / 3};
  const ProportionalFit f = fit_proportional(x, y);
  EXPECT_NEAR(f.slope, 2.0, 1e-14);
  const double rss = 0.01 + 0.01 + 0.01 / 9;
  EXPECT_NEAR(f.sigma, std::sqrt(rss / 2 / 14), 1e-14);
  EXPECT_NEAR(f.ci_high - f.slope, 4.302652729749464 * f.sigma, 1e-12);  // t_{0.975, 2}
  EXPECT_EQ(f.n, 3);
  EXPECT_THROW(fit_proportional(std::vector<double>{1}, std::vector<double>{1}), InputError);
  EXPECT_THROW(fit_proportional(std::vector<double>{0, 0}, std::vector<double>{1, 2}), InputError);
}

TEST(ChiSquare, UpperTailKnownValues) {
  EXPECT_NEAR(chi2_upper_tail(3.841458820694124, 1), 0.05, 1e-12);
  EXPECT_NEAR(chi2_upper_tail(18.307038053275146, 10), 0.05, 1e-12);
  EXPECT_EQ(chi2_upper_tail(0, 3), 1.0);
  EXPECT_TRUE(std::isnan(chi2_upper_tail(1, 0)));
}

}  // namespace
}  // namespace tribolab::analysis
