// Tests of analyze_bounce on synthetic videos made by the project's own simulators.
#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_synth.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "analysis/analysis_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <iostream>

namespace tribolab::analysis {
namespace {

using testing::real_time;
using testing::expect_binomial;

TEST(BounceAnalyze, ExactDataRecoversTheFlights) {
  SynthVideoOptions o;
  o.noise = 0;
  const auto v = synth_video(o);
  const auto r = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8));
  const auto& tr = v.truth;
  // The impact time lies within the contact (the parabolas of free flight meet there up to
  // the contact's own few ms).
  EXPECT_GT(r.impact_time, tr.t_touch - 1e-3);
  EXPECT_LT(r.impact_time, tr.t_separation + 1e-3);
  // Exact flights: fits are exact to rounding (1e-9 m/s allows for the 1e-10 integrator).
  EXPECT_NEAR(r.pre.vx, tr.touch.vx, 1e-7);
  EXPECT_NEAR(r.post.vx, tr.separation.vx, 1e-6);
  EXPECT_NEAR(r.pre.vy, tr.vy_flight(true, r.impact_time), 1e-6);
  EXPECT_NEAR(r.post.vy, tr.vy_flight(false, r.impact_time), 1e-6);
  EXPECT_NEAR(r.pre.omega, tr.touch.omega, 1e-6);
  EXPECT_NEAR(r.post.omega, tr.separation.omega, 1e-6);
  EXPECT_NEAR(r.pre.acceleration_y, -9.8, 1e-6);
  EXPECT_NEAR(r.pre.y_parabola.r_squared, 1.0, 1e-12);
  // The floor's bracket holds the truth, and the apex heights are exact to the bracket.
  EXPECT_LE(std::abs(r.floor_y - tr.floor_y), r.floor_half_width);
  EXPECT_NEAR(r.pre.apex_height, tr.release_apex, r.floor_half_width);
  EXPECT_NEAR(r.post.apex_height, tr.post_apex, r.floor_half_width);
  // With the floor given, apex heights are exact (1e-6 m: the fits of exact flights).
  BounceAnalyzeOptions with_floor;
  with_floor.floor_y = 0;
  const auto rf = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), with_floor);
  EXPECT_NEAR(rf.pre.apex_height, tr.release_apex, 1e-6);
  EXPECT_NEAR(rf.post.apex_height, tr.post_apex, 1e-6);
  EXPECT_NEAR(rf.e_height, std::sqrt(tr.post_apex / tr.release_apex), 1e-6);
  EXPECT_NEAR(r.theta_impact_deg, to_deg(bounce::wrap_angle(tr.touch.theta + tr.touch.omega * (r.impact_time - tr.t_touch))), 1e-5);
  // Energies at the impact from the fitted velocities.
  EXPECT_NEAR(r.pre.energy.rotational, 0.5 * 4.1e-3 * tr.touch.omega * tr.touch.omega, 1e-9);
}

// Coverage of the stated 95% intervals over many noisy runs (1 mm, 240 and 80 fps). With
// n runs the count of covering intervals is Binomial(n, 0.95): sd = sqrt(n 0.95 0.05); we
// accept within 3 sd (for n = 200: 190 +- 9.2, i.e. 181..199). The sanitizer tree runs 60
// (study_draws), the same orientations' range more coarsely, and each count must reach
// binomial_floor(60, 0.905) = 46 (expect_binomial).
struct Coverage {
  int n = 0;
  int vx_pre = 0, vx_post = 0, vy_pre = 0, vy_post = 0, om_pre = 0, om_post = 0, e = 0, e_touch = 0, eh = 0, floor_bracket = 0, eh_default = 0, eh_duration = 0;
  double eh_duration_abs_z = 0;  ///< sum of |error| / sigma of e_height with the floor from T
};

Coverage run_coverage(double fps, int runs) {
  Coverage c;
  std::mt19937_64 rng(42);
  for (int s = 0; s < runs; ++s) {
    SynthVideoOptions o;
    o.fps = fps;
    o.seed = 1000 + s;
    o.theta_deg = -60 + 100.0 * s / runs;  // touch orientations with a clear rebound
    const auto v = synth_video(o);
    const auto r = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8));
    BounceAnalyzeOptions with_floor;
    with_floor.floor_y = 0;  // the seed's procedure: y = 0 set on the floor in Tracker
    const auto rf = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), with_floor);
    const auto& tr = v.truth;
    // Without the floor but with a contact duration known to within half a frame, as
    // analyze_bounce assumes (uniform error, sd dt / sqrt 12): the truth plus a uniform error
    // in +-dt/2. (Rounding the truth to whole frames would give nearly the same error in every
    // run here, the synthetic contacts all lasting ~20 ms, which a coverage count cannot test.)
    std::uniform_real_distribution<double> half_frame(-0.5 / fps, 0.5 / fps);
    BounceAnalyzeOptions with_duration;
    with_duration.contact_duration = tr.t_separation - tr.t_touch + half_frame(rng);
    const auto rd = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), with_duration);
    EXPECT_EQ(rd.floor_method, FloorMethod::contact_duration);
    auto in = [&](double est, double sigma, double truth, int dof) {
      return std::abs(est - truth) <= sigma * (dof > 60 ? 1.96 : 2.0);
    };
    ++c.n;
    c.vx_pre += in(r.pre.vx, r.pre.sigma_vx, tr.touch.vx, r.pre.x_line.dof);
    c.vx_post += in(r.post.vx, r.post.sigma_vx, tr.separation.vx, r.post.x_line.dof);
    const double vyp = tr.vy_flight(true, r.impact_time), vyq = tr.vy_flight(false, r.impact_time);
    c.vy_pre += in(r.pre.vy, r.pre.sigma_vy, vyp, r.pre.y_parabola.dof);
    c.vy_post += in(r.post.vy, r.post.sigma_vy, vyq, r.post.y_parabola.dof);
    c.om_pre += in(r.pre.omega, r.pre.sigma_omega, tr.touch.omega, r.pre.n_points);
    c.om_post += in(r.post.omega, r.post.sigma_omega, tr.separation.omega, r.post.n_points);
    // e_velocity_common (both flights at impact_time) against the same ratio of the truth;
    // e_velocity (with the floor: touch and separation located) against simulate's e.
    c.e += in(r.e_velocity_common, r.sigma_e_velocity_common, -vyq / vyp, r.pre.n_points);
    c.e_touch += in(rf.e_velocity, rf.sigma_e_velocity, -tr.separation.vy / tr.touch.vy, r.pre.n_points);
    c.eh += in(rf.e_height, rf.sigma_e_height, std::sqrt(tr.post_apex / tr.release_apex), r.post.n_points);
    c.floor_bracket += std::abs(r.floor_y - tr.floor_y) <= r.floor_half_width;
    c.eh_duration_abs_z += std::abs(rd.e_height - std::sqrt(tr.post_apex / tr.release_apex)) / rd.sigma_e_height;
    c.eh_duration += in(rd.e_height, rd.sigma_e_height, std::sqrt(tr.post_apex / tr.release_apex), r.post.n_points);
    c.eh_default += in(r.e_height, r.sigma_e_height, std::sqrt(tr.post_apex / tr.release_apex), r.post.n_points);
  }
  std::cout << "coverage at " << fps << " fps over " << c.n << " runs: vx " << c.vx_pre << "/" << c.vx_post
            << " vy " << c.vy_pre << "/" << c.vy_post << " omega " << c.om_pre << "/" << c.om_post
            << " e_common " << c.e << " e (touch, floor given) " << c.e_touch << " e_height " << c.eh << " (floor from the contact duration: " << c.eh_duration
            << ", mean |z| " << c.eh_duration_abs_z / c.n << "; floor bracketed: " << c.eh_default << ", floor in bracket " << c.floor_bracket << ")\n";
  return c;
}

/// e_height with the floor from the contact duration. Its error is mostly the floor's, which
/// is uniform (T known to +-dt/2): a uniform error of sd sigma never exceeds sqrt(3) sigma =
/// 1.73 sigma, so the 95% interval covers it in (nearly) every run; only the lower binomial
/// bound applies. That the intervals are not needlessly wide is checked by the mean |z|
/// (0.87 for a uniform error, 0.80 for a normal one; well-sized intervals lie near these).
/// At 60 runs (the sanitizer tree) the sd of the mean |z| is ~0.5 / sqrt(60) = 0.065 for the
/// uniform error, so 0.5 and 1.2 are still > 5 sds from 0.87; a sigma half the true one gives
/// a mean |z| of 1.7 and fails. The count there: at least binomial_floor(60, 0.95) = 51.
void expect_floor_from_duration(const Coverage& c, int full) {
  if (is_full_study(c.n, full)) {
    EXPECT_GE(c.eh_duration, 0.95 * c.n - 3 * std::sqrt(c.n * 0.95 * 0.05));
  } else {
    EXPECT_GE(c.eh_duration, binomial_floor(c.n, 0.95));
  }
  const double mean_abs_z = c.eh_duration_abs_z / c.n;
  EXPECT_GT(mean_abs_z, 0.5) << "intervals wider than the errors warrant";
  EXPECT_LT(mean_abs_z, 1.2) << "intervals narrower than the errors";
}

TEST(BounceAnalyze, IntervalsCoverTheTruthAt240Fps) {
  const auto c = run_coverage(240, study_draws(200, 60));
  for (auto [k, name] : {std::pair{c.vx_pre, "vx pre"}, {c.vx_post, "vx post"}, {c.vy_pre, "vy pre"},
                         {c.vy_post, "vy post"}, {c.om_pre, "omega pre"}, {c.om_post, "omega post"},
                         {c.e, "e_velocity_common"}, {c.e_touch, "e_velocity"}, {c.eh, "e_height"}})
    expect_binomial(k, c.n, 200, name);
  expect_floor_from_duration(c, 200);
}

TEST(BounceAnalyze, IntervalsCoverTheTruthAt80Fps) {
  const auto c = run_coverage(80, study_draws(200, 60));
  for (auto [k, name] : {std::pair{c.vx_pre, "vx pre"}, {c.vx_post, "vx post"}, {c.vy_pre, "vy pre"},
                         {c.vy_post, "vy post"}, {c.om_pre, "omega pre"}, {c.om_post, "omega post"},
                         {c.e, "e_velocity_common"}, {c.e_touch, "e_velocity"}, {c.eh, "e_height"}})
    expect_binomial(k, c.n, 200, name);
  expect_floor_from_duration(c, 200);
}

// The methods' text is the JSON value of "floor_method" and "force_duration_method" (docs/cli.md).
TEST(FloorMethod, TextIsTheJsonValue) {
  EXPECT_STREQ(to_string(FloorMethod::given), "given");
  EXPECT_STREQ(to_string(FloorMethod::contact_duration), "contact_duration");
  EXPECT_STREQ(to_string(FloorMethod::bracket), "bracket");
  EXPECT_STREQ(to_string(ForceDurationMethod::given), "given");
  EXPECT_STREQ(to_string(ForceDurationMethod::located), "located");
}

}  // namespace
}  // namespace tribolab::analysis
