// A planar rigid body from two tracked points on it (the rugby ball's two tips, seed 001):
// centre = midpoint, orientation theta = atan2(yB - yA, xB - xA) unwrapped to a continuous
// angle, spin rate omega = dtheta/dt from linear least-squares fits of theta(t), globally over
// a range of points and locally over a sliding window. See docs/theory.md#rigid-body.
//
// Aliasing: unwrapping assumes the body turns by less than pi between consecutive points
// (|omega| dt < pi, e.g. |omega| < 750 rad/s at 240 fps).
#pragma once

#include "track/track.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::track {

struct RigidBodyOptions {
  int window = 7;  ///< points per local linear fit of theta(t) (>= 3), e.g. 7
  std::string validate() const;
};

/// The body at one frame where both points were marked.
struct RigidBodyRow {
  int frame = 0;
  double t = 0;               ///< s
  double xc = 0, yc = 0;      ///< centre (midpoint of the tips), m
  double theta = 0;           ///< orientation of A->B from +x, counter-clockwise, unwrapped, rad
  double length = 0;          ///< distance between the two points, m (2a for the tips)
  double omega = 0;           ///< local spin rate, rad/s (NaN where the window does not fit)
  double sigma_omega = 0;     ///< its standard error, rad/s
};

/// The turn per frame, degrees, above which a spin read from two ends that look alike (a ball's
/// tips seen as an ellipse) is ambiguous: half a turn looks the same, so the other reading,
/// 180 degrees minus this the other way, turns at most 1.5 times as fast. `bounce analyze` and
/// `track video --ellipse` warn above it (docs/theory.md#plausibility-checks).
inline constexpr double kAmbiguousTurnDeg = 72;

/// Linear fit theta = theta_ref + omega (t - t_ref) over a range of rows.
struct SpinFit {
  double omega = 0;        ///< rad/s, counter-clockwise positive
  double sigma_omega = 0;  ///< standard error, rad/s (NaN with fewer than 3 points)
  double t_ref = 0;        ///< mean time of the fitted points, s
  double theta_ref = 0;    ///< fitted angle at t_ref, rad
  double rms_residual = 0; ///< rad
  int points = 0;
};

struct RigidBody {
  std::string point_a, point_b;     ///< names of the two tracks
  std::vector<RigidBodyRow> rows;   ///< frames where both points exist, in order
  SpinFit spin;                     ///< global fit over all rows
  double length_mean = 0;           ///< mean distance between the points, m
  double length_sd = 0;             ///< its standard deviation, m (tracking quality)
};

/// Builds the body from two tracks (matched by frame). Throws InputError when fewer than two
/// common frames exist or the options are invalid.
RigidBody rigid_body_from_points(const Track& a, const Track& b, const RigidBodyOptions& options = {});

/// Linear fit of theta(t) over rows [begin, end) (e.g. one flight segment).
SpinFit fit_spin(const std::vector<RigidBodyRow>& rows, std::size_t begin, std::size_t end);

/// The centre as a Track (for kinematics and impact detection), named "<a>+<b>".
Track centre_track(const RigidBody& body);

}  // namespace tribolab::track
