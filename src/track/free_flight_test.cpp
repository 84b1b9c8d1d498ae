// The free-flight check (free_flight.hpp, docs/theory.md#free-flight-check) on synthetic
// tracks with 1 mm noise: a throw at the right frame rate falls at g; wrong times, a flipped
// or turned axis are caught; a slide, a cart on a slope and a pendulum are not held against g.
#include "track/free_flight.hpp"

#include "track/synthetic_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace tribolab::track {
namespace {

constexpr double kNoise = 1e-3;  // m: a ball tracked to about a pixel at 1 mm per pixel

/// A track sampled at `fps` for `duration` s from the motion p(t) = (x, y), with 1 mm noise;
/// the times written into the file are multiplied by `time_factor` (a wrong frame rate).
Track sampled(const std::function<std::array<double, 2>(double)>& p, double fps, double duration, unsigned seed,
              double time_factor = 1) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, kNoise);
  Track t;
  t.name = "ball";
  for (int i = 0; i < static_cast<int>(duration * fps); ++i) {
    const auto q = p(i / fps);
    t.points.push_back({i, time_factor * i / fps, q[0] + n(rng), q[1] + n(rng)});
  }
  return t;
}

/// A ball thrown up at 3 m/s (and 1.5 m/s across) at 240 fps for 0.6 s: apex at 0.31 s.
Track throw_up(unsigned seed, double time_factor = 1, double g = kDefaultG) {
  return sampled([g](double s) { return std::array<double, 2>{0.2 + 1.5 * s, 1.0 + 3.0 * s - 0.5 * g * s * s}; }, 240,
                 0.6, seed, time_factor);
}

SegmentAcceleration check_one(const Track& t, const FreeFlightOptions& o = {}) {
  const std::vector<double> ts = [&] {
    std::vector<double> v;
    for (const auto& p : t.points) v.push_back(p.t);
    return v;
  }();
  std::vector<double> xs, ys;
  for (const auto& p : t.points) xs.push_back(p.x), ys.push_back(p.y);
  const auto r = check_free_flight(t, {{0, t.points.size()}}, robust_noise(ts, xs), robust_noise(ts, ys), o);
  EXPECT_EQ(r.size(), 1u);
  return r.front();
}

TEST(FreeFlight, AThrowAtTheRightFrameRateFallsAtG) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const SegmentAcceleration a = check_one(throw_up(seed));
    ASSERT_EQ(a.shape, FlightShape::free_flight) << "seed " << seed;
    EXPECT_TRUE(a.plausible()) << "seed " << seed << ": |a| = " << a.magnitude << ", tilt " << a.tilt_deg;
    // 144 points of 1 mm noise over 0.6 s: sigma(a) = 2 sqrt(180/(n T^4)) 1 mm ~ 0.03 m/s^2;
    // the fitted a lies within 5 of its own standard errors of the truth.
    EXPECT_NEAR(a.ay, -kDefaultG, 5 * a.sigma_ay) << "seed " << seed;
    EXPECT_NEAR(a.ax, 0, 5 * a.sigma_ax) << "seed " << seed;
    EXPECT_LT(a.sigma_ay, 0.1);
  }
}

TEST(FreeFlight, TimesWrongByTwoOrEightAreCaught) {
  // A frame rate read c times too low stretches every time by c and divides a by c^2.
  for (double c : {2.0, 8.0, 0.5, 0.125}) {
    const SegmentAcceleration a = check_one(throw_up(3, c));
    ASSERT_EQ(a.shape, FlightShape::free_flight) << "time factor " << c;
    EXPECT_TRUE(a.magnitude_off) << "time factor " << c << ": |a| = " << a.magnitude;
    EXPECT_FALSE(a.points_up);
    // |a| = g / c^2 within 5 standard errors (the noise is the same, the time unit is not).
    EXPECT_NEAR(a.magnitude, kDefaultG / (c * c), 5 * a.sigma_magnitude) << "time factor " << c;
  }
}

TEST(FreeFlight, AFlippedYAxisIsCaught) {
  Track t = throw_up(5);
  for (auto& p : t.points) p.y = -p.y;  // image rows: y grows downwards
  const SegmentAcceleration a = check_one(t);
  ASSERT_EQ(a.shape, FlightShape::free_flight);
  EXPECT_TRUE(a.points_up);
  EXPECT_FALSE(a.magnitude_off);  // |a| is still g: only the direction is wrong
  EXPECT_NEAR(std::abs(a.tilt_deg), 180, 1);  // 1 deg: ~30 sds of the tilt with 1 mm noise
}

TEST(FreeFlight, ACameraTurnedBy8DegreesIsCaught) {
  const double turn = 8 * std::numbers::pi / 180, c = std::cos(turn), s = std::sin(turn);
  Track t = throw_up(6);
  for (auto& p : t.points) {
    const double x = p.x, y = p.y;
    p.x = c * x - s * y;
    p.y = s * x + c * y;
  }
  const SegmentAcceleration a = check_one(t);
  ASSERT_EQ(a.shape, FlightShape::free_flight);
  EXPECT_TRUE(a.tilted);
  EXPECT_FALSE(a.magnitude_off);
  // Axes turned by +8 deg turn the data by +8 deg: g then points 8 deg counter-clockwise from -y.
  EXPECT_NEAR(a.tilt_deg, 8, 5 * a.sigma_tilt_deg);
}

TEST(FreeFlight, ACartUpAndDownA20DegreeSlopeIsNotHeldAgainstG) {
  // A cart on an air track (no friction) launched up a 20 deg slope seen from the side: one
  // constant acceleration g sin(20 deg) = 3.35 m/s^2 along the slope, and it turns back.
  const double phi = 20 * std::numbers::pi / 180, a = kDefaultG * std::sin(phi);
  const Track t = sampled(
      [&](double s) {
        const double along = 2.0 * s - 0.5 * a * s * s;
        return std::array<double, 2>{along * std::cos(phi), along * std::sin(phi)};
      },
      240, 1.0, 8);
  const SegmentAcceleration r = check_one(t);
  EXPECT_EQ(r.shape, FlightShape::not_along_y);
  // 90 - 20 deg from -y, down-slope to the -x side; 1 deg: the tilt's sd is ~0.01 deg here
  EXPECT_NEAR(r.tilt_deg, -70, 1);
  EXPECT_NEAR(r.magnitude, a, 0.05);  // 0.05 m/s^2: > 5 sd of the fit (1 mm over 1 s)
}

TEST(FreeFlight, ASlideDownTheFallLineInTheInclineFrameIsNotHeldAgainstG) {
  // Seed 000's frame: y up the slope, so a slide straight down accelerates along -y, at
  // g (sin phi - mu cos phi) = 3.2 m/s^2 for phi = 30 deg, mu = 0.2.
  const double phi = 30 * std::numbers::pi / 180, mu = 0.2;
  const double down = kDefaultG * (std::sin(phi) - mu * std::cos(phi));
  const Track slide = sampled([&](double s) { return std::array<double, 2>{0.0, -0.5 * s - 0.5 * down * s * s}; },
                              80, 0.8, 9);
  EXPECT_EQ(check_one(slide).shape, FlightShape::no_turning_point);
  // At rest for 0.13 s, then sliding (the demo's slide_41.09deg): one parabola fits it to about
  // the noise and puts its vertex inside the record, but the data never rise.
  const double a41 = 1.72;
  const Track rest_then_slide = sampled(
      [&](double s) {
        const double r = std::max(0.0, s - 0.13);
        return std::array<double, 2>{0.05, -0.5 * a41 * r * r};
      },
      240, 0.7, 14);
  const SegmentAcceleration r = check_one(rest_then_slide);
  EXPECT_EQ(r.shape, FlightShape::no_turning_point);
  EXPECT_LT(r.rms_y, 2 * kNoise + 1e-3);  // it passed the constant-acceleration test
  // Launched up the slope it turns back, but the friction flips at the turn: two accelerations.
  const double up = kDefaultG * (std::sin(phi) + mu * std::cos(phi));
  const double v0 = 2.0, t_turn = v0 / up, y_turn = v0 * t_turn - 0.5 * up * t_turn * t_turn;
  const Track turn = sampled(
      [&](double s) {
        if (s < t_turn) return std::array<double, 2>{0.0, v0 * s - 0.5 * up * s * s};
        const double r = s - t_turn;
        return std::array<double, 2>{0.0, y_turn - 0.5 * down * r * r};
      },
      80, 1.0, 10);
  EXPECT_EQ(check_one(turn).shape, FlightShape::not_constant_acceleration);
}

TEST(FreeFlight, APendulumIsNotHeldAgainstG) {
  // 1 m pendulum swinging 30 deg each way for 2 s at 60 fps: the bob turns back in y twice
  // per swing and its acceleration changes all the time.
  const double L = 1.0, amp = 30 * std::numbers::pi / 180, w = std::sqrt(kDefaultG / L);
  const Track t = sampled(
      [&](double s) {
        const double th = amp * std::cos(w * s);
        return std::array<double, 2>{L * std::sin(th), -L * std::cos(th)};
      },
      60, 2.0, 11);
  EXPECT_EQ(check_one(t).shape, FlightShape::not_constant_acceleration);
}

TEST(FreeFlight, ADropFromRestAndShortSegmentsAreNotChecked) {
  // Released from rest: no turn in y, indistinguishable from a slide from rest.
  const Track drop = sampled([](double s) { return std::array<double, 2>{0.0, 1.0 - 0.5 * kDefaultG * s * s}; }, 240,
                             0.4, 12);
  EXPECT_EQ(check_one(drop).shape, FlightShape::no_turning_point);
  Track few = throw_up(13);
  few.points.resize(7);  // fewer than min_points = 8
  EXPECT_EQ(check_one(few).shape, FlightShape::too_few_points);
}

TEST(FreeFlight, EachBounceOfABallIsCheckedBetweenImpacts) {
  // Point-mass bounces at 240 fps with 1 mm noise (synthetic_test_util.hpp); the first flight
  // falls from rest (not checked), the later ones rise and fall (checked, at g). Contacts at
  // 0.46, 1.19 and 1.77 s, the last apex at 2.00 s: the record ends at 2.2 s, past it.
  const auto b = testing::bouncing_ball(240, 2.2, 1.0, 0.4, 0.8, kNoise, 21);
  const ImpactResult im = detect_impacts(b.track);
  ASSERT_EQ(im.impacts.size(), b.contact_times.size());
  const auto fits = check_free_flight(b.track, flight_segments(b.track.points.size(), im.impacts), im.noise_x,
                                      im.noise_y);
  ASSERT_EQ(fits.size(), 4u);
  EXPECT_EQ(fits.front().shape, FlightShape::no_turning_point);
  for (std::size_t i = 1; i < fits.size(); ++i) {
    EXPECT_EQ(fits[i].shape, FlightShape::free_flight) << "segment " << i;
    EXPECT_TRUE(fits[i].plausible()) << "segment " << i << ": |a| = " << fits[i].magnitude;
  }
}

TEST(FreeFlight, TimesTooClusteredForAParabolaAreReportedNotThrown) {
  // Increasing times 1e-200 s apart: t^2 underflows, the least-squares parabola is singular.
  // The check must say so and never fail the command that asked for derivatives.
  Track t;
  for (int i = 0; i < 12; ++i) t.points.push_back({i, i * 1e-200, 0.001 * (i % 3), 0.002 * (i % 2)});
  const auto r = check_free_flight(t, {{0, t.points.size()}}, 1e-3, 1e-3);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].shape, FlightShape::no_fit);
  EXPECT_TRUE(std::isnan(r[0].ax));
}

TEST(FreeFlightOptions, BadValuesAreNamed) {
  FreeFlightOptions o;
  o.g = 0;
  EXPECT_NE(o.validate().find("g"), std::string::npos);
  o = {};
  o.max_tilt_deg = 95;
  EXPECT_NE(o.validate().find("max_tilt_deg"), std::string::npos);
  EXPECT_EQ(FreeFlightOptions{}.validate(), "");
}

}  // namespace
}  // namespace tribolab::track
