#include "bounce/drop.hpp"

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"

#include <algorithm>
#include <cmath>

namespace tribolab::bounce {

std::string DropOptions::validate() const {
  if (max_bounces == 0) return "max_bounces must be at least 1";
  if (!std::isfinite(rest_height) || !(rest_height >= 0)) return "rest_height must be >= 0";
  if (!std::isfinite(sample_dt) || !(sample_dt >= 0)) return "sample_dt must be >= 0";
  if (auto e = flight.validate(); !e.empty()) return e;
  if (!(flight.g > 0)) return "g: a drop needs gravitational acceleration > 0";
  if (auto e = contact.validate(); !e.empty()) return e;
  return {};
}

std::string_view to_string(DropStatus s) {
  switch (s) {
    case DropStatus::max_bounces: return "max_bounces";
    case DropStatus::rest: return "rest";
    case DropStatus::failed: return "failed";
  }
  return "?";
}

namespace {

void sample_flight(const BodyState& s0, double t0, double duration, double g, double dt,
                   std::vector<TrajectorySample>& out) {
  const auto n = static_cast<std::size_t>(std::floor(duration / dt));
  for (std::size_t i = 0; i <= n; ++i) {
    const double tau = static_cast<double>(i) * dt;
    out.push_back({t0 + tau, free_flight(s0, g, tau), false});
  }
}

}  // namespace

DropResult simulate_drop(const Ball& ball, const NormalLawSpec& law, const FrictionModel& friction,
                         const DropRelease& release, const DropOptions& options) {
  if (auto e = ball.validate(); !e.empty()) throw InputError(e);
  if (auto e = options.validate(); !e.empty()) throw InputError(e);
  if (auto e = law.validate(); !e.empty()) throw InputError(e);
  if (auto e = friction.validate(); !e.empty()) throw InputError(e);
  for (double v : {release.height, release.theta, release.omega, release.vx, release.vy})
    require_finite(v, "release");
  const double g = options.flight.g;
  ContactOptions copt = options.contact;
  copt.g = g;

  BodyState s;
  s.y = release.height;
  s.theta = release.theta;
  s.omega = release.omega;
  s.vx = release.vx;
  s.vy = release.vy;
  if (!(s.y > support(ball, s.theta).Y)) {
    throw InputError("height", "the ball touches the floor at release (centre height " +
                                   message_number(s.y) + " m, lowest point needs > " +
                                   message_number(support(ball, s.theta).Y) + " m)");
  }
  DropResult r;
  r.release_apex = s.y + (s.vy > 0 ? s.vy * s.vy / (2 * g) : 0.0);
  const bool sampling = options.sample_dt > 0;
  std::vector<ContactSample> history;
  double t = 0;
  FlightResult fr = first_contact(ball, s, options.flight);
  while (true) {
    if (fr.status != FlightStatus::contact) {
      r.status = DropStatus::failed;
      r.message = "flight: " + fr.message;
      return r;
    }
    if (sampling) sample_flight(s, t, fr.t_contact, g, options.sample_dt, r.trajectory);
    Bounce b;
    b.t_touch = t + fr.t_contact;
    b.touch = fr.state;
    b.collision_angle_deg = collision_angle_deg(ball, b.touch.theta, b.touch.vx < 0 ? -1 : 1);
    b.contact = simulate_contact(ball, law, friction, b.touch, copt, sampling ? &history : nullptr);
    if (sampling) {
      for (const ContactSample& cs : history) r.trajectory.push_back({b.t_touch + cs.t, cs.state, true});
    }
    const ContactResult& c = b.contact;
    const double t_out = b.t_touch + c.contact_duration;
    if (c.status == ContactStatus::failed) {
      r.status = DropStatus::failed;
      r.message = "contact " + std::to_string(r.bounces.size() + 1) + ": " + std::string(c.message);
      r.bounces.push_back(b);
      return r;
    }
    if (c.status == ContactStatus::max_duration) {
      b.t_apex = t_out;
      b.apex_height = c.out.y;
      r.bounces.push_back(b);
      r.status = DropStatus::rest;
      r.message = "the ball stayed on the floor (contact longer than max_duration)";
      return r;
    }
    // Next flight from the take-off state; the apex is the top of the ballistic arc unless
    // the ball touches again first.
    s = c.out;
    t = t_out;
    fr = first_contact(ball, s, options.flight);
    const double tau_top = s.vy > 0 ? s.vy / g : 0.0;
    const double tau_apex = fr.status == FlightStatus::contact ? std::min(tau_top, fr.t_contact) : tau_top;
    b.t_apex = t + tau_apex;
    b.apex_height = free_flight(s, g, tau_apex).y;
    b.above_release = b.apex_height > r.release_apex;
    if (b.above_release) {
      // s.y + vy tau - g tau^2 / 2 = release_apex, first (rising) root.
      const double c0 = s.y - r.release_apex;  // may be negative (take-off below)
      const double disc = std::sqrt(std::max(0.0, s.vy * s.vy + 2 * g * c0));
      b.t_cross_release = c0 >= 0 ? t : t + (s.vy - disc) / g;
      if (r.first_above_release < 0) r.first_above_release = static_cast<int>(r.bounces.size());
    }
    // Energy above the lowest resting position (centre at b), as a height.
    const double spare = kinetic_energy(ball, s).total() / (ball.mass * g) + s.y - ball.b;
    r.bounces.push_back(b);
    if (spare < options.rest_height) {
      r.status = DropStatus::rest;
      r.message = "mechanical energy within rest_height of rest: the ball is taken to be at rest";
      return r;
    }
    if (r.bounces.size() >= options.max_bounces) {
      r.status = DropStatus::max_bounces;
      r.message = "simulated the requested number of bounces";
      if (sampling && fr.status == FlightStatus::contact)
        sample_flight(s, t, tau_apex, g, options.sample_dt, r.trajectory);
      return r;
    }
  }
}

}  // namespace tribolab::bounce
