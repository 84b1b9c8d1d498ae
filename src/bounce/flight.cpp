#include "bounce/flight.hpp"

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"
#include "numerics/roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::bounce {

std::string FlightOptions::validate() const {
  if (!std::isfinite(g) || !(g >= 0)) return "g: gravitational acceleration must be >= 0";
  if (!std::isfinite(gap_tol) || !(gap_tol > 0)) return "gap_tol must be positive";
  if (!std::isfinite(start_tol) || !(start_tol >= 0)) return "start_tol must be >= 0";
  if (max_iterations == 0) return "max_iterations must be positive";
  if (std::isnan(t_end) || !(t_end >= 0)) return "t_end must be >= 0";
  return {};
}

BodyState free_flight(const BodyState& s0, double g, double t) {
  BodyState s = s0;
  s.x = s0.x + s0.vx * t;
  s.y = s0.y + s0.vy * t - 0.5 * g * t * t;
  s.vy = s0.vy - g * t;
  s.theta = s0.theta + s0.omega * t;
  return s;
}

namespace {

/// Earliest t >= 0 with y0 + vy t - g t^2 / 2 = h, for h < y0 (the falling crossing);
/// infinite when the centre never comes down to h (g = 0 and vy >= 0).
double time_to_height(double y0, double vy, double g, double h) {
  // g t^2/2 - vy t - (y0 - h) = 0, positive root, stable form.
  const double c = y0 - h;  // > 0
  const double disc = std::sqrt(vy * vy + 2 * g * c);
  if (vy < 0) return 2 * c / (disc - vy);
  return g > 0 ? (vy + disc) / g : std::numeric_limits<double>::infinity();
}

}  // namespace

// docs/theory.md#bounce-flight. gap(t) = y(t) - Y(theta0 + omega t), with
//   gap'(t)  = vy - g t - omega Y'(theta),           |Y'| <= a - b,
//   gap''(t) = -g - omega^2 Y''(theta) >= -M2,        M2 = g + omega^2 (a^2 - b^2) / b.
// From a point t with gap > 0 two steps are root-free:
//   (1) Lipschitz: (|gap'|max over [t, t+h]) h <= gap with |gap'| <= |vy - g t| + g h + |omega|(a-b);
//   (2) Taylor:    gap(t+h) >= gap + gap' h - M2 h^2 / 2 > 0 for h below its positive root.
// The larger is taken. When gap' < 0, gap is strictly decreasing on [t, t - gap'/M2]; if the
// gap is <= 0 at the end of that window, the window holds exactly one root (the first one,
// since no root lies before t) and TOMS 748 finds it.
FlightResult first_contact(const Ball& ball, const BodyState& s0, const FlightOptions& options) {
  if (auto e = ball.validate(); !e.empty()) throw InputError(e);
  if (auto e = options.validate(); !e.empty()) throw InputError(e);
  for (double v : {s0.x, s0.y, s0.theta, s0.vx, s0.vy, s0.omega}) require_finite(v, "flight state");
  const double g = options.g;
  const double a = ball.a, b = ball.b;
  const double w = s0.omega;
  const double lip_spin = std::abs(w) * (a - b);
  // Any larger M2 is still a bound; the floor keeps the steps finite when g = 0 and omega = 0.
  const double M2 = std::max(g + w * w * (a * a - b * b) / b, 1e-300);

  auto gap_at = [&](double t) {
    const BodyState s = free_flight(s0, g, t);
    return s.y - support(ball, s.theta).Y;
  };
  auto gap_rate = [&](double t) {
    const BodyState s = free_flight(s0, g, t);
    return s.vy - w * support(ball, s.theta).dY;
  };

  FlightResult r;
  const double gap0 = gap_at(0);
  // Leaving the floor (just after a bounce): gap ~ 0 but opening. Allowed within a rounding
  // band; the first Taylor step below is root-free from there.
  const bool leaving = gap0 >= -options.start_tol && gap0 <= options.gap_tol && gap_rate(0) > 0;
  if (!(gap0 > 0) && !leaving) {
    r.status = FlightStatus::touching_start;
    r.message = "the ball touches or penetrates the floor at the start (centre height " +
                message_number(s0.y) + " m <= support depth " +
                message_number(support(ball, s0.theta).Y) + " m)";
    r.state = s0;
    return r;
  }
  // No contact while the centre is above a; contact at the latest when it reaches b.
  r.t_min = s0.y > a ? time_to_height(s0.y, s0.vy, g, a) : 0.0;
  r.t_max = time_to_height(s0.y, s0.vy, g, b);
  // The search ends at t_hi. Up to t_max a contact is certain (the centre reaches b); a
  // horizon before it, or a centre that never comes down (g = 0, vy >= 0: it rises past a
  // at (a - y0)/vy, and without vy only the spin can close the gap), may leave none.
  double t_hi = std::min(r.t_max, options.t_end);
  if (g == 0 && s0.vy > 0) t_hi = std::min(t_hi, std::max(0.0, (a - s0.y) / s0.vy));
  const bool certain = t_hi == r.t_max && std::isfinite(r.t_max);
  auto none = [&]() {
    r.status = FlightStatus::no_contact;
    r.message = "no contact";  // short: no allocation (the sweep calls this per cell)
    r.t_contact = std::numeric_limits<double>::quiet_NaN();
    r.state = s0;
    return r;
  };
  if (!certain && !(r.t_min <= t_hi)) return none();

  auto finish = [&](double t, bool grazing) {
    r.t_contact = t;
    r.state = free_flight(s0, g, t);
    const Support sp = support(ball, r.state.theta);
    r.contact_x = sp.X;
    r.contact_y = -sp.Y;
    r.contact_velocity = {r.state.vx + w * sp.Y, r.state.vy + w * sp.X};
    r.grazing = grazing;
    r.status = FlightStatus::contact;
    r.message = grazing ? "first contact (grazing touch)" : "first contact";
    return r;
  };

  double t = r.t_min;
  if (leaving) {
    const double rate = gap_rate(0);
    t = (rate + std::sqrt(rate * rate + 2 * M2 * std::max(gap0, 0.0))) / M2;
    if (!certain && !(t < t_hi)) return none();
  }
  double gap = gap_at(t);
  if (leaving) gap = std::max(gap, 0.0);
  for (std::size_t it = 0; it < options.max_iterations; ++it) {
    r.iterations = it + 1;
    if (gap <= options.gap_tol) return finish(t, gap > 0);
    const double rate = gap_rate(t);
    if (rate < 0) {
      // Monotone window: gap' <= rate + M2 s < 0 for s < -rate / M2.
      const double window = std::min(-rate / M2, t_hi - t + (certain ? 1e-12 : 0.0));
      if (window > 0 && gap_at(t + window) <= 0) {
        const auto root = numerics::find_root(gap_at, t, t + window);
        TRIBOLAB_ASSERT(root.converged, "flight root bracket lost");
        return finish(root.x, false);
      }
    }
    // Root-free steps.
    const double v_abs = std::abs(s0.vy - g * t) + lip_spin;  // |gap'| bound at t (without g h)
    const double h_lip = 2 * gap / (v_abs + std::sqrt(v_abs * v_abs + 4 * g * gap));
    const double root = std::sqrt(rate * rate + 2 * M2 * gap);
    const double h_tay = rate > 0 ? (rate + root) / M2 : 2 * gap / (root - rate);
    const double h = std::max(h_lip, h_tay);
    t += h;
    if (!certain && !(t < t_hi)) return none();  // [t - h, t_hi] is root-free
    gap = gap_at(t);
    if (gap < 0) gap = 0;  // rounding at a touch: h is root-free, so this is the root
  }
  r.status = FlightStatus::max_iterations;
  r.message = "first-contact search gave up after max_iterations steps";
  r.t_contact = t;
  r.state = free_flight(s0, g, t);
  return r;
}

FlightResult first_contact_from_apex(const Ball& ball, double H, double omega, double theta0,
                                     const FlightOptions& options) {
  BodyState s;
  s.y = H;
  s.omega = omega;
  s.theta = theta0;
  return first_contact(ball, s, options);
}

}  // namespace tribolab::bounce
