// Geometry of a planar rigid ellipse (the rugby ball of seed 001) over the floor y = 0:
// the support (lowest) point of the rotated ellipse, its depth below the centre, the
// velocity of the material point there, and the seed's "collision angle".
// Frame (SPEC section 1): x horizontal, y up; theta = angle of the major axis from the
// horizontal, counter-clockwise positive; omega counter-clockwise positive.
// See docs/theory.md#bounce-geometry.
#pragma once

#include <string>

namespace tribolab::bounce {

/// The ball: a planar rigid ellipse. Defaults: a size-5 rugby ball (SPEC section 3).
struct Ball {
  double a = 0.145;        ///< semi-major axis, m (usually 0.14-0.15 for a rugby ball)
  double b = 0.095;        ///< semi-minor axis, m; 0 < b <= a
  double mass = 0.435;     ///< mass, kg (size-5 rugby ball about 0.41-0.46)
  double inertia = 4.1e-3; ///< moment of inertia about the centre for spin in the plane, kg m^2

  /// Empty when valid, else a message naming the bad field ("a", "b", "mass", "inertia").
  std::string validate() const;
};

/// Depth of the support point below the centre, Y(theta) = sqrt(a^2 sin^2 + b^2 cos^2), m.
/// (seed 001 eq 20 uses Y^2 correctly; its eq 15/18 print a wrong Y: docs/theory.md#errata)
double support_depth(const Ball& ball, double theta);

/// dY/dtheta = (a^2 - b^2) sin(theta) cos(theta) / Y, m/rad; |dY/dtheta| <= a - b.
double support_depth_slope(const Ball& ball, double theta);

/// d^2Y/dtheta^2 = a^2 b^2 / Y^3 - Y, m/rad^2; it lies in [-(a^2-b^2)/a, (a^2-b^2)/b].
double support_depth_curvature(const Ball& ball, double theta);

/// Everything about the support point for one orientation, computed with one sin/cos/sqrt.
struct Support {
  double Y = 0;       ///< depth of the support point below the centre, m (b <= Y <= a)
  double X = 0;       ///< horizontal offset of the support point from the centre, m (= -dY/dtheta)
  double dY = 0;      ///< dY/dtheta, m/rad
  double d2Y = 0;     ///< d^2Y/dtheta^2, m/rad^2
};
Support support(const Ball& ball, double theta);

/// Velocity of the material point of the ball that is at the support point, m/s:
/// v_p = v_centre + omega x r with r = (X, -Y): (vx + omega Y, vy + omega X).
struct PointVelocity {
  double vx = 0;  ///< horizontal (slip) velocity of the contact point, m/s
  double vy = 0;  ///< vertical velocity of the contact point, m/s (< 0 approaching the floor)
};
PointVelocity contact_point_velocity(const Ball& ball, double theta, double vx, double vy,
                                     double omega);

/// Collision angle (seed 001, figure 30), degrees in [0, 180]: the angle at the centre
/// between the ray to the support point and the ray to the "rear" tip of the major axis,
/// the tip that is behind the centre with respect to the horizontal direction of motion
/// `direction` (+1 moving to +x, -1 to -x). See docs/theory.md#collision-angle for the
/// precise definition, including the tie-break when the major axis is vertical.
double collision_angle_deg(const Ball& ball, double theta, int direction);

/// Inverse of collision_angle_deg on the branch theta in [-pi/2, pi/2] (direction +1; mirrored
/// for -1), where the angle falls monotonically from 180 to 0 deg: the orientation, rad, at
/// which the ball touches with the given collision angle (0..180 deg). For sweeps over the
/// seed's collision angle (figures 53-56).
double theta_for_collision_angle(const Ball& ball, double angle_deg, int direction);

/// Wraps an angle to (-pi, pi].
double wrap_angle(double theta);

}  // namespace tribolab::bounce
