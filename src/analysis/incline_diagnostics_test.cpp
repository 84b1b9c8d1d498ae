// The seed's diagnostics (eq b: a_N against sin(theta); eq c: theta_c at the v_y extremum and
// cos(theta_c) against tan(phi) over runs) on synthetic runs with known truth.
#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/incline_synthetic.hpp"
#include "numerics/coverage_test_util.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>

namespace tribolab::analysis {
namespace {

InclineSynthOptions run_options(double phi_deg, double noise, std::uint64_t seed,
                                double normal_accel = 0, double fps = 120) {
  InclineSynthOptions o;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(phi_deg);
  o.params.v0 = 2.62;
  o.params.normal_accel = normal_accel;
  o.fps = fps;
  o.noise = noise;
  o.seed = seed;
  return o;
}

InclineAnalysis analyze(const InclineSynthOptions& s) {
  InclineFitOptions o;
  o.phi = s.params.phi;
  return analyze_incline_run(synthesize_incline_run(s).track, o);
}

TEST(NormalAccelDiagnostic, LineHasSlopeGSinPhiThroughTheOriginForModelB) {
  // Noise-free (1e-7 m) run: what remains is the bias of the local quadratics over blocks of
  // ~11 points, measured at <= 1.5 % of the slope and <= 0.05 m/s^2 of intercept.
  const auto a = analyze(run_options(20.96, 1e-7, 1));
  ASSERT_TRUE(a.a_n.has_value());
  EXPECT_NEAR(a.a_n->slope, a.a_n->slope_expected, 0.015 * a.a_n->slope_expected);
  EXPECT_NEAR(a.a_n->slope_expected, 9.8 * std::sin(incline::deg_to_rad(20.96)), 1e-12);
  EXPECT_NEAR(a.a_n->intercept, 0.0, 0.05);
  // sin(theta) goes from ~1 (launch along x) toward 0 (down the fall line).
  EXPECT_GT(a.a_n->sin_theta.front(), 0.95);
  EXPECT_LT(a.a_n->sin_theta.back(), 0.5);
}

TEST(NormalAccelDiagnostic, InterceptIsMinusTheNormalAcceleration) {
  // Model A with f_N/m = 1 m/s^2: eq b's intercept is -f_N/m. Noise-free bias of the blocks:
  // 0.071 m/s^2 measured here, larger than model B's (< 0.05) because the path curves faster;
  // the window runs from model A's launch to 0.9 of its stop (until the frame-rotation fix it
  // ended at model B's stop, which the unmodelled f_N put earlier and which hid part of this
  // bias). Tolerance 0.08 = that bias plus margin; the noisy intercept's sigma is ~1 m/s^2.
  const auto a = analyze(run_options(20.96, 1e-7, 1, 1.0));
  ASSERT_TRUE(a.a_n.has_value());
  EXPECT_NEAR(a.a_n->intercept, -1.0, 0.08);
  EXPECT_NEAR(a.a_n->slope, a.a_n->slope_expected, 0.03 * a.a_n->slope_expected);
  EXPECT_TRUE(a.a_n->intercept_excludes_zero);
}

TEST(ThetaC, CosineEqualsKForModelB) {
  // eq c': cos(theta_c) = tan(phi)/mu. Noise-free: the error of the local fits over the
  // window was measured at <= 0.0023 (quartics; with the degree chosen now: <= 0.0004); with 1 mm
  // noise the truth lies within 3.3 sigma (+ that bias).
  for (double phi_deg : {10.0, 16.0, 20.96, 26.0}) {
    const double k = std::tan(incline::deg_to_rad(phi_deg)) / 0.634;
    const auto clean = analyze(run_options(phi_deg, 1e-7, 2));
    ASSERT_TRUE(clean.theta_c.has_value()) << phi_deg;
    EXPECT_NEAR(clean.theta_c->cos_theta_c, k, 0.003) << phi_deg;
    EXPECT_NEAR(clean.cos_theta_c_model, k, 1e-4) << phi_deg;
    const auto noisy = analyze(run_options(phi_deg, 0.001, 3));
    ASSERT_TRUE(noisy.theta_c.has_value()) << phi_deg;
    EXPECT_NEAR(noisy.theta_c->cos_theta_c, k, 3.3 * noisy.theta_c->sigma_cos_theta_c + 0.003) << phi_deg;
  }
}

TEST(ThetaC, IntervalCoversTheTruth) {
  // 100 runs at each of two angles: the 95 % interval cos +- 1.96 sigma covers k at a rate
  // within the binomial tolerance 3 sqrt(0.95 0.05/100) = 0.065 of 0.95. (Measured: 0.91 at
  // 20.96 deg, 0.98 at 26 deg with the truncation error in sigma; 0.93 and 0.97 with quartics
  // before. At 10 and 16 deg the v_y extremum is flatter and earlier and the delta method
  // is less accurate: see docs/theory.md.)
  // The sanitizer tree runs the first 40 seeds at each angle. The bound keeps the normal tree's
  // lowest accepted rate, 0.885: binomial_floor(40, 0.885) = 28 covering at each angle (P(X <
  // 28) = 3.6e-4) and binomial_floor(80, 0.885) = 61 over both (P(X < 61) = 5.9e-4). A sigma
  // half the true one (coverage 0.67) passes the pooled count with probability 0.053.
  const int runs = study_draws(100, 40);
  int covered_all = 0;
  for (double phi_deg : {20.96, 26.0}) {
    const double k = std::tan(incline::deg_to_rad(phi_deg)) / 0.634;
    int covered = 0, found = 0;
    for (int i = 0; i < runs; ++i) {
      auto s = run_options(phi_deg, 0.001, 100 + i);
      InclineFitOptions o;
      o.phi = s.params.phi;
      o.fit_model_a = false;
      const auto a = analyze_incline_run(synthesize_incline_run(s).track, o);
      if (!a.theta_c) continue;
      ++found;
      covered += std::abs(a.theta_c->cos_theta_c - k) < 1.96 * a.theta_c->sigma_cos_theta_c;
    }
    std::printf("theta_c at %.2f deg: found in %d of %d runs, coverage %.2f\n", phi_deg, found, runs,
                covered / double(found));
    EXPECT_EQ(found, runs);
    if (is_full_study(runs, 100)) {
      EXPECT_NEAR(covered / double(found), 0.95, 0.065);
    } else {
      EXPECT_GE(covered, binomial_floor(found, 0.885));
    }
    covered_all += covered;
  }
  if (!is_full_study(runs, 100)) {
    EXPECT_GE(covered_all, binomial_floor(2 * runs, 0.885));
  }
}

TEST(ThetaC, ModelAFollowsEquationC) {
  // eq c with f_N: cos(theta_c) = k - (f_N/m) sin(theta_c)/(g mu cos(phi)), a fixed point in
  // theta_c; the measured value satisfies it within the noise-free bias (0.004).
  const double fn = 1.0, phi = incline::deg_to_rad(20.96), mu = 0.634;
  const auto a = analyze(run_options(20.96, 1e-7, 4, fn));
  ASSERT_TRUE(a.theta_c.has_value());
  const double c = a.theta_c->cos_theta_c, s = std::sqrt(1 - c * c);
  EXPECT_NEAR(c, std::tan(phi) / mu - fn * s / (9.8 * mu * std::cos(phi)), 0.004);
}

TEST(NormalFrictionTest, SlopeIsOneOverMuAndInterceptZeroForModelB) {
  std::vector<ThetaCPoint> pts;
  int seed = 10;
  for (double phi_deg : {8.0, 12.0, 16.0, 20.0, 24.0}) {
    const auto a = analyze(run_options(phi_deg, 0.001, ++seed));
    ASSERT_TRUE(a.theta_c.has_value());
    pts.push_back({incline::deg_to_rad(phi_deg), a.theta_c->cos_theta_c,
                   a.theta_c->sigma_cos_theta_c, "run"});
  }
  const NormalFrictionTest t = normal_friction_test(pts);
  // mu within 3.3 sigma of the truth (sigma from the line's scatter, 3 dof).
  EXPECT_NEAR(t.mu, 0.634, 3.3 * t.sigma_mu);
  EXPECT_LT(t.sigma_mu, 0.03);
  EXPECT_LE(t.intercept_ci_low, 0.0);
  EXPECT_GE(t.intercept_ci_high, 0.0);
  EXPECT_EQ(t.verdict, Verdict::absent);
}

TEST(NormalFrictionTest, ExactLineGivesExactMu) {
  // cos(theta_c) = tan(phi)/0.5 + 0.1 exactly (no scatter, but 3 dof): slope 2, intercept 0.1.
  std::vector<ThetaCPoint> pts;
  for (double phi : {0.1, 0.15, 0.2, 0.25})
    pts.push_back({phi, std::tan(phi) / 0.5 + 0.1 * (1 + 1e-9 * phi), 0, "row"});
  const auto t = normal_friction_test(pts);
  EXPECT_NEAR(t.mu, 0.5, 1e-6);
  EXPECT_NEAR(t.intercept, 0.1, 1e-6);
  EXPECT_EQ(t.verdict, Verdict::present);
}

TEST(NormalFrictionTest, RejectsDataThatCannotSupportTheLine) {
  std::vector<ThetaCPoint> two{{0.2, 0.5, 0, "a"}, {0.3, 0.6, 0, "b"}};
  EXPECT_THROW(normal_friction_test(two), InputError);
  std::vector<ThetaCPoint> same{{0.2, 0.5, 0, "a"}, {0.2, 0.6, 0, "b"}, {0.2, 0.55, 0, "c"}};
  EXPECT_THROW(normal_friction_test(same), InputError);
  std::vector<ThetaCPoint> bad{{0.2, 1.5, 0, "a"}, {0.3, 0.6, 0, "b"}, {0.25, 0.55, 0, "c"}};
  EXPECT_THROW(normal_friction_test(bad), InputError);
}

// The verdict's text is the JSON value `incline analyze` and the series print (docs/cli.md).
TEST(Verdict, TextIsTheJsonValue) {
  EXPECT_STREQ(to_string(Verdict::absent), "absent");
  EXPECT_STREQ(to_string(Verdict::present), "present");
  EXPECT_EQ(verdict_from(true), Verdict::present);
  EXPECT_EQ(verdict_from(false), Verdict::absent);
}

/// z = (measured - k) / stated sigma of cos(theta_c) over a grid of model B runs (mu 0.4-0.9,
/// phi 10-30 deg, v0 1.5 and 2.62 m/s, 60-1000 fps) with noise `noise`, `seeds` runs each;
/// runs with k >= 0.95 (barely stopping) or no diagnostic are left out.
std::vector<double> theta_c_z_over_grid(double noise, int seeds) {
  std::vector<double> z;
  for (double mu : {0.4, 0.634, 0.9})
    for (double phi : {10.0, 20.96, 30.0})
      for (double v0 : {1.5, 2.62})
        for (double fps : {60.0, 240.0, 1000.0})
          for (int seed = 1; seed <= seeds; ++seed) {
            InclineSynthOptions s;
            s.params.mu = mu;
            s.params.phi = incline::deg_to_rad(phi);
            s.params.v0 = v0;
            s.fps = fps;
            s.noise = noise;
            s.seed = static_cast<std::uint64_t>(seed);
            const double k = std::tan(s.params.phi) / mu;
            if (k >= 0.95) continue;
            InclineFitOptions o;
            o.phi = s.params.phi;
            o.fit_model_a = false;
            const auto a = analyze_incline_run(synthesize_incline_run(s).track, o);
            if (!a.theta_c) continue;
            z.push_back((a.theta_c->cos_theta_c - k) / a.theta_c->sigma_cos_theta_c);
          }
  return z;
}

TEST(ThetaC, ExactDataLieWithinTheStatedSigma) {
  // Noise-free runs: the only error is the polynomial model's truncation, which the stated
  // sigma must include. Quartics were up to 8.6 sd off (0.0021 at 20.96 deg, 1000 fps); the
  // sextics' error was at most 1.15 of the sigma over this grid (0.8 in all runs but one,
  // whose fits happen to agree) and at most 0.0044 absolute (k = 0.91, where v_y is flat).
  const auto z = theta_c_z_over_grid(0, 1);
  ASSERT_GE(z.size(), 40u);
  double worst = 0;
  for (double v : z) {
    EXPECT_LT(std::abs(v), 1.5);
    worst = std::max(worst, std::abs(v));
  }
  std::printf("theta_c on %zu exact runs: worst %.2f sd\n", z.size(), worst);
  // The reviewer's case: the 0.002 (6 sd) error of the quartics.
  InclineSynthOptions s = run_options(20.96, 0, 1, 0, 1000);
  const double k = std::tan(s.params.phi) / 0.634;
  const auto a = analyze(s);
  ASSERT_TRUE(a.theta_c.has_value());
  EXPECT_NEAR(a.theta_c->cos_theta_c, k, a.theta_c->sigma_cos_theta_c);
  EXPECT_LT(std::abs(a.theta_c->cos_theta_c - k), 3e-4);  // sextic truncation measured 1.3e-4
}

TEST(ThetaC, StatedSigmaCoversTheTruthOverAGridOfNoisyRuns) {
  // 0.2 and 0.5 mm of noise over the grid. For a Gaussian 95 % lie within 2 sd and 99.7 %
  // within 3; measured 0.94 and 0.99, worst 3.5 sd (quartics alone: 0.74 and 0.80, worst 125
  // sd). The misses are short runs at 60 fps and k < 0.3 (an early, flat extremum), where the
  // delta method is poor; runs with fewer than kThetaCMinPoints in the window are warned about
  // (DISABLED_MeasureWarnedAndUnwarnedRuns, docs/theory.md). Bounds: measured minus ~3 binomial
  // sd (n = 82).
  // The sanitizer tree runs the grid at 0.5 mm only (41 runs, the same runs as the normal
  // tree's second half). Its bounds are the exact binomial ones around the same measured rates:
  // binomial_floor(41, 0.94) = 33 within 2 sd (P(X < 33) = 6.1e-4) and binomial_floor(41, 0.99)
  // = 38 within 3 sd (P(X < 38) = 7.5e-4). A sigma half the true one puts a normal error within
  // 2 stated sd 68 % of the time: that passes with probability 0.06.
  const bool full = !TRIBOLAB_ASAN;
  std::vector<double> z = full ? theta_c_z_over_grid(2e-4, 1) : std::vector<double>{};
  for (double v : theta_c_z_over_grid(5e-4, 1)) z.push_back(v);
  ASSERT_GE(z.size(), full ? 75u : 37u);
  int in2 = 0, in3 = 0;
  for (double v : z) {
    in2 += std::abs(v) < 2;
    in3 += std::abs(v) < 3;
  }
  double worst = 0;
  for (double v : z) worst = std::max(worst, std::abs(v));
  std::printf("theta_c z over %zu noisy runs: %.3f within 2 sd, %.3f within 3 sd, worst %.2f sd\n", z.size(),
              in2 / double(z.size()), in3 / double(z.size()), worst);
  if (full) {
    EXPECT_GE(in2 / double(z.size()), 0.85);
    EXPECT_GE(in3 / double(z.size()), 0.92);
  } else {
    EXPECT_GE(in2, binomial_floor(static_cast<int>(z.size()), 0.94));
    EXPECT_GE(in3, binomial_floor(static_cast<int>(z.size()), 0.99));
  }
}

/// A model B run (normal acceleration normal_accel, launch speed v0) analysed without model A,
/// so the eq b verdict comes from the a_N intercept (`incline analyze --no-model-a`).
InclineAnalysis analyze_b_only(double mu, double phi_deg, double fps, double noise, std::uint64_t seed,
                               double normal_accel = 0, double v0 = 2.62) {
  InclineSynthOptions s;
  s.params.mu = mu;
  s.params.phi = incline::deg_to_rad(phi_deg);
  s.params.v0 = v0;
  s.params.normal_accel = normal_accel;
  s.fps = fps;
  s.noise = noise;
  s.seed = seed;
  InclineFitOptions o;
  o.phi = s.params.phi;
  o.fit_model_a = false;
  return analyze_incline_run(synthesize_incline_run(s).track, o);
}

/// A model-B-only analysis launched at v0 (m/s).
InclineAnalysis analyze_theta_c_run(double mu, double phi_deg, double v0, double fps, double noise,
                                    std::uint64_t seed) {
  return analyze_b_only(mu, phi_deg, fps, noise, seed, 0, v0);
}

bool warns_about_theta_c(const InclineAnalysis& a) {
  for (const auto& w : a.warnings)
    if (w.find("theta_c") != std::string::npos) return true;
  return false;
}

TEST(ThetaC, PointsCountTheWindow) {
  // `points` is the number of tracked points with window_low <= t <= window_high, counted here
  // independently on the track the analysis read (exact integers: no tolerance).
  InclineSynthOptions s = run_options(20.96, 5e-4, 1);
  const track::Track track = synthesize_incline_run(s).track;
  InclineFitOptions o;
  o.phi = s.params.phi;
  o.fit_model_a = false;
  const auto a = analyze_incline_run(track, o);
  ASSERT_TRUE(a.theta_c.has_value());
  int n = 0;
  for (const auto& p : track.points) n += p.t >= a.theta_c->window_low && p.t <= a.theta_c->window_high;
  EXPECT_EQ(a.theta_c->points, n);
  EXPECT_GE(n, 10);  // the diagnostic needs at least 10
}

TEST(ThetaC, ShortRunAt60FpsIsWarnedAbout) {
  // v0 1.5 m/s, 60 fps: a short run, 17 points around the extremum; runs like it lay 1.4 stated
  // sd off rms (DISABLED_MeasureWarnedAndUnwarnedRuns), so the tool must say so.
  const auto a = analyze_theta_c_run(0.634, 20.96, 1.5, 60, 5e-4, 1);
  ASSERT_TRUE(a.theta_c.has_value());
  EXPECT_LT(a.theta_c->points, kThetaCMinPoints);
  EXPECT_TRUE(warns_about_theta_c(a));
}

TEST(ThetaC, LongRunAtHighFrameRateIsNotWarnedAbout) {
  // The seed's launch filmed at 240 and 1000 fps: 119 and 498 points, no theta_c warning.
  for (double fps : {240.0, 1000.0}) {
    const auto a = analyze_theta_c_run(0.634, 20.96, 2.62, fps, 5e-4, 1);
    ASSERT_TRUE(a.theta_c.has_value()) << fps;
    EXPECT_GE(a.theta_c->points, kThetaCMinPoints) << fps;
    EXPECT_FALSE(warns_about_theta_c(a)) << fps;
  }
}

/// Measurement behind kThetaCMinPoints (docs/theory.md, "theta_c truncation"); slow, run with
/// --gtest_also_run_disabled_tests --gtest_filter=ThetaC.DISABLED_MeasureWarnedAndUnwarnedRuns.
TEST(ThetaC, DISABLED_MeasureWarnedAndUnwarnedRuns) {
  struct Row { double z; int points; double k; double fps; bool warned; };
  std::vector<Row> rows;
  for (double mu : {0.4, 0.634, 0.9})
    for (double phi : {5.0, 10.0, 20.96, 30.0})
      for (double v0 : {1.0, 1.5, 2.62})
        for (double fps : {60.0, 120.0, 240.0, 1000.0})
          for (double noise : {2e-4, 5e-4})
            for (std::uint64_t seed : {1u, 2u, 3u}) {
              const double k = std::tan(incline::deg_to_rad(phi)) / mu;
              if (k >= 0.95) continue;
              const auto a = analyze_theta_c_run(mu, phi, v0, fps, noise, seed + (noise > 3e-4 ? 100 : 0));
              if (!a.theta_c) continue;
              rows.push_back({(a.theta_c->cos_theta_c - k) / a.theta_c->sigma_cos_theta_c, a.theta_c->points, k, fps,
                              warns_about_theta_c(a)});
            }
  auto summary = [&](const char* name, auto pick) {
    int n = 0, in2 = 0, in3 = 0;
    double worst = 0;
    for (const auto& r : rows)
      if (pick(r)) {
        ++n;
        in2 += std::abs(r.z) < 2;
        in3 += std::abs(r.z) < 3;
        worst = std::max(worst, std::abs(r.z));
      }
    std::printf("%-28s n %4d  within 2 sd %.3f  within 3 sd %.3f  worst %.2f sd\n", name, n, n ? in2 / double(n) : 0.0,
                n ? in3 / double(n) : 0.0, worst);
  };
  summary("all", [](const Row&) { return true; });
  summary("warned", [](const Row& r) { return r.warned; });
  summary("not warned", [](const Row& r) { return !r.warned; });
  summary("not warned, k < 0.3", [](const Row& r) { return !r.warned && r.k < 0.3; });
  summary("not warned, k >= 0.3", [](const Row& r) { return !r.warned && r.k >= 0.3; });
  summary("warned, k < 0.3", [](const Row& r) { return r.warned && r.k < 0.3; });
  summary("60 fps", [](const Row& r) { return r.fps < 61; });
  // rms z (1 when the sigma is right) and the share beyond 3 sd by k and by points.
  const double kb[] = {0, 0.3, 0.6, 0.95}, pb[] = {0, 20, 30, 60, 150, 1e9};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 5; ++j) {
      int n = 0, out3 = 0;
      double ss = 0;
      for (const auto& r : rows)
        if (r.k >= kb[i] && r.k < kb[i + 1] && r.points >= pb[j] && r.points < pb[j + 1]) {
          ++n;
          ss += r.z * r.z;
          out3 += std::abs(r.z) > 3;
        }
      std::printf("k [%.2f, %.2f) points [%g, %g): n %3d rms z %.2f beyond 3 sd %d\n", kb[i], kb[i + 1], pb[j],
                  pb[j + 1], n, n ? std::sqrt(ss / n) : 0.0, out3);
    }
  if (std::getenv("THETA_C_ROWS"))
    for (const auto& r : rows) std::printf("row,%.4f,%d,%.4f,%.0f\n", r.z, r.points, r.k, r.fps);
  for (const auto& r : rows)
    if (std::abs(r.z) > 3)
      std::printf("  off %.2f sd: points %d k %.3f fps %.0f warned %d\n", r.z, r.points, r.k, r.fps, r.warned);
}

}  // namespace
}  // namespace tribolab::analysis

namespace tribolab::analysis {
namespace {

TEST(NormalAccelDiagnostic, ExactDataLieWithinTheStatedSigma) {
  // The two cases: the local quadratics' truncation bias gave slope 3.5094 +- 0.0001
  // (40 sd from g sin(phi)) and an intercept 0.0045 off zero that "excluded zero", so the
  // verdict on exact model B data was "present". The bias, measured on the fitted model's
  // noise-free path, is now subtracted: slope and intercept within 2 of their sigmas (measured
  // errors < 1e-5 m/s^2, < 0.01 sigma) and the verdict absent.
  for (const auto& [mu, phi, fps] : {std::tuple{0.634, 20.96, 1000.0}, std::tuple{0.9, 30.0, 240.0}}) {
    const auto a = analyze_b_only(mu, phi, fps, 0, 1);
    ASSERT_TRUE(a.a_n.has_value());
    const auto& d = *a.a_n;
    std::printf("a_N exact mu %.3f phi %.2f fps %.0f: degree %d, slope %.5f +- %.5f (expected %.5f), "
                "intercept %.5f +- %.5f\n", mu, phi, fps, d.degree, d.slope, d.sigma_slope, d.slope_expected,
                d.intercept, d.sigma_intercept);
    // 1e-9 m/s^2: floor for the case where the quartics are exact to rounding (error and
    // sigma both ~1e-12 at 1000 fps).
    EXPECT_LE(std::abs(d.slope - d.slope_expected), 2 * d.sigma_slope + 1e-9);
    EXPECT_LE(std::abs(d.intercept), 2 * d.sigma_intercept + 1e-9);
    EXPECT_FALSE(d.intercept_excludes_zero);
    EXPECT_EQ(a.verdict_source, VerdictSource::a_n_intercept);
    EXPECT_EQ(a.verdict, Verdict::absent);
  }
}

TEST(NormalAccelDiagnostic, NoisyModelBIsCalledPresentAtAboutTheTestSize) {
  // Model B over a grid (mu 0.4-0.9, phi 10-30 deg, 60-1000 fps, 0.2 and 0.5 mm noise, 3
  // seeds each): the 95 % interval should exclude zero in ~5 % of runs. Bound: with n ~ 156
  // runs and p = 0.05 the binomial sd is sqrt(p (1 - p) / n) ~ 0.017, so 0.05 + 3 sd ~ 0.10.
  // Measured 0.090 (14 / 156; the coverage study of 1040 runs gives 0.059, 4.5-7.5 %,
  // incline_coverage_study_test.cpp); 0.071 with the former doubled truncation estimate (whose
  // 1040-run size was 0.025), 0.090 with no truncation term, 0.103 when quartic blocks were
  // also offered and the smaller sigma chosen. (A guard against gross over-confidence; the
  // calibration itself is SixtyFpsModelBIsCalledPresentAtTheTestSizeNotLess and the study.)
  // The sanitizer tree runs the same grid with seed 1 only (54 cells, ~52 runs with the
  // diagnostic): at most binomial_ceiling(n, 0.05) present, 9 of 52-54 (P(X > 9) <= 3.1e-4 at
  // the stated 5 %; 8 at n = 50). A sigma half the true one calls 33 % present: passes with
  // probability 0.01.
  const int seeds = study_draws(3, 1);  // per cell
  int runs = 0, present = 0;
  for (double mu : {0.4, 0.634, 0.9})
    for (double phi : {10.0, 20.96, 30.0})
      for (double fps : {60.0, 240.0, 1000.0})
        for (double noise : {2e-4, 5e-4})
          for (std::uint64_t seed = 1; seed <= static_cast<std::uint64_t>(seeds); ++seed) {
            const auto a = analyze_b_only(mu, phi, fps, noise, seed + (noise > 3e-4 ? 100 : 0));
            if (!a.a_n) continue;
            ++runs;
            present += a.a_n->intercept_excludes_zero;
          }
  const double rate = present / double(runs);
  std::printf("a_N false-present rate %d / %d = %.3f\n", present, runs, rate);
  if (is_full_study(seeds, 3)) {
    ASSERT_GE(runs, 120);
    EXPECT_LE(rate, 0.10);
  } else {
    ASSERT_GE(runs, 40 * seeds);  // 120 of 162 cells above: the same share of 54 per seed
    EXPECT_LE(present, binomial_ceiling(runs, 0.05));
  }
}

// Issue 27: the eq b diagnostic's size, calibrated by coverage. Its truncation error used to be
// estimated from the lines of cubic and quartic blocks (the difference, less its noise part,
// doubled): on noisy data that estimate is itself noise, positive in about a third of the runs
// and then several times the statistical sigma, so the diagnostic was conservative, most of
// all with few long blocks: over the coverage study's 1040 model-B runs it said "present" in
// 2.5 % (1.6-3.6 %) at a stated 5 %, at 60 fps in 3 of 320 (0.9 %). The bias is now measured
// on the fitted model's noise-free path and subtracted (docs/theory.md#incline-analysis, "a_N
// truncation"): 61 / 1040 (5.9 %, 4.5-7.5 %), at 60 fps 20 of 320 (6.2 %). These are the
// study's 60 fps runs (the same seeds): the count must lie within the exact binomial bounds
// of a 5 % test at alpha = 1e-3 each side, binomial_floor(320, 0.05) = 5 to
// binomial_ceiling(320, 0.05) = 29; the former estimate (3 of 320) fails the floor. The
// sanitizer tree runs 4 seeds per cell (64 runs; floor 0, ceiling 10): only the ceiling bites.
TEST(NormalAccelDiagnostic, SixtyFpsModelBIsCalledPresentAtTheTestSizeNotLess) {
  const int seeds = study_draws(20, 4);  // per cell
  int runs = 0, present = 0;
  for (double mu : {0.4, 0.634, 0.9})
    for (double phi : {10.0, 20.96, 30.0})
      for (double noise : {2e-4, 5e-4})
        for (int seed = 0; seed < seeds; ++seed) {
          const auto a = analyze_b_only(mu, phi, 60, noise, 700000 + seed + (noise > 3e-4 ? 1000 : 0));
          if (!a.a_n) continue;
          ++runs;
          present += a.a_n->intercept_excludes_zero;
        }
  std::printf("a_N at 60 fps: present in %d of %d model-B runs (accepted %d to %d)\n", present, runs,
              binomial_floor(runs, 0.05), binomial_ceiling(runs, 0.05));
  ASSERT_GE(runs, 16 * seeds);  // 320 of the 360 cells' runs have 3 or more blocks
  EXPECT_GE(present, binomial_floor(runs, 0.05));
  EXPECT_LE(present, binomial_ceiling(runs, 0.05));
}

TEST(NormalAccelDiagnostic, ModelARunIsStillCalledPresent) {
  // Real normal friction (f_N/m = 1 m/s^2, intercept -1) on noise-free data at 1000 fps: the
  // added truncation term must not hide it, with model A fitted or not (--no-model-a, where
  // the verdict comes from this intercept).
  for (bool with_a : {true, false}) {
    InclineSynthOptions s = run_options(20.96, 1e-7, 1, 1.0, 1000);
    InclineFitOptions o;
    o.phi = s.params.phi;
    o.fit_model_a = with_a;
    const auto a = analyze_incline_run(synthesize_incline_run(s).track, o);
    ASSERT_TRUE(a.a_n.has_value());
    std::printf("a_N model A (model A fitted: %d): intercept %.4f +- %.4f\n", with_a, a.a_n->intercept,
                a.a_n->sigma_intercept);
    EXPECT_TRUE(a.a_n->intercept_excludes_zero);
    EXPECT_EQ(a.verdict, Verdict::present);
  }
}

// Regression (issue 26): a valid 50 kHz run was refused ("local fit: the x values cannot
// determine a degree-4 fit"; it worked with --block 50): the a_N blocks' truncation check then
// fitted degree 4 over 25 frames = 0.5 ms (issue 27 replaced that check), whose raw powers of t
// QR took for dependent (numerics/polyfit.cpp now fits in t / max|t|). Then the block was still capped at 25 frames,
// chosen for film, not from the data: 0.5 ms blocks see 10 um of noise as a_N errors of
// ~1e3 m/s^2 (the intercept's interval was -622..655 m/s^2 on this run, useless). The block
// now spans about an eighth of the run, as at film rates.
TEST(NormalAccelDiagnostic, FiftyKilohertzRunIsAnalysedWithABlockChosenFromTheData) {
  InclineSynthOptions s = run_options(20.96, 1e-5, 3, 0, 5e4);
  s.params.v0 = 0.15;  // a short slide: stops after 0.041 s, ~1,800 frames analysed
  // Filmed from 5 ms before the launch to 20 ms after the stop (the defaults, 0.1 s before
  // and 0.3 s after, give ten times the frames and the work).
  s.t_launch = 0.005;
  s.duration = 0.065;
  InclineFitOptions o;
  o.phi = s.params.phi;
  o.fit_model_a = false;  // not needed here, and the slow part at this many frames
  const InclineAnalysis a = analyze_incline_run(synthesize_incline_run(s).track, o);
  ASSERT_TRUE(a.a_n.has_value());
  EXPECT_GT(a.a_n->block, 100);  // ~8 blocks of the ~1,800 frames, not 25 frames
  EXPECT_LE(a.a_n->t.size(), 9u);
  // The interval of the intercept was +-638 m/s^2 with 25-frame blocks; a block ~9 times
  // longer divides each block's a_N noise by ~9^2.5 = 250 (sd ~ noise / (T^2 sqrt(w))), so
  // about +-3 m/s^2 is expected (3.9 measured, truncation included): 10 is the bound.
  const double half = 0.5 * (a.a_n->intercept_ci_high - a.a_n->intercept_ci_low);
  EXPECT_LT(half, 10.0);
  EXPECT_FALSE(a.a_n->intercept_excludes_zero);  // model B: no normal friction
  // Model B's mu from the whole track (the fit, not the diagnostic): the truth within 4 sigma.
  EXPECT_NEAR(a.model_b.mu.value, 0.634, 4 * a.model_b.mu.sigma);
}
}  // namespace
}  // namespace tribolab::analysis
