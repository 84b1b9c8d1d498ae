#include "bounce/drop.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tribolab::bounce {
namespace {

TEST(Drop, ElasticFrictionlessBallReturnsToItsHeight) {
  NormalLawSpec law;
  law.model = NormalModel::hertz;
  law.n = 1.5;
  law.D = 0;
  FrictionModel f;
  f.mu = 0;
  DropRelease rel;
  rel.height = 0.8;
  DropOptions o;
  o.max_bounces = 4;
  const DropResult r = simulate_drop(Ball{}, law, f, rel, o);
  ASSERT_EQ(r.status, DropStatus::max_bounces) << r.message;
  ASSERT_EQ(r.bounces.size(), 4u);
  for (const Bounce& b : r.bounces) {
    // Energy conserved to the contact's ~1e-8 relative: apex to ~1e-8 m.
    EXPECT_NEAR(b.apex_height, 0.8, 1e-7);
    EXPECT_FALSE(b.above_release && b.apex_height > 0.8 + 1e-7);
  }
  // Free fall to the first touch: sqrt(2 (H - b) / g).
  EXPECT_NEAR(r.bounces[0].t_touch, std::sqrt(2 * (0.8 - 0.095) / 9.8), 1e-12);
}

TEST(Drop, DampedBallLosesEnergyEveryBounce) {
  // The centre's apex may rise from one bounce to the next (rotation turns into vertical
  // motion as the ball tumbles), but the mechanical energy at take-off must fall.
  DropRelease rel;
  rel.height = 1.0;
  rel.theta = 0.3;
  DropOptions o;
  o.max_bounces = 6;
  const DropResult r = simulate_drop(Ball{}, NormalLawSpec{}, FrictionModel{}, rel, o);
  ASSERT_FALSE(r.bounces.empty());
  const Ball ball;
  double prev = ball.mass * 9.8 * rel.height;
  for (const Bounce& b : r.bounces) {
    const double E = kinetic_energy(ball, b.contact.out).total() + ball.mass * 9.8 * b.contact.out.y;
    EXPECT_LT(E, prev);
    prev = E;
  }
  EXPECT_EQ(r.first_above_release, -1);
}

TEST(Drop, SpinningElasticBallCanRiseAboveItsRelease) {
  // The seed's phenomenon: with enough spin and an elastic contact, the first rebound rises
  // above the release height. Scan the release orientation; at least one must do it, and the
  // crossing time must lie between take-off and apex.
  NormalLawSpec law;
  law.model = NormalModel::hertz;
  law.n = 1.5;
  law.D = 0;
  DropOptions o;
  o.max_bounces = 1;
  int above = 0;
  for (int k = 0; k < 36; ++k) {
    DropRelease rel;
    rel.height = 0.6;
    rel.omega = -40;
    rel.theta = k * kPi / 36;
    const DropResult r = simulate_drop(Ball{}, law, FrictionModel{}, rel, o);
    if (r.first_above_release == 0) {
      ++above;
      const Bounce& b = r.bounces[0];
      EXPECT_GE(b.t_cross_release, b.t_touch + b.contact.contact_duration - 1e-12);
      EXPECT_LE(b.t_cross_release, b.t_apex + 1e-12);
      EXPECT_GT(b.apex_height, 0.6);
    }
  }
  EXPECT_GT(above, 0);
}

TEST(Drop, TrajectorySamplesAreContinuous) {
  DropRelease rel;
  rel.height = 0.7;
  rel.omega = 20;
  rel.vx = 1;
  DropOptions o;
  o.max_bounces = 2;
  o.sample_dt = 1e-3;
  const DropResult r = simulate_drop(Ball{}, NormalLawSpec{}, FrictionModel{}, rel, o);
  ASSERT_GT(r.trajectory.size(), 100u);
  for (std::size_t i = 1; i < r.trajectory.size(); ++i) {
    const auto& p = r.trajectory[i - 1];
    const auto& q = r.trajectory[i];
    EXPECT_GE(q.t, p.t - 1e-15);
    // Speeds are below 10 m/s: positions move less than 10 * dt between samples.
    EXPECT_LT(std::abs(q.state.y - p.state.y), 10 * (q.t - p.t) + 1e-12);
  }
}

TEST(Drop, DampedFlatBallComesToRest) {
  // Seed's law, central (e ~ 0.4 at these speeds, lower as they fall): the energy above rest
  // shrinks by ~e^2 per bounce and drops below m g rest_height well before 50 bounces.
  DropRelease rel;
  rel.height = 0.5;
  DropOptions o;
  o.max_bounces = 50;
  const DropResult r = simulate_drop(Ball{}, NormalLawSpec{}, FrictionModel{}, rel, o);
  EXPECT_EQ(r.status, DropStatus::rest) << r.message;
  EXPECT_LT(r.bounces.size(), 50u);
  EXPECT_EQ(r.first_above_release, -1);
}

TEST(Drop, ReleaseThroughTheFloorIsAnInputError) {
  DropRelease rel;
  rel.height = 0.05;
  EXPECT_THROW(simulate_drop(Ball{}, NormalLawSpec{}, FrictionModel{}, rel), InputError);
}

}  // namespace
}  // namespace tribolab::bounce
