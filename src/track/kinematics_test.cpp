#include "track/kinematics.hpp"

#include "numerics/error.hpp"
#include "track/synthetic_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tribolab::track {
namespace {

Track polynomial_track(int n, double fps, double (*fx)(double), double (*fy)(double),
                       int first_frame = 0) {
  Track t{"p", {}};
  for (int i = 0; i < n; ++i) {
    const double ti = (first_frame + i) / fps;
    t.points.push_back({first_frame + i, ti, fx(ti), fy(ti)});
  }
  return t;
}

double quad_x(double t) { return 0.3 + 1.7 * t - 4.9 * t * t; }
double quad_y(double t) { return 1.2 - 2.5 * t + 3.1 * t * t; }
double cubic(double t) { return 0.4 - 1.1 * t + 2.3 * t * t + 5.0 * t * t * t; }

KinematicsOptions tracker_no_impacts() {
  KinematicsOptions o;
  o.method = DerivativeMethod::tracker;
  o.split_at_impacts = false;
  return o;
}

TEST(TrackerStencils, VelocityExactOnQuadraticAccelerationExactOnCubic) {
  // Central difference is exact for degree 2; the symmetric 5-point second-derivative
  // stencil is exact for degree 3 (odd terms cancel). Round-off: positions ~1 m divided by
  // dt = 1/240 s (velocity, ~1e-13) or 7 dt^2 (acceleration, ~1e-10).
  const Track t = polynomial_track(40, 240, quad_x, cubic);
  const Kinematics k = differentiate(t, tracker_no_impacts());
  for (std::size_t i = 2; i + 2 < t.points.size(); ++i) {
    const double ti = t.points[i].t;
    EXPECT_NEAR(k.rows[i].vx, 1.7 - 9.8 * ti, 1e-10);
    EXPECT_NEAR(k.rows[i].ax, -9.8, 1e-7);
    EXPECT_NEAR(k.rows[i].ay, 4.6 + 30.0 * ti, 1e-7);
  }
}

TEST(TrackerStencils, VelocityErrorOnCubicIsTheTruncationTerm) {
  // (x(t+h) - x(t-h)) / 2h = x'(t) + h^2 x'''/6: the stencil is second order, not exact.
  const double h = 1.0 / 240;
  const Track t = polynomial_track(20, 240, quad_x, cubic);
  const Kinematics k = differentiate(t, tracker_no_impacts());
  const std::size_t i = 10;
  const double ti = t.points[i].t;
  const double exact = -1.1 + 4.6 * ti + 15.0 * ti * ti;
  EXPECT_NEAR(k.rows[i].vy - exact, h * h * 30.0 / 6, 1e-10);
}

TEST(TrackerStencils, UndefinedAtTheEndsAndAroundGaps) {
  Track t = polynomial_track(20, 100, quad_x, quad_y);
  t.points.erase(t.points.begin() + 10);  // frame 10 missing
  const Kinematics k = differentiate(t, tracker_no_impacts());
  EXPECT_TRUE(std::isnan(k.rows[0].vx));
  EXPECT_TRUE(std::isnan(k.rows[1].ax));
  EXPECT_FALSE(std::isnan(k.rows[1].vx));
  EXPECT_FALSE(std::isnan(k.rows[2].ax));
  // rows 9 (frame 9) and 10 (frame 11) lack a neighbour for v; 8..11 lack one for a
  EXPECT_TRUE(std::isnan(k.rows[9].vx));
  EXPECT_TRUE(std::isnan(k.rows[10].vx));
  EXPECT_FALSE(std::isnan(k.rows[8].vx));
  for (std::size_t i = 8; i <= 11; ++i) EXPECT_TRUE(std::isnan(k.rows[i].ay)) << i;
  EXPECT_FALSE(std::isnan(k.rows[12].ay));
  EXPECT_TRUE(std::isnan(k.rows.back().vx));
  EXPECT_TRUE(std::isnan(k.rows[5].sigma_vx));  // Tracker's method has no uncertainties
}

TEST(TrackerStencils, StepSizeTwoIsNotAGap) {
  // frames 0, 2, 4, ...: consecutive steps are 2 frames apart
  Track t{"s", {}};
  for (int i = 0; i < 10; ++i) t.points.push_back({2 * i, i * 0.01, quad_x(i * 0.01), 0});
  const Kinematics k = differentiate(t, tracker_no_impacts());
  EXPECT_NEAR(k.rows[4].vx, 1.7 - 9.8 * 0.04, 1e-10);
}

TEST(SavitzkyGolay, ExactOnPolynomialsOfItsOrderWithUnevenTimesAndGaps) {
  // A least-squares polynomial of degree P reproduces any polynomial of degree <= P exactly,
  // whatever the abscissae; round-off of the scaled normal equations: ~1e-9 here.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Track t{"u", {}};
  for (int i = 0; i < 60; ++i) {
    if (i % 7 == 3) continue;  // missing points
    const double ti = (i + jitter(rng)) / 120;
    t.points.push_back({i, ti, cubic(ti), quad_y(ti)});
  }
  KinematicsOptions o;
  o.method = DerivativeMethod::savgol;
  o.window = 9;
  o.order = 3;
  o.split_at_impacts = false;
  const Kinematics k = differentiate(t, o);
  for (const auto& r : k.rows) {
    EXPECT_NEAR(r.vx, -1.1 + 4.6 * r.t + 15.0 * r.t * r.t, 1e-8);
    EXPECT_NEAR(r.ax, 4.6 + 30.0 * r.t, 1e-6);
    EXPECT_NEAR(r.vy, -2.5 + 6.2 * r.t, 1e-8);
    EXPECT_NEAR(r.ay, 6.2, 1e-6);
  }
  EXPECT_LT(k.residual_sigma_x, 1e-9);
}

TEST(SavitzkyGolay, StandardErrorsMatchTheScatterOfRepeatedRuns) {
  // 400 seeded runs of a parabola with 1 mm noise at 240 fps. At each checked point the
  // mean of z^2 = ((v - v_true)/sigma)^2 over runs has standard deviation sqrt(2/400) = 0.07
  // for a correct sigma; the tolerance 0.3 is about 4 of those (plus a little for the pooled
  // noise estimate's own scatter, ~1/sqrt(dof ~ 900) per run).
  const int runs = 400;
  const double fps = 240, noise = 0.001;
  const std::vector<std::size_t> checked = {0, 3, 60, 119};
  std::vector<double> zv(checked.size()), za(checked.size());
  KinematicsOptions o;
  o.method = DerivativeMethod::savgol;
  o.window = 11;
  o.order = 2;
  o.split_at_impacts = false;
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> n(0, noise);
  for (int r = 0; r < runs; ++r) {
    Track t{"n", {}};
    for (int i = 0; i < 120; ++i) {
      const double ti = i / fps;
      t.points.push_back({i, ti, quad_x(ti) + n(rng), quad_y(ti) + n(rng)});
    }
    const Kinematics k = differentiate(t, o);
    for (std::size_t c = 0; c < checked.size(); ++c) {
      const auto& row = k.rows[checked[c]];
      const double dv = (row.vx - (1.7 - 9.8 * row.t)) / row.sigma_vx;
      const double da = (row.ay - 6.2) / row.sigma_ay;
      zv[c] += dv * dv / runs;
      za[c] += da * da / runs;
    }
  }
  for (std::size_t c = 0; c < checked.size(); ++c) {
    EXPECT_NEAR(zv[c], 1.0, 0.3) << "velocity at point " << checked[c];
    EXPECT_NEAR(za[c], 1.0, 0.3) << "acceleration at point " << checked[c];
  }
}

TEST(Kinematics, NeverDifferencesAcrossAnImpact) {
  const auto b = testing::bouncing_ball(240, 1.6, 1.0, 0.5, 0.8, 0.001, 11);
  for (auto method : {DerivativeMethod::tracker, DerivativeMethod::savgol}) {
    KinematicsOptions o;
    o.method = method;
    const Kinematics k = differentiate(b.track, o);
    ASSERT_EQ(k.impacts.size(), b.contact_times.size());
    EXPECT_EQ(k.segments, static_cast<int>(b.contact_times.size()) + 1);
    // in flight ay = -g. Tracker's 5-point stencil with 1 mm noise at 240 fps scatters by
    // 1 mm * sqrt(14) / (7 dt^2) = 31 m/s^2: every defined row must lie within 6.5 of those
    // (200 m/s^2), their mean within 8 m/s^2 (~5 standard errors over ~350 correlated rows).
    // A stencil across the bounce gives several hundred m/s^2 (checked below).
    double sum = 0;
    int count = 0;
    for (const auto& r : k.rows) {
      if (std::isnan(r.ay)) continue;
      EXPECT_LT(std::abs(r.ay + 9.8), 200) << to_string(method) << " t = " << r.t;
      sum += r.ay;
      ++count;
    }
    EXPECT_NEAR(sum / count, -9.8, 8) << to_string(method);
  }
  // control: without the impact split, the stencils straddle the bounces
  KinematicsOptions smeared;
  smeared.split_at_impacts = false;
  double worst = 0;
  for (const auto& r : differentiate(b.track, smeared).rows) {
    if (!std::isnan(r.ay)) worst = std::max(worst, r.ay);
  }
  EXPECT_GT(worst, 300);
}

TEST(SavitzkyGolay, ClusteredTimesGiveUndefinedValuesNotACrash) {
  // six times within 6e-12 s and one 1 s later: a degree-6 fit is numerically singular
  Track t{"c", {}};
  for (int i = 0; i < 6; ++i) t.points.push_back({i, i * 1e-12, 1.0 * i, 0});
  t.points.push_back({6, 1.0, 7, 0});
  KinematicsOptions o;
  o.method = DerivativeMethod::savgol;
  o.order = 6;
  o.window = 8;
  o.split_at_impacts = false;
  const Kinematics k = differentiate(t, o);
  ASSERT_EQ(k.rows.size(), 7u);
  EXPECT_TRUE(std::isnan(k.rows[0].vx));
}

TEST(KinematicsOptions, RejectsImpossibleSettings) {
  KinematicsOptions o;
  o.method = DerivativeMethod::savgol;
  o.order = 2;
  o.window = 3;
  EXPECT_NE(o.validate(), "");
  o.window = 5;
  o.order = 0;
  EXPECT_NE(o.validate(), "");
  o.order = 2;
  EXPECT_EQ(o.validate(), "");
  o.window = 2;
  EXPECT_THROW(differentiate(Track{"x", {}}, o), InputError);
}

}  // namespace
}  // namespace tribolab::track
