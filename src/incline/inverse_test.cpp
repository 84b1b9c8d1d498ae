// mu from the stopping point (seed 000, eq 十A): root selection, the seed's formulas,
// uncertainty propagation against Monte Carlo, and the angle advice.
#include "incline/inverse.hpp"

#include "incline/closed_form.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tribolab::incline {
namespace {

StopMeasurement stop_of(double mu, double phi_deg, double v0) {
  Parameters p;
  p.mu = mu;
  p.phi = deg_to_rad(phi_deg);
  p.v0 = v0;
  const Prediction pr = ClosedForm(p).predict();
  StopMeasurement m;
  m.phi = p.phi;
  m.x_stop = *pr.x_stop;
  m.y_stop = *pr.y_stop;
  return m;
}

TEST(MuFromStop, RecoversMuFromThePredictedStop) {
  for (double mu : {0.2, 0.634, 1.5}) {
    for (double frac : {0.01, 0.3, 0.7, 0.99}) {
      const double phi_deg = rad_to_deg(std::atan(frac * mu));  // k = frac
      const MuFromStopResult r = mu_from_stop(stop_of(mu, phi_deg, 2.0));
      // The bracketed root is exact to a few ulps of k; r(k) amplifies by at most ~1e2 at
      // k = 0.99 where dr/dk is small.
      EXPECT_NEAR(r.mu / mu, 1, 1e-12) << mu << " " << frac;
      EXPECT_NEAR(r.k, frac, 1e-12) << mu << " " << frac;
      EXPECT_NEAR(r.v0, 2.0, 1e-11) << mu << " " << frac;
    }
  }
}

TEST(MuFromStop, CubicHasExactlyOnePhysicalRoot) {
  // Q(k) = 8(1-k^2) - r k (4-k^2): scan (0,1) finely for sign changes; exactly one, and the
  // two other real roots (seed eqs 10.4, 10.5) lie above 2 and below 0.
  for (double r : {1e-6, 0.01, 0.5, 2.0, 10.0, 1e3, 1e8}) {
    int changes = 0;
    double prev = 8;
    for (int i = 1; i <= 100000; ++i) {
      const double k = i / 100000.0;
      const double q = 8 * (1 - k * k) - r * k * (4 - k * k);
      if ((q < 0) != (prev < 0)) ++changes;
      prev = q;
    }
    EXPECT_EQ(changes, 1) << r;
    const double k = k_from_ratio(r);
    EXPECT_GT(k, 0);
    EXPECT_LT(k, 1);
    // Residual relative to the size of the terms.
    EXPECT_NEAR(8 * (1 - k * k) - r * k * (4 - k * k), 0, 1e-14 * (8 + 4 * r)) << r;
  }
}

TEST(MuFromStop, SeedAppendixFormulaAgreesButTheMainTextOneDoesNot) {
  // Seed 000: appendix eq 10.6 puts -2 pi inside the 1/3 and gives the physical root; the
  // main-text (十A) puts it outside, which is cos(theta/3) = the root near 2 (eq 10.4).
  for (double r : {0.3, 3.0, 14.1, 30.0}) {
    EXPECT_NEAR(k_from_ratio_seed_formula(r, false), k_from_ratio(r), 1e-12) << r;
    const double k1 = k_from_ratio_seed_formula(r, true);
    EXPECT_GT(k1, 2) << r;  // a root of the cubic, but where the disc never stops
    EXPECT_NEAR(8 * (1 - k1 * k1) - r * k1 * (4 - k1 * k1), 0, 1e-12 * (8 + 4 * r) * k1 * k1 * k1);
  }
}

TEST(MuFromStop, RejectsInputsWithoutAPhysicalRoot) {
  StopMeasurement m = stop_of(0.6, 20, 2);
  StopMeasurement bad = m;
  bad.x_stop = 0;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  bad = m;
  bad.x_stop = -0.2;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  bad = m;
  bad.y_stop = 0.01;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  bad = m;
  bad.phi = 0;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  bad = m;
  bad.phi = M_PI / 2;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  bad = m;
  bad.sigma_pos = -1;
  EXPECT_THROW(mu_from_stop(bad), InputError);
  EXPECT_THROW(k_from_ratio(0), InputError);
}

TEST(MuFromStop, DerivativesMatchFiniteDifferences) {
  const StopMeasurement m = stop_of(0.634, 20.96, 2.0);
  const MuFromStopResult r = mu_from_stop(m);
  auto mu_at = [&](double dphi, double dx, double dy) {
    StopMeasurement q = m;
    q.phi += dphi;
    q.x_stop += dx;
    q.y_stop += dy;
    return mu_from_stop(q).mu;
  };
  // Central differences, h = 1e-6: truncation ~h^2 |mu'''| and rounding ~eps/h ~ 1e-10.
  const double h = 1e-6;
  EXPECT_NEAR((mu_at(h, 0, 0) - mu_at(-h, 0, 0)) / (2 * h), r.dmu_dphi, 1e-7);
  EXPECT_NEAR((mu_at(0, h, 0) - mu_at(0, -h, 0)) / (2 * h), r.dmu_dx, 1e-7);
  EXPECT_NEAR((mu_at(0, 0, h) - mu_at(0, 0, -h)) / (2 * h), r.dmu_dy, 1e-7);
}

TEST(MuFromStop, SigmaAgreesWithMonteCarlo) {
  StopMeasurement m = stop_of(0.634, 14.48, 2.2);
  m.sigma_phi = deg_to_rad(0.2);
  m.sigma_pos = 0.002;
  const double sigma = mu_from_stop(m).sigma_mu;
  std::mt19937_64 rng(20261122);
  std::normal_distribution<double> n(0.0, 1.0);
  constexpr int N = 40000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < N; ++i) {
    StopMeasurement q = m;
    q.phi += m.sigma_phi * n(rng);
    q.x_stop += m.sigma_pos * n(rng);
    q.y_stop += m.sigma_pos * n(rng);
    const double mu = mu_from_stop(q).mu;
    sum += mu;
    sum2 += mu * mu;
  }
  const double mean = sum / N, sd = std::sqrt((sum2 - N * mean * mean) / (N - 1));
  // The sample standard deviation has relative standard error 1/sqrt(2(N-1)) = 0.35%;
  // 4 of those (1.4%) plus ~0.5% for the curvature of mu(x, y, phi) at these sigmas
  // (sigma_pos/|y_stop| ~ 2%) gives 2%.
  EXPECT_NEAR(sd / sigma, 1, 0.02) << "Monte Carlo " << sd << " vs analytic " << sigma;
}

TEST(BestAngle, InteriorMinimumWhenOnlyTheAngleIsUncertain) {
  // sigma_mu = mu sigma_phi / (sin phi cos phi) = 2 mu sigma_phi / sin(2 phi): minimum at
  // 45 deg, inside (0, atan 1.5 = 56.3 deg). Brent with 40 bits: |phi - pi/4| < 1e-6.
  const AngleAdvice a = best_angle(1.5, 2.0, SetupConstraint::launch_speed, 0.01, 0.0,
                                   INFINITY);
  EXPECT_NEAR(a.phi, M_PI / 4, 1e-6);
  EXPECT_FALSE(a.at_boundary);
  EXPECT_NEAR(a.sigma_mu, 2 * 1.5 * 0.01, 1e-9);
}

TEST(BestAngle, SteepestAngleThatStopsOnThePlate) {
  // For mu < 1 sigma_mu falls all the way to atan(mu); with a plate of 1 m the best angle is
  // where the stop distance reaches 1 m.
  const AngleAdvice a = best_angle(0.634, 2.6, SetupConstraint::launch_speed, deg_to_rad(0.2),
                                   0.005, 1.0);
  EXPECT_TRUE(a.at_boundary);
  EXPECT_NEAR(std::hypot(a.x_stop, a.y_stop), 1.0, 1e-9);
  EXPECT_LT(a.phi, std::atan(0.634));
  EXPECT_LT(a.sigma_mu, stop_method_sigma_mu(0.634, 0.9 * a.phi, 2.6, deg_to_rad(0.2), 0.005));
  EXPECT_THROW(best_angle(0.634, 2.6, SetupConstraint::launch_speed, 0.0, 0.0, 1.0), InputError);
}

}  // namespace
}  // namespace tribolab::incline
