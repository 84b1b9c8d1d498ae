// Free flight of the ellipse to its FIRST contact with the floor (seed 001, experiment 3).
// The centre moves ballistically and the ball spins freely; the gap between the lowest
// point and the floor, gap(t) = y(t) - Y(theta(t)), is not monotone, so roots are found by
// guaranteed steps that can never jump over one (docs/theory.md#bounce-flight).
#pragma once

#include "bounce/geometry.hpp"
#include "numerics/units.hpp"

#include <cstddef>
#include <limits>
#include <string>

namespace tribolab::bounce {

/// Rigid-body state of the ball in the plane.
struct BodyState {
  double x = 0;      ///< centre, horizontal, m
  double y = 0;      ///< centre height above the floor, m (typically 0.1-2)
  double theta = 0;  ///< major axis from the horizontal, CCW, rad
  double vx = 0;     ///< centre velocity, m/s
  double vy = 0;     ///< centre velocity, m/s (negative falling)
  double omega = 0;  ///< spin, CCW, rad/s (seed: 30-50)
};

/// Free flight: x(t) = x0 + vx t, y(t) = y0 + vy t - g t^2/2, theta(t) = theta0 + omega t.
BodyState free_flight(const BodyState& s0, double g, double t);

struct FlightOptions {
  /// Gravitational acceleration, m/s^2 (kDefaultG). 0 is allowed: the centre then moves uniformly
  /// and a ball moving up (or not at all, without spin) may never touch (status no_contact).
  double g = kDefaultG;
  /// A gap below this counts as touching, m: ends the search at a grazing touch, where the
  /// gap has a double root. Default 1e-13 m (far below any measurable gap).
  double gap_tol = 1e-13;
  /// A start with the gap in [-start_tol, gap_tol] and opening (the ball just left the floor)
  /// is a take-off, not an error, m. Default 1e-9 m covers the rounding of a contact's end.
  double start_tol = 1e-9;
  std::size_t max_iterations = 10'000'000;  ///< guaranteed steps before giving up
  /// Search horizon, s (default infinite): a first contact later than t_end is not looked
  /// for (status no_contact). E.g. the apex time vy/g: is there a contact before the apex?
  double t_end = std::numeric_limits<double>::infinity();

  std::string validate() const;  ///< empty when valid
};

enum class FlightStatus {
  contact,         ///< first contact found
  touching_start,  ///< the ball already touches or penetrates the floor at t = 0
  max_iterations,  ///< gave up (only at a near-grazing pass, never seen in practice)
  no_contact,      ///< no contact in [0, t_end], or never (g = 0 and the gap cannot close)
};

struct FlightResult {
  FlightStatus status = FlightStatus::contact;
  double t_contact = 0;   ///< time of first contact after the start, s
  BodyState state;        ///< state at first contact (y = Y(theta) up to rounding)
  double contact_x = 0;   ///< contact point relative to the centre, m (X)
  double contact_y = 0;   ///< contact point relative to the centre, m (-Y, negative)
  PointVelocity contact_velocity;  ///< velocity of the material contact point, m/s
  bool grazing = false;   ///< the gap touched zero without crossing (gap_tol reached)
  std::size_t iterations = 0;  ///< guaranteed steps taken
  double t_min = 0;       ///< earliest possible contact (centre at height a), s
  double t_max = 0;       ///< latest possible contact (centre at height b), s (inf when g = 0 and vy >= 0)
  std::string message;    ///< human-readable status
};

/// First contact of a ball released in state s0 (any vy; typically the apex, vy = 0).
/// Throws InputError for an invalid ball or options.
FlightResult first_contact(const Ball& ball, const BodyState& s0, const FlightOptions& options = {});

/// Convenience for seed 001's setting: centre apex height H, spin omega, orientation
/// theta0 at the apex (vx = 0, vy = 0).
FlightResult first_contact_from_apex(const Ball& ball, double H, double omega, double theta0,
                                     const FlightOptions& options = {});

}  // namespace tribolab::bounce
