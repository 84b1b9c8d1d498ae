// docs/theory.md#plausibility-checks ("wild frames").
#include "analysis/bounce_glitch.hpp"

#include "numerics/polyfit.hpp"
#include "track/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace tribolab::analysis {
namespace {

/// The frames of points [begin, end) of `centre` that one free flight leaves out when it fits
/// the others (iterated: refit without the points beyond `limit`, 4 rounds), or empty when
/// the frames are not a glitch: one flight must fit the kept points to the noise, keep
/// at least 5 on each side of the wild ones, and leave out at most 10 and a fifth of them.
std::vector<std::size_t> glitch_in(const track::Track& centre, std::size_t begin, std::size_t end, double limit,
                                   double noise, double& worst) {
  std::vector<bool> keep(end - begin, true);
  std::vector<double> dist(end - begin, 0);
  for (int round = 0; round < 4; ++round) {
    std::vector<double> t, x, y;
    for (std::size_t i = begin; i < end; ++i)
      if (keep[i - begin]) t.push_back(centre.points[i].t), x.push_back(centre.points[i].x), y.push_back(centre.points[i].y);
    if (t.size() < 8) return {};
    const auto fx = numerics::fit_polynomial(t, x, 2, "x(t)");
    const auto fy = numerics::fit_polynomial(t, y, 2, "y(t)");
    bool changed = false;
    for (std::size_t i = begin; i < end; ++i) {
      const auto& p = centre.points[i];
      dist[i - begin] = std::hypot(p.x - fx(p.t), p.y - fy(p.t));
      const bool k = dist[i - begin] <= limit;
      changed |= k != keep[i - begin];
      keep[i - begin] = k;
    }
    if (!changed) break;
  }
  std::vector<std::size_t> wild;
  double rss = 0;
  std::size_t n_keep = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if (keep[i - begin]) {
      rss += dist[i - begin] * dist[i - begin];
      ++n_keep;
    } else {
      wild.push_back(i);
    }
  }
  if (wild.empty() || wild.size() > 10 || 5 * wild.size() > end - begin || n_keep < 8) return {};
  const auto before = static_cast<std::size_t>(std::count(keep.begin(), keep.begin() + static_cast<std::ptrdiff_t>(wild.front() - begin), true));
  const auto after = static_cast<std::size_t>(std::count(keep.begin() + static_cast<std::ptrdiff_t>(wild.back() - begin), keep.end(), true));
  // One flight on both sides, at the noise (2-D rms of the centre: sqrt 2 x the per-axis noise,
  // doubled, plus 1 mm for drag and a slight tilt).
  if (before < 5 || after < 5 || std::sqrt(rss / static_cast<double>(n_keep)) > 2 * std::sqrt(2.0) * noise + 1e-3) return {};
  for (std::size_t i : wild) worst = std::max(worst, dist[i - begin]);
  return wild;
}

}  // namespace

Glitches drop_glitches(track::Track& a, track::Track& b, const track::ImpactOptions& options) {
  Glitches out;
  for (int round = 0; round < 10; ++round) {
    const track::Track centre = track::centre_track(track::rigid_body_from_points(a, b));
    track::ImpactOptions any_jump = options;
    any_jump.veto_smooth_turning = false;  // a glitch out and back is smooth to no motion model
    const auto found = track::detect_impacts(centre, any_jump);
    const double noise = std::max({found.noise_x, found.noise_y, 1e-6});
    const double limit = 8 * noise + 2e-3;  // as the wild-frame warning (bounce_plausibility.cpp)
    const auto segs = track::flight_segments(centre.points.size(), found.impacts);
    std::set<int> frames;
    for (std::size_t k = 0; k + 1 < segs.size() && frames.empty(); ++k) {
      // The flights on both sides of impact k (and of k + 1: a glitch of a few frames is often
      // seen as two impacts, out and back).
      for (std::size_t span = 2; span <= 3 && frames.empty() && k + span <= segs.size(); ++span) {
        for (std::size_t i : glitch_in(centre, segs[k].begin, segs[k + span - 1].end, limit, noise, out.worst)) {
          frames.insert(centre.points[i].frame);
          out.times.push_back(centre.points[i].t);
        }
      }
    }
    if (frames.empty()) break;
    for (auto* tr : {&a, &b})
      std::erase_if(tr->points, [&](const track::TrackPoint& p) { return frames.count(p.frame) > 0; });
  }
  std::sort(out.times.begin(), out.times.end());
  return out;
}

}  // namespace tribolab::analysis
