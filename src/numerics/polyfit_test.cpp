// Polynomial least squares (numerics/polyfit.hpp): exact polynomials recovered, and the
// conditioning of fits over short spans of x.
#include "numerics/polyfit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tribolab::numerics {
namespace {

/// y = 1 + 2 x - 3 x^2 + 4 x^3 - 5 x^4 at n points spaced h, centred on 0, with a small
/// alternating perturbation so that the residuals (and sigmas) are not all zero.
PolyFit quartic_over(double h, int n) {
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = (i - (n - 1) / 2.0) * h;
    const double t = x[i];
    y[i] = 1 + 2 * t - 3 * t * t + 4 * t * t * t - 5 * t * t * t * t + ((i % 2) ? 1e-9 : -1e-9);
  }
  return fit_polynomial(x, y, 4, "local fit");
}

// Regression (issue 26): a valid 50 kHz run was refused ("local fit: the x values cannot
// determine a degree-4 fit"): 25 frames span |x| <= 2.4e-4 s, x^4 <= 3.3e-15, and QR's rank
// test on the raw powers took the columns for dependent. Fitting in x / max|x| keeps them
// apart; the coefficients are scaled back.
TEST(Polyfit, QuarticOverTwentyFiveFramesAt50kHzIsDetermined) {
  const PolyFit f = quartic_over(2e-5, 25);
  ASSERT_EQ(f.coef.size(), 5u);
  // c0 and c1 carry the signal over such a span; 1e-9 of perturbation over a lever of
  // 2.4e-4 s moves c1 by at most ~1e-9 / 2.4e-4 = 4e-6.
  EXPECT_NEAR(f.coef[0], 1, 1e-8);
  EXPECT_NEAR(f.coef[1], 2, 1e-4);
  for (double s : f.sigma) EXPECT_TRUE(std::isfinite(s));
}

TEST(Polyfit, ScalingKeepsCoefficientsAndCovarianceInTheUnitsOfX) {
  // The same quartic on a span of 2: every coefficient recovered (perturbation 1e-9).
  const PolyFit f = quartic_over(1.0 / 12, 25);
  const double want[] = {1, 2, -3, 4, -5};
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(f.coef[k], want[k], 1e-6) << k;
  for (int k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(f.sigma[k], std::sqrt(f.covariance(k, k))) << k;
  EXPECT_NEAR(f(0.5), 1 + 1 - 0.75 + 0.5 - 0.3125, 1e-8);
}

TEST(Polyfit, LeastSquaresPolynomialAloneFitsExactlyAndAgreesWithTheFullFit) {
  // Three points give the parabola through them (fit_polynomial needs one more, for its noise).
  const std::vector<double> t{-2, -1, 0}, y{7, 3, 1};  // 1 - t + t^2
  const std::vector<double> c = least_squares_polynomial(t, y, 2);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0], 1, 1e-12);
  EXPECT_NEAR(c[1], -1, 1e-12);
  EXPECT_NEAR(c[2], 1, 1e-12);
  // Over more points it is the same least-squares solution as the fit with statistics.
  const std::vector<double> s{-7, -6, -5, -4, -3, -2, -1, 0}, v{3.1, 2.2, 1.6, 0.9, 0.5, 0.4, 0.2, 0.3};
  const std::vector<double> d = least_squares_polynomial(s, v, 2);
  const PolyFit f = fit_polynomial(s, v, 2);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[static_cast<std::size_t>(k)], f.coef[static_cast<std::size_t>(k)], 1e-12);
}

}  // namespace
}  // namespace tribolab::numerics
