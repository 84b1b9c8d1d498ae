#include "track/rigid_body.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "track/check.hpp"
#include "track/local_spin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tribolab::track {

namespace {
}

std::string RigidBodyOptions::validate() const {
  if (window < 3) return "spin window must be at least 3 points, got " + std::to_string(window);
  return "";
}

SpinFit fit_spin(const std::vector<RigidBodyRow>& rows, std::size_t begin, std::size_t end) {
  TRACK_CHECK(begin <= end && end <= rows.size(), "fit_spin range out of bounds");
  SpinFit f;
  f.points = static_cast<int>(end - begin);
  f.omega = f.sigma_omega = f.t_ref = f.theta_ref = f.rms_residual = kNaN;
  if (f.points < 2) return f;
  double tm = 0, thm = 0;
  for (std::size_t i = begin; i < end; ++i) {
    tm += rows[i].t;
    thm += rows[i].theta;
  }
  tm /= f.points;
  thm /= f.points;
  double stt = 0, sth = 0;
  for (std::size_t i = begin; i < end; ++i) {
    stt += (rows[i].t - tm) * (rows[i].t - tm);
    sth += (rows[i].t - tm) * (rows[i].theta - thm);
  }
  f.t_ref = tm;
  f.theta_ref = thm;
  f.omega = sth / stt;
  double rss = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const double r = rows[i].theta - (thm + f.omega * (rows[i].t - tm));
    rss += r * r;
  }
  f.rms_residual = std::sqrt(rss / f.points);
  if (f.points >= 3) f.sigma_omega = std::sqrt(rss / (f.points - 2) / stt);
  return f;
}

void local_spins(std::vector<RigidBodyRow>& rows, int window) {
  const std::size_t n = rows.size();
  // local fits: slope of theta(t) over `window` rows (centred, shifted at the ends), with the
  // noise pooled from all windows' residuals
  const int w = std::min<int>(window, static_cast<int>(n));
  if (w >= 3) {
    double rss = 0;
    long long dof = 0;
    std::vector<double> unit(n, kNaN);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t lo = static_cast<std::size_t>(
          std::clamp<long long>(static_cast<long long>(i) - w / 2, 0, static_cast<long long>(n) - w));
      const SpinFit f = fit_spin(rows, lo, lo + static_cast<std::size_t>(w));
      rows[i].omega = f.omega;
      double stt = 0;
      for (std::size_t k = lo; k < lo + static_cast<std::size_t>(w); ++k) {
        stt += (rows[k].t - f.t_ref) * (rows[k].t - f.t_ref);
      }
      unit[i] = 1 / std::sqrt(stt);
      rss += f.rms_residual * f.rms_residual * f.points;
      dof += f.points - 2;
    }
    const double s = std::sqrt(rss / static_cast<double>(dof));
    for (std::size_t i = 0; i < n; ++i) rows[i].sigma_omega = s * unit[i];
  }
}

RigidBody rigid_body_from_points(const Track& a, const Track& b, const RigidBodyOptions& options) {
  if (const auto err = options.validate(); !err.empty()) throw InputError("rigid body", err);
  validate_track(a, "");
  validate_track(b, "");
  RigidBody body;
  body.point_a = a.name;
  body.point_b = b.name;
  std::size_t j = 0;
  for (const TrackPoint& p : a.points) {
    while (j < b.points.size() && b.points[j].frame < p.frame) ++j;
    if (j == b.points.size()) break;
    if (b.points[j].frame != p.frame) continue;
    const TrackPoint& q = b.points[j];
    RigidBodyRow r;
    r.frame = p.frame;
    r.t = p.t;
    r.xc = 0.5 * (p.x + q.x);
    r.yc = 0.5 * (p.y + q.y);
    r.theta = std::atan2(q.y - p.y, q.x - p.x);
    r.length = std::hypot(q.x - p.x, q.y - p.y);
    r.omega = r.sigma_omega = kNaN;
    if (!body.rows.empty()) {  // unwrap: nearest branch to the previous angle
      const double prev = body.rows.back().theta;
      r.theta += 2 * std::numbers::pi * std::round((prev - r.theta) / (2 * std::numbers::pi));
    }
    body.rows.push_back(r);
  }
  const std::size_t n = body.rows.size();
  if (n < 2) {
    throw InputError("rigid body", "tracks '" + a.name + "' and '" + b.name + "' share " +
                                       std::to_string(n) + " frame(s); at least 2 are needed");
  }
  body.spin = fit_spin(body.rows, 0, n);
  double lm = 0;
  for (const auto& r : body.rows) lm += r.length;
  lm /= static_cast<double>(n);
  double lv = 0;
  for (const auto& r : body.rows) lv += (r.length - lm) * (r.length - lm);
  body.length_mean = lm;
  body.length_sd = std::sqrt(lv / static_cast<double>(n - 1));
  local_spins(body.rows, options.window);
  return body;
}

Track centre_track(const RigidBody& body) {
  Track t;
  t.name = body.point_a + "+" + body.point_b;
  for (const auto& r : body.rows) t.points.push_back({r.frame, r.t, r.xc, r.yc});
  return t;
}

}  // namespace tribolab::track
