// A drop: release, flight, contact, flight ... until the ball rests or a bounce count is
// reached (SPEC section 3.4). Apex heights after every bounce and the detection of a
// rebound above the release height (the seed's "反跳變高"). docs/theory.md#bounce-drop.
#pragma once

#include "bounce/contact.hpp"
#include "bounce/flight.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::bounce {

struct DropRelease {
  double height = 1.0;  ///< centre height at release, m
  double theta = 0;     ///< orientation at release, rad
  double omega = 0;     ///< spin at release, rad/s
  double vx = 0;        ///< horizontal speed, m/s
  double vy = 0;        ///< vertical speed at release, m/s (0 = released at the apex)
};

struct DropOptions {
  std::size_t max_bounces = 5;   ///< stop after this many contacts
  /// The drop ends (status rest) when, at a take-off, the mechanical energy exceeds that of
  /// the ball lying flat (centre at b) by less than m g rest_height, m.
  double rest_height = 1e-4;
  FlightOptions flight{};        ///< g here is used for the whole drop
  ContactOptions contact{};      ///< its g is overwritten by flight.g
  double sample_dt = 0;          ///< trajectory sampling step of the flights, s; 0 = no trajectory

  std::string validate() const;
};

struct Bounce {
  double t_touch = 0;        ///< time of first touch from release, s
  BodyState touch;           ///< state at first touch
  double collision_angle_deg = 0;  ///< seed 001 figure 30, deg (direction of motion from vx)
  ContactResult contact;     ///< the contact (phases, energies, ...)
  double t_apex = 0;         ///< time of the following apex from release, s
  double apex_height = 0;    ///< centre height at the following apex, m
  bool above_release = false;  ///< apex_height > release apex height
  double t_cross_release = -1; ///< time the centre rises through the release apex height, s (-1 if never)
};

struct TrajectorySample {
  double t = 0;       ///< s from release
  BodyState state;
  bool in_contact = false;
};

enum class DropStatus {
  max_bounces,  ///< the requested number of contacts was simulated
  rest,         ///< the ball came to rest (contact did not end, or rebound below rest_height)
  failed,       ///< a contact or flight search failed (message)
};
std::string_view to_string(DropStatus s);

struct DropResult {
  DropStatus status = DropStatus::max_bounces;
  std::string message;
  double release_apex = 0;         ///< highest centre height before the first touch, m
  std::vector<Bounce> bounces;
  int first_above_release = -1;    ///< index of the first bounce whose apex exceeds release_apex
  std::vector<TrajectorySample> trajectory;  ///< when DropOptions::sample_dt > 0
};

DropResult simulate_drop(const Ball& ball, const NormalLawSpec& law, const FrictionModel& friction,
                         const DropRelease& release, const DropOptions& options = {});

}  // namespace tribolab::bounce
