// docs/theory.md#plausibility-checks ("isolated outliers").
#include "track/outliers.hpp"

#include "numerics/message_number.hpp"
#include "numerics/polyfit.hpp"
#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace tribolab::track {
namespace {

constexpr int kSide = 4;            // points per one-sided quadratic
constexpr double kSds = 10;         // a normal residual beyond 10 sd: p ~ 1e-23
constexpr double kExtentShare = 0.25;  // of the 2nd..98th percentile range of the axis

/// The residual of point i against the quadratic through points [b, e), or NaN when that
/// quadratic does not fit its own points to 2 % of the residual (a wild point among them).
double residual(const Track& tr, std::size_t i, std::size_t b, std::size_t e, bool x_axis) {
  std::vector<double> tau, v;
  for (std::size_t k = b; k < e; ++k) {
    tau.push_back(tr.points[k].t - tr.points[i].t);
    v.push_back(x_axis ? tr.points[k].x : tr.points[k].y);
  }
  const numerics::PolyFit f = numerics::fit_polynomial(tau, v, 2, "outlier screen");
  const double r = (x_axis ? tr.points[i].x : tr.points[i].y) - f(0.0);
  return f.rms <= 0.02 * std::abs(r) || f.rms == 0 ? r : std::numeric_limits<double>::quiet_NaN();
}

double percentile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

std::vector<Outlier> isolated_outliers(const Track& tr) {
  const std::size_t n = tr.points.size();
  if (n < 3 * kSide) return {};
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  // Residuals of each point against the left and the right one-sided predictions, per axis.
  std::vector<double> left[2], right[2];
  for (int a = 0; a < 2; ++a) {
    left[a].assign(n, kNaN);
    right[a].assign(n, kNaN);
  }
  std::vector<char> spoiled[2];  // a side whose own points are not smooth (see residual)
  for (int a = 0; a < 2; ++a) spoiled[a].assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 2; ++a) {
      if (i >= kSide) left[a][i] = residual(tr, i, i - kSide, i, a == 0);
      if (i + kSide < n) right[a][i] = residual(tr, i, i + 1, i + 1 + kSide, a == 0);
      spoiled[a][i] = (i >= kSide && std::isnan(left[a][i])) || (i + kSide < n && std::isnan(right[a][i]));
    }
  }
  auto sd_of = [](const std::vector<double>& r) {
    std::vector<double> ok;
    for (double v : r)
      if (!std::isnan(v)) ok.push_back(v);
    return mad_sd(ok);
  };
  double sd_left[2], sd_right[2], extent[2];
  for (int a = 0; a < 2; ++a) {
    sd_left[a] = sd_of(left[a]);
    sd_right[a] = sd_of(right[a]);
    std::vector<double> v;
    for (const auto& p : tr.points) v.push_back(a == 0 ? p.x : p.y);
    extent[a] = percentile(v, 0.98) - percentile(v, 0.02);
  }
  std::vector<Outlier> out;
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<Outlier> worst;
    double worst_off = 0;
    for (int a = 0; a < 2; ++a) {
      const double bound = kExtentShare * extent[a];
      if (spoiled[a][i]) continue;
      const double l = left[a][i], r = right[a][i];
      auto off = [&](double res, double sd) { return std::abs(res) > std::max(kSds * sd, bound); };
      bool is_out = false;
      if (!std::isnan(l) && !std::isnan(r)) {
        // Both sides miss it, and agree with each other far better than with it (neighbours
        // that are wild too pull one side's prediction: not an isolated outlier).
        is_out = off(l, sd_left[a]) && off(r, sd_right[a]) && (l > 0) == (r > 0) &&
                 std::abs(l - r) < 0.5 * std::min(std::abs(l), std::abs(r));
      } else if (!std::isnan(l)) {
        is_out = off(l, sd_left[a]);
      } else if (!std::isnan(r)) {
        is_out = off(r, sd_right[a]);
      }
      if (!is_out) continue;
      const double v = a == 0 ? tr.points[i].x : tr.points[i].y;
      const double res = std::isnan(l) ? r : std::isnan(r) ? l : 0.5 * (l + r);
      if (!worst || std::abs(res) > worst_off) {
        worst_off = std::abs(res);
        worst = Outlier{i, a == 0 ? 'x' : 'y', v, v - res,
                        std::max(std::isnan(l) ? 0 : sd_left[a], std::isnan(r) ? 0 : sd_right[a])};
      }
    }
    if (worst) out.push_back(*worst);
  }
  // A point next to an outlier is predicted from it and may look off too; only points whose
  // neighbours are not themselves off count (an isolated outlier, the screen's scope).
  std::vector<Outlier> isolated;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const bool near_prev = k > 0 && out[k].index - out[k - 1].index <= kSide;
    const bool near_next = k + 1 < out.size() && out[k + 1].index - out[k].index <= kSide;
    if (!near_prev && !near_next) isolated.push_back(out[k]);
  }
  return isolated;
}

Track without(const Track& track, const std::vector<Outlier>& outliers) {
  Track t;
  t.name = track.name;
  std::size_t k = 0;
  for (std::size_t i = 0; i < track.points.size(); ++i) {
    if (k < outliers.size() && outliers[k].index == i) {
      ++k;
      continue;
    }
    t.points.push_back(track.points[i]);
  }
  return t;
}

std::string outlier_warning(const Track& track, const Outlier& o) {
  const TrackPoint& p = track.points[o.index];
  return "track '" + track.name + "' frame " + std::to_string(p.frame) + " (t = " + message_number(p.t) +
         " s): " + o.axis + " = " + message_number(o.value) + " m lies far off the motion of its neighbours, " +
         "which give " + message_number(o.expected) + " m there (noise " + message_number(o.noise) +
         " m): left out as a typo, a lost decimal point or a tracking glitch; correct or delete that point";
}

}  // namespace tribolab::track
