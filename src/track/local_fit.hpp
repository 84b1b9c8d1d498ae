// Ordinary least-squares polynomial fits on a few points, the building block of the
// Savitzky–Golay derivatives, the impact detector and the spin-rate fits.
//
// The polynomial is written in powers of (t - t0): p(t) = sum_k c_k (t - t0)^k, so c_1 and
// 2 c_2 are the first and second derivatives at t0. Internally the abscissa is scaled by the
// half-span of the window so the normal equations stay well conditioned for any time unit.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tribolab::track {

/// Result of fitting one or more ordinates against the same abscissae.
struct PolyFit {
  int order = 0;                        ///< polynomial degree P
  int points = 0;                       ///< n, number of points used
  std::vector<std::vector<double>> c;   ///< c[j][k]: coefficient k of ordinate j
  std::vector<double> rss;              ///< residual sum of squares of ordinate j
  /// (A^T A)^{-1} diagonal in the (t - t0)^k basis: var(c_k) = sigma^2 * cov_unit[k].
  std::vector<double> cov_unit;
  /// Full (A^T A)^{-1}, row-major (P+1)x(P+1), same basis.
  std::vector<double> cov_unit_full;
  int dof() const { return points - (order + 1); }
  /// Value of the fitted polynomial j at t (t0 is the expansion point of the fit).
  double value(std::size_t j, double t, double t0) const;
  /// First derivative of polynomial j at t.
  double slope(std::size_t j, double t, double t0) const;
};

/// Fits polynomials of degree `order` to the ordinates ys[j][0..n) against t[0..n), expanded
/// about t0. Requires n >= order + 1 distinct abscissae (asserted).
PolyFit fit_polynomial(const double* t, const std::vector<const double*>& ys, int n, double t0,
                       int order);

/// Variance factor of a linear functional g^T c of the coefficients: g^T (A^T A)^{-1} g.
double variance_factor(const PolyFit& fit, const std::vector<double>& g);

}  // namespace tribolab::track
