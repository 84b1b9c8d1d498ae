#include "analysis/series_stats.hpp"

#include "numerics/error.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <limits>

namespace tribolab::analysis {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double chi2_upper_tail(double chi2, int dof) {
  if (dof <= 0 || !std::isfinite(chi2)) return kNaN;
  if (chi2 <= 0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), chi2));
}

WeightedMean weighted_mean(std::span<const double> x, std::span<const double> s) {
  if (x.empty()) throw InputError("weighted mean: no values");
  if (x.size() != s.size())
    throw InputError("weighted mean: " + std::to_string(x.size()) + " values but " + std::to_string(s.size()) +
                     " uncertainties");
  double sw = 0, swx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw InputError("weighted mean: value " + std::to_string(i + 1) + " is not finite");
    if (!(std::isfinite(s[i]) && s[i] > 0))
      throw InputError("weighted mean: uncertainty " + std::to_string(i + 1) + " must be finite and > 0");
    const double w = 1.0 / (s[i] * s[i]);
    sw += w;
    swx += w * x[i];
  }
  WeightedMean r;
  r.n = static_cast<int>(x.size());
  r.mean = swx / sw;
  r.sigma = 1.0 / std::sqrt(sw);
  r.dof = r.n - 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - r.mean;
    r.chi2 += d * d / (s[i] * s[i]);
    const double var = s[i] * s[i] - r.sigma * r.sigma;  // var(x_i - mean) >= 0
    r.pulls.push_back(r.n > 1 && var > 0 ? d / std::sqrt(var) : kNaN);
  }
  r.p_value = chi2_upper_tail(r.chi2, r.dof);
  r.birge_ratio = r.dof > 0 ? std::sqrt(r.chi2 / r.dof) : kNaN;
  r.sigma_scaled = r.dof > 0 ? r.sigma * std::max(1.0, r.birge_ratio) : r.sigma;
  return r;
}

ProportionalFit fit_proportional(std::span<const double> x, std::span<const double> y, double level,
                                 const std::string& what) {
  if (x.size() != y.size())
    throw InputError(what + ": " + std::to_string(x.size()) + " x values but " + std::to_string(y.size()) + " y values");
  if (x.size() < 2) throw InputError(what + ": a line through the origin needs at least 2 points, got " +
                                     std::to_string(x.size()));
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) throw InputError(what + ": point " + std::to_string(i + 1) + " is not finite");
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  if (!(sxx > 0)) throw InputError(what + ": every x is zero");
  ProportionalFit f;
  f.n = static_cast<int>(x.size());
  f.slope = sxy / sxx;
  double rss = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - f.slope * x[i];
    rss += r * r;
  }
  f.rms = std::sqrt(rss / f.n);
  f.sigma = std::sqrt(rss / (f.n - 1) / sxx);
  const double t = boost::math::quantile(boost::math::complement(boost::math::students_t(f.n - 1), (1 - level) / 2));
  f.ci_low = f.slope - t * f.sigma;
  f.ci_high = f.slope + t * f.sigma;
  return f;
}

}  // namespace tribolab::analysis
