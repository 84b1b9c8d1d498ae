// Is a flight segment a free flight, and does it fall at g? (docs/theory.md#free-flight-check)
//
// One constant acceleration is fitted to each flight segment of a track (least-squares
// parabolas x(t), y(t), a = 2 c2). A segment is taken for a free flight only when the data
// themselves show the three marks of one, because a slide, a cart or a pendulum must not be
// held against g:
//   1. the parabolas fit to the noise: rms residual of x and of y <= fit_noise_factor x the
//      robust position noise + fit_floor (a pendulum, a rolling start, a contact do not);
//   2. the acceleration lies within max_tilt_deg of the y axis, either way (a slide or cart
//      seen from the side accelerates along its slope; -y is down, +y a flipped axis);
//   3. the motion along y turns within the segment: straight lines through the first and the
//      last third of its points have slopes of opposite signs, each beyond 3 standard errors
//      (thrown up and falling back, a bounce). A slide seen in seed 000's frame (y up the
//      slope) accelerates along -y too, but never turns back with one constant acceleration
//      (friction flips at the turn).
// Only such a segment is compared with g: its |a| (within tolerance of g beyond 3 sd), its
// direction (down, not up) and its tilt from -y (within min_tilt_deg beyond 3 sd).
#pragma once

#include "numerics/units.hpp"
#include "track/impacts.hpp"
#include "track/track.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::track {

struct FreeFlightOptions {
  double g = kDefaultG;          ///< gravity the data are held against, m/s^2, e.g. 9.8
  int min_points = 8;            ///< fewer points in a segment: not checked, e.g. 8
  double fit_noise_factor = 2;   ///< parabolas fit when rms <= this x noise + fit_floor, e.g. 2
  double fit_floor = 1e-3;       ///< m: air drag over a 0.3 s flight bends it by ~2 mm, e.g. 0.001
  double max_tilt_deg = 20;      ///< a within this of the +-y axis counts as vertical, deg, e.g. 20
  double tolerance = 0.10;       ///< |a|/g - 1 allowed (beyond 3 sd): drag, perspective, e.g. 0.10
  double min_tilt_deg = 2;       ///< tilt from -y allowed (beyond 3 sd), deg, e.g. 2
  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
};

/// Why a segment was not taken for a free flight.
enum class FlightShape {
  free_flight,                ///< all three marks: checked against g
  too_few_points,             ///< fewer than min_points
  no_fit,                     ///< the times cannot determine a parabola (numerically clustered)
  not_constant_acceleration,  ///< the parabolas miss the points by more than the noise
  not_along_y,                ///< the acceleration is tilted more than max_tilt_deg from +-y
  no_turning_point,           ///< the motion along y does not reverse within the segment (first vs last third)
};
/// "free_flight", "too_few_points", "no_fit", "not_constant_acceleration", "not_along_y",
/// "no_turning_point".
const char* to_string(FlightShape s);

/// The constant-acceleration fit of one flight segment and its comparison with g.
struct SegmentAcceleration {
  Segment range;                    ///< points [begin, end) of the track
  int frame_first = 0, frame_last = 0;
  double t_first = 0, t_last = 0;   ///< s
  double ax = 0, ay = 0;            ///< fitted acceleration, m/s^2, e.g. (0, -9.8) in free flight
  double sigma_ax = 0, sigma_ay = 0;  ///< standard errors from the fit's residuals, m/s^2
  double magnitude = 0, sigma_magnitude = 0;  ///< |a| and its standard error, m/s^2
  /// Angle of a from the -y axis, counter-clockwise positive (atan2(ax, -ay)), deg: 0 for a
  /// level camera, +-180 for a y axis pointing down.
  double tilt_deg = 0, sigma_tilt_deg = 0;
  double rms_x = 0, rms_y = 0;      ///< rms residual of the parabolas, m
  FlightShape shape = FlightShape::too_few_points;
  // Set only for a free flight (shape == free_flight):
  bool points_up = false;           ///< a along +y beyond 3 sd: the y axis points down
  bool magnitude_off = false;       ///< ||a| - g| > 3 sd and > tolerance g
  bool tilted = false;              ///< |tilt| > 3 sd and > min_tilt_deg (a pointing down)
  bool checked() const { return shape == FlightShape::free_flight; }
  bool plausible() const { return !points_up && !magnitude_off && !tilted; }
};

/// Fits and classifies every segment of `track` (noise_x, noise_y: the robust position noise
/// of the track, m, as Kinematics gives it). Values are NaN where a segment has fewer than 4
/// points or no fit. Throws InputError for invalid options only: a segment that cannot be
/// fitted is reported (no_fit), never an error, so the check cannot fail a command.
std::vector<SegmentAcceleration> check_free_flight(const Track& track, const std::vector<Segment>& segments,
                                                   double noise_x, double noise_y,
                                                   const FreeFlightOptions& options = {});

}  // namespace tribolab::track
