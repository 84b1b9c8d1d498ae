#include "track/impacts.hpp"

#include "numerics/error.hpp"
#include "track/check.hpp"
#include "track/local_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  auto mid = z.begin() + static_cast<std::ptrdiff_t>(z.size() / 2);
  std::nth_element(z.begin(), mid, z.end());
  return 1.482602218505602 * *mid;  // 1 / Phi^-1(3/4): MAD -> standard deviation
}

namespace {

struct SplitTest {
  double dvx = 0, dvy = 0, sig = 0, t = 0;
};

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
  std::vector<double> t(n), x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = track.points[i].t;
    x[i] = track.points[i].x;
    y[i] = track.points[i].y;
  }
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
