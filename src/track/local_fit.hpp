// Ordinary least-squares polynomial fits on a few points, the building block of the
// Savitzky–Golay derivatives and the impact detector (docs/theory.md#kinematics).
//
// The polynomial is written in powers of (t - t0): p(t) = sum_k c_k (t - t0)^k, so c_1 and
// 2 c_2 are the first and second derivatives at t0. Internally the abscissa is scaled by the
// half-span of the window so the normal equations stay well conditioned for any time unit;
// they are solved by Cholesky on the stack (no allocation: this runs once per point).
#pragma once

#include <array>
#include <cstddef>

namespace tribolab::track {

constexpr int kMaxFitOrder = 6;
constexpr int kMaxFitTerms = kMaxFitOrder + 1;

/// Result of fitting one or two ordinates against the same abscissae.
struct PolyFit {
  bool ok = false;  ///< false when the abscissae are too clustered for this degree (all NaN)
  int order = 0;   ///< polynomial degree P
  int points = 0;  ///< n, number of points used
  std::array<std::array<double, kMaxFitTerms>, 2> c{};  ///< c[j][k]: coefficient k of ordinate j
  std::array<double, 2> rss{};                          ///< residual sum of squares of ordinate j
  /// (A^T A)^{-1} in the (t - t0)^k basis, row-major with stride kMaxFitTerms:
  /// cov(c_k, c_l) = sigma^2 * cov_unit[k * kMaxFitTerms + l].
  std::array<double, kMaxFitTerms * kMaxFitTerms> cov_unit{};
  int dof() const { return points - (order + 1); }
  /// var(c_k) / sigma^2.
  double var_unit(int k) const { return cov_unit[static_cast<std::size_t>(k * kMaxFitTerms + k)]; }
  /// Value of the fitted polynomial j at t (t0 is the expansion point of the fit).
  double value(std::size_t j, double t, double t0) const;
};

/// Fits polynomials of degree `order` (<= kMaxFitOrder) to y0[0..n) and, when y1 is not null,
/// y1[0..n), against t[0..n), expanded about t0. Requires n >= order + 1 (checked: an
/// internal error otherwise). When the normal equations are numerically singular (abscissae
/// clustered far below the window's span) the result has ok = false and NaN coefficients.
PolyFit fit_polynomial(const double* t, const double* y0, const double* y1, int n, double t0,
                       int order);

}  // namespace tribolab::track
