#include "track/kinematics.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "track/check.hpp"
#include "track/local_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::track {

const char* to_string(DerivativeMethod m) {
  return m == DerivativeMethod::tracker ? "tracker" : "savgol";
}

std::string KinematicsOptions::validate() const {
  if (method == DerivativeMethod::savgol) {
    if (order < 1 || order > 6) return field("order") + " must be 1..6, got " + std::to_string(order);
    if (window < order + 2) {
      return field("window") + " must be at least order + 2 = " + std::to_string(order + 2) + ", got " +
             std::to_string(window);
    }
    if (window > 1001) return field("window") + " must be at most 1001, got " + std::to_string(window);
  }
  if (split_at_impacts) return impacts.validate();
  return "";
}

namespace {

void tracker_stencils(const Track& track, const Segment& s, int step,
                      std::vector<KinematicsRow>& rows) {
  const auto& p = track.points;
  // consecutive(i, j): points i..j are all in the segment and one frame step apart
  auto consecutive = [&](std::size_t lo, std::size_t hi) {
    if (lo < s.begin || hi >= s.end) return false;
    for (std::size_t k = lo; k < hi; ++k) {
      if (static_cast<long long>(p[k + 1].frame) - p[k].frame != step) return false;
    }
    return true;
  };
  for (std::size_t i = s.begin; i < s.end; ++i) {
    KinematicsRow& r = rows[i];
    if (i >= 1 && consecutive(i - 1, i + 1)) {
      const double dt = p[i + 1].t - p[i - 1].t;
      r.vx = (p[i + 1].x - p[i - 1].x) / dt;
      r.vy = (p[i + 1].y - p[i - 1].y) / dt;
    }
    if (i >= 2 && consecutive(i - 2, i + 2)) {
      const double dt = 0.25 * (p[i + 2].t - p[i - 2].t);
      const double d = 7 * dt * dt;
      r.ax = (2 * p[i - 2].x - p[i - 1].x - 2 * p[i].x - p[i + 1].x + 2 * p[i + 2].x) / d;
      r.ay = (2 * p[i - 2].y - p[i - 1].y - 2 * p[i].y - p[i + 1].y + 2 * p[i + 2].y) / d;
    }
  }
}

struct SavgolPass {
  double rss_x = 0, rss_y = 0;
  long long dof = 0;
};

/// First pass: derivatives and unit variances (stored in the sigma fields, scaled later).
void savgol(const std::vector<double>& t, const std::vector<double>& x,
            const std::vector<double>& y, const Segment& s, int window, int order,
            std::vector<KinematicsRow>& rows, SavgolPass& pass) {
  const int m = static_cast<int>(s.size());
  const int w = std::min(window, m);
  if (w < order + 1) return;  // too short for this polynomial: undefined
  for (int i = 0; i < m; ++i) {
    const int lo = std::clamp(i - w / 2, 0, m - w);
    const std::size_t g = s.begin + static_cast<std::size_t>(i);
    const std::size_t g0 = s.begin + static_cast<std::size_t>(lo);
    const PolyFit f = fit_polynomial(&t[g0], &x[g0], &y[g0], w, t[g], order);
    if (!f.ok) continue;  // times too clustered for this degree: undefined here
    KinematicsRow& r = rows[g];
    r.vx = f.c[0][1];
    r.vy = f.c[1][1];
    r.sigma_vx = r.sigma_vy = std::sqrt(f.var_unit(1));
    if (order >= 2) {
      r.ax = 2 * f.c[0][2];
      r.ay = 2 * f.c[1][2];
      r.sigma_ax = r.sigma_ay = 2 * std::sqrt(f.var_unit(2));
    }
    if (f.dof() > 0) {
      pass.rss_x += f.rss[0];
      pass.rss_y += f.rss[1];
      pass.dof += f.dof();
    }
  }
}

}  // namespace

Kinematics differentiate(const Track& track, const KinematicsOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError("kinematics", err);
  validate_track(track, "");
  const std::size_t n = track.points.size();
  Kinematics out;
  out.track = track.name;
  out.method = options.method;
  out.rows.resize(n);
  std::vector<double> t(n), x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    const TrackPoint& p = track.points[i];
    t[i] = p.t;
    x[i] = p.x;
    y[i] = p.y;
    KinematicsRow& r = out.rows[i];
    r.frame = p.frame;
    r.t = p.t;
    r.x = p.x;
    r.y = p.y;
    r.vx = r.vy = r.ax = r.ay = kNaN;
    r.sigma_vx = r.sigma_vy = r.sigma_ax = r.sigma_ay = kNaN;
  }
  if (options.split_at_impacts) {
    ImpactResult im = detect_impacts(track, options.impacts);
    out.impacts = std::move(im.impacts);
    out.noise_x = im.noise_x;
    out.noise_y = im.noise_y;
  } else {
    out.noise_x = robust_noise(t, x);
    out.noise_y = robust_noise(t, y);
  }
  const std::vector<Segment> segments = flight_segments(n, out.impacts);
  out.segments = static_cast<int>(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (std::size_t i = segments[s].begin; i < segments[s].end; ++i) {
      out.rows[i].segment = static_cast<int>(s);
    }
  }
  out.residual_sigma_x = out.residual_sigma_y = kNaN;
  if (options.method == DerivativeMethod::tracker) {
    const int step = frame_step(track);
    for (const Segment& s : segments) tracker_stencils(track, s, step, out.rows);
    return out;
  }
  SavgolPass pass;
  for (const Segment& s : segments) savgol(t, x, y, s, options.window, options.order, out.rows, pass);
  const double sx = pass.dof > 0 ? std::sqrt(pass.rss_x / static_cast<double>(pass.dof)) : kNaN;
  const double sy = pass.dof > 0 ? std::sqrt(pass.rss_y / static_cast<double>(pass.dof)) : kNaN;
  out.residual_sigma_x = sx;
  out.residual_sigma_y = sy;
  for (KinematicsRow& r : out.rows) {
    r.sigma_vx *= sx;
    r.sigma_vy *= sy;
    r.sigma_ax *= sx;
    r.sigma_ay *= sy;
  }
  return out;
}

}  // namespace tribolab::track
