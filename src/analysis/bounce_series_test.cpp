// Tests of the bounce series summary on hand-computable cases, and of the adapter point_of.
#include "analysis/bounce_series.hpp"

#include "analysis/bounce_synth.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::analysis {
namespace {

BounceSeriesPoint point(double angle, double e, double sigma_e) {
  BounceSeriesPoint p;
  p.collision_angle_deg = angle;
  p.e_velocity = e;
  p.sigma_e_velocity = sigma_e;
  p.e_height = p.sigma_e_height = NAN;
  p.mean_normal_force = p.sigma_mean_normal_force = NAN;
  p.energy_pre.translational_y = 1;
  p.energy_post.translational_y = e * e;  // a vertical bounce: E'/E = e^2
  return p;
}

TEST(BounceSeriesMean, TwoValuesByHand) {
  // (1 + 3)/2 = 2; sigma = 1/sqrt(2); chi2 = 1 + 1 = 2 on 1 dof; P(chi2_1 >= 2) = erfc(1).
  const auto m = weighted_mean_of_finite({1, 3}, {1, 1});
  EXPECT_EQ(m.n, 2);
  EXPECT_DOUBLE_EQ(m.mean, 2);
  EXPECT_DOUBLE_EQ(m.sigma, 1 / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.chi2, 2);
  EXPECT_EQ(m.dof, 1);
  EXPECT_NEAR(m.p_value, std::erfc(1.0), 1e-14);  // two closed forms of one number: rounding only
  EXPECT_NEAR(m.sigma_scaled, 1.0, 1e-15);          // sigma sqrt(chi2/dof) = sqrt(1/2) sqrt(2)
}

TEST(BounceSeriesMean, WeightsAndSkipsMissingValues) {
  // Weights 1/0.1^2 = 100 and 1/0.2^2 = 25: (100*1 + 25*2)/125 = 1.2, sigma = 1/sqrt(125);
  // the NaN value and the zero sigma are left out (a run without e_height, a broken sigma).
  const auto m = weighted_mean_of_finite({1, 2, NAN, 5}, {0.1, 0.2, 0.1, 0});
  EXPECT_EQ(m.n, 2);
  EXPECT_NEAR(m.mean, 1.2, 1e-15);
  EXPECT_NEAR(m.sigma, 1 / std::sqrt(125.0), 1e-15);
  // Consistent values: chi2 < dof, so the scaled sigma is the plain one.
  const auto c = weighted_mean_of_finite({1, 1.01}, {0.1, 0.1});
  EXPECT_DOUBLE_EQ(c.sigma_scaled, c.sigma);
  const auto none = weighted_mean_of_finite({NAN}, {0.1});
  EXPECT_EQ(none.n, 0);
  EXPECT_TRUE(std::isnan(none.mean));
}

TEST(BounceSeries, HeadlinesTheRelationWithTheAngleWhenTheRunsAreNotOneValue) {
  // e rising with the collision angle, 0.5 +- 0.01 at 10 deg to 1.1 +- 0.01 at 130 deg (issue
  // 27: the demo's series was headlined "e_v weighted mean 0.908 +- 0.090" at chi2 = 7.9e5).
  std::vector<BounceSeriesPoint> pts;
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 3; ++j) pts.push_back(point(10 + 20 * k + j, 0.5 + 0.1 * k, 0.01));
  const auto s = summarize_bounce_series(pts);
  EXPECT_FALSE(is_one_value(s.e_velocity));
  const std::string h = e_velocity_headline(s);
  EXPECT_EQ(h.find("weighted mean"), std::string::npos) << h;
  EXPECT_NE(h.find("not one value"), std::string::npos) << h;
  // The span of the relation, bin by bin: the lowest (0-20) and the highest (120-140) bin.
  EXPECT_NE(h.find("from 0.500 +- 0.006 at 11 deg (bin 0-20) to 1.100 +- 0.006 at 131 deg (bin 120-140) over 7 bins"),
            std::string::npos) << h;
  // Runs that agree keep their mean as the headline.
  const auto one = summarize_bounce_series({point(10, 0.80, 0.01), point(90, 0.81, 0.01), point(150, 0.79, 0.01)});
  EXPECT_TRUE(is_one_value(one.e_velocity));
  EXPECT_NE(e_velocity_headline(one).find("e_velocity = 0.8000 +- 0.0058, weighted mean of 3 runs"), std::string::npos)
      << e_velocity_headline(one);
}

TEST(BounceSeries, AboveOneCountsAndSignificance) {
  // 1.2 +- 0.05 is 4 sigma above 1 (significant); 1.05 +- 0.05 is 1 sigma (not); 0.9 is below.
  const std::vector<BounceSeriesPoint> pts = {point(110, 1.2, 0.05), point(115, 1.05, 0.05), point(170, 0.9, 0.05)};
  const auto s = summarize_bounce_series(pts);
  EXPECT_EQ(s.n_runs, 3);
  EXPECT_EQ(s.above_one_velocity.n, 3);
  EXPECT_EQ(s.above_one_velocity.above, 2);
  EXPECT_EQ(s.above_one_velocity.significant, 1);
  EXPECT_EQ(s.above_one_height.n, 0);  // no run has e_height
  // Equal sigmas: the plain mean (1.2 + 1.05 + 0.9)/3 = 1.05.
  EXPECT_NEAR(s.e_velocity.mean, 1.05, 1e-14);
  // 1.645 sigma is the one-sided 95% threshold; a stricter z makes 1.2 (4 sigma) still count.
  BounceSeriesOptions o;
  o.z_above_one = 5;
  EXPECT_EQ(summarize_bounce_series(pts, o).above_one_velocity.significant, 0);
}

TEST(BounceSeries, BinsByCollisionAngle) {
  // Width 20: [100,120) holds 110 and 115, [120,140) 125, [160,180] 170 and 180 (closed end).
  const std::vector<BounceSeriesPoint> pts = {point(110, 1.0, 0.1), point(115, 1.2, 0.1), point(125, 0.8, 0.2),
                                              point(170, 0.6, 0.1), point(180, 0.7, 0.1)};
  const auto s = summarize_bounce_series(pts);
  ASSERT_EQ(s.bins.size(), 3u);
  EXPECT_EQ(s.bins[0].low_deg, 100);
  EXPECT_EQ(s.bins[0].high_deg, 120);
  EXPECT_EQ(s.bins[0].n, 2);
  EXPECT_NEAR(s.bins[0].centre_deg, 112.5, 1e-12);
  EXPECT_NEAR(s.bins[0].e_velocity.mean, 1.1, 1e-14);
  EXPECT_EQ(s.bins[0].e_min, 1.0);
  EXPECT_EQ(s.bins[0].e_max, 1.2);
  EXPECT_EQ(s.bins[0].n_above_one, 1);  // 1.0 is not above 1
  EXPECT_EQ(s.bins[1].n, 1);
  EXPECT_EQ(s.bins[1].e_velocity.dof, 0);
  EXPECT_EQ(s.bins[2].low_deg, 160);
  EXPECT_EQ(s.bins[2].high_deg, 180);
  EXPECT_EQ(s.bins[2].n, 2);
  EXPECT_NEAR(s.bins[2].e_velocity.mean, 0.65, 1e-14);
}

TEST(BounceSeries, NamesTheOutlierOfABin) {
  // Median 0.51; deviations 0.01, 0.01, 0.03, 0, 0.39 -> MAD 0.01; the run at 0.9 has
  // modified z 0.6745 * 0.39 / 0.01 = 26.3 (> 3.5), the one at 0.48 has 2.02 (not named).
  const std::vector<BounceSeriesPoint> pts = {point(121, 0.5, 0.02), point(122, 0.52, 0.02), point(123, 0.48, 0.02),
                                              point(124, 0.51, 0.02), point(125, 0.9, 0.02), point(60, 0.3, 0.02)};
  const auto s = summarize_bounce_series(pts);
  ASSERT_EQ(s.outliers.size(), 1u);
  EXPECT_EQ(s.outliers[0].run, 4u);
  EXPECT_NE(s.outliers[0].reason.find("0.9"), std::string::npos) << s.outliers[0].reason;
  EXPECT_NE(s.outliers[0].reason.find("26.3"), std::string::npos) << s.outliers[0].reason;
  // A bin with fewer runs than outlier_min_bin names nobody.
  BounceSeriesOptions o;
  o.outlier_min_bin = 6;
  EXPECT_TRUE(summarize_bounce_series(pts, o).outliers.empty());
}

TEST(BounceSeries, EnergiesAndForce) {
  std::vector<BounceSeriesPoint> pts = {point(110, 1.2, 0.05), point(120, 0.5, 0.05), point(130, 0.6, 0.05)};
  // E'/E = e^2: 1.44, 0.25, 0.36 -> mean 0.6833..., one run gained.
  pts[0].mean_normal_force = 300;
  pts[1].mean_normal_force = 100;
  pts[2].mean_normal_force = 150;
  pts[0].contact_point_speed = 2;
  pts[1].contact_point_speed = 5;
  pts[2].contact_point_speed = 1;
  const auto s = summarize_bounce_series(pts);
  EXPECT_NEAR(s.energy_ratio_mean, (1.44 + 0.25 + 0.36) / 3, 1e-14);
  EXPECT_EQ(s.n_energy_gain, 1);
  EXPECT_EQ(s.n_force, 3);
  EXPECT_NEAR(s.force_mean, 550.0 / 3, 1e-12);
  // sd: deviations 116.67, -83.33, -33.33 -> sqrt((13611.1 + 6944.4 + 1111.1)/2) = 104.08.
  EXPECT_NEAR(s.force_sd, std::sqrt((std::pow(350.0 / 3, 2) + std::pow(250.0 / 3, 2) + std::pow(100.0 / 3, 2)) / 2), 1e-9);
  // Force and e exactly linear (e = 0.3 + 0.003 N) would give r = 1; here by hand:
  // f - mean = (350, -250, -100)/3, e - mean = (0.43333, -0.26667, -0.16667).
  const double df[] = {350.0 / 3, -250.0 / 3, -100.0 / 3}, de[] = {1.2 - 2.3 / 3, 0.5 - 2.3 / 3, 0.6 - 2.3 / 3};
  double sfe = 0, sff = 0, see = 0;
  for (int i = 0; i < 3; ++i) {
    sfe += df[i] * de[i];
    sff += df[i] * df[i];
    see += de[i] * de[i];
  }
  EXPECT_NEAR(s.force_e_correlation, sfe / std::sqrt(sff * see), 1e-12);
  EXPECT_EQ(s.fastest_contact_run, 1u);
  EXPECT_EQ(s.slowest_contact_run, 2u);
}

TEST(BounceSeries, RejectsNoRunsAndBadOptions) {
  EXPECT_THROW(summarize_bounce_series({}), InputError);
  BounceSeriesOptions o;
  o.bin_width_deg = 0;
  EXPECT_THROW(summarize_bounce_series({point(100, 1, 0.1)}, o), InputError);
}

TEST(BounceSeriesAdapter, ReadsTheTouchAndSeparationFields) {
  // Every value the series reads is the touch / separation one, never its impact_time
  // counterpart: the two are given different values so a wrong field shows.
  BounceAnalysis r;
  r.collision_angle_deg = 130;
  r.sigma_collision_angle_deg = 0.7;
  r.collision_angle_impact_deg = 140;
  r.theta_touch_deg = 12;
  r.theta_impact_deg = 20;
  r.e_velocity = 1.1;
  r.sigma_e_velocity = 0.02;
  r.e_velocity_common = 1.15;
  r.e_height = 1.05;
  r.sigma_e_height = 0.03;
  r.pre.vx = 1;
  r.pre.vy = -2.9;  // at impact_time
  r.vy_touch = -3;
  r.pre.omega = -10;
  r.post.vx = 0.5;
  r.post.vy = 3.4;  // at impact_time
  r.vy_separation = 3.3;
  r.post.omega = 5;
  r.pre.energy.rotational = 0.2;
  r.post.energy.rotational = 0.05;
  r.mean_normal_force = 250;
  r.sigma_mean_normal_force = 10;
  r.contact_point_vx = 0.05;
  r.contact_point_vy = -3;
  r.contact_point_speed = std::hypot(0.05, 3.0);
  r.sigma_contact_point_speed = 0.04;
  const auto p = point_of(r);
  EXPECT_EQ(p.collision_angle_deg, 130);
  EXPECT_EQ(p.sigma_collision_angle_deg, 0.7);
  EXPECT_EQ(p.theta_deg, 12);
  EXPECT_EQ(p.e_velocity, 1.1);
  EXPECT_EQ(p.e_height, 1.05);
  EXPECT_EQ(p.vy_in, -3);
  EXPECT_EQ(p.vy_out, 3.3);
  EXPECT_EQ(p.omega_out, 5);
  EXPECT_EQ(p.energy_post.rotational, 0.05);
  EXPECT_EQ(p.mean_normal_force, 250);
  EXPECT_EQ(p.contact_point_vx, 0.05);
  EXPECT_EQ(p.contact_point_vy, -3);
  EXPECT_EQ(p.contact_point_speed, std::hypot(0.05, 3.0));
  EXPECT_EQ(p.sigma_contact_point_speed, 0.04);
  const auto row = bounce_row_of(p);
  EXPECT_EQ(row.theta_deg, 12);
  EXPECT_EQ(row.vx_in, 1);
  EXPECT_EQ(row.vy_in, -3);
  EXPECT_EQ(row.omega_in, -10);
  EXPECT_EQ(row.vx_out, 0.5);
  EXPECT_EQ(row.vy_out, 3.3);
  EXPECT_EQ(row.omega_out, 5);
  // Without a contact duration there is no force.
  r.mean_normal_force.reset();
  r.sigma_mean_normal_force.reset();
  EXPECT_TRUE(std::isnan(point_of(r).mean_normal_force));
}

}  // namespace
}  // namespace tribolab::analysis
