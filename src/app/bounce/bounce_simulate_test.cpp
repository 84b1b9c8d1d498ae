// The bounce simulation workflows called directly (src/app/bounce/bounce_simulate.cpp): their JSON
// against independent physics, their arrays against their JSON, and errors naming the option.
// (That the binary prints exactly this JSON: cli/bounce_app_test.cpp.)
#include "app/bounce/bounce_simulate.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tribolab::app {
namespace {

template <class F>
std::string simulate_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// At theta = 0 without spin the lowest point stays at depth b: the centre falls H - b in
// sqrt(2 (H - b) / g) (docs/theory.md#bounce-flight). The root finder works to ~1e-12 s.
TEST(BounceContactTime, FallWithoutSpinTakesTheFreeFallTime) {
  BounceContactTimeOptions o;
  o.height = 0.7;
  o.g = 9.81;
  const auto r = bounce_contact_time(o);
  const double b = o.ball.ball.b;
  EXPECT_NEAR(r.json["t_contact"].get<double>(), std::sqrt(2 * (0.7 - b) / 9.81), 1e-9);
  EXPECT_NEAR(r.json["vy"].get<double>(), -std::sqrt(2 * 9.81 * (0.7 - b)), 1e-8);
  // The samples end at the contact: gap 0 (to the root's tolerance, 1e-9 m) and start at H - b.
  ASSERT_EQ(r.samples.size(), 801u);
  EXPECT_NEAR(r.samples.front().gap, 0.7 - b, 1e-12);
  EXPECT_NEAR(r.samples.back().gap, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.samples.back().t, r.json["t_contact"].get<double>());
}

TEST(BounceContactTime, ErrorsNameTheOption) {
  BounceContactTimeOptions o;
  o.height = 0.7;
  o.direction = 2;
  EXPECT_NE(simulate_error_of([&] { bounce_contact_time(o); }).find("direction"), std::string::npos);
  o.direction = 1;
  o.g = -1;
  EXPECT_NE(simulate_error_of([&] { bounce_contact_time(o); }).find("g"), std::string::npos);
}

// The contact history is the whole impact: it starts at the touch with the given velocity,
// and its last sample is the separation state the JSON reports (the same numbers, exactly).
TEST(BounceSimulate, HistoryMatchesTheJson) {
  BounceSimulateOptions o;
  o.vx = 0.5;
  o.vy = -4;
  o.omega = 40;
  o.theta_deg = 30;
  const auto r = bounce_simulate(o);
  ASSERT_GT(r.history.size(), 10u);
  EXPECT_EQ(r.history.front().t, 0.0);
  EXPECT_EQ(r.history.front().state.vy, -4.0);
  EXPECT_EQ(r.json["contacts"].get<std::size_t>(), r.impact.contacts);
  EXPECT_EQ(r.json["vy"].get<double>(), r.impact.whole.out.vy);
  // Energy is not created: out <= in (a dissipative law, and the work of gravity over ~1 ms
  // is m g dy ~ 4e-4 J, far below the ~1 J lost to damping).
  EXPECT_LT(r.json["energy_out"].get<double>(), r.json["energy_in"].get<double>());
  EXPECT_EQ(r.json["law"]["model"], "hunt-crossley");
}

TEST(BounceSimulate, ErrorsNameTheOption) {
  BounceSimulateOptions o;
  o.vy = 2;
  EXPECT_NE(simulate_error_of([&] { bounce_simulate(o); }).find("vy"), std::string::npos);
  o.vy = -4;
  o.law.model = "nope";
  EXPECT_NE(simulate_error_of([&] { bounce_simulate(o); }).find("model"), std::string::npos);
}

// The drop's apex list and trajectory: the release apex is the height (released at rest),
// every rebound apex lies below it without spin (energy only lost), and the trajectory
// kept for a notebook starts at the release.
TEST(BounceDrop, ApexesFallAndTrajectoryIsKept) {
  BounceDropOptions o;
  o.height = 0.8;
  o.bounces = 3;
  o.keep_trajectory = true;
  const auto r = bounce_drop(o);
  EXPECT_DOUBLE_EQ(r.json["release_apex"].get<double>(), 0.8);
  ASSERT_EQ(r.json["apex_heights"].size(), 3u);
  double last = 0.8;
  for (const auto& h : r.json["apex_heights"]) {
    EXPECT_LT(h.get<double>(), last);
    last = h.get<double>();
  }
  ASSERT_FALSE(r.trajectory.empty());
  EXPECT_EQ(r.trajectory.front().t, 0.0);
  EXPECT_DOUBLE_EQ(r.trajectory.front().state.y, 0.8);
}

TEST(BounceDrop, ErrorsNameTheOption) {
  BounceDropOptions o;
  o.height = 0.8;
  o.bounces = 0;
  EXPECT_NE(simulate_error_of([&] { bounce_drop(o); }).find("bounces"), std::string::npos);
  o.bounces = 5;
  o.keep_trajectory = true;
  o.sample_dt = 0;
  EXPECT_NE(simulate_error_of([&] { bounce_drop(o); }).find("sample_dt"), std::string::npos);
}

}  // namespace
}  // namespace tribolab::app
