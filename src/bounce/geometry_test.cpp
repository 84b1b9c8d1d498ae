#include "bounce/geometry.hpp"
#include "numerics/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace tribolab::bounce {
namespace {

// Lowest point of the rotated ellipse by brute force: dense scan of the parameter s, then a
// golden-section polish; independent of the closed form.
struct Lowest {
  double x, y;
};
Lowest brute_force_lowest(const Ball& b, double theta) {
  auto height = [&](double s) { return b.a * std::cos(s) * std::sin(theta) + b.b * std::sin(s) * std::cos(theta); };
  double best = 0, hb = 1e9;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double s = 2 * kPi * i / n;
    if (height(s) < hb) { hb = height(s); best = s; }
  }
  double lo = best - 2 * kPi / n, hi = best + 2 * kPi / n;
  const double r = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 100; ++k) {
    const double m1 = hi - r * (hi - lo), m2 = lo + r * (hi - lo);
    (height(m1) < height(m2) ? hi : lo) = (height(m1) < height(m2) ? m2 : m1);
  }
  const double s = 0.5 * (lo + hi);
  return {b.a * std::cos(s) * std::cos(theta) - b.b * std::sin(s) * std::sin(theta), height(s)};
}

TEST(Geometry, SupportDepthAtAxesIsTheSemiAxis) {
  const Ball ball;
  EXPECT_DOUBLE_EQ(support_depth(ball, 0), ball.b);
  EXPECT_NEAR(support_depth(ball, kPi / 2), ball.a, 1e-15);  // rounding of cos(pi/2) only
}

TEST(Geometry, SupportPointMatchesBruteForceMinimum) {
  const Ball ball;
  for (int k = -18; k <= 18; ++k) {
    const double th = k * kPi / 18 + 0.01;
    const Support sp = support(ball, th);
    const Lowest lo = brute_force_lowest(ball, th);
    // Golden section converges to the bracket width ~1e-13 in s; the height is quadratic
    // near the minimum, so depth agrees to ~1e-15 and position to ~1e-9 (sqrt of rounding).
    EXPECT_NEAR(-sp.Y, lo.y, 1e-13) << th;
    EXPECT_NEAR(sp.X, lo.x, 1e-7) << th;
  }
}

TEST(Geometry, SeedEquation18IsWrongAtNinetyDegrees) {
  // seed 001 prints Y = |-b [cos^2 + (a/b)^2 sin^2]|; at theta = 90 deg that is a^2/b, but the
  // lowest point of an upright ellipse is the tip of the major axis, a below the centre.
  const Ball ball;
  const double seed_Y = ball.b * (0 + (ball.a / ball.b) * (ball.a / ball.b) * 1);
  const Lowest lo = brute_force_lowest(ball, kPi / 2);
  EXPECT_NEAR(-lo.y, ball.a, 1e-12);
  EXPECT_GT(std::abs(seed_Y + lo.y), 0.07);  // a^2/b - a = 0.076 m
}

TEST(Geometry, SeedEquations5And9And17) {
  // seed 001, experiment 3 (實驗三) 6-7: the ellipse of eq 4, F(x, y) = 1 with
  // F = ((x c - y s)/a)^2 + ((y c + x s)/b)^2, differentiated implicitly. On points of the
  // ellipse (x' = a cos u, y' = b sin u rotated back) central differences (h = 1e-6, error
  // ~1e-10) give dF/dx = A1 + A2 as printed, dF/dy = B1 + B2 only with B2's +2x sin cos
  // (eq 9 prints -), and the curve's slope dy/dx = -(A1 + A2)/(B1 + B2) (eq 5 drops the minus).
  const double a = 0.145, b = 0.095, h = 1e-6;
  for (double th : {0.3, 1.1, 2.0}) {
    const double c = std::cos(th), s = std::sin(th);
    auto F = [&](double x, double y) {
      const double p = (x * c - y * s) / a, q = (y * c + x * s) / b;
      return p * p + q * q;
    };
    auto point = [&](double u) {  // inverse of eqs 2-3
      const double xp = a * std::cos(u), yp = b * std::sin(u);
      return std::pair{xp * c + yp * s, yp * c - xp * s};
    };
    for (double u : {0.4, 2.5, 4.0}) {
      const auto [x, y] = point(u);
      ASSERT_NEAR(F(x, y), 1, 1e-12);
      const double A = (2 * x * c * c - 2 * y * s * c) / (a * a) + (2 * x * s * s + 2 * y * s * c) / (b * b);
      const double B1 = (2 * y * s * s - 2 * x * s * c) / (a * a);
      const double B2_right = (2 * y * c * c + 2 * x * s * c) / (b * b);
      const double B2_printed = (2 * y * c * c - 2 * x * s * c) / (b * b);
      const double Fx = (F(x + h, y) - F(x - h, y)) / (2 * h), Fy = (F(x, y + h) - F(x, y - h)) / (2 * h);
      EXPECT_NEAR(Fx, A, 1e-6 * std::abs(A) + 1e-6);
      EXPECT_NEAR(Fy, B1 + B2_right, 1e-6 * std::abs(Fy) + 1e-6);
      EXPECT_GT(std::abs(Fy - (B1 + B2_printed)), 0.1);  // 4 |x s c| / b^2 >= 0.36 at these points
      const auto [x1, y1] = point(u + h);
      const auto [x0, y0] = point(u - h);
      const double slope = (y1 - y0) / (x1 - x0);
      EXPECT_NEAR(slope, -A / (B1 + B2_right), 1e-6 * std::abs(slope) + 1e-6);
    }
    // Eq 17: r sin(phi + theta - theta) = r sin(phi + theta) cos theta - r sin theta cos(phi + theta).
    const double r = 0.12, phi = 0.7;
    EXPECT_NEAR(r * std::sin(phi + th) * c - r * s * std::cos(phi + th), r * std::sin(phi), 1e-15);
    EXPECT_GT(std::abs(r * std::sin(phi + th) * c + r * s * std::cos(phi + th) - r * std::sin(phi)), 0.01);
  }
}

TEST(Geometry, DerivativesMatchFiniteDifferences) {
  const Ball ball;
  const double h = 1e-5;
  for (double th = -3; th < 3; th += 0.37) {
    const Support sp = support(ball, th);
    const double fd1 = (support_depth(ball, th + h) - support_depth(ball, th - h)) / (2 * h);
    const double fd2 = (support_depth(ball, th + h) - 2 * sp.Y + support_depth(ball, th - h)) / (h * h);
    // Central differences: error h^2 Y'''/6 ~ 1e-11 for the first, rounding eps Y / h^2 ~ 3e-7
    // for the second.
    EXPECT_NEAR(sp.dY, fd1, 1e-9) << th;
    EXPECT_NEAR(sp.d2Y, fd2, 2e-6) << th;
    EXPECT_DOUBLE_EQ(sp.X, -sp.dY);
  }
}

TEST(Geometry, SlopeAndCurvatureBoundsAreSharp) {
  const Ball ball;
  const double a = ball.a, b = ball.b;
  double max_slope = 0, max_curv = -1e9, min_curv = 1e9;
  for (int i = 0; i < 200000; ++i) {
    const Support sp = support(ball, kPi * i / 200000);
    max_slope = std::max(max_slope, std::abs(sp.dY));
    max_curv = std::max(max_curv, sp.d2Y);
    min_curv = std::min(min_curv, sp.d2Y);
  }
  // max |Y'| = a - b, reached at sin^2 = b / (a + b) (docs/theory.md#bounce-flight).
  EXPECT_LE(max_slope, a - b + 1e-15);
  EXPECT_NEAR(max_slope, a - b, 1e-9);  // grid spacing 1.6e-5 rad, quadratic maximum
  const double th_star = std::asin(std::sqrt(b / (a + b)));
  EXPECT_NEAR(std::abs(support(ball, th_star).dY), a - b, 1e-15);
  EXPECT_NEAR(max_curv, (a * a - b * b) / b, 1e-12);
  EXPECT_NEAR(min_curv, -(a * a - b * b) / a, 1e-9);
}

TEST(Geometry, ContactPointVelocityIsRigidBodyVelocity) {
  const Ball ball;
  const double th = 0.7, vx = 1.3, vy = -2.1, w = 35;
  const Support sp = support(ball, th);
  const PointVelocity pv = contact_point_velocity(ball, th, vx, vy, w);
  // v + omega x r, r = (X, -Y): (vx - w ry, vy + w rx).
  EXPECT_DOUBLE_EQ(pv.vx, vx + w * sp.Y);
  EXPECT_DOUBLE_EQ(pv.vy, vy + w * sp.X);
}

TEST(Geometry, CollisionAngleKnownValues) {
  const Ball ball;
  // Horizontal axis: support point straight below, rear tip straight behind: 90 deg.
  EXPECT_NEAR(collision_angle_deg(ball, 0, +1), 90, 1e-12);
  // Rear tip nearly down (moving +x, axis tilted so the rear end is low): near 0 deg.
  EXPECT_LT(collision_angle_deg(ball, kPi / 2 - 0.01, +1), 1.0);
  // Front tip nearly down: the support point is opposite the rear tip, near 180 deg.
  EXPECT_GT(collision_angle_deg(ball, kPi / 2 + 0.01, +1), 179.0);
  // Mirror image: (theta, +1) and (-theta, -1).
  for (double th = -3; th < 3; th += 0.29)
    EXPECT_NEAR(collision_angle_deg(ball, th, +1), collision_angle_deg(ball, -th, -1), 1e-12) << th;
}

TEST(Geometry, CollisionAngleInverseRoundTrips) {
  const Ball ball;
  double prev = -1;
  for (double th = -1.55; th < 1.56; th += 0.05) {
    const double ang = collision_angle_deg(ball, th, +1);
    if (prev >= 0) {
      EXPECT_LT(ang, prev) << th;  // monotone on the branch
    }
    prev = ang;
  }
  for (double ang = 5; ang < 180; ang += 5) {
    for (int dir : {+1, -1}) {
      const double th = theta_for_collision_angle(ball, ang, dir);
      // TOMS 748 to the last bits of theta; the angle is a smooth function of it.
      EXPECT_NEAR(collision_angle_deg(ball, th, dir), ang, 1e-9) << ang << " " << dir;
    }
  }
}

TEST(Geometry, BallValidationNamesTheField) {
  Ball b;
  b.b = 0.2;
  EXPECT_NE(b.validate().find("b"), std::string::npos);
  b = Ball{};
  b.mass = -1;
  EXPECT_NE(b.validate().find("mass"), std::string::npos);
  EXPECT_TRUE(Ball{}.validate().empty());
}

}  // namespace
}  // namespace tribolab::bounce
