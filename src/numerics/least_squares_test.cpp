#include "numerics/least_squares.hpp"
#include "numerics/polyfit.hpp"

#include "numerics/coverage_test_util.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>

namespace tribolab::numerics {
namespace {

// y = A exp(-t / tau) + c sampled at 50 points with Gaussian noise.
struct DecayData {
  std::vector<double> t, y;
  DecayData(double A, double tau, double c, double noise, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, noise);
    for (int i = 0; i < 50; ++i) {
      t.push_back(0.1 * i);
      y.push_back(A * std::exp(-t.back() / tau) + c + n(rng));
    }
  }
};

struct DecayResidual {
  const DecayData* d;
  template <class T>
  bool operator()(const T* p, T* r) const {
    for (std::size_t i = 0; i < d->t.size(); ++i) {
      r[i] = p[0] * exp(-T(d->t[i]) / p[1]) + p[2] - T(d->y[i]);
    }
    return true;
  }
};

FitParameter param(const char* name, double initial) {
  FitParameter p;
  p.name = name;
  p.initial = initial;
  return p;
}

std::vector<FitParameter> decay_start() {
  std::vector<FitParameter> p{param("A", 1.0), param("tau", 1.0), param("c", 0.0)};
  p[1].lower = 0.01;
  return p;
}

TEST(LeastSquares, RecoversNoiseFreeParametersExactly) {
  const DecayData d(2.0, 0.7, 0.3, 0.0, 1);
  const FitResult r = fit_least_squares_autodiff(DecayResidual{&d}, 50, decay_start());
  ASSERT_TRUE(r.ok()) << r.message;
  // Noise-free data: the optimum is exact up to the solver's tolerances (1e-12 relative).
  EXPECT_NEAR(r.value("A"), 2.0, 1e-9);
  EXPECT_NEAR(r.value("tau"), 0.7, 1e-9);
  EXPECT_NEAR(r.value("c"), 0.3, 1e-9);
}

TEST(LeastSquares, NumericAndAutomaticDerivativesAgree) {
  const DecayData d(2.0, 0.7, 0.3, 0.01, 2);
  const DecayResidual f{&d};
  const FitResult a = fit_least_squares_autodiff(f, 50, decay_start());
  const FitResult n = fit_least_squares([&](const double* p, double* r) { return f(p, r); }, 50,
                                        decay_start());
  ASSERT_TRUE(a.ok() && n.ok());
  for (int i = 0; i < 3; ++i) {
    // Same minimum; central differences give Jacobians good to ~1e-8 relative.
    EXPECT_NEAR(a.values[i], n.values[i], 1e-7 * (1 + std::abs(a.values[i])));
    EXPECT_NEAR(a.sigma[i], n.sigma[i], 1e-4 * a.sigma[i]);
  }
}

TEST(LeastSquares, ConfidenceIntervalsCoverTheTruthNinetyFivePercent) {
  // 400 independent noisy data sets; the 95% interval of tau must contain the truth in
  // 95% of them. Binomial sd = sqrt(400 * .95 * .05) = 4.4 runs: accept 380 +- 3 sd.
  int covered = 0;
  const int runs = 400;
  for (int s = 0; s < runs; ++s) {
    const DecayData d(2.0, 0.7, 0.3, 0.05, 100 + s);
    const FitResult r = fit_least_squares_autodiff(DecayResidual{&d}, 50, decay_start());
    ASSERT_TRUE(r.ok()) << r.message;
    const std::size_t i = r.index("tau");
    covered += std::abs(r.values[i] - 0.7) <= r.ci_half_width(i, 0.95);
  }
  EXPECT_NEAR(covered, 380, 13.2) << covered << " of " << runs;
}

// A straight line y = 1 + 2 x on x in [0, 1] (50 points by default) with noise growing along x
// (sd 0.02 + 0.2 x) and, in a fraction of the points, a gross error of size 1: what Huber's
// loss (scale 0.1) and the sandwich are for.
struct LineData {
  std::vector<double> x, y;
  LineData(unsigned seed, double outlier_fraction, int points = 50) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < points; ++i) {
      x.push_back(i / (points - 1.0));
      double e = (0.02 + 0.2 * x.back()) * n(rng);
      if (u(rng) < outlier_fraction) e += u(rng) < 0.5 ? -1.0 : 1.0;
      y.push_back(1 + 2 * x.back() + e);
    }
  }
};

struct LineResidual {
  const LineData* d;
  template <class T>
  bool operator()(const T* p, T* r) const {
    for (std::size_t i = 0; i < d->x.size(); ++i) r[i] = p[0] + p[1] * T(d->x[i]) - T(d->y[i]);
    return true;
  }
};

FitOptions huber_sandwich() {
  FitOptions o;
  o.loss = RobustLoss::huber;
  o.loss_scale = 0.1;
  o.covariance = Covariance::sandwich;
  return o;
}

TEST(LeastSquares, RobustLossActsOnEveryResidual) {
  // One point of 50 off by 100: Huber's loss bounds its pull (the slope moves by about
  // c / sum (x - xbar)^2 ~ 0.02), least squares is dragged by ~100 x 0.05 / 4 ~ 1. Before the
  // loss was applied per residual it acted on the whole block's sum of squares, a monotone
  // transform with the least-squares minimiser.
  LineData d(3, 0.0);
  d.y[49] += 100;
  FitOptions o = huber_sandwich();
  const FitResult h = fit_least_squares_autodiff(LineResidual{&d}, 50, {param("a", 0), param("b", 0)}, o);
  o.loss = RobustLoss::none;
  const FitResult ls = fit_least_squares_autodiff(LineResidual{&d}, 50, {param("a", 0), param("b", 0)}, o);
  ASSERT_TRUE(h.ok() && ls.ok());
  EXPECT_NEAR(h.values[1], 2, 0.1);  // noise sd <= 0.22: slope sd ~0.03, plus the bounded pull
  EXPECT_GT(std::abs(ls.values[1] - 2), 1.0);
  // The cost reported is the least-squares one of the raw residuals (documented).
  double ss = 0;
  for (double r : h.residuals) ss += r * r;
  EXPECT_DOUBLE_EQ(h.cost, 0.5 * ss);
}

TEST(LeastSquares, SandwichIsHubersFormula) {
  // The documented formula written out for a line (exact Jacobian rows (1, x_i)): Huber's
  // loss with scale c gives rho' = 1, rho'' = 0 inside, rho' = c/|r|, rho' + 2 rho'' r^2 = 0
  // outside, so H = sum_inliers J^T J, B = sum min(|r|, c)^2 J^T J, Cov = N/(N-2) H^-1 B H^-1.
  const LineData d(7, 0.1);
  const FitOptions o = huber_sandwich();
  const FitResult r = fit_least_squares_autodiff(LineResidual{&d}, 50, {param("a", 0), param("b", 0)}, o);
  ASSERT_TRUE(r.ok()) << r.message;
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero(), B = H;
  int outliers = 0;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d j(1.0, d.x[i]);
    const double res = r.residuals[i];
    if (std::abs(res) <= o.loss_scale) {
      H += j * j.transpose();
    } else {
      ++outliers;
    }
    const double psi = std::min(std::abs(res), o.loss_scale);
    B += psi * psi * j * j.transpose();
  }
  ASSERT_GT(outliers, 0);
  const Eigen::Matrix2d C = (50.0 / 48.0) * H.inverse() * B * H.inverse();
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      // Same numbers up to rounding (both evaluate the same sums; 1e-9 relative).
      EXPECT_NEAR(r.covariance(a, b), C(a, b), 1e-9 * std::abs(C(a, a))) << a << b;
    }
  }
}

// The sandwich is an asymptotic estimator: with many points per data set (400) its slope
// interval covers under unequal noise and 10% outliers, where s^2 (J~^T J~)^-1 (counting the
// outliers at full size) is far too wide and Huber's scalar form (one noise level) too narrow.
// 200 data sets; Binomial(200, 0.95): mean 190, sd 3.1; accepted 181..199 (3 sd). The
// sanitizer tree fits the first 40: at least binomial_floor(40, 0.95) = 33 covering (P(X < 33)
// = 7.1e-4); an interval of half the true sigma (coverage 0.67) passes with probability 0.026.
TEST(LeastSquares, SandwichIntervalsCoverWithUnequalNoiseAndOutliers) {
  int covered = 0, covered_gn = 0, covered_h = 0;
  const int runs = study_draws(200, 40), points = 400;
  const std::vector<FitParameter> start{param("a", 0), param("b", 0)};
  for (int s = 0; s < runs; ++s) {
    const LineData d(1000 + s, 0.1, points);
    FitOptions o = huber_sandwich();
    const FitResult r = fit_least_squares_autodiff(LineResidual{&d}, points, start, o);
    ASSERT_TRUE(r.ok()) << r.message;
    covered += std::abs(r.values[1] - 2) <= r.ci_half_width(1);
    o.covariance = Covariance::gauss_newton;
    const FitResult g = fit_least_squares_autodiff(LineResidual{&d}, points, start, o);
    covered_gn += std::abs(g.values[1] - 2) <= g.ci_half_width(1);
    o.covariance = Covariance::huber;
    const FitResult h = fit_least_squares_autodiff(LineResidual{&d}, points, start, o);
    covered_h += std::abs(h.values[1] - 2) <= h.ci_half_width(1);
  }
  std::cout << "slope coverage over " << runs << " data sets of " << points << " points: sandwich " << covered
            << ", gauss_newton " << covered_gn << ", huber " << covered_h << "\n";
  if (is_full_study(runs, 200)) {
    EXPECT_NEAR(covered, 190, 9.3);
  } else {
    EXPECT_GE(covered, binomial_floor(runs, 0.95));
  }
}

TEST(LeastSquares, FixedParameterStaysAndHasNoSigma) {
  const DecayData d(2.0, 0.7, 0.3, 0.01, 3);
  auto params = decay_start();
  params[2].initial = 0.3;
  params[2].fixed = true;
  const FitResult r = fit_least_squares_autodiff(DecayResidual{&d}, 50, params);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.value("c"), 0.3);
  EXPECT_EQ(r.sigma_of("c"), 0.0);
  EXPECT_EQ(r.dof, 48);
}

TEST(LeastSquares, UnidentifiableParametersAreReported) {
  // y = (a * b) t: only the product is determined by the data.
  const std::vector<double> t{0, 1, 2, 3}, y{0, 2, 4, 6};
  const FitResult r = fit_least_squares(
      [&](const double* p, double* res) {
        for (int i = 0; i < 4; ++i) res[i] = p[0] * p[1] * t[i] - y[i];
        return true;
      },
      4, {param("a", 1.0), param("b", 1.5)});
  EXPECT_EQ(r.status, FitStatus::not_identifiable) << r.message;
}

TEST(LeastSquares, TooFewPointsIsReported) {
  const FitResult r = fit_least_squares(
      [](const double* p, double* res) {
        res[0] = p[0] + p[1];
        return true;
      },
      1, {param("a", 1.0), param("b", 1.0)});
  EXPECT_EQ(r.status, FitStatus::too_few_points);
}

TEST(PolyFit, ExactOnPolynomialData) {
  std::vector<double> x, y;
  for (int i = 0; i < 10; ++i) {
    x.push_back(0.05 * i);
    y.push_back(0.55 + 1.06 * x.back() - 4.74 * x.back() * x.back());
  }
  const PolyFit f = fit_polynomial(x, y, 2);
  EXPECT_NEAR(f.coef[0], 0.55, 1e-12);
  EXPECT_NEAR(f.coef[1], 1.06, 1e-11);
  EXPECT_NEAR(f.coef[2], -4.74, 1e-10);
  EXPECT_NEAR(f.r_squared, 1.0, 1e-12);
}

TEST(PolyFit, StandardErrorMatchesTextbookLineFormula) {
  // For a straight line, sigma_slope = s / sqrt(sum (x - mean)^2) exactly.
  const std::vector<double> x{0, 1, 2, 3, 4, 5}, y{0.1, 0.9, 2.2, 2.8, 4.1, 5.2};
  const PolyFit f = fit_polynomial(x, y, 1);
  double mx = 2.5, sxx = 0;
  for (double v : x) sxx += (v - mx) * (v - mx);
  EXPECT_NEAR(f.sigma[1], f.noise / std::sqrt(sxx), 1e-14);
}

TEST(PolyFit, RejectsDegenerateData) {
  const std::vector<double> x{1, 1, 1, 1}, y{1, 2, 3, 4};
  EXPECT_THROW(fit_polynomial(x, y, 1), InputError);
  const std::vector<double> x2{1, 2}, y2{1, 2};
  EXPECT_THROW(fit_polynomial(x2, y2, 1), InputError);
}

// Serially correlated residuals (docs/theory.md#fitting, "Serially correlated residuals").
std::vector<double> ar1_series(double rho, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<double> e(static_cast<std::size_t>(n));
  double prev = z(rng) / std::sqrt(1 - rho * rho);
  for (double& v : e) v = prev = rho * prev + z(rng);
  return e;
}

TEST(SerialCorrelation, FactorIsTheLongRunVarianceRatio) {
  // Independent noise: about 1 (at least 1 by construction); AR(1) noise: the long-run
  // variance ratio (1 + rho) / (1 - rho), 3 at rho = 0.5 and 9 at rho = 0.8. Measured over
  // seeds 1-5 at 2000 points: 1.000-1.012, 2.49-3.08 and 6.65-9.30 (the Bartlett estimate is
  // biased low and scatters with the series).
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const double white = serial_correlation_factor({ar1_series(0.0, 2000, seed), ar1_series(0.0, 2000, seed + 100)});
    EXPECT_GE(white, 1.0);
    EXPECT_LE(white, 1.05) << "seed " << seed;
    EXPECT_NEAR(serial_correlation_factor({ar1_series(0.5, 2000, seed)}), 3.0, 0.7) << "seed " << seed;
    EXPECT_NEAR(serial_correlation_factor({ar1_series(0.8, 2000, seed)}), 9.0, 3.0) << "seed " << seed;
  }
  // Too short to estimate anything: left as it is.
  EXPECT_EQ(serial_correlation_factor({{1.0, 2.0}}), 1.0);
  EXPECT_EQ(serial_correlation_factor({}), 1.0);
}

TEST(SerialCorrelation, WidenedIntervalsCoverTheTruth) {
  // A straight line through AR(1) noise (rho 0.7): the slope's 95 % interval from the
  // independent-noise covariance covers the truth far too rarely; widened, about 95 %.
  const int runs = 300, n = 200;
  int covered = 0, covered_widened = 0;
  for (int k = 0; k < runs; ++k) {
    const std::vector<double> e = ar1_series(0.7, n, 1000 + static_cast<unsigned>(k));
    auto residuals = [&](const double* p, double* r) {
      for (int i = 0; i < n; ++i) r[i] = p[0] + p[1] * (i / double(n)) - (1.0 + 2.0 * (i / double(n)) + e[i]);
      return true;
    };
    FitResult f = fit_least_squares(residuals, n, {param("a", 0.0), param("b", 0.0)});
    ASSERT_TRUE(f.ok()) << f.message;
    covered += std::abs(f.value("b") - 2.0) <= f.ci_half_width(1) ? 1 : 0;
    widen_for_serial_correlation(f, serial_correlation_factor({f.residuals}));
    covered_widened += std::abs(f.value("b") - 2.0) <= f.ci_half_width(1) ? 1 : 0;
  }
  // Measured 164 of 300 (55 %) and, widened, 268 (89 %): the long-run variance estimated
  // from 200 points is biased low, so the widened interval still covers a little too rarely.
  std::printf("coverage of the slope's 95 %% interval: %d of %d, widened %d\n", covered, runs, covered_widened);
  EXPECT_LT(covered, 0.7 * runs);
  EXPECT_GT(covered_widened, 0.85 * runs);
}

}  // namespace
}  // namespace tribolab::numerics
