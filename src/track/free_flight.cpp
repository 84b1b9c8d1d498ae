#include "track/free_flight.hpp"

#include "numerics/error.hpp"
#include "numerics/polyfit.hpp"
#include "numerics/units.hpp"
#include "track/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace tribolab::track {

namespace {
constexpr double kSd = 3;  // "beyond 3 standard errors": 0.3 % two-sided for a Gaussian estimate
}  // namespace

const char* to_string(FlightShape s) {
  switch (s) {
    case FlightShape::free_flight: return "free_flight";
    case FlightShape::too_few_points: return "too_few_points";
    case FlightShape::no_fit: return "no_fit";
    case FlightShape::not_constant_acceleration: return "not_constant_acceleration";
    case FlightShape::not_along_y: return "not_along_y";
    case FlightShape::no_turning_point: return "no_turning_point";
  }
  return "?";
}

std::string FreeFlightOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(g)) return field("g") + " must be a positive number of m/s^2";
  if (min_points < 4) return field("min_points") + " must be at least 4";
  if (!positive(fit_noise_factor) || !(fit_floor >= 0)) return field("fit_noise_factor") + " must be positive";
  if (!(max_tilt_deg > 0 && max_tilt_deg < 90)) return field("max_tilt_deg") + " must lie in (0, 90)";
  if (!positive(tolerance) || !(min_tilt_deg >= 0)) return field("tolerance") + " must be positive";
  return "";
}

namespace {

/// The segment's range and times, every fitted value NaN.
SegmentAcceleration blank(const Track& track, const Segment& seg) {
  TRACK_CHECK(seg.begin < seg.end && seg.end <= track.points.size(), "a flight segment holds points of the track");
  const auto& p = track.points;
  SegmentAcceleration a;
  a.range = seg;
  a.frame_first = p[seg.begin].frame;
  a.frame_last = p[seg.end - 1].frame;
  a.t_first = p[seg.begin].t;
  a.t_last = p[seg.end - 1].t;
  a.ax = a.ay = a.sigma_ax = a.sigma_ay = a.magnitude = a.sigma_magnitude = kNaN;
  a.tilt_deg = a.sigma_tilt_deg = a.rms_x = a.rms_y = kNaN;
  return a;
}

SegmentAcceleration fit_segment_unchecked(const Track& track, const Segment& seg, double noise_x, double noise_y,
                                          const FreeFlightOptions& o) {
  const auto& p = track.points;
  SegmentAcceleration a = blank(track, seg);
  if (seg.size() < 4) return a;  // a parabola and its residual scatter need 4 points
  // Time about the segment's middle: the coefficients are then nearly uncorrelated.
  const double t_mid = 0.5 * (a.t_first + a.t_last);
  std::vector<double> s, x, y;
  for (std::size_t i = seg.begin; i < seg.end; ++i) {
    s.push_back(p[i].t - t_mid);
    x.push_back(p[i].x);
    y.push_back(p[i].y);
  }
  const numerics::PolyFit fx = numerics::fit_polynomial(s, x, 2, "x(t)");
  const numerics::PolyFit fy = numerics::fit_polynomial(s, y, 2, "y(t)");
  a.ax = 2 * fx.coef[2];
  a.ay = 2 * fy.coef[2];
  a.sigma_ax = 2 * fx.sigma[2];
  a.sigma_ay = 2 * fy.sigma[2];
  a.rms_x = fx.rms;
  a.rms_y = fy.rms;
  // |a| and its angle from -y; ax and ay come from separate fits, so they are uncorrelated.
  const double vax = a.sigma_ax * a.sigma_ax, vay = a.sigma_ay * a.sigma_ay;
  a.magnitude = std::hypot(a.ax, a.ay);
  const double m2 = std::max(a.magnitude * a.magnitude, 1e-300);
  a.sigma_magnitude = std::sqrt((a.ax * a.ax * vax + a.ay * a.ay * vay) / m2);
  a.tilt_deg = to_deg(std::atan2(a.ax, -a.ay));
  a.sigma_tilt_deg = to_deg(std::sqrt(a.ay * a.ay * vax + a.ax * a.ax * vay) / m2);

  if (static_cast<int>(seg.size()) < o.min_points) return a;  // shape stays too_few_points
  // 1. One constant acceleration explains the points to their noise.
  const double floor = std::max(o.fit_floor, 1e-9);
  if (fx.rms > o.fit_noise_factor * noise_x + floor || fy.rms > o.fit_noise_factor * noise_y + floor) {
    a.shape = FlightShape::not_constant_acceleration;
    return a;
  }
  // 2. Along the y axis, down or up.
  const double off_axis = std::min(std::abs(a.tilt_deg), 180 - std::abs(a.tilt_deg));
  if (!(off_axis <= o.max_tilt_deg)) {
    a.shape = FlightShape::not_along_y;
    return a;
  }
  // 3. The motion along y turns, in the data themselves: straight lines through the first and
  //    the last third of the points have slopes of opposite signs, each beyond 3 standard
  //    errors. (The fitted parabola's vertex is no proof: a disc resting, then sliding, is
  //    fitted by a parabola whose vertex lies inside the segment.)
  const std::size_t third = std::max<std::size_t>(3, seg.size() / 3);
  auto slope = [&](std::size_t lo, double& sd) {
    const std::span<const double> ts(s.data() + lo, third), ys(y.data() + lo, third);
    const numerics::PolyFit line = numerics::fit_polynomial(ts, ys, 1, "y(t)");
    sd = line.sigma[1];
    return line.coef[1];
  };
  double sd0 = 0, sd1 = 0;
  const double v0 = slope(0, sd0), v1 = slope(seg.size() - third, sd1);
  if (!(v0 * v1 < 0 && std::abs(v0) > kSd * sd0 && std::abs(v1) > kSd * sd1)) {
    a.shape = FlightShape::no_turning_point;
    return a;
  }
  a.shape = FlightShape::free_flight;
  a.points_up = a.ay > kSd * a.sigma_ay;
  a.magnitude_off = std::abs(a.magnitude - o.g) > kSd * a.sigma_magnitude &&
                    std::abs(a.magnitude - o.g) > o.tolerance * o.g;
  a.tilted = !a.points_up && std::abs(a.tilt_deg) > kSd * a.sigma_tilt_deg &&
             std::abs(a.tilt_deg) > o.min_tilt_deg;
  return a;
}

SegmentAcceleration fit_segment(const Track& track, const Segment& seg, double noise_x, double noise_y,
                                const FreeFlightOptions& o) {
  try {
    return fit_segment_unchecked(track, seg, noise_x, noise_y, o);
  } catch (const InputError&) {  // times too clustered for a parabola or a line (fit_polynomial)
    SegmentAcceleration a = blank(track, seg);
    a.shape = FlightShape::no_fit;
    return a;
  }
}

}  // namespace

std::vector<SegmentAcceleration> check_free_flight(const Track& track, const std::vector<Segment>& segments,
                                                   double noise_x, double noise_y, const FreeFlightOptions& o) {
  if (const auto err = o.validate(); !err.empty()) throw InputError("free-flight check", err);
  const double nx = std::isfinite(noise_x) ? noise_x : 0, ny = std::isfinite(noise_y) ? noise_y : 0;
  std::vector<SegmentAcceleration> out;
  out.reserve(segments.size());
  for (const Segment& s : segments) out.push_back(fit_segment(track, s, nx, ny, o));
  return out;
}

}  // namespace tribolab::track
