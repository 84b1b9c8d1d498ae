// Linear least squares for polynomials y = c0 + c1 x + ... + cd x^d, with the covariance of
// the coefficients, R^2 and the residual noise. Used for the seeds' trend lines (x–t lines,
// y–t parabolas, v–t slopes, a_N against sin(theta)). Solved by column-pivoted Householder QR
// (Eigen), never by the normal equations. See docs/theory.md#fitting.
#pragma once

#include <Eigen/Dense>

#include <span>
#include <string>
#include <vector>

namespace tribolab::numerics {

struct PolyFit {
  std::vector<double> coef;    ///< c0..cd, in the units of y / x^k
  std::vector<double> sigma;   ///< standard errors of coef (noise estimated from residuals)
  Eigen::MatrixXd covariance;  ///< (d+1) x (d+1)
  double r_squared = 0.0;      ///< coefficient of determination (as Excel's trend line)
  double rms = 0.0;            ///< sqrt(sum r^2 / n)
  double noise = 0.0;          ///< sqrt(sum r^2 / (n - d - 1)), estimated y noise
  int n = 0;                   ///< points used
  int dof = 0;                 ///< n - d - 1

  double operator()(double x) const;
  /// Half-width of the two-sided interval at `level` for coefficient k (Student t, dof).
  double ci_half_width(int k, double level = 0.95) const;
};

/// Widens `f`'s covariance by `factor` (its sigmas by the square root), as
/// numerics::widen_for_serial_correlation does a least-squares fit's; a factor of at most 1
/// leaves it as it is (docs/theory.md#fitting, "Serially correlated residuals").
void widen_for_serial_correlation(PolyFit& f, double factor);

/// Fits a polynomial of `degree` to (x, y). Throws InputError when fewer than degree + 2
/// points are given (no noise estimate) or when the x values cannot determine the
/// coefficients (e.g. all equal). `what` names the data in the message.
PolyFit fit_polynomial(std::span<const double> x, std::span<const double> y, int degree,
                       const std::string& what = "data");

/// The coefficients c0..c_degree of the least-squares polynomial through (x, y) alone, with no
/// statistics and as few as degree + 1 points (an exact fit): for the short fits a tracker's
/// motion model makes every frame (a parabola through the last centres). x must hold at least
/// degree + 1 values; with fewer distinct ones the solution is one of the least-squares ones.
std::vector<double> least_squares_polynomial(std::span<const double> x, std::span<const double> y, int degree);

}  // namespace tribolab::numerics
