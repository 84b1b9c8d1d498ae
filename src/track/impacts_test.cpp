#include "track/impacts.hpp"

#include "track/synthetic_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace tribolab::track {
namespace {

TEST(Impacts, FoundAtTheRightFrameOnNoisyBouncesFrom80To240Fps) {
  // Ball dropped from 1 m, e = 0.8, 1 mm noise; 20 seeds per frame rate. The truth: the
  // contact instant lies between points k and k+1. When it lies within 10% of a frame of a
  // sample, that sample sits on both parabolas and either split is right.
  for (double fps : {80.0, 120.0, 240.0}) {
    for (unsigned seed = 0; seed < 20; ++seed) {
      const auto b = testing::bouncing_ball(fps, 1.6, 1.0, 0.4, 0.8, 0.001, seed,
                                            0.0123 + 0.0007 * seed);
      const ImpactResult r = detect_impacts(b.track);
      ASSERT_EQ(r.impacts.size(), b.contact_times.size()) << fps << " fps, seed " << seed;
      const double dt = 1 / fps;
      for (std::size_t j = 0; j < r.impacts.size(); ++j) {
        const double tc = b.contact_times[j];
        const auto& pts = b.track.points;
        std::size_t k = 0;
        while (k + 1 < pts.size() && pts[k + 1].t < tc) ++k;
        const Impact& im = r.impacts[j];
        const bool near_sample = std::abs(tc - pts[k].t) < 0.1 * dt ||
                                 std::abs(tc - pts[k + 1].t) < 0.1 * dt;
        if (near_sample) {
          EXPECT_LE(std::abs(static_cast<long>(im.index) - static_cast<long>(k)), 1);
        } else {
          EXPECT_EQ(im.index, k) << fps << " fps, seed " << seed << ", impact " << j;
        }
        // contact time from the crossing parabolas: position noise 1 mm at ~3 m/s is ~0.3 ms
        EXPECT_NEAR(im.t, tc, 0.25 * dt) << fps << " fps, seed " << seed;
        EXPECT_GT(im.dvy, 0);  // a bounce turns the velocity upwards
      }
    }
  }
}

TEST(Impacts, NoneOnASmoothNoisyParabola) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0, 0.001);
  for (int run = 0; run < 50; ++run) {
    Track t{"p", {}};
    for (int i = 0; i < 200; ++i) {
      const double ti = i / 240.0;
      t.points.push_back({i, ti, 0.5 * ti + n(rng), 2 + 3 * ti - 4.9 * ti * ti + n(rng)});
    }
    EXPECT_TRUE(detect_impacts(t).impacts.empty()) << "run " << run;
  }
}

TEST(Impacts, NoneOnAMarkOnAWheelTurningUpTo43DegreesPerFrame) {
  // Issue 24/27: a mark on a bicycle wheel (22.7 rad/s at 30 fps, 43 degrees per frame) gave
  // an "impact" of significance 18.7. A parabola cannot follow a circle sampled that coarsely:
  // before the smooth-turning test every split from 20 degrees per frame on was a candidate
  // (z 16-21 for these wheels). Fixed axle and rolling wheel (the axle moving r omega, the mark
  // on the rim), radius 0.3 m, 2 mm noise, 4 seeds each.
  for (double deg_per_frame : {20.0, 30.0, 43.0}) {
    for (bool rolling : {false, true}) {
      for (unsigned seed = 0; seed < 4; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> n(0, 0.002);
        const double fps = 30, r = 0.3, omega = deg_per_frame * std::numbers::pi / 180 * fps;
        Track t{"rim", {}};
        for (int i = 0; i < 45; ++i) {
          const double ti = i / fps;
          const double axle = rolling ? r * omega * ti : 0;
          t.points.push_back({i, ti, axle + r * std::cos(-omega * ti + 1) + n(rng), 0.5 + r * std::sin(-omega * ti + 1) + n(rng)});
        }
        EXPECT_TRUE(detect_impacts(t).impacts.empty())
            << deg_per_frame << " deg/frame, rolling " << rolling << ", seed " << seed << ": significance "
            << detect_impacts(t).impacts.front().significance;
      }
    }
  }
}

TEST(Impacts, RobustNoiseEstimateIgnoresGravityAndBounces) {
  // MAD of normalised third differences: consistent for Gaussian noise; 3000 points give a
  // few % scatter, bounces touch only ~3 differences each. Tolerance 15%.
  const auto b = testing::bouncing_ball(240, 12.0, 1.0, 0.4, 0.9, 0.002, 5);
  const ImpactResult r = detect_impacts(b.track);
  EXPECT_NEAR(r.noise_y / 0.002, 1.0, 0.15);
  EXPECT_NEAR(r.noise_x / 0.002, 1.0, 0.15);
}

TEST(Impacts, SplitTrackIntoFlightSegments) {
  const auto b = testing::bouncing_ball(240, 1.6, 1.0, 0.4, 0.8, 0.001, 1);
  const ImpactResult r = detect_impacts(b.track);
  const auto parts = split_track(b.track, r.impacts);
  ASSERT_EQ(parts.size(), r.impacts.size() + 1);
  std::size_t total = 0;
  for (const auto& p : parts) total += p.points.size();
  EXPECT_EQ(total, b.track.points.size());
  EXPECT_EQ(parts[0].name, "ball#1");
  EXPECT_EQ(parts[1].points.front().frame, b.track.points[r.impacts[0].index + 1].frame);
  const auto segs = flight_segments(10, {});
  ASSERT_EQ(segs.size(), 1u);
  EXPECT_EQ(segs[0].size(), 10u);
}

}  // namespace
}  // namespace tribolab::track
