// The whole impact of the ellipse on the floor: the first contact from first touch, then,
// while the ball leaves the floor without a rebound (still moving down) or touches again
// before its apex, the flight to the next touch (flight.hpp's first-contact search) and
// that contact, until the ball is in free flight with no contact before its apex (g = 0:
// until the gap can no longer close). What `bounce simulate` and every sweep cell report;
// the first contact phase alone is kept as `first`. docs/theory.md#bounce-contact.
#pragma once

#include "bounce/contact.hpp"
#include "bounce/flight.hpp"

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace tribolab::bounce {

struct ImpactOptions {
  ContactOptions contact{};  ///< every contact; its g is used for the flights between them
  /// The first-contact search between contacts (gap_tol, start_tol, max_iterations); its g
  /// and t_end are set by simulate_impact.
  FlightOptions flight{};
  std::size_t max_contacts = 64;  ///< contacts before giving up (status max_contacts)

  std::string validate() const;  ///< empty when valid
};

enum class ImpactStatus {
  free_flight,   ///< the ball left the floor and reaches its apex (or escapes, g = 0) untouched
  rest,          ///< a contact did not end (ContactStatus::max_duration): the ball stays down
  max_contacts,  ///< still touching again after max_contacts contacts (chatter)
  failed,        ///< a contact or a flight search failed (message)
};
std::string_view to_string(ImpactStatus s);

/// One contact of the impact; times from the first touch.
struct ImpactContact {
  double t_touch = 0;       ///< s
  double t_separation = 0;  ///< s
  double vy_in = 0;         ///< centre velocity at this touch, m/s
  double vy_out = 0;        ///< centre velocity at this separation, m/s
  double peak_force = 0;    ///< N
};

inline constexpr std::size_t kMaxStoredContacts = 16;

struct ImpactResult {
  ImpactStatus status = ImpactStatus::free_flight;
  std::string_view message = "free flight";  ///< static text
  /// The first contact phase alone: first touch to first separation.
  ContactResult first;
  /// The whole impact, summed over its contacts: in = first touch, out = last separation,
  /// restitution -vy_out/vy_in between them, contact_duration = first touch to last
  /// separation (flights between contacts included), peak_force / max_penetration the
  /// largest, impulses, dissipation and integrator counts summed, phases concatenated
  /// (times from the first touch), energy_in of the first touch and energy_out of the last
  /// separation, work_gravity over the whole time. status is the last contact's.
  ContactResult whole;
  std::size_t contacts = 0;  ///< number of contacts (1 = the first phase was the whole impact)
  std::array<ImpactContact, kMaxStoredContacts> contact{};  ///< the first kMaxStoredContacts
};

/// Simulates the whole impact from first touch in state `touch` (as simulate_contact). The
/// law is resolved once, at the first touch (a restitution-based law keeps that damping for
/// the later contacts: one ball, one material). No shared state (sweeps call it from many
/// threads). With `history`: every contact's samples, times from the first touch (flights
/// are not sampled).
ImpactResult simulate_impact(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                             const BodyState& touch, const ImpactOptions& options = {},
                             std::vector<ContactSample>* history = nullptr);

ImpactResult simulate_impact(const Ball& ball, const NormalLawSpec& spec, const FrictionModel& friction,
                             const BodyState& touch, const ImpactOptions& options = {},
                             std::vector<ContactSample>* history = nullptr);

}  // namespace tribolab::bounce
