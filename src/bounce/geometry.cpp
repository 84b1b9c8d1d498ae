#include "bounce/geometry.hpp"

#include "numerics/physical_range.hpp"

#include "numerics/error.hpp"
#include "numerics/roots.hpp"
#include "numerics/units.hpp"

#include <cmath>
#include <numbers>

namespace tribolab::bounce {

std::string Ball::validate() const {
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  if (auto e = range_error(a, ranges::size, "a"); !e.empty()) return e;
  if (auto e = range_error(b, ranges::size, "b"); !e.empty()) return e;
  if (b > a) return "b: semi-minor axis must not exceed the semi-major axis a (a >= b)";
  if (auto e = range_error(mass, ranges::mass, "mass"); !e.empty()) return e;
  if (auto e = range_error(inertia, ranges::inertia, "inertia"); !e.empty()) return e;
  return {};
}

// Support point of the ellipse rotated by theta (docs/theory.md#bounce-geometry).
// Body points p(s) = R(theta) (a cos s, b sin s); their height a cos s sin(theta) +
// b sin s cos(theta) is least, -Y, at (cos s, sin s) = -(a sin(theta), b cos(theta)) / Y,
// where the point sits at X = -(a^2 - b^2) sin(theta) cos(theta) / Y = -dY/dtheta.
Support support(const Ball& ball, double theta) {
  const double s = std::sin(theta), c = std::cos(theta);
  const double a2 = ball.a * ball.a, b2 = ball.b * ball.b;
  Support sp;
  sp.Y = std::sqrt(a2 * s * s + b2 * c * c);
  sp.dY = (a2 - b2) * s * c / sp.Y;
  sp.X = -sp.dY;
  // Support function h of a convex curve: h + h'' = radius of curvature = (ab)^2 / h^3.
  sp.d2Y = a2 * b2 / (sp.Y * sp.Y * sp.Y) - sp.Y;
  return sp;
}

double support_depth(const Ball& ball, double theta) { return support(ball, theta).Y; }
double support_depth_slope(const Ball& ball, double theta) { return support(ball, theta).dY; }
double support_depth_curvature(const Ball& ball, double theta) {
  return support(ball, theta).d2Y;
}

PointVelocity contact_point_velocity(const Ball& ball, double theta, double vx, double vy,
                                     double omega) {
  const Support sp = support(ball, theta);
  return {vx + omega * sp.Y, vy + omega * sp.X};
}

double wrap_angle(double theta) {
  constexpr double pi = std::numbers::pi;
  double r = std::remainder(theta, 2 * pi);  // in [-pi, pi]
  if (r <= -pi) r += 2 * pi;
  return r;
}

double collision_angle_deg(const Ball& ball, double theta, int direction) {
  const Support sp = support(ball, theta);
  const double c = std::cos(theta), s = std::sin(theta);
  // Rear tip: the end of the major axis whose horizontal offset points against the motion;
  // with the axis exactly vertical, the lower tip (where the ball then touches).
  double sign = (c * direction < 0) ? 1.0 : -1.0;
  if (c == 0) sign = (s < 0) ? 1.0 : -1.0;
  const double tx = sign * c, ty = sign * s;
  const double rx = sp.X, ry = -sp.Y;
  const double cross = rx * ty - ry * tx, dot = rx * tx + ry * ty;
  return to_deg(std::atan2(std::abs(cross), dot));
}

double theta_for_collision_angle(const Ball& ball, double angle_deg, int direction) {
  if (!(angle_deg >= 0 && angle_deg <= 180)) {
    throw InputError("collision angle", "must lie in [0, 180] degrees");
  }
  constexpr double half = std::numbers::pi / 2;
  if (angle_deg == 0) return direction * half;
  if (angle_deg == 180) return -direction * half;
  // On (-pi/2, pi/2) with direction +1 the angle decreases from 180 to 0.
  auto f = [&](double th) { return collision_angle_deg(ball, th, +1) - angle_deg; };
  const double lo = std::nextafter(-half, 0.0), hi = std::nextafter(half, 0.0);
  const numerics::RootResult r = numerics::find_root(f, lo, hi);
  if (!r.converged) throw SolverError("collision angle", "no orientation found");
  return direction * r.x;
}

}  // namespace tribolab::bounce
