#include "bounce/impact.hpp"

#include "numerics/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::bounce {

std::string ImpactOptions::validate() const {
  if (auto e = contact.validate(); !e.empty()) return e;
  FlightOptions f = flight;
  f.g = contact.g;
  f.t_end = std::numeric_limits<double>::infinity();
  if (auto e = f.validate(); !e.empty()) return e;
  if (max_contacts == 0) return "max_contacts must be at least 1";
  return {};
}

std::string_view to_string(ImpactStatus s) {
  switch (s) {
    case ImpactStatus::free_flight: return "free_flight";
    case ImpactStatus::rest: return "rest";
    case ImpactStatus::max_contacts: return "max_contacts";
    case ImpactStatus::failed: return "failed";
  }
  return "?";
}

namespace {

/// Adds contact `c`, which began `t0` s after the first touch, to the running whole `w`.
void accumulate(ContactResult& w, const ContactResult& c, double t0) {
  w.status = c.status;
  w.message = c.message;
  w.out = c.out;
  w.contact_duration = t0 + c.contact_duration;
  if (c.peak_force > w.peak_force) {
    w.peak_force = c.peak_force;
    w.t_peak = t0 + c.t_peak;
  }
  w.max_penetration = std::max(w.max_penetration, c.max_penetration);
  w.impulse_normal += c.impulse_normal;
  w.v_t_out = c.v_t_out;
  w.energy_out = c.energy_out;
  w.dissipated_normal += c.dissipated_normal;
  w.dissipated_friction += c.dissipated_friction;
  w.energy_residual += c.energy_residual;  // a free flight conserves E_kin + m g y exactly
  for (std::size_t i = 0; i < std::min(c.n_phases, kMaxStoredPhases); ++i) {
    if (w.n_phases + i >= kMaxStoredPhases) break;
    w.phases[w.n_phases + i] = {c.phases[i].kind, t0 + c.phases[i].t_start, t0 + c.phases[i].t_end};
  }
  w.n_phases += c.n_phases;
  w.steps += c.steps;
  w.rhs_calls += c.rhs_calls;
}

void record(ImpactResult& r, const ContactResult& c, double t0) {
  if (r.contacts < kMaxStoredContacts) {
    r.contact[r.contacts] = {t0, t0 + c.contact_duration, c.in.vy, c.out.vy, c.peak_force};
  }
  ++r.contacts;
}

}  // namespace

// docs/theory.md#bounce-contact ("Whole impact").
ImpactResult simulate_impact(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                             const BodyState& touch, const ImpactOptions& options,
                             std::vector<ContactSample>* history) {
  if (auto e = options.validate(); !e.empty()) throw InputError(e);
  const double g = options.contact.g;
  ImpactResult r;
  r.first = simulate_contact(ball, law, friction, touch, options.contact, history);
  r.whole = r.first;
  record(r, r.first, 0);
  std::vector<ContactSample> more;
  while (true) {
    const ContactResult& last = r.whole;
    if (last.status == ContactStatus::failed) {
      r.status = ImpactStatus::failed;
      r.message = last.message;
      break;
    }
    if (last.status == ContactStatus::max_duration) {
      r.status = ImpactStatus::rest;
      r.message = "a contact did not end (max_duration): the ball stays on the floor";
      break;
    }
    // Separated. A rebound is a free flight up to the apex (vy/g); a ball still moving
    // down (vy <= 0) has not rebounded and must touch again (with g > 0 the centre falls to
    // b; with g = 0 the search ends when the gap can no longer close).
    const BodyState s = last.out;
    FlightOptions fo = options.flight;
    fo.g = g;
    fo.t_end = s.vy > 0 && g > 0 ? s.vy / g : std::numeric_limits<double>::infinity();
    const FlightResult fl = first_contact(ball, s, fo);
    if (fl.status == FlightStatus::no_contact) {
      r.status = ImpactStatus::free_flight;
      r.message = "free flight";
      break;
    }
    if (fl.status != FlightStatus::contact) {
      r.status = ImpactStatus::failed;
      r.message = fl.status == FlightStatus::touching_start
                      ? "the ball does not leave the floor at a separation"
                      : "the first-contact search between contacts gave up";
      break;
    }
    if (r.contacts >= options.max_contacts) {
      r.status = ImpactStatus::max_contacts;
      r.message = "still touching again after max_contacts contacts";
      break;
    }
    if (!(contact_point_velocity(ball, fl.state.theta, fl.state.vx, fl.state.vy, fl.state.omega).vy < 0)) {
      // A grazing touch (double root of the gap) with no approach: no force acts. Rare
      // enough to stop with a clear status rather than to step over it.
      r.status = ImpactStatus::failed;
      r.message = "a grazing touch between contacts (the contact point does not approach)";
      break;
    }
    const double t0 = last.contact_duration + fl.t_contact;
    const ContactResult c = simulate_contact(ball, law, friction, fl.state, options.contact,
                                             history != nullptr ? &more : nullptr);
    if (history != nullptr) {
      for (ContactSample smp : more) {
        smp.t += t0;
        history->push_back(smp);
      }
    }
    accumulate(r.whole, c, t0);
    record(r, c, t0);
  }
  ContactResult& w = r.whole;
  w.restitution = w.in.vy != 0 ? -w.out.vy / w.in.vy : std::numeric_limits<double>::quiet_NaN();
  w.impulse_tangential = ball.mass * (w.out.vx - w.in.vx);  // no horizontal force in flight
  w.work_gravity = -ball.mass * g * (w.out.y - w.in.y);
  return r;
}

ImpactResult simulate_impact(const Ball& ball, const NormalLawSpec& spec, const FrictionModel& friction,
                             const BodyState& touch, const ImpactOptions& options,
                             std::vector<ContactSample>* history) {
  if (auto e = ball.validate(); !e.empty()) throw InputError(e);
  const PointVelocity pv = contact_point_velocity(ball, touch.theta, touch.vx, touch.vy, touch.omega);
  const NormalLaw law = resolve(spec, -pv.vy, ball.mass);
  return simulate_impact(ball, law, friction, touch, options, history);
}

}  // namespace tribolab::bounce
