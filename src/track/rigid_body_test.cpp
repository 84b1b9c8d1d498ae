#include "track/rigid_body.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace tribolab::track {
namespace {

struct Tips {
  Track a, b;
};

/// Tips of a rod of half-length `half` spinning at omega about a centre in free flight.
Tips spinning(double omega, double half, double fps, int n, double noise, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0, noise);
  Tips t{{"tip A", {}}, {"tip B", {}}};
  for (int i = 0; i < n; ++i) {
    const double ti = i / fps;
    const double xc = 0.2 + 1.5 * ti, yc = 1.0 + 2.0 * ti - 4.9 * ti * ti;
    const double th = 0.3 + omega * ti;
    t.a.points.push_back({i, ti, xc - half * std::cos(th) + nd(rng), yc - half * std::sin(th) + nd(rng)});
    t.b.points.push_back({i, ti, xc + half * std::cos(th) + nd(rng), yc + half * std::sin(th) + nd(rng)});
  }
  return t;
}

TEST(RigidBody, ExactCentreOrientationAndSpinWithoutNoise) {
  // 30 rad/s over 0.5 s is 2.4 turns: the unwrapped angle must stay a straight line.
  const Tips t = spinning(30, 0.145, 240, 120, 0, 0);
  const RigidBody body = rigid_body_from_points(t.a, t.b);
  ASSERT_EQ(body.rows.size(), 120u);
  for (const auto& r : body.rows) {
    EXPECT_NEAR(r.theta, 0.3 + 30 * r.t, 1e-12);
    EXPECT_NEAR(r.xc, 0.2 + 1.5 * r.t, 1e-12);
    EXPECT_NEAR(r.length, 0.29, 1e-12);
    EXPECT_NEAR(r.omega, 30, 1e-9);
  }
  EXPECT_NEAR(body.spin.omega, 30, 1e-9);
  EXPECT_NEAR(body.length_mean, 0.29, 1e-12);
  EXPECT_EQ(centre_track(body).points.size(), 120u);
}

TEST(RigidBody, NegativeSpinUnwrapsDownwards) {
  const RigidBody body = rigid_body_from_points(spinning(-50, 0.1, 240, 100, 0, 0).a,
                                                spinning(-50, 0.1, 240, 100, 0, 0).b);
  EXPECT_NEAR(body.rows.back().theta - body.rows.front().theta, -50 * 99 / 240.0, 1e-9);
}

TEST(RigidBody, SpinStandardErrorMatchesTheScatter) {
  // 400 runs with 1 mm noise on each tip: the mean of ((omega - 30)/sigma)^2 has standard
  // deviation sqrt(2/400) = 0.07 for a correct sigma; tolerance 0.3 (about 4 of those).
  double z2 = 0, z2_local = 0;
  const int runs = 400;
  for (int r = 0; r < runs; ++r) {
    const Tips t = spinning(30, 0.145, 240, 60, 0.001, 100 + r);
    const RigidBody body = rigid_body_from_points(t.a, t.b);
    z2 += std::pow((body.spin.omega - 30) / body.spin.sigma_omega, 2) / runs;
    const auto& mid = body.rows[30];
    z2_local += std::pow((mid.omega - 30) / mid.sigma_omega, 2) / runs;
  }
  EXPECT_NEAR(z2, 1.0, 0.3);
  EXPECT_NEAR(z2_local, 1.0, 0.3);
}

TEST(RigidBody, NeedsTwoCommonFrames) {
  Track a{"a", {{0, 0, 0, 0}, {1, 0.1, 0, 0}}}, b{"b", {{1, 0.1, 1, 0}, {2, 0.2, 1, 0}}};
  EXPECT_THROW(rigid_body_from_points(a, b), InputError);
}

}  // namespace
}  // namespace tribolab::track
