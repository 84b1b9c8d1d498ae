// analyze_bounce over a grid of the synthesizer's own throws (issue 27): every throw
// synth_video makes, long and repeated contacts included, is analysed, and e_velocity lies
// at the truth within its stated sigma. docs/theory.md#bounce-analysis.
#include "analysis/bounce_analyze.hpp"
#include "numerics/sanitizer.hpp"
#include "analysis/bounce_synth.hpp"
#include "numerics/error.hpp"
#include "analysis/analysis_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace tribolab::analysis {
namespace {

using testing::real_time;

struct GridResult {
  int n = 0, analysed = 0, z1 = 0, z2 = 0, z3 = 0;
  double max_abs_z = 0;
  double max_penetration = 0;  ///< m: the largest compression of the throws' first contacts
  std::vector<std::string> failures;  ///< the throw and the error, or its z beyond 3
};

/// The throws of issue 27: released at `height` with orientation 0..165 deg (`theta_step`)
/// and spin -50..50 rad/s (`omegas`), vx 1.5 m/s, tip noise `noise`, 240 fps, floor given at
/// y = 0 (the seed's Tracker procedure); seed = the throw's index.
/// `only` (when not empty): analyse just the throws with these spins, each with the seed it has
/// in the whole grid, so a thinned grid checks a subset of the same throws.
GridResult analyse_grid(double noise, double theta_step, const std::vector<double>& omegas, double height = 0.7,
                        const std::vector<double>& only = {}) {
  GridResult g;
  std::uint64_t seed = 0;
  for (double theta = 0; theta < 166; theta += theta_step) {
    for (double omega : omegas) {
      SynthVideoOptions o;
      o.theta_deg = theta;
      o.omega = omega;
      o.height = height;
      o.noise = noise;
      o.seed = ++seed;
      if (!only.empty() && std::find(only.begin(), only.end(), omega) == only.end()) continue;
      char name[160];
      std::snprintf(name, sizeof name, "--theta-deg %g --omega %g --height %g --noise %g --seed %llu", theta, omega,
                    height, noise, static_cast<unsigned long long>(o.seed));
      ++g.n;
      const auto v = synth_video(o);
      const double e_true = -v.truth.separation.vy / v.truth.touch.vy;
      g.max_penetration = std::max(
          g.max_penetration, bounce::simulate_contact(o.ball, o.law, o.friction, v.truth.touch).max_penetration);
      BounceAnalyzeOptions ao;
      ao.floor_y = 0;
      try {
        const auto r = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), ao);
        ++g.analysed;
        const double z = std::abs(r.e_velocity - e_true) / r.sigma_e_velocity;
        g.z1 += z <= 1;
        g.z2 += z <= 2;
        g.z3 += z <= 3;
        g.max_abs_z = std::max(g.max_abs_z, std::isfinite(z) ? z : 1e9);
        if (!(z <= 3)) {
          char buf[200];
          std::snprintf(buf, sizeof buf, ": e %.4f +- %.4f, truth %.4f (|z| %.2f)", r.e_velocity, r.sigma_e_velocity,
                        e_true, z);
          g.failures.push_back(name + std::string(buf));
        }
      } catch (const Error& e) {
        g.failures.push_back(name + std::string(": ") + e.what());
      }
    }
  }
  std::printf("grid at %g mm: analysed %d/%d; |z| <= 1: %d, <= 2: %d, <= 3: %d; max |z| %.2f; max penetration %.1f mm\n",
              1e3 * noise, g.analysed, g.n, g.z1, g.z2, g.z3, g.max_abs_z, 1e3 * g.max_penetration);
  for (const auto& f : g.failures) std::printf("  %s\n", f.c_str());
  return g;
}

/// Binomial bounds, 3 sds: the count of |z| <= k among n throws when z is standard normal.
void expect_coverage(int count, int n, double p, const char* what) {
  const double mean = p * n, sd = std::sqrt(n * p * (1 - p));
  EXPECT_GE(count, mean - 3 * sd) << what;
  EXPECT_LE(count, std::min<double>(n, mean + 3 * sd)) << what;
}

// The grid of issue 27 (orientation 0..165 deg x spin -50..50 rad/s, 0.7 m). Before the
// fix 7 of its 84 throws failed at 1 mm of noise (5 "no impact found": long contacts, whose
// velocity turns without a jump between adjacent windows of 6 frames; 2 refused for frames
// "on the floor" that were contact frames of low rebounds), and all 84 at 3 and 5 mm (a
// 6-frame window's velocity too uncertain for the detector's threshold); filming the whole
// impact added throws of two contacts whose flight between them was taken for the rebound.
// Now every throw is analysed, e_velocity lies within 3.5 of its sigmas of the truth (the
// whole impact's -vy_out / vy_in; p = 5e-4 per throw for a normal error), and within 1 and 2
// sigmas as often as a normal error would (binomial, 3 sds). The noise levels share seeds
// (the same normal draws, scaled), so they are not independent samples: each is checked on
// its own. Under ASan (several times slower) the spins are thinned to 4 and the levels to 1
// and 5 mm; the bounds follow n.
TEST(BounceGrid, EveryThrowIsAnalysedAndEWithinItsSigma) {
  const std::vector<double> omegas = {-50, -30, -10, 0, 10, 30, 50};
#if TRIBOLAB_ASAN
  // The whole grid's throws with these spins, at their own seeds (a thinned grid with seeds
  // renumbered drew a throw the whole grid does not hold).
  const std::vector<double> only = {-50, -10, 10, 50};
  const std::vector<double> noises = {0.001, 0.005};
#else
  const std::vector<double> only;
  const std::vector<double> noises = {0.001, 0.003, 0.005};
#endif
  for (double noise : noises) {
    SCOPED_TRACE("noise " + std::to_string(noise));
    const auto g = analyse_grid(noise, 15, omegas, 0.7, only);
    EXPECT_EQ(g.analysed, g.n);
    EXPECT_LE(g.max_abs_z, 3.5);
    // Below the 3 cm compression analyze_bounce allows frames in contact (bounce_analyze.cpp,
    // require_plausible_floor).
    EXPECT_LT(g.max_penetration, 0.03);
    expect_coverage(g.z1, g.analysed, 0.6827, "within 1 sigma");
    expect_coverage(g.z2, g.analysed, 0.9545, "within 2 sigma");
  }
}

// The throws the issue names: a 49 ms contact (vy -3.31 to +1.92 m/s), one more not found,
// and the whole impact of two contacts (release 30 deg, no spin) refused before.
TEST(BounceGrid, TheIssuesThrowsAreAnalysed) {
  struct Throw {
    double theta_deg, omega;
    std::uint64_t seed;
  };
  for (const Throw& k : {Throw{105, -30, 37}, Throw{40, 50, 8}, Throw{30, 0, 1}}) {
    SynthVideoOptions o;
    o.theta_deg = k.theta_deg;
    o.omega = k.omega;
    o.height = 0.7;
    o.seed = k.seed;
    const auto v = synth_video(o);
    BounceAnalyzeOptions ao;
    ao.floor_y = 0;
    SCOPED_TRACE("theta " + std::to_string(k.theta_deg) + " omega " + std::to_string(k.omega));
    const auto r = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), ao);
    // 4 sigmas: three fixed seeds, p = 6e-5 each for a chance failure.
    EXPECT_NEAR(r.e_velocity, -v.truth.separation.vy / v.truth.touch.vy, 4 * r.sigma_e_velocity);
    EXPECT_NEAR(r.t_separation, v.truth.t_separation, 4 * r.sigma_t_separation);
  }
}

// Issue 27: at 0.7 m with 5 mm of noise the 60 deg / -10 rad/s throw leaves the floor at
// 0.23 m/s (e 0.069) and lands again 7-9 frames later (the video ends there): its centre rises
// ~3 mm against ~3.5 mm of noise. A free parabola through those frames cannot tell the
// velocity from the curvature: before, seeds 4 and 6 of 1-6 (8 of 20) were refused ("no
// impact found") and the others analysed with sigma_e up to 0.3. Now the impact search and the
// post-impact fit take the pre-impact flight's gravity for so short a flight
// (docs/theory.md#bounce-analysis, "short post-impact flight"): every seed is analysed, e
// within 3.5 of its sigmas (p = 5e-4 per seed for a normal error) and within 1 and 2 sigmas as
// often as a normal error would (binomial, 3 sds). 40 seeds, 1.5 s.
TEST(BounceGrid, TheLowHopOfALowReboundIsAnalysed) {
  int n = 0, analysed = 0, z1 = 0, z2 = 0;
  double max_z = 0;
  const std::uint64_t seeds = std::getenv("TRIBOLAB_SLOW_TESTS") ? 200 : 40;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    SynthVideoOptions o;
    o.theta_deg = 60;
    o.omega = -10;
    o.height = 0.7;
    o.noise = 0.005;
    o.seed = seed;
    const auto v = synth_video(o);
    BounceAnalyzeOptions ao;
    ao.floor_y = 0;
    SCOPED_TRACE("seed " + std::to_string(seed));
    ++n;
    try {
      const auto r = analyze_bounce(real_time(v.tip_a, 8), real_time(v.tip_b, 8), ao);
      ++analysed;
      const double z = std::abs(r.e_velocity - (-v.truth.separation.vy / v.truth.touch.vy)) / r.sigma_e_velocity;
      z1 += z <= 1;
      z2 += z <= 2;
      max_z = std::max(max_z, std::isfinite(z) ? z : 1e9);
      EXPECT_LE(z, 3.5) << "e " << r.e_velocity << " +- " << r.sigma_e_velocity;
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
  std::printf("60 deg / -10 rad/s at 5 mm: %d of %d seeds analysed; |z| <= 1: %d, <= 2: %d; max |z| %.2f\n", analysed,
              n, z1, z2, max_z);
  EXPECT_EQ(analysed, n);
  expect_coverage(z1, analysed, 0.6827, "within 1 sigma");
  expect_coverage(z2, analysed, 0.9545, "within 2 sigma");
}

}  // namespace
}  // namespace tribolab::analysis
