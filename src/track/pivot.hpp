// The spin of ONE tracked point about a pivot (a mark on a wheel, a pendulum bob, a point on a
// diabolo): no second track is needed when the point turns about a centre that is fixed (given
// or fitted) or moves uniformly (a rolling wheel's axle). See docs/theory.md#rotation-about-a-pivot.
//
// Method: an algebraic circle fit (Kasa 1976) starts a joint geometric least-squares fit of
//   x_i = x_p + v_x u_i + r cos theta_i,  y_i = y_p + v_y u_i + r sin theta_i,
//   theta_i = theta_0 + omega u_i + alpha u_i^2 / 2,  u_i = t_i - t_ref (t_ref the mean time),
// to all 2n coordinates (Ceres, numerics/least_squares.hpp), so that the standard errors of
// omega and alpha include the uncertainty of the pivot and the radius (the noise level from
// the residuals, the same on x and y). v_x = v_y = 0 unless the pivot moves; x_p, y_p fixed
// when given. When that fit leaves residuals above twice those of a geometric circle fit
// (|p_i - c| - r, no time: a pendulum's angle swings, no quadratic follows it), the circle
// places the pivot and the angle model is refitted about it. The angle of every point about the fitted pivot is then unwrapped against the
// fitted theta(t), and local spins come from sliding linear fits (track/local_spin.hpp).
//
// Aliasing: the point must turn by less than pi between consecutive points.
#pragma once

#include "track/rigid_body.hpp"
#include "track/track.hpp"

#include <limits>
#include <string>
#include <vector>

namespace tribolab::track {

/// An option not given (NaN).
inline constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();

struct PivotOptions {
  /// Given pivot, m (both NaN: fitted); a given pivot is fixed
  double pivot_x = kNotGiven;
  double pivot_y = kNotGiven;  ///< m
  bool moving_pivot = false;  ///< fit a pivot moving uniformly (a rolling wheel's axle)
  int window = 7;             ///< points per local linear fit of theta(t) (>= 3)
  /// Largest standard error of the fitted pivot and radius, fraction of the radius, before
  /// the data are said not to determine the pivot (too short an arc), e.g. 0.1
  double max_pivot_sigma = 0.1;
  /// Empty when valid, else a message naming the field (field() marks).
  std::string validate() const;
  bool pivot_given() const { return pivot_x == pivot_x && pivot_y == pivot_y; }
};

/// An algebraic circle (Kasa 1976, IEEE Trans. Instrum. Meas. 25, 8): minimises
/// sum (x^2 + y^2 + D x + E y + F)^2; centre (-D/2, -E/2).
struct Circle {
  double x = 0, y = 0;  ///< centre, m
  double r = 0;         ///< radius, m (NaN when the points are collinear)
};
Circle kasa_circle(const std::vector<double>& x, const std::vector<double>& y);

/// The point at one frame.
struct PivotRow {
  int frame = 0;
  double t = 0;            ///< s
  double x = 0, y = 0;     ///< the tracked point, m
  double theta = 0;        ///< angle of pivot -> point from +x, counter-clockwise, unwrapped, rad
  double radius = 0;       ///< distance from the pivot (at t), m
  double omega = 0;        ///< local spin, rad/s (NaN where the window does not fit)
  double sigma_omega = 0;  ///< its standard error, rad/s
};

struct PivotRotation {
  std::string track;
  std::vector<PivotRow> rows;
  Circle kasa;                        ///< the algebraic start (of the detrended points when moving)
  double t_ref = 0;                   ///< s, mean time of the points
  double pivot_x = 0, pivot_y = 0;    ///< pivot at t_ref, m
  double sigma_pivot_x = 0, sigma_pivot_y = 0;  ///< m (0 when given)
  double pivot_vx = 0, pivot_vy = 0;  ///< pivot velocity, m/s (0 unless moving)
  double sigma_pivot_vx = 0, sigma_pivot_vy = 0;  ///< m/s
  double radius = 0, sigma_radius = 0;  ///< m
  double theta_ref = 0, sigma_theta_ref = 0;  ///< angle at t_ref, rad
  double omega = 0, sigma_omega = 0;  ///< spin at t_ref, rad/s, counter-clockwise positive
  double alpha = 0, sigma_alpha = 0;  ///< angular acceleration, rad/s^2
  double rms_residual = 0;            ///< per coordinate, m (the noise estimate)
  int dof = 0;                        ///< 2n - free parameters
  /// True when theta(t) is not quadratic (a pendulum swings): the pivot then comes from the
  /// geometric circle fit alone and omega, alpha only summarise the spin
  bool pivot_from_circle = false;
  double arc = 0;                     ///< theta_last - theta_first, rad
  double max_turn = 0;                ///< largest |theta_i+1 - theta_i|, rad
};

/// Fits the rotation of `track` about its pivot. Throws InputError (naming the fields) for
/// invalid options, too few points (6; 8 with a moving pivot), points that do not turn about
/// any centre (collinear), and when the data cannot determine the pivot (the standard error of
/// the pivot or radius above max_pivot_sigma of the radius: too short an arc, or noise).
PivotRotation rotation_about_pivot(const Track& track, const PivotOptions& options = {});

}  // namespace tribolab::track
