// The workflows on tracked incline runs called directly: synth -> analyze / mu-from-slide
// recover the friction the simulator used, the normal-friction test from a table whose points lie
// on eq c's line, a series that keeps going past a failed run, and errors naming the option.
#include "app/incline/incline_analysis.hpp"
#include "app/incline/incline_analyze.hpp"
#include "numerics/error.hpp"
#include "app/track/track_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace tribolab::app {
namespace {

using testing::temp_dir;

namespace fs = std::filesystem;

void expect_input_error(const std::function<void()>& f, const std::string& option) {
  try {
    f();
    ADD_FAILURE() << "no error for " << option;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(option + ": ", 0), 0u) << e.what();
  }
}

InclineSynthOptions seed_run(double phi_deg, double v0) {
  InclineSynthOptions o;
  o.mu = 0.634;
  o.phi_deg = phi_deg;
  o.v0 = v0;
  o.fps = 120;
  return o;
}

TEST(InclineSynth, KeepsTheTrackAndTruthWithoutWritingAFile) {
  const InclineSynthResult r = incline_synth(seed_run(20.96, 2.62));
  EXPECT_TRUE(r.json["out"].is_null());
  ASSERT_EQ(r.run.track.points.size(), r.json["points"].get<std::size_t>());
  ASSERT_EQ(r.run.truth.size(), r.run.track.points.size());
  EXPECT_EQ(r.json["model"], "B");
  // The truth ends at rest at the reported stopping point.
  EXPECT_EQ(r.json["x_stop"].get<double>(), r.run.truth.back().x);
  InclineSynthOptions bad = seed_run(20.96, 2.62);
  bad.frame_rotation_deg = 25;
  expect_input_error([&] { incline_synth(bad); }, "frame_rotation_deg");
  bad = seed_run(20.96, 2.62);
  bad.format = "xml";
  expect_input_error([&] { incline_synth(bad); }, "format");
  bad = seed_run(20.96, 2.62);
  bad.mu.reset();
  expect_input_error([&] { incline_synth(bad); }, "mu");
}

TEST(InclineAnalyze, RecoversTheFrictionOfASynthesizedRun) {
  const std::string dir = temp_dir("analyze");
  InclineSynthOptions s = seed_run(20.96, 2.62);
  s.out = dir + "/run.txt";
  incline_synth(s);
  InclineAnalyzeOptions o;
  o.files = {s.out};
  o.phi_deg = {20.96};
  const InclineAnalyzeResult r = incline_analyze(o);
  ASSERT_EQ(r.runs.size(), 1u);
  ASSERT_TRUE(r.runs[0].analysis);
  const double mu = r.json["mu"].get<double>(), sigma = r.json["sigma_mu"].get<double>();
  // Seeded noise, one run: the truth within 3 standard errors (the fit's calibration over 200
  // runs is in src/analysis/incline_fit_test.cpp).
  EXPECT_NEAR(mu, 0.634, 3 * sigma);
  EXPECT_EQ(r.runs[0].analysis->data.size(), r.json["n_points"].get<std::size_t>());
  EXPECT_EQ(r.runs[0].analysis->model_b_at_data.size(), r.runs[0].analysis->data.size());
  o.phi_deg = {20.96, 12};
  expect_input_error([&] { incline_analyze(o); }, "phi_deg");  // two angles, one file
  o.phi_deg = {20.96};
  o.frame_rotation = "guess";
  expect_input_error([&] { incline_analyze(o); }, "frame_rotation");
  o.frame_rotation = "fit";
  o.block = 3;
  expect_input_error([&] { incline_analyze(o); }, "block");
  fs::remove_all(dir);
}

TEST(InclineAnalyze, ASeriesKeepsGoingPastAFailedRun) {
  const std::string dir = temp_dir("analyze_series");
  InclineSynthOptions s = seed_run(20.96, 2.62);
  s.out = dir + "/a.txt";
  incline_synth(s);
  InclineAnalyzeOptions o;
  o.files = {s.out, dir + "/missing.txt", s.out};
  o.phi_deg = {20.96};
  o.series.threads = 1;
  const InclineAnalyzeResult r = incline_analyze(o);  // no throw: the failure is a row
  ASSERT_EQ(r.runs.size(), 3u);
  EXPECT_FALSE(r.runs[1].analysis);
  EXPECT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.json["summary"]["n_failed"], 1);
  EXPECT_EQ(r.json["runs"][1]["file"], o.files[1]);
  EXPECT_TRUE(r.json["runs"][1].contains("error"));
  // The same file twice gives the same fit (the runs are independent of the threads).
  EXPECT_EQ(r.json["runs"][0]["mu"], r.json["runs"][2]["mu"]);
  fs::remove_all(dir);
}

TEST(InclineMuFromSlide, RecoversTheFrictionOfASynthesizedSlide) {
  const std::string dir = temp_dir("slide");
  InclineSynthOptions s = seed_run(41.09, 0);
  s.fps = 240;
  s.duration = 0.7;
  s.out = dir + "/slide.txt";
  incline_synth(s);
  InclineMuFromSlideOptions o;
  o.files = {s.out};
  o.phi_deg = {41.09};
  const InclineMuFromSlideResult r = incline_mu_from_slide(o);
  ASSERT_TRUE(r.runs[0].result);
  // Eq a on seeded noise: the truth within 3 standard errors.
  EXPECT_NEAR(r.json["mu"].get<double>(), 0.634, 3 * r.json["sigma_mu"].get<double>());
  EXPECT_EQ(r.runs[0].result->t.size(), r.runs[0].result->s.size());
  o.sigma_phi_deg = {0.1};
  o.phi_deg.clear();
  expect_input_error([&] { incline_mu_from_slide(o); }, "sigma_phi_deg");  // needs an angle
  fs::remove_all(dir);
}

TEST(InclineNormalFrictionTest, ATableOnEqCsLineGivesItsSlope) {
  const std::string dir = temp_dir("nft");
  const std::string table = dir + "/t.csv";
  {
    // cos(theta_c) = tan(phi) / mu with mu = 0.6 and no intercept (eq c without normal friction).
    std::ofstream f(table);
    f << "phi_deg,cos_theta_c\n";
    for (double phi : {10.0, 15.0, 20.0, 25.0}) f << phi << ',' << std::tan(phi * M_PI / 180) / 0.6 << '\n';
  }
  InclineNormalFrictionTestOptions o;
  o.table = table;
  const InclineNormalFrictionTestResult r = incline_normal_friction_test(o);
  // Exact points: least squares returns the line to rounding (the table holds 6 digits: 1e-5).
  EXPECT_NEAR(r.json["mu"].get<double>(), 0.6, 1e-4);
  EXPECT_NEAR(r.json["intercept"].get<double>(), 0, 1e-5);
  ASSERT_EQ(r.tan_phi.size(), 4u);
  EXPECT_EQ(r.json["runs"][0]["source"], table + ":2");
  o.files = {"a.csv"};
  expect_input_error([&] { incline_normal_friction_test(o); }, "table");
  o.table.clear();
  o.files = {"a.csv", "b.csv"};
  o.phi_deg = {10};
  expect_input_error([&] { incline_normal_friction_test(o); }, "phi_deg");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::app
