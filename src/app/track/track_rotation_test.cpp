// `track rotation` and `track kinematics --from/--to` in the application layer
// (src/app/track/track_rotation.hpp, track_kinematics.hpp): one point turning about a pivot, the
// kinematics of the same point (no impact in smooth circular motion), a restricted time range.
#include "app/track/track_rotation.hpp"

#include "app/track/track_kinematics.hpp"
#include "app/track/track_rigid_body.hpp"
#include "app/track/track_test_util.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace tribolab::app {
namespace {

/// A body at rest turning at 22.7 rad/s filmed at 30 fps (43 degrees per frame, the issue's
/// bicycle wheel): point B is a mark 0.3 m from the axle at (0.1, 1.2), 2 mm noise.
testing::SpinningBody wheel() {
  testing::SpinningBody b;
  b.fps = 30;
  b.frames = 45;
  b.vx = b.vy = b.g = 0;
  b.omega = 22.7;
  b.length = 0.6;
  b.noise = 0.002;
  return b;
}

TEST(TrackRotation, SpinOfOneWheelMarkAboutItsFittedPivot) {
  const std::string dir = testing::temp_dir("rotation");
  const testing::SpinningBody b = wheel();
  TrackRotationOptions o;
  o.input.file = b.write(dir + "/wheel.csv");
  o.track = "B";
  o.out = dir + "/rotation.csv";
  const auto r = track_rotation(o);
  const auto& j = r.json;
  // 45 frames, 2 mm on a 0.3 m radius: sigma_omega ~ 0.02 rad/s; within 4 sigmas
  EXPECT_NEAR(j["omega"].get<double>(), b.omega, 4 * j["sigma_omega"].get<double>()) << j;
  EXPECT_LT(j["sigma_omega"].get<double>(), 0.05) << j;
  EXPECT_NEAR(j["pivot_x"].get<double>(), b.x0, 4 * j["sigma_pivot_x"].get<double>()) << j;
  EXPECT_NEAR(j["pivot_y"].get<double>(), b.y0, 4 * j["sigma_pivot_y"].get<double>()) << j;
  EXPECT_NEAR(j["radius"].get<double>(), 0.3, 4 * j["sigma_radius"].get<double>()) << j;
  EXPECT_NEAR(j["alpha"].get<double>(), 0, 4 * j["sigma_alpha"].get<double>()) << j;
  EXPECT_EQ(j["pivot"], "fitted");
  // 43.4 deg per frame; the largest of 44 noisy differences (each with sd sqrt(2) 2 mm / 0.3 m
  // = 0.54 deg) lies up to ~4 sd above it
  EXPECT_NEAR(j["max_turn_per_frame_deg"].get<double>(), 43.4, 2.5) << j;
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"];
  std::ifstream csv(o.out);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "frame,t,x,y,theta,radius,omega,sigma_omega");
  ASSERT_EQ(r.rotation.rows.size(), 45u);
}

// Two commands measure the same spin: `track rigid-body` from two marks (no pivot needed)
// and `track rotation` from one mark about its fitted pivot. On the same film they must
// agree within their combined uncertainty (4 sigmas: both are fits of the same noisy frames).
TEST(TrackRotation, OneMarkAboutItsPivotAgreesWithTwoMarksAsARigidBody) {
  const std::string dir = testing::temp_dir("rotation_vs_rigid");
  const testing::SpinningBody b = wheel();
  const std::string file = b.write(dir + "/wheel.csv");
  TrackRotationOptions o;
  o.input.file = file;
  o.track = "B";
  const auto one = track_rotation(o).json;
  TrackRigidBodyOptions two;
  two.input.file = file;
  two.track_a = "A";
  two.track_b = "B";
  const auto body = track_rigid_body(two).json;
  const double d = one["omega"].get<double>() - body["omega"].get<double>();
  const double sigma = std::hypot(one["sigma_omega"].get<double>(), body["sigma_omega"].get<double>());
  EXPECT_LT(std::abs(d), 4 * sigma) << one["omega"] << " vs " << body["omega"];
  EXPECT_NEAR(body["omega"].get<double>(), b.omega, 4 * body["sigma_omega"].get<double>());
}

TEST(TrackRotation, AWheelMarkHasNoImpact) {
  // Issue 24/27: `track kinematics` called a bicycle wheel's rim mark an impact (significance
  // 18.7) and fitted "accelerations" to its two halves. The same mark is one smooth segment.
  const std::string dir = testing::temp_dir("rotation_kin");
  TrackKinematicsOptions o;
  o.input.file = wheel().write(dir + "/wheel.csv");
  o.track = "B";
  o.out = dir + "/k.csv";
  const auto r = track_kinematics(o);
  EXPECT_TRUE(r.json["impacts"].empty()) << r.json["impacts"];
  EXPECT_EQ(r.json["segments"], 1);
  EXPECT_EQ(r.json["segment_fits"][0]["free_flight"], false);  // a circle is no free flight
  EXPECT_TRUE(r.json["warnings"].empty()) << r.json["warnings"];
}

TEST(TrackRotation, TheGivenRangeAndPivotAreUsedAndBadOnesNamed) {
  const std::string dir = testing::temp_dir("rotation_range");
  const testing::SpinningBody b = wheel();
  TrackRotationOptions o;
  o.input.file = b.write(dir + "/wheel.csv");
  o.track = "B";
  o.t_from = 0.2;
  o.t_to = 1.0;
  o.pivot_x = b.x0;
  o.pivot_y = b.y0;
  const auto r = track_rotation(o);
  EXPECT_EQ(r.json["pivot"], "given");
  EXPECT_GE(r.json["t_first"].get<double>(), 0.2);
  EXPECT_LE(r.json["t_last"].get<double>(), 1.0);
  std::size_t kept = 0;
  const track::TrackSet set = b.tracks();  // named: a range-for over a temporary's element would dangle
  for (const auto& p : set.tracks[1].points) kept += p.t >= 0.2 && p.t <= 1.0;
  EXPECT_EQ(r.json["points"], kept);
  EXPECT_EQ(r.json["sigma_pivot_x"], 0.0);
  o.t_from = 1.0;
  o.t_to = 0.2;
  EXPECT_THROW(track_rotation(o), InputError);
  o.t_from = 0.2;
  o.t_to = 0.29;  // 3 points: t = 0.2, 0.233, 0.267
  try {
    track_rotation(o);
    FAIL() << "3 points accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t_from/t_to keep 3 point(s)"), std::string::npos) << e.what();
  }
}

TEST(TrackKinematics, FromToFitsOnlyTheFreeFallOfALanding) {
  // A ball thrown up at 2 m/s from 1 m lands at t = 0.70 s on a cushion that stops it within
  // ~20 ms (y = v_in tau (1 - exp(-(t - tc)/tau))), filmed at 240 fps with 1 mm noise. The
  // whole record's segment(s) carry the landing; --to 0.65 keeps only the flight, which falls
  // at g within its sigmas (0.6 s of 1 mm noise: sd about 0.02 m/s^2; 5 sds).
  const std::string dir = testing::temp_dir("kin_from_to");
  const double g = 9.8, tc = (2 + std::sqrt(4 + 2 * g)) / g, vin = 2 - g * tc, tau = 0.02;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0, 0.001);
  track::TrackSet set;
  set.tracks = {track::Track{"ball", {}}};
  for (int i = 0; i < 240; ++i) {
    const double t = i / 240.0;
    const double y = t < tc ? 1 + 2 * t - 0.5 * g * t * t : vin * tau * (1 - std::exp(-(t - tc) / tau));
    set.tracks[0].points.push_back({i, t, 0.3 * std::min(t, tc) + n(rng), y + n(rng)});
  }
  TrackKinematicsOptions o;
  o.input.file = dir + "/landing.csv";
  {
    std::ofstream f(o.input.file);
    io::write_tidy_csv(f, set);
  }
  o.out = dir + "/k.csv";
  o.t_to = 0.65;
  const auto r = track_kinematics(o);
  EXPECT_EQ(r.json["points"], 157);  // t = 0 .. 0.65 s: frames 0..156
  EXPECT_EQ(r.json["t_to"], 0.65);
  EXPECT_TRUE(r.json["t_from"].is_null());
  ASSERT_EQ(r.json["segments"], 1);
  const auto& s = r.json["segment_fits"][0];
  EXPECT_EQ(s["free_flight"], true) << s;
  EXPECT_NEAR(s["acceleration"].get<double>(), g, 5 * s["sigma_acceleration"].get<double>()) << s;
  EXPECT_TRUE(r.json["warnings"].empty()) << r.json["warnings"];
  o.t_from = 2;
  o.t_to = 3;  // after the record
  try {
    track_kinematics(o);
    FAIL() << "an empty range accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("runs from t = 0 to 0.995833 s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribolab::app
