#include "track/impacts.hpp"

#include "numerics/error.hpp"
#include "track/check.hpp"
#include "track/local_fit.hpp"
#include "numerics/statistics.hpp"

#include <Eigen/Dense>
#include <boost/math/distributions/fisher_f.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tribolab::track {

std::string ImpactOptions::validate() const {
  if (window < 3) return "impact window must be at least 3 points, got " + std::to_string(window);
  if (!(threshold > 0) || !std::isfinite(threshold)) return "impact threshold must be positive";
  if (!(min_jump >= 0) || !std::isfinite(min_jump)) return "impact min_jump must be >= 0 m/s";
  if (!(min_noise >= 0) || !std::isfinite(min_noise)) return "impact min_noise must be >= 0 m";
  return "";
}

double robust_noise(const std::vector<double>& t, const std::vector<double>& v) {
  const std::size_t n = t.size();
  if (n < 4) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> z;
  z.reserve(n - 3);
  for (std::size_t i = 0; i + 3 < n; ++i) {
    // third divided difference f[t_i..t_i+3] = sum_j f_j / prod_{m != j} (t_j - t_m)
    double d = 0, norm2 = 0;
    for (std::size_t j = i; j < i + 4; ++j) {
      double w = 1;
      for (std::size_t m = i; m < i + 4; ++m) {
        if (m != j) w /= (t[j] - t[m]);
      }
      d += w * v[j];
      norm2 += w * w;
    }
    z.push_back(std::abs(d) / std::sqrt(norm2));
  }
  return kMadToSd * upper_median(std::move(z));
}

namespace {

/// Size of the F test that keeps a candidate only when smooth turning motion does not explain
/// its windows as well as two parabolas with a jump (docs/theory.md#impacts).
constexpr double kSmoothP = 1e-3;

struct SplitTest {
  double dvx = 0, dvy = 0, sig = 0, t = 0;
  double chi2_two = 0;  ///< RSS of the four parabolas (x, y on each side) in units of the noise
  std::size_t begin = 0, end = 0;  ///< the points of the two windows, [begin, end)
};

/// Residual sum of squares (in units of the noise) of the smooth turning model over points
/// [b, e): p(t) = c0 + c1 u + R(omega u) r, u = t - tm (a point on a body that translates
/// uniformly and turns uniformly: a mark on a rolling or fixed wheel, an arc of any constant
/// curvature; a parabola's arc too when omega u is small). Linear in c0, c1, r for a given
/// omega; omega is searched on a grid of 2-degree steps per frame over (-pi, pi] per frame
/// (faster is aliased) and refined by golden section; the search stops as soon as chi2 falls
/// to `enough` (the question is only whether the model fits that well). docs/theory.md#impacts.
double turning_chi2(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y,
                    std::size_t b, std::size_t e, double tm, double sx, double sy, double enough) {
  const int m = static_cast<int>(e - b);
  const double h = (t[e - 1] - t[b]) / (m - 1);  // mean frame interval, s
  Eigen::MatrixXd A(2 * m, 6);
  Eigen::VectorXd rhs(2 * m);
  const auto chi2 = [&](double omega) {
    for (int i = 0; i < m; ++i) {
      const std::size_t j = b + static_cast<std::size_t>(i);
      const double u = t[j] - tm, c = std::cos(omega * u), s = std::sin(omega * u);
      A.row(2 * i) << 1 / sx, 0, u / sx, 0, c / sx, -s / sx;
      A.row(2 * i + 1) << 0, 1 / sy, 0, u / sy, s / sy, c / sy;
      rhs(2 * i) = x[j] / sx;
      rhs(2 * i + 1) = y[j] / sy;
    }
    const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(rhs);
    return (A * coef - rhs).squaredNorm();
  };
  constexpr int steps = 90;  // 2 degrees per frame
  const double step = std::numbers::pi / h / steps;
  double best = std::numeric_limits<double>::infinity(), best_omega = 0;
  for (int i = -steps + 1; i <= steps; ++i) {
    const double c = chi2(i * step);
    if (c <= enough) return c;
    if (c < best) {
      best = c;
      best_omega = i * step;
    }
  }
  // golden section on [best - step, best + step]
  const double g = (std::sqrt(5.0) - 1) / 2;
  double lo = best_omega - step, hi = best_omega + step;
  double c1 = hi - g * (hi - lo), c2 = lo + g * (hi - lo);
  double f1 = chi2(c1), f2 = chi2(c2);
  for (int it = 0; it < 30; ++it) {
    if (f1 < f2) {
      hi = c2;
      c2 = c1;
      f2 = f1;
      c1 = hi - g * (hi - lo);
      f1 = chi2(c1);
    } else {
      lo = c1;
      c1 = c2;
      f1 = f2;
      c2 = lo + g * (hi - lo);
      f2 = chi2(c2);
    }
  }
  return std::min({best, f1, f2});
}

/// True when the smooth turning model explains the points of split `s` as well as the two
/// parabolas with a velocity jump between them: the F statistic of the two-piece model's
/// 6 extra parameters (12 against 6 + omega) does not reach its (1 - p) quantile.
bool smooth_motion_explains(const std::vector<double>& t, const std::vector<double>& x,
                            const std::vector<double>& y, const SplitTest& s, double tm, double sx, double sy,
                            double p) {
  const int numbers = 2 * static_cast<int>(s.end - s.begin);
  const int dof_two = numbers - 12, extra = 12 - 7;
  if (dof_two < 1) return false;  // too few points to judge: the jump test alone decides
  const boost::math::fisher_f dist(extra, dof_two);
  const double f_crit = boost::math::quantile(boost::math::complement(dist, p));
  // chi2_turn <= chi2_crit  <=>  F <= f_crit
  const double chi2_crit = s.chi2_two * (1 + extra * f_crit / dof_two);
  const double chi2_turn = turning_chi2(t, x, y, s.begin, s.end, tm, sx, sy, chi2_crit);
  return !(chi2_turn > chi2_crit);
}

SplitTest test_split(const std::vector<double>& t, const std::vector<double>& x,
                     const std::vector<double>& y, std::size_t k, int w, double sx, double sy) {
  const std::size_t n = t.size();
  const int nl = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(w), k + 1));
  const int nr = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(w), n - k - 1));
  const double tm = 0.5 * (t[k] + t[k + 1]);
  const std::size_t l0 = k + 1 - static_cast<std::size_t>(nl);
  const PolyFit left = fit_polynomial(&t[l0], &x[l0], &y[l0], nl, tm, 2);
  const PolyFit right = fit_polynomial(&t[k + 1], &x[k + 1], &y[k + 1], nr, tm, 2);
  SplitTest r;
  r.dvx = right.c[0][1] - left.c[0][1];
  r.dvy = right.c[1][1] - left.c[1][1];
  const double f = left.var_unit(1) + right.var_unit(1);
  r.sig = std::sqrt(r.dvx * r.dvx / (sx * sx * f) + r.dvy * r.dvy / (sy * sy * f));
  r.chi2_two = (left.rss[0] + right.rss[0]) / (sx * sx) + (left.rss[1] + right.rss[1]) / (sy * sy);
  r.begin = l0;
  r.end = k + 1 + static_cast<std::size_t>(nr);
  // contact time: where the two y parabolas meet, nearest to the midpoint; noise can push
  // the crossing slightly outside [t_k, t_k+1] (or remove it: then the closest approach), and
  // contact must lie between the two samples, so the estimate is clamped to them
  const double a = right.c[1][2] - left.c[1][2], b = right.c[1][1] - left.c[1][1],
               c = right.c[1][0] - left.c[1][0];
  std::vector<double> roots;
  if (std::abs(a) > 1e-300) {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0) roots.push_back(c / q);
      roots.push_back(q / a);
    } else {
      roots.push_back(-b / (2 * a));
    }
  } else if (b != 0) {
    roots.push_back(-c / b);
  }
  double u = 0;
  double best = std::numeric_limits<double>::infinity();
  for (double root : roots) {
    if (std::isfinite(root) && std::abs(root) < best) {
      best = std::abs(root);
      u = root;
    }
  }
  r.t = std::clamp(tm + u, t[k], t[k + 1]);
  return r;
}

}  // namespace

ImpactResult detect_impacts(const Track& track, const ImpactOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError("impacts", err);
  const std::size_t n = track.points.size();
  const TrackColumns columns = columns_of(track);
  const std::vector<double>& t = columns.t;
  const std::vector<double>& x = columns.x;
  const std::vector<double>& y = columns.y;
  ImpactResult result;
  result.noise_x = robust_noise(t, x);
  result.noise_y = robust_noise(t, y);
  if (n < 6) return result;  // three points each side is the least a parabola needs
  const double sx = std::max(result.noise_x, options.min_noise);
  const double sy = std::max(result.noise_y, options.min_noise);
  const double floor = std::max(options.min_noise, 1e-300);
  std::vector<SplitTest> tests(n);
  std::vector<bool> candidate(n, false);
  for (std::size_t k = 2; k + 4 <= n; ++k) {  // at least 3 points on each side
    tests[k] = test_split(t, x, y, k, options.window, std::max(sx, floor), std::max(sy, floor));
    const double jump = std::hypot(tests[k].dvx, tests[k].dvy);
    candidate[k] = tests[k].sig > options.threshold && jump > options.min_jump;
    // the jump test holds each side to a parabola; a smooth curve sampled coarsely (a mark on
    // a wheel turning 20+ degrees per frame) fits neither, and the extrapolated parabolas then
    // disagree by far more than the noise: no impact unless smooth turning motion fails too
    if (candidate[k] && options.veto_smooth_turning) {
      candidate[k] = !smooth_motion_explains(t, x, y, tests[k], 0.5 * (t[k] + t[k + 1]), std::max(sx, floor),
                                             std::max(sy, floor), kSmoothP);
    }
  }
  // keep the most significant split of each run of candidates closer than `window`
  std::size_t k = 0;
  while (k < n) {
    if (!candidate[k]) {
      ++k;
      continue;
    }
    std::size_t best = k, last = k;
    for (std::size_t j = k; j < n && j <= last + static_cast<std::size_t>(options.window); ++j) {
      if (!candidate[j]) continue;
      last = j;
      if (tests[j].sig > tests[best].sig) best = j;
    }
    Impact im;
    im.index = best;
    im.frame = track.points[best].frame;
    im.t = tests[best].t;
    im.dvx = tests[best].dvx;
    im.dvy = tests[best].dvy;
    im.significance = tests[best].sig;
    result.impacts.push_back(im);
    k = last + 1;
  }
  return result;
}

std::vector<Segment> flight_segments(std::size_t n, const std::vector<Impact>& impacts) {
  std::vector<Segment> out;
  std::size_t begin = 0;
  for (const Impact& im : impacts) {
    TRACK_CHECK(im.index + 1 > begin && im.index < n, "impacts out of order");
    out.push_back({begin, im.index + 1});
    begin = im.index + 1;
  }
  if (begin < n || out.empty()) out.push_back({begin, n});
  return out;
}

std::vector<Track> split_track(const Track& track, const std::vector<Impact>& impacts) {
  std::vector<Track> out;
  int i = 0;
  for (const Segment& s : flight_segments(track.points.size(), impacts)) {
    Track part;
    part.name = track.name + "#" + std::to_string(++i);
    part.points.assign(track.points.begin() + static_cast<std::ptrdiff_t>(s.begin),
                       track.points.begin() + static_cast<std::ptrdiff_t>(s.end));
    out.push_back(std::move(part));
  }
  return out;
}

}  // namespace tribolab::track
