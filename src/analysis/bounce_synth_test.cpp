// Synthetic bounce video: the motion it draws is continuous through the contact.
#include "analysis/bounce_synth.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tribolab::analysis {
namespace {

TEST(SynthVideo, CentreMovesContinuouslyThroughTheContact) {
  for (double omega : {-45.0, 45.0}) {
    SynthVideoOptions o;
    o.noise = 0;
    o.omega = omega;
    const auto v = synth_video(o);
    const auto& t = v.truth;
    // The contact lasts ~15 ms: the centre moves at most max|v_x| times that horizontally.
    const double vx_max = std::max(std::abs(t.touch.vx), std::abs(t.separation.vx)) + 1;  // + friction's change, m/s
    EXPECT_LT(std::abs(t.separation.x - t.touch.x), vx_max * (t.t_separation - t.t_touch)) << omega;
    // Frame to frame, no coordinate of a tip jumps by more than the fastest tip moves in one
    // frame: |v| + |omega| a, with |v| below 5 m/s for a 0.8 m drop at 1.5 m/s.
    const double dt = 1 / o.fps;
    const double step = (5 + std::abs(omega) * o.ball.a) * dt;
    for (std::size_t k = 1; k < v.tip_a.points.size(); ++k) {
      const auto& p = v.tip_a.points[k - 1];
      const auto& q = v.tip_a.points[k];
      EXPECT_LT(std::abs(q.x - p.x), step) << "frame " << k << ", omega " << omega;
      EXPECT_LT(std::abs(q.y - p.y), step) << "frame " << k << ", omega " << omega;
    }
  }
}

TEST(ThrowMotion, PoseIsContinuousAtTouchAndSeparationAndFollowsTheContactHistory) {
  SynthVideoOptions o;
  const ThrowMotion m = simulate_throw(o);
  const auto& tr = m.truth;
  ASSERT_GT(m.contact.size(), 2u);
  // At the history's own times the interpolation returns the history (to rounding).
  for (std::size_t i = 0; i < m.contact.size(); i += std::max<std::size_t>(1, m.contact.size() / 7)) {
    const auto s = m.state(tr.t_touch + m.contact[i].t);
    EXPECT_NEAR(s.x, m.contact[i].state.x, 1e-12);
    EXPECT_NEAR(s.y, m.contact[i].state.y, 1e-12);
    EXPECT_NEAR(s.theta, m.contact[i].state.theta, 1e-12);
  }
  // Across the touch and the separation the pose moves by no more than the speed allows in
  // 1 us (|v| + |omega| a < 5 m/s: 5 um), so it is continuous where the formulas change.
  const double eps = 1e-6;
  for (double t : {tr.t_touch, tr.t_separation}) {
    const auto a = m.state(t - eps), b = m.state(t + eps);
    EXPECT_LT(std::hypot(b.x - a.x, b.y - a.y), 5 * 2 * eps) << t;
    EXPECT_LT(std::abs(b.theta - a.theta), 50 * 2 * eps) << t;  // |omega| < 50 rad/s
  }
  // Between two history samples, the Hermite pose lies within the samples' bracket of y
  // extended by the motion's curvature; checked coarsely: within 10 um of linear interpolation.
  for (std::size_t i = 0; i + 1 < m.contact.size(); i += std::max<std::size_t>(1, m.contact.size() / 11)) {
    const auto& p = m.contact[i];
    const auto& q = m.contact[i + 1];
    const auto s = m.state(tr.t_touch + 0.5 * (p.t + q.t));
    EXPECT_NEAR(s.y, 0.5 * (p.state.y + q.state.y), 1e-5) << i;
  }
  EXPECT_GT(m.t_end, tr.t_separation);
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

// numerics/error.hpp: a contact whose integration gives up on valid input is a solver
// failure, not the user's: a Hooke law so overdamped (K = 1e3 N/m, D = 1e9 N s/m) that the
// ball creeps and the integrator's step budget runs out (the same law makes `bounce
// simulate --vy -4` print "integrator step budget exhausted").
TEST(ThrowMotion, ContactIntegrationThatGivesUpIsASolverError) {
  SynthVideoOptions o;
  o.law.model = bounce::NormalModel::hooke;
  o.law.K = 1e3;
  o.law.D = 1e9;
  ASSERT_TRUE(o.validate().empty()) << o.validate();
  EXPECT_THROW(simulate_throw(o), SolverError);
  try {
    simulate_throw(o);
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("the contact did not end"), std::string::npos) << e.what();
  }
}

TEST(SynthTable, ALawThatNeverBouncesIsAnErrorNotAHang) {
  // Issue 26: `bounce synth-table --K 1e-310` (inside the stated range) ran for over 400 s:
  // no drop ever separated, and the draws were repeated without end.
  SynthTableOptions o;
  // K = 1e-310 made every contact fail (chi = D/K overflows); K = 1e-6 N/m^n without damping
  // lets the ball sink for the whole max_duration: either way no drop ever bounces.
  o.law.K = 1e-6;
  o.law.D = 0;
  try {
    synth_table(o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("200 random drops in a row gave no bounce ("), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("0 of 40 rows made): these law parameters and speeds give no "
                                         "bounce table"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(synth_table(SynthTableOptions{}).size(), 40u);  // the defaults still make their table
}

}  // namespace
}  // namespace tribolab::analysis
