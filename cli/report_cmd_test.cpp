// Golden tests of `--report FILE.html` on the simulation commands: the report appears, is
// self-contained (no external script), holds the expected figures and the seed's equation
// numbers; a bad report path is one error line with no output at all.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;

/// Runs `command --report DIR/r.html` and checks the report; returns its text.
std::string expect_report(const std::string& name, const std::string& command, std::size_t figures) {
  const std::string dir = temp_dir("report_" + name);
  const std::string path = dir + "/r.html";
  const auto r = run_tribolab(command + " --report '" + path + "'");
  EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  if (!fs::exists(path)) {
    ADD_FAILURE() << command << ": no report written";
    return {};
  }
  const std::string html = slurp(path);
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), figures) << command;
  EXPECT_EQ(html.find("<script src"), std::string::npos) << command;
  EXPECT_EQ(html.find("src=\"http"), std::string::npos) << command;
  return html;
}

TEST(ReportCmd, InclineSimulateModelBOverlaysClosedFormAndNumeric) {
  const std::string out = temp_dir("report_sim") + "/t.csv";
  const std::string html =
      expect_report("incline_sim", "incline simulate --mu 0.634 --phi-deg 23.2 --v0 2.3 --out '" + out + "'", 7);
  EXPECT_NE(html.find("incline study, eq 2 (二)"), std::string::npos);
  EXPECT_NE(html.find("numeric (Dormand"), std::string::npos);  // the overlay
  EXPECT_TRUE(fs::exists(out));
}

TEST(ReportCmd, InclineSimulateWithManyRowsKeepsTheReportSmall) {
  const std::string out = temp_dir("report_sim_rows") + "/t.csv";
  const std::string html = expect_report(
      "incline_sim_rows", "incline simulate --mu 0.634 --phi-deg 23.2 --v0 2.3 --dt 1e-5 --out '" + out + "'", 7);
  // ~93000 rows in the CSV; the report draws at most 2001 samples per curve: 14 curves of
  // 2001 points of ~20 characters each add well under 2 MB to the 4.8 MB library.
  EXPECT_LT(html.size(), 7'000'000u);
}

TEST(ReportCmd, InclineSimulateModelA) {
  const std::string out = temp_dir("report_sim_a") + "/t.csv";
  const std::string html = expect_report(
      "incline_sim_a", "incline simulate --model A --normal-accel 0.5 --mu 0.6 --phi-deg 20 --v0 2 --out '" + out + "'", 7);
  EXPECT_NE(html.find("model A"), std::string::npos);
}

TEST(ReportCmd, InclineFamilies) {
  const std::string out = temp_dir("report_fam") + "/f.csv";
  const std::string html = expect_report(
      "incline_fam", "incline families --mu 0.634 --phi-deg 20.96 --vary v0 --values 1,2,2.62 --out '" + out + "'", 7);
  EXPECT_NE(html.find("v0 = 2.62"), std::string::npos);
}

TEST(ReportCmd, InclinePredict) {
  const std::string html = expect_report("incline_pred", "incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62", 7);
  EXPECT_NE(html.find("incline study, eqs 7, 8, 9 (七, 八, 九)"), std::string::npos);
}

TEST(ReportCmd, BounceSimulateShowsHistoriesAndPhases) {
  const std::string html =
      expect_report("bounce_sim", "bounce simulate --vy -4 --omega -40 --theta-deg 20", 7);
  EXPECT_NE(html.find("Stick/slip phases"), std::string::npos);
  EXPECT_NE(html.find("rugby-ball study"), std::string::npos);
}

TEST(ReportCmd, BounceDrop) {
  const std::string html = expect_report("bounce_drop", "bounce drop --height 0.8 --theta-deg 30 --omega -45 --bounces 2", 2);
  EXPECT_NE(html.find("Bounces"), std::string::npos);
}

TEST(ReportCmd, BounceContactTime) {
  const std::string html =
      expect_report("bounce_ct", "bounce contact-time --height 0.715 --omega -47.6 --theta-deg 11.29 --a 0.143", 2);
  EXPECT_NE(html.find("Gap between the lowest point"), std::string::npos);
}

/// A ball bouncing once at t = 0.3 s (vy -2.94 -> +2.5 m/s), sampled at 100 fps, 1 mm noise free.
std::string bouncing_table(const std::string& dir) {
  const std::string path = dir + "/ball.txt";
  std::ofstream f(path);
  f << "t\tx\ty\n";
  for (int i = 0; i < 60; ++i) {
    const double t = 0.01 * i;
    const double y = t < 0.3 ? 0.6 - 4.9 * t * t : 0.159 + 2.5 * (t - 0.3) - 4.9 * (t - 0.3) * (t - 0.3);
    char line[96];
    std::snprintf(line, sizeof line, "%.3f\t%.6f\t%.6f\n", t, 0.5 * t, y);
    f << line;
  }
  return path;
}

TEST(ReportCmd, TrackKinematicsWithErrorBarsAndImpacts) {
  const std::string dir = temp_dir("report_track_input");
  const std::string in = bouncing_table(dir);
  const std::string html = expect_report(
      "track", "track kinematics '" + in + "' --method savgol --out '" + dir + "/k.csv'", 6);
  EXPECT_NE(html.find("Impacts"), std::string::npos);
  EXPECT_NE(html.find("savgol ± 1 standard error"), std::string::npos);
}

TEST(ReportCmd, BadReportPathIsOneErrorLineAndNoOutput) {
  const std::string dir = temp_dir("report_bad_out");
  expect_bad_report_paths("incline simulate --mu 0.6 --phi-deg 20 --v0 2 --out '" + dir + "/s.csv'", dir + "/s.csv");
  expect_bad_report_paths("incline families --mu 0.6 --phi-deg 20 --vary v0 --values 1,2 --out '" + dir + "/f.csv'",
                    dir + "/f.csv");
  expect_bad_report_paths("incline predict --mu 0.6 --phi-deg 20 --v0 2", "");
  expect_bad_report_paths("bounce simulate --vy -4", "");
  expect_bad_report_paths("bounce drop --height 0.8", "");
  expect_bad_report_paths("bounce contact-time --height 0.8", "");
  expect_bad_report_paths("bounce sweep --theta-deg 100:170:3 --omega 30:50:2 --out '" + dir + "/w.csv'", dir + "/w.csv");
  expect_bad_report_paths("bounce merge '" + dir + "/p0.csv' --out '" + dir + "/all.csv'", dir + "/all.csv");
  const std::string in = bouncing_table(dir);
  expect_bad_report_paths("track kinematics '" + in + "' --out '" + dir + "/k.csv'", dir + "/k.csv");
}

}  // namespace
}  // namespace tribolab::cli::testing
