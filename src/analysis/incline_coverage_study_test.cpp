// Coverage studies of the incline analysis's stated error rates (issue 27), too long for every
// `make test` (minutes): run them on demand with
//
//   build/bin/analysis_tests --gtest_also_run_disabled_tests --gtest_filter='InclineCoverageStudy.*'
//
// Each prints its table (docs/theory.md, "Coverage study" under the a_N diagnostic, keeps the figures
// with the date and machine) and checks it against binomial / chi-square bounds, so a run of
// the study also says whether the calibration still holds. The quick guards that do run in
// `make test` are NormalAccelDiagnostic.NoisyModelBIsCalledPresentAtAboutTheTestSize,
// NormalAccelDiagnostic.SixtyFpsModelBIsCalledPresentAtTheTestSizeNotLess,
// InclineFit.NormalAccelSigmaWithTheFrameRotationFittedCoversTheTruth and
// InclineFit.TurnedCameraFrameIsNotMistakenForNormalFriction.
#include "analysis/incline_fit.hpp"
#include "analysis/incline_synthetic.hpp"
#include "incline/params.hpp"
#include "numerics/coverage_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tribolab::analysis {
namespace {

/// Wilson score interval of k successes in n at 95 %.
std::pair<double, double> wilson95(int k, int n) {
  const double z = 1.959964, p = double(k) / n, d = 1 + z * z / n;
  const double c = (p + z * z / (2 * n)) / d, h = z * std::sqrt(p * (1 - p) / n + z * z / (4.0 * n * n)) / d;
  return {c - h, c + h};
}

struct RateCount {
  int runs = 0, hits = 0;
};

void print_rate(const std::string& label, const RateCount& c) {
  const auto [lo, hi] = wilson95(c.hits, std::max(1, c.runs));
  std::printf("  %-28s %4d / %4d = %.3f  (95 %% interval %.3f to %.3f)\n", label.c_str(), c.hits, c.runs,
              c.hits / double(std::max(1, c.runs)), lo, hi);
}

TEST(InclineCoverageStudy, DISABLED_NormalAccelDiagnosticSizeOnModelB) {
  // The eq-b a_N diagnostic on model-B runs (no normal friction): its stated size is 5 %. The
  // grid of the quick guard (mu 0.4-0.9, phi 10-30 deg, 60-1000 fps, 0.2 and 0.5 mm noise) with
  // 20 seeds per cell instead of 3.
  std::map<std::string, RateCount> by;
  RateCount all;
  for (double mu : {0.4, 0.634, 0.9})
    for (double phi : {10.0, 20.96, 30.0})
      for (double fps : {60.0, 240.0, 1000.0})
        for (double noise : {2e-4, 5e-4})
          for (std::uint64_t seed = 0; seed < 20; ++seed) {
            InclineSynthOptions s;
            s.params.mu = mu;
            s.params.phi = incline::deg_to_rad(phi);
            s.params.v0 = 2.62;
            s.fps = fps;
            s.noise = noise;
            s.seed = 700000 + seed + (noise > 3e-4 ? 1000 : 0);
            InclineFitOptions o;
            o.phi = s.params.phi;
            o.fit_model_a = false;
            const InclineAnalysis a = analyze_incline_run(synthesize_incline_run(s).track, o);
            if (!a.a_n) continue;
            const bool present = a.a_n->intercept_excludes_zero;
            for (RateCount* c : {&all, &by["fps " + std::to_string(int(fps))], &by["noise " + std::to_string(noise * 1e3).substr(0, 3) + " mm"],
                                 &by["mu " + std::to_string(mu).substr(0, 5)], &by["phi " + std::to_string(phi).substr(0, 5)]}) {
              ++c->runs;
              c->hits += present;
            }
          }
  std::printf("a_N diagnostic called 'present' on model-B runs (stated size 0.05):\n");
  print_rate("all", all);
  for (const auto& [k, c] : by) print_rate(k, c);
  ASSERT_GE(all.runs, 1000);
  // At the stated size, neither more nor fewer false "present" than a 5 % test: the count
  // within the exact binomial bounds at alpha = 1e-3 each side (32 to 75 of 1040). Measured
  // 6 Dec 2026: 61 / 1040 = 5.9 % (4.5-7.5 %) with the truncation bias measured on the model's
  // path and subtracted; 26 / 1040 = 2.5 % (1.6-3.6 %) with the former doubled estimate from
  // cubic and quartic blocks, which fails the lower bound (docs/theory.md, "Coverage study").
  EXPECT_GE(all.hits, binomial_floor(all.runs, 0.05));
  EXPECT_LE(all.hits, binomial_ceiling(all.runs, 0.05));
}

TEST(InclineCoverageStudy, DISABLED_NormalAccelDiagnosticPowerWithModelA) {
  // Power of the eq b diagnostic against f_N/m = 0.5 m/s^2 (intercept -0.5) in the default
  // analysis (model A fitted: its launch, stop and rotation place the blocks): mu 0.634, phi 12,
  // 20.96 and 28 deg, 60, 240 and 1000 fps, 0.2 and 0.5 mm, 6 seeds (108 runs). Measured 6 Dec
  // 2026: present in 31 (28.7 %; 60 fps 14/36, 240 fps 14/36, 1000 fps 3/36), the truth outside
  // the 95 % interval in 5 (4.6 %); with the former doubled truncation estimate 21 (19.4 %) and 3.
  std::map<std::string, RateCount> by;
  RateCount all, miss;
  for (double phi : {12.0, 20.96, 28.0})
    for (double fps : {60.0, 240.0, 1000.0})
      for (double noise : {2e-4, 5e-4})
        for (std::uint64_t seed = 0; seed < 6; ++seed) {
          InclineSynthOptions s;
          s.params.mu = 0.634;
          s.params.phi = incline::deg_to_rad(phi);
          s.params.v0 = 2.62;
          s.params.normal_accel = 0.5;
          s.fps = fps;
          s.noise = noise;
          s.seed = 700000 + seed + (noise > 3e-4 ? 1000 : 0);
          InclineFitOptions o;
          o.phi = s.params.phi;
          const InclineAnalysis a = analyze_incline_run(synthesize_incline_run(s).track, o);
          if (!a.a_n) continue;
          const auto& d = *a.a_n;
          for (RateCount* c : {&all, &by["fps " + std::to_string(int(fps))]}) {
            ++c->runs;
            c->hits += d.intercept_excludes_zero;
          }
          ++miss.runs;
          miss.hits += !(d.intercept_ci_low <= -0.5 && -0.5 <= d.intercept_ci_high);
        }
  std::printf("a_N diagnostic against f_N/m = 0.5 m/s^2, model A fitted:\n");
  print_rate("present (power)", all);
  for (const auto& [k, c] : by) print_rate(k, c);
  print_rate("truth outside the interval", miss);
  EXPECT_LE(miss.hits, binomial_ceiling(miss.runs, 0.05));
}

TEST(InclineCoverageStudy, DISABLED_NormalAccelSigmaWithTheFrameRotationFitted) {
  // Model A with the camera frame's rotation fitted (the seed's figure 五 launch, 1 mm noise,
  // 80/120/240 fps; psi 0.5 deg): the pulls (f_N/m - truth) / sigma should have sd 1, and the
  // 95 % intervals cover 95 %. Earlier 16 runs gave chi2 8.6 on 15 dof (sd ~0.76). At the
  // demo's settings the same check runs in every `make test` with 150 runs
  // (InclineFit.NormalAccelSigmaWithTheFrameRotationFittedCoversTheTruth; 1000 on demand with
  // TRIBOLAB_COVERAGE_RUNS=1000).
  for (double truth : {0.0, 0.3}) {
    double sum2 = 0;
    RateCount cover;
    std::vector<double> pulls;
    for (int i = 0; i < 300; ++i) {
      InclineSynthOptions s;
      s.params.mu = 0.634;
      s.params.phi = incline::deg_to_rad(20.96);
      s.params.v0 = 2.62;
      s.params.normal_accel = truth;
      s.fps = i % 3 == 0 ? 80 : (i % 3 == 1 ? 120 : 240);
      s.noise = 0.001;
      s.t_launch = 0.1234;
      s.seed = 800000 + i + (truth > 0 ? 5000 : 0);
      s.frame_rotation = incline::deg_to_rad(0.5);
      InclineFitOptions o;
      o.phi = s.params.phi;
      o.fit_frame_rotation = true;
      const InclineAnalysis a = analyze_incline_run(synthesize_incline_run(s).track, o);
      ASSERT_TRUE(a.model_a.has_value());
      const auto& na = a.model_a->normal_accel;
      const double z = (na.value - truth) / na.sigma;
      pulls.push_back(z);
      sum2 += z * z;
      ++cover.runs;
      cover.hits += std::abs(z) < 1.959964;
    }
    const double n = double(pulls.size()), sd = std::sqrt(sum2 / n);
    // sd of the pulls: its own standard error is ~ 1/sqrt(2n) = 0.041 at n = 300.
    std::printf("f_N/m = %.1f m/s^2, rotation fitted: %d runs, pull sd %.3f (+- %.3f), chi2 %.1f on %d dof\n", truth,
                cover.runs, sd, 1 / std::sqrt(2 * n), sum2, cover.runs);
    print_rate("95 % intervals covering", cover);
    EXPECT_NEAR(sd, 1.0, 3 / std::sqrt(2 * n));
    EXPECT_NEAR(cover.hits / n, 0.95, 3 * std::sqrt(0.05 * 0.95 / n));
  }
}

}  // namespace
}  // namespace tribolab::analysis
