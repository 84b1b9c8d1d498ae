// docs/theory.md#plausibility-checks.
#include "analysis/series_plausibility.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tribolab::analysis {
namespace {

std::string num(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::string disagreement_warning(const WeightedMean& m, const std::string& what,
                                 const std::vector<std::string>& outliers) {
  if (m.dof < 1 || !std::isfinite(m.p_value) || m.p_value >= kContradictionP) return {};
  std::string w = "the runs contradict each other on " + what + ": chi2 = " + num(m.chi2, 3) + " for " +
                  std::to_string(m.dof) + " degrees of freedom (p = " + num(m.p_value, 2) +
                  "), a scatter " + num(m.birge_ratio, 2) +
                  " times their stated uncertainties; the mean's sigma_scaled allows for it, but check that every run "
                  "used the same surface, ball, calibration and time scale";
  if (!outliers.empty()) {
    w += " (outliers:";
    for (std::size_t k = 0; k < outliers.size(); ++k) w += (k ? "; " : " ") + outliers[k];
    w += ")";
  }
  return w;
}

std::vector<std::string> bounce_series_warnings(const std::vector<const BounceAnalysis*>& runs,
                                                const std::vector<std::string>& files) {
  std::vector<std::string> out;
  std::vector<double> g, len;
  for (const auto* r : runs)
    if (r) g.push_back(r->gravity), len.push_back(r->body.length_mean);
  if (g.size() < 3) return out;  // a median of two cannot say which one stands apart
  const double g_med = median(g), len_med = median(len);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto* r = runs[i];
    if (!r) continue;
    // Gravity: 5 % is a frame rate 2.5 % off; 5 sd keeps noise out.
    if (std::abs(r->gravity / g_med - 1) > 0.05 && std::abs(r->gravity - g_med) > 5 * r->sigma_gravity)
      out.push_back(files[i] + ": its flights fall at g = " + num(r->gravity, 3) + " m/s^2 while the series' median is " +
                    num(g_med, 3) + ": this file's time scale (frame rate) differs from the others'; correct it "
                    "(" + field("time_scale") + " per file) before comparing the runs");
    // The ball's length: the same ball gives the same tip distance in every file; 3 % is
    // 8 mm on a 28 cm ball, far beyond the mean's noise (0.1 mm at 1 mm per tip).
    if (std::abs(r->body.length_mean / len_med - 1) > 0.03)
      out.push_back(files[i] + ": its tips are " + num(r->body.length_mean, 3) + " m apart while the series' median is " +
                    num(len_med, 3) + " m: this file's length calibration differs (or another ball was tracked); "
                    "calibrate it like the others");
  }
  return out;
}

}  // namespace tribolab::analysis
