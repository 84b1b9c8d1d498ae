// Statistics over a series of runs (docs/theory.md#series-of-runs): the inverse-variance
// weighted mean of one quantity measured by every run, with the chi-square test of whether the
// runs agree within their uncertainties, and a line through the origin fitted to one quantity
// against another (the seed's stop-point scalings, figure 八).
#pragma once

#include <span>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// Inverse-variance weighted mean of values x_i with standard uncertainties s_i:
///   w_i = 1/s_i^2,  mean = sum w_i x_i / sum w_i,  sigma = 1/sqrt(sum w_i),
///   chi2 = sum w_i (x_i - mean)^2  with dof = n - 1,  p_value = P(chi2_dof > chi2).
/// sigma is the mean's standard error when the s_i are right; a small p_value says they are
/// not (the runs scatter more than their errors allow, e.g. mu differs between discs).
struct WeightedMean {
  double mean = 0;      ///< in the unit of x
  double sigma = 0;     ///< 1/sqrt(sum w), the unit of x
  double chi2 = 0;      ///< sum of squared pulls about the mean
  int dof = 0;          ///< n - 1
  double p_value = 0;   ///< upper tail of chi-square(dof) at chi2; NaN when dof = 0
  /// sqrt(chi2/dof) (Birge ratio); NaN when dof = 0. Near 1 when the s_i are right.
  double birge_ratio = 0;
  /// sigma * max(1, birge_ratio): the error inflated by the observed scatter (the Particle
  /// Data Group's scale factor), for when the runs disagree.
  double sigma_scaled = 0;
  int n = 0;            ///< values used
  /// Per value: (x_i - mean)/sqrt(s_i^2 - sigma^2), standard normal when the s_i are right
  /// (the variance of x_i - mean is s_i^2 - sigma^2 because x_i is part of the mean).
  /// NaN for a single value.
  std::vector<double> pulls;
};

/// The weighted mean of x with uncertainties s. Throws InputError when there are no values,
/// the sizes differ, or a value is not finite or an uncertainty not finite and > 0.
WeightedMean weighted_mean(std::span<const double> x, std::span<const double> s);

/// y = slope x fitted by least squares (the line through the origin; the points weighted
/// equally, their scatter about the line gives the uncertainty):
///   slope = sum x y / sum x^2,  s^2 = sum (y - slope x)^2/(n - 1),  sigma = s/sqrt(sum x^2),
/// interval: slope +- t_{n-1} sigma at `level`.
struct ProportionalFit {
  double slope = 0;      ///< unit of y / unit of x
  double sigma = 0;      ///< standard error of slope
  double ci_low = 0, ci_high = 0;  ///< interval at `level`
  double rms = 0;        ///< sqrt(sum (y - slope x)^2 / n), unit of y
  int n = 0;             ///< points
};

/// Fits y = slope x. Throws InputError with fewer than 2 points, sizes that differ, non-finite
/// values or all x zero; `what` names the data in the message.
ProportionalFit fit_proportional(std::span<const double> x, std::span<const double> y, double level = 0.95,
                                 const std::string& what = "data");

/// Upper tail P(X > chi2) of the chi-square distribution with dof degrees of freedom
/// (Boost.Math); NaN for dof <= 0.
double chi2_upper_tail(double chi2, int dof);

}  // namespace tribolab::analysis
