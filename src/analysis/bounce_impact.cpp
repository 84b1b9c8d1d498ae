// docs/theory.md#bounce-analysis ("impact search").
#include "analysis/bounce_impact.hpp"

#include "track/local_fit.hpp"
#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tribolab::analysis::detail {

std::optional<GapImpact> find_impact_across_gap(const track::Track& centre, const track::ImpactResult& found,
                                                const track::ImpactOptions& options) {
  const std::size_t n = centre.points.size();
  const track::TrackColumns columns = track::columns_of(centre);
  const std::vector<double>& t = columns.t;
  const std::vector<double>& x = columns.x;
  const std::vector<double>& y = columns.y;
  if (n < 8) return std::nullopt;
  const double sx = std::max(found.noise_x, options.min_noise), sy = std::max(found.noise_y, options.min_noise);
  if (!(sx > 0 && sy > 0)) return std::nullopt;
  // The frame period (median): gaps of up to 0.1 s, longer than any bounce's contact.
  std::vector<double> dts;
  for (std::size_t i = 1; i < n; ++i) dts.push_back(t[i] - t[i - 1]);
  const double dt = upper_median(std::move(dts));
  const auto max_gap = static_cast<std::size_t>(std::clamp(0.1 / std::max(dt, 1e-12), 1.0, 200.0));
  // The split after point k with the outgoing fit from point b: kept in `best` when it is a
  // bounce (the centre falls before and rises after: a window reaching into the contact or
  // across the apex fails this), its velocity jump is significant and larger than min_jump,
  // and it is more significant than the best so far.
  const auto offer = [&](std::optional<GapImpact>& best, const auto& left, const auto& right, std::size_t k,
                         std::size_t b, double tm) {
    const double dvx = right.c[0][1] - left.c[0][1], dvy = right.c[1][1] - left.c[1][1];
    const double f = left.var_unit(1) + right.var_unit(1);
    const double sig = std::sqrt(dvx * dvx / (sx * sx * f) + dvy * dvy / (sy * sy * f));
    if (!(left.c[1][1] < 0 && right.c[1][1] > 0)) return;
    if (!(sig > options.threshold) || !(std::hypot(dvx, dvy) > options.min_jump)) return;
    if (best && sig <= best->impact.significance) return;
    GapImpact g;
    g.impact.index = k;
    g.impact.frame = centre.points[k].frame;
    g.impact.t = tm;
    g.impact.dvx = dvx;
    g.impact.dvy = dvy;
    g.impact.significance = sig;
    g.first_post = b;
    best = g;
  };
  // Windows of w points on each side, w doubling; then (w = 0) all the points on each side:
  // no other impact was detected, so each side is one flight.
  for (auto w = static_cast<std::size_t>(options.window);; w = 2 * w <= n ? 2 * w : 0) {
    std::optional<GapImpact> best;
    for (std::size_t k = std::max<std::size_t>(w, 4) - 1; k + 1 + std::max<std::size_t>(w, 4) <= n; ++k) {
      for (std::size_t gap = 0; gap <= max_gap && k + 1 + gap + std::max<std::size_t>(w, 4) <= n; ++gap) {
        const std::size_t b = k + 1 + gap;  // first point of the right window
        const std::size_t wl = w ? w : k + 1, wr = w ? w : n - b;
        const double tm = 0.5 * (t[k] + t[b]);
        const auto left = track::fit_polynomial(&t[k + 1 - wl], &x[k + 1 - wl], &y[k + 1 - wl], static_cast<int>(wl), tm, 2);
        const auto right = track::fit_polynomial(&t[b], &x[b], &y[b], static_cast<int>(wr), tm, 2);
        if (!left.ok || !right.ok) continue;
        offer(best, left, right, k, b, tm);
      }
    }
    if (best) return best;
    if (w == 0) break;
  }
  // Last, a short outgoing flight (a low hop ended by the next touch, or the end of the
  // video): its own parabola cannot tell its velocity from its curvature under noise, while
  // gravity is the incoming flight's. All the points on each side; the outgoing side is fitted
  // by lines through x and through y less the incoming parabola's curvature term, so its
  // velocity is measured as in analyze_bounce's short post-impact flight
  // (docs/theory.md#bounce-analysis, "short post-impact flight").
  std::optional<GapImpact> best;
  std::vector<double> y_rest(n);
  for (std::size_t k = 3; k + 1 + 4 <= n; ++k) {
    for (std::size_t gap = 0; gap <= max_gap && k + 1 + gap + 4 <= n; ++gap) {
      const std::size_t b = k + 1 + gap;
      const double tm = 0.5 * (t[k] + t[b]);
      const auto left = track::fit_polynomial(&t[0], &x[0], &y[0], static_cast<int>(k + 1), tm, 2);
      if (!left.ok) continue;
      for (std::size_t i = b; i < n; ++i) y_rest[i] = y[i] - left.c[1][2] * (t[i] - tm) * (t[i] - tm);
      const auto right = track::fit_polynomial(&t[b], &x[b], &y_rest[b], static_cast<int>(n - b), tm, 1);
      if (!right.ok) continue;
      offer(best, left, right, k, b, tm);
    }
  }
  return best;
}

}  // namespace tribolab::analysis::detail
