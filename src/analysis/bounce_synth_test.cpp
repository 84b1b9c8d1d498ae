// Synthetic bounce video: the motion it draws is continuous through the contact.
#include "analysis/bounce_synth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

}  // namespace
}  // namespace tribolab::analysis
