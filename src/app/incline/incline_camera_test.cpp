// `incline analyze` (the app function, through a tracked file) on runs filmed by a camera turned
// by +-0.5 deg: the realistic imperfection of a plumb line set slightly off (docs/theory.md,
// "Frame rotation"). The synthetic runs are seed figure 五's launch (phi = 20.96 deg, mu = 0.634,
// v0 = 2.62 m/s, model B, 1 mm noise, 80 and 240 fps); the tracked points are turned about the
// image centre, not about the launch point, as a real camera turns. Checked over noise seeds:
// the fitted frame_rotation_deg recovers the turn within its stated uncertainty, mu of both
// models keeps its stated uncertainty, and the normal-friction verdict keeps its 5 % false-alarm
// rate; with --frame-rotation none (psi held at 0) the bias it causes is measured, and the
// command must say that the data contradict the aligned frame it was told.
#include "app/incline/incline_analysis.hpp"
#include "app/incline/incline_analyze.hpp"
#include "io/track_csv.hpp"
#include "numerics/coverage_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;

constexpr double kMu = 0.634, kPhiDeg = 20.96, kV0 = 2.62;

// An image point the camera turns about: the frame's centre, 0.4 m right of and 0.25 m above
// the launch point (0.05, 0) (a 1 m field of view); any centre other than the launch point
// moves the rest point, which the fit must absorb in (x0, y0).
constexpr double kCentreX = 0.45, kCentreY = 0.25;

/// Writes the seeded model-B run, its points turned CCW by psi_deg about the image centre, to
/// `file` (tidy CSV, as Tracker's data would be read).
void write_turned_run(const std::string& file, std::uint64_t seed, double fps, double psi_deg) {
  InclineSynthOptions s;
  s.mu = kMu;
  s.phi_deg = kPhiDeg;
  s.v0 = kV0;
  s.fps = fps;
  s.noise = 0.001;
  s.seed = seed;
  s.t_offset = 0.1234;
  InclineSynthResult r = incline_synth(s);
  const double c = std::cos(to_rad(psi_deg)), n = std::sin(to_rad(psi_deg));
  track::TrackSet set;
  set.tracks.push_back(r.run.track);
  for (auto& p : set.tracks.front().points) {
    // The noise is isotropic, so turning the noisy points is the same as turning the true ones
    // and adding the noise in the image.
    const double u = p.x - kCentreX, v = p.y - kCentreY;
    p.x = kCentreX + c * u - n * v;
    p.y = kCentreY + n * u + c * v;
  }
  std::ofstream out(file);
  io::write_tidy_csv(out, set);
}

struct Counts {
  int runs = 0, psi_in_2sd = 0, mu_b_in_1sd = 0, mu_a_in_1sd = 0, mu_b_in_ci = 0, present = 0, warned = 0;
  int frame_warned = 0;  ///< runs warned that the frame held aligned is turned
  double sum_psi = 0, sum_sigma_psi = 0, sum_mu_b = 0, sum_sigma_mu_b = 0, sum_normal_accel = 0;
};

Counts analyse_turned(const std::string& tag, int runs, std::uint64_t first_seed, double psi_deg,
                      const std::string& frame_rotation) {
  const fs::path dir = fs::temp_directory_path() / ("tribolab_app_camera_" + tag);
  fs::remove_all(dir);
  fs::create_directories(dir);
  Counts k;
  for (int i = 0; i < runs; ++i) {
    const double fps = i % 2 == 0 ? 80 : 240;
    const std::string file = (dir / ("run" + std::to_string(i) + ".csv")).string();
    write_turned_run(file, first_seed + i, fps, psi_deg);
    InclineAnalyzeOptions o;
    o.files = {file};
    o.phi_deg = {kPhiDeg};
    o.frame_rotation = frame_rotation;
    const InclineAnalyzeResult r = incline_analyze(o);
    const nlohmann::json& j = r.json;
    EXPECT_FALSE(j["model_a"].is_null()) << file;
    if (j["model_a"].is_null()) continue;
    ++k.runs;
    const double psi = j["frame_rotation_deg"].get<double>(), sd_psi = j["sigma_frame_rotation_deg"].get<double>();
    const double mu_b = j["mu"].get<double>(), sd_b = j["sigma_mu"].get<double>();
    const double mu_a = j["model_a"]["mu"].get<double>(), sd_a = j["model_a"]["sigma_mu"].get<double>();
    k.psi_in_2sd += std::abs(psi - psi_deg) <= 2 * sd_psi;
    k.mu_b_in_1sd += std::abs(mu_b - kMu) <= sd_b;
    k.mu_a_in_1sd += std::abs(mu_a - kMu) <= sd_a;
    const auto ci = j["ci95"]["mu"];
    k.mu_b_in_ci += ci[0].get<double>() <= kMu && kMu <= ci[1].get<double>();
    k.present += j["normal_friction"]["verdict"] == "present";
    // theta_c's few-points warning (fewer than 50 around the v_y extremum: ~40 at 80 fps) is
    // about the diagnostic's sigma, not this fit (docs/theory.md); any other warning counts.
    bool other_warning = false;
    for (const auto& w : j["warnings"])
      other_warning |= w.get<std::string>().rfind("theta_c rests on only", 0) != 0;
    k.warned += other_warning;
    bool frame_warning = false;
    for (const auto& w : j["warnings"])
      frame_warning |= w.get<std::string>().find(field("frame_rotation") + " fit") != std::string::npos;
    k.frame_warned += frame_warning;
    if (i == 0) for (const auto& w : j["warnings"]) std::printf("warning: %s\n", w.get<std::string>().c_str());
    k.sum_psi += psi;
    k.sum_sigma_psi += sd_psi;
    k.sum_mu_b += mu_b;
    k.sum_sigma_mu_b += sd_b;
    k.sum_normal_accel += j["model_a"]["normal_accel"].get<double>();
  }
  fs::remove_all(dir);
  const double n = std::max(1, k.runs);
  std::printf("camera turned %+.1f deg, frame rotation %s: %d runs, psi within 2 sd %d (mean %.4f, mean sd %.4f), "
              "mu B within 1 sd %d, within ci95 %d (mean %.5f, mean sd %.5f), mu A within 1 sd %d, present %d, "
              "mean f_N/m %.4f, warned %d (frame %d)\n",
              psi_deg, frame_rotation.c_str(), k.runs, k.psi_in_2sd, k.sum_psi / n, k.sum_sigma_psi / n, k.mu_b_in_1sd,
              k.mu_b_in_ci, k.sum_mu_b / n, k.sum_sigma_mu_b / n, k.mu_a_in_1sd, k.present, k.sum_normal_accel / n,
              k.warned, k.frame_warned);
  return k;
}

// Binomial tolerance of a rate p over N runs: 3 sqrt(p(1-p)/N), so an honest interval fails
// a check with probability ~0.3 % (the seeds are fixed: the outcome is reproducible).
double tolerance(double p, int n) { return 3 * std::sqrt(p * (1 - p) / n); }

constexpr int kRuns = 100;  // per sign: 50 at 80 fps, 50 at 240 fps

// The sanitizer tree runs the first 30 seeds per sign (study_draws) against the exact binomial
// bounds for 30 (each fails an honest fit with probability < 1e-3): psi within 2 sd in at least
// binomial_floor(30, 0.954) = 24, mu within 1 sd in 12..28 (binomial_floor and _ceiling at
// 0.683), within its 95 % interval in at least 24, `present` at most 6. A sigma half the true
// one passes the psi count with probability 0.12 and the ci95 count with 0.095 per sign.
void expect_honest(const Counts& k, int runs) {
  ASSERT_EQ(k.runs, runs);
  if (!is_full_study(runs, kRuns)) {
    EXPECT_GE(k.psi_in_2sd, binomial_floor(runs, 0.954));
    for (int in_1sd : {k.mu_b_in_1sd, k.mu_a_in_1sd}) {
      EXPECT_GE(in_1sd, binomial_floor(runs, 0.683));
      EXPECT_LE(in_1sd, binomial_ceiling(runs, 0.683));
    }
    EXPECT_GE(k.mu_b_in_ci, binomial_floor(runs, 0.95));
    EXPECT_LE(k.present, binomial_ceiling(runs, 0.05));
    EXPECT_EQ(k.warned, 0);
    return;
  }
  // psi within 2 of its sd: 95.4 % for a Gaussian estimate (the Student t on 2n - 6 >= 170
  // degrees of freedom is Gaussian to 0.1 %); lower bound 95.4 % - 3 binomial sd = 85 %.
  EXPECT_GE(k.psi_in_2sd / double(kRuns), 0.954 - tolerance(0.954, kRuns));
  // mu within 1 sd: 68.3 %, +-3 binomial sd (0.22 at N = 40) both ways, so an overstated
  // sigma fails too; and within its 95 % interval.
  EXPECT_NEAR(k.mu_b_in_1sd / double(kRuns), 0.683, tolerance(0.683, kRuns));
  EXPECT_NEAR(k.mu_a_in_1sd / double(kRuns), 0.683, tolerance(0.683, kRuns));
  EXPECT_GE(k.mu_b_in_ci / double(kRuns), 0.95 - tolerance(0.95, kRuns));
  // Model-B data: `present` at most at the test's 5 % size + 3 binomial sd (at most 6 of 40).
  EXPECT_LE(k.present / double(kRuns), 0.05 + tolerance(0.05, kRuns));
  // An honest fit of an honest run has nothing to warn about.
  EXPECT_EQ(k.warned, 0);
}

// psi fitted (the default): the turn is recovered and nothing is biased.
TEST(InclineAnalyze, RecoversACameraTurnedHalfADegree) {
  const int runs = study_draws(kRuns, 30);
  expect_honest(analyse_turned("plus", runs, 31000, 0.5, "fit"), runs);
}

TEST(InclineAnalyze, RecoversACameraTurnedMinusHalfADegree) {
  const int runs = study_draws(kRuns, 30);
  expect_honest(analyse_turned("minus", runs, 32000, -0.5, "fit"), runs);
}

// --frame-rotation none on the same turned camera: the bias it causes, and the warning. Measured
// over 20 runs per sign (before the warning existed, the only warning was the g check's,
// g = 9.53 or 10.07 m/s^2 at +-0.5 deg, which sends the user to the frame rate): mu +0.0045
// (+0.5 deg) and -0.0045 (-0.5 deg), ~13 of its sd 0.00035; `present` in every run with
// f_N/m = +-0.075 m/s^2. The command must say that the frame it was told is aligned is not.
// The sanitizer tree runs the first 5 seeds per sign (each run's checks are ~13 and ~7.5 sd
// events, so 5 runs check them as 20 do) and 12 aligned runs (below).
TEST(InclineAnalyze, WarnsWhenAFrameHeldAlignedIsTurned) {
  const int runs = study_draws(20, 5);
  for (double psi : {0.5, -0.5}) {
    const Counts k = analyse_turned(psi > 0 ? "none_plus" : "none_minus", runs, psi > 0 ? 33000 : 34000, psi, "none");
    ASSERT_EQ(k.runs, runs);
    // The bias is ~6 sd: every fit misses mu by more than its sd, and its mean is off by more
    // than 4 sd in the direction of the turn (a documented defect of the option, not noise).
    // The turned frame leaves residuals correlated in time, which widen the sd about 2 times
    // (the bias was ~13 sd of the independent-noise sd; docs/theory.md#fitting).
    EXPECT_EQ(k.mu_b_in_1sd, 0);
    EXPECT_GT(psi * (k.sum_mu_b / runs - kMu), 4 * 0.5 * k.sum_sigma_mu_b / runs);
    EXPECT_EQ(k.present, runs);
    // psi held at 0 is refitted free with model A as a check (sd ~0.067 deg there, against
    // model B's 0.028: A's psi shares the path's bending with f_N/m): a 0.5 deg turn is ~7.5 sd,
    // so the 3-sd warning fires in every run (measured 20 of 20 each sign; 0 before the check).
    EXPECT_EQ(k.frame_warned, runs);
  }
  // Without model A the check refits model B's psi and says so (B's psi also absorbs a normal
  // friction). One seeded run at 0.5 deg: B's sd is ~0.03 deg, so the turn is ~17 sd.
  {
    const fs::path dir = fs::temp_directory_path() / "tribolab_app_camera_no_a";
    fs::create_directories(dir);
    const std::string file = (dir / "run.csv").string();
    write_turned_run(file, 33100, 80, 0.5);
    InclineAnalyzeOptions o;
    o.files = {file};
    o.phi_deg = {kPhiDeg};
    o.frame_rotation = "none";
    o.no_model_a = true;
    const nlohmann::json j = incline_analyze(o).json;
    bool warned = false;
    for (const auto& w : j["warnings"]) {
      const std::string text = w.get<std::string>();
      warned |= text.find(field("frame_rotation") + " fit") != std::string::npos && text.find("model B") != std::string::npos;
    }
    EXPECT_TRUE(warned) << j["warnings"];
    fs::remove_all(dir);
  }
  // An aligned camera analysed with --frame-rotation none must not be warned about: the check
  // is a 3-sd test (0.27 % false alarms), so 40 runs allow at most 1 (P(>= 2) ~ 0.5 %).
  // Sanitizer tree: 12 runs, at most 1 warned (P(>= 2) = 4.7e-4), mu within 1 sd in at least
  // binomial_floor(12, 0.683) = 3 (P(X < 3) = 3.4e-4; the coverage of mu is checked with power
  // by the two tests above).
  const int aligned_runs = study_draws(40, 12);
  const Counts aligned = analyse_turned("none_aligned", aligned_runs, 35000, 0.0, "none");
  ASSERT_EQ(aligned.runs, aligned_runs);
  EXPECT_LE(aligned.frame_warned, 1);
  if (is_full_study(aligned_runs, 40)) {
    EXPECT_NEAR(aligned.mu_b_in_1sd / 40.0, 0.683, tolerance(0.683, 40));
  } else {
    EXPECT_GE(aligned.mu_b_in_1sd, binomial_floor(aligned_runs, 0.683));
  }
}

}  // namespace
}  // namespace tribolab::app
