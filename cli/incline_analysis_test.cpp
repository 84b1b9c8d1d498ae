// Golden tests of the tracked-run analyses: `incline synth`, `mu-from-slide`, `analyze`,
// `normal-friction-test` — keys of SPEC section 5, values against the synthetic truth, and bad
// input (one stderr line, non-zero exit, nothing on stdout, no output file).
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const std::string kSeedRun = " --mu 0.634 --phi-deg 20.96 --v0 2.62 ";

TEST(InclineAnalysisCli, SynthThenAnalyzeRecoversModelB) {
  const std::string dir = temp_dir("incline_analyze_b");
  const std::string f = dir + "/run.txt";
  const json s = run_json("incline synth" + kSeedRun + "--fps 120 --seed 11 --t-offset 0.2 --out " + f);
  EXPECT_EQ(s["model"], "B");
  EXPECT_NEAR(s["t_stop"].get<double>(), 0.2 + 0.7111, 1e-3);  // seed eq 七: 0.711 s
  const json j = run_json("incline analyze " + f + " --phi-deg 20.96");
  for (const char* key : {"mu", "sigma_mu", "v0", "rms_residual", "normal_friction", "model_a",
                          "sigma_v0", "t0", "x0", "y0", "ci95", "theta_c", "n_points"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"slope", "slope_expected", "intercept", "intercept_ci95", "verdict"})
    EXPECT_TRUE(j["normal_friction"].contains(key)) << key;
  for (const char* key : {"mu", "normal_accel", "normal_accel_ci95"})
    EXPECT_TRUE(j["model_a"].contains(key)) << key;
  // The truth within the 95 % intervals (a fixed seed; coverage itself is tested in
  // src/analysis/incline_fit_test.cpp).
  const auto in = [&](const json& ci, double v) { return ci[0].get<double>() <= v && v <= ci[1].get<double>(); };
  EXPECT_TRUE(in(j["ci95"]["mu"], 0.634)) << j["ci95"]["mu"];
  EXPECT_TRUE(in(j["ci95"]["v0"], 2.62)) << j["ci95"]["v0"];
  EXPECT_TRUE(in(j["ci95"]["t0"], 0.2)) << j["ci95"]["t0"];
  EXPECT_EQ(j["normal_friction"]["verdict"], "absent");
  EXPECT_NEAR(j["normal_friction"]["slope_expected"].get<double>(), 9.8 * std::sin(20.96 * M_PI / 180), 1e-12);
  EXPECT_NEAR(j["rms_residual"].get<double>(), 0.001, 0.00015);  // 1 mm noise, ~250 residuals
}

TEST(InclineAnalysisCli, AnalyzeDetectsModelA) {
  const std::string dir = temp_dir("incline_analyze_a");
  const std::string f = dir + "/run.csv";
  run_json("incline synth" + kSeedRun + "--normal-accel 0.3 --format csv --seed 5 --out " + f);
  const json j = run_json("incline analyze " + f + " --phi-deg 20.96 --track disc");
  EXPECT_EQ(j["normal_friction"]["verdict"], "present");
  // The verdict says what it is: a test with a p-value and a size.
  EXPECT_LT(j["normal_friction"]["p_value"].get<double>(), 0.05);
  EXPECT_EQ(j["normal_friction"]["test_size"].get<double>(), 0.05);
  EXPECT_NE(j["normal_friction"]["meaning"].get<std::string>().find("one run in 20 without normal friction is called present"),
            std::string::npos)
      << j["normal_friction"]["meaning"];
  EXPECT_EQ(j["normal_friction"]["verdict_source"], "model_a_test");
  const json& ci = j["model_a"]["normal_accel_ci95"];
  EXPECT_LE(ci[0].get<double>(), 0.3);
  EXPECT_GE(ci[1].get<double>(), 0.3);
  EXPECT_LT(j["model_a"]["p_value"].get<double>(), 0.05);
}

TEST(InclineAnalysisCli, ATurnedCameraFrameIsFittedNotCalledNormalFriction) {
  // Model B filmed with the axes turned 1 deg: the rotation is reported with its interval and
  // the verdict stays absent; holding the frame aligned (--frame-rotation none) reproduces the
  // old defect (present, f_N/m ~0.15 m/s^2, far outside its interval).
  const std::string dir = temp_dir("incline_turned");
  const std::string f = dir + "/run.txt";
  run_json("incline synth" + kSeedRun + "--fps 120 --seed 12 --frame-rotation-deg 1 --out " + f);
  const json j = run_json("incline analyze " + f + " --phi-deg 20.96");
  const json& ci = j["frame_rotation_ci95_deg"];
  EXPECT_LE(ci[0].get<double>(), 1.0) << ci;
  EXPECT_GE(ci[1].get<double>(), 1.0) << ci;
  EXPECT_LT(j["sigma_frame_rotation_deg"].get<double>(), 0.05);  // ~0.02 deg at 1 mm noise
  EXPECT_EQ(j["normal_friction"]["verdict"], "absent");
  for (const char* key : {"frame_rotation_deg", "frame_rotation_ci95_deg", "normal_accel_rotation_correlation"})
    EXPECT_TRUE(j["model_a"].contains(key)) << key;
  const json n = run_json("incline analyze " + f + " --phi-deg 20.96 --frame-rotation none");
  EXPECT_EQ(n["normal_friction"]["verdict"], "present");
  EXPECT_EQ(n["frame_rotation_deg"].get<double>(), 0.0);
  EXPECT_GT(n["model_a"]["normal_accel"].get<double>(), 0.05);
  expect_error(run_tribolab("incline analyze " + f + " --phi-deg 20.96 --frame-rotation maybe"), "--frame-rotation");
}

TEST(InclineAnalysisCli, SynthIsDeterministic) {
  const std::string dir = temp_dir("incline_synth_det");
  run_json("incline synth" + kSeedRun + "--seed 9 --out " + dir + "/a.txt");
  run_json("incline synth" + kSeedRun + "--seed 9 --out " + dir + "/b.txt");
  run_json("incline synth" + kSeedRun + "--seed 10 --out " + dir + "/c.txt");
  EXPECT_EQ(slurp(dir + "/a.txt"), slurp(dir + "/b.txt"));
  EXPECT_NE(slurp(dir + "/a.txt"), slurp(dir + "/c.txt"));
}

TEST(InclineAnalysisCli, MuFromSlide) {
  // The seed's slide (伍-一-(一)): phi = 41.09 deg, a = 1.758 m/s^2, written as a plain
  // t,x,y table without noise, released at t = 0.05 s: the parabola is exact.
  const std::string dir = temp_dir("incline_slide");
  const std::string f = dir + "/slide.csv";
  std::string text = "t,x,y\n";
  for (int i = 0; i < 50; ++i) {
    const double t = i / 80.0, tr = std::max(0.0, t - 0.05);
    text += std::to_string(t) + ",0.1," + std::to_string(-0.5 * 1.758 * tr * tr) + "\n";
  }
  write_text(f, text);
  const json j = run_json("incline mu-from-slide " + f + " --phi-deg 41.09 --sigma-phi-deg 0.2");
  const double phi = 41.09 * M_PI / 180;
  // 6 significant digits in the file: a to ~1e-4.
  EXPECT_NEAR(j["a"].get<double>(), 1.758, 2e-4);
  EXPECT_NEAR(j["mu"].get<double>(), (9.8 * std::sin(phi) - 1.758) / (9.8 * std::cos(phi)), 1e-4);
  EXPECT_GT(j["sigma_mu"].get<double>(), 0.2 * M_PI / 180);  // includes the angle's share
  for (const char* key : {"a", "sigma_a", "mu", "sigma_mu", "r_squared", "n_points"})
    EXPECT_TRUE(j.contains(key)) << key;
  const json no_angle = run_json("incline mu-from-slide " + f);
  EXPECT_TRUE(no_angle["mu"].is_null());
}

TEST(InclineAnalysisCli, NormalFrictionTestFromFilesAndFromATable) {
  const std::string dir = temp_dir("incline_nft");
  std::string files;
  int seed = 20;
  for (const char* phi : {"10", "15", "20", "25"}) {
    const std::string f = dir + "/run" + phi + ".txt";
    run_json(std::string("incline synth --mu 0.634 --v0 2.62 --fps 120 --phi-deg ") + phi +
             " --seed " + std::to_string(++seed) + " --out " + f);
    files += " " + f;
  }
  const json j = run_json("incline normal-friction-test" + files + " --phi-deg 10,15,20,25");
  EXPECT_EQ(j["n_runs"], 4);
  // mu within 3.3 sigma of the truth (fixed seeds).
  EXPECT_NEAR(j["mu"].get<double>(), 0.634, 3.3 * j["sigma_mu"].get<double>());
  EXPECT_EQ(j["verdict"], "absent");

  const std::string table = dir + "/table.csv";
  write_text(table, "# the seed's 圖三-2 shape\nphi_deg,cos_theta_c\n10,0.2781\n15,0.4226\n20,0.5741\n25,0.7355\n");
  const json t = run_json("incline normal-friction-test --table " + table);
  EXPECT_NEAR(t["mu"].get<double>(), 0.634, 0.005);  // the rows are tan(phi)/0.634 to 4 digits
  EXPECT_EQ(t["verdict"], "absent");
  write_text(table, "phi_deg,cos_theta_c\n10,0.2781\n15,abc\n20,0.5741\n");
  expect_error("incline normal-friction-test --table " + table, "table.csv:3");
  expect_error("incline normal-friction-test" + files + " --phi-deg 10,15", "--phi-deg");
}

TEST(InclineAnalysisCli, BadInput) {
  const std::string dir = temp_dir("incline_analysis_bad");
  const std::string few = dir + "/few.csv", still = dir + "/still.csv", bad = dir + "/bad.csv";
  write_text(few, "t,x,y\n0,0,0\n0.0125,0.03,0\n0.025,0.06,-0.001\n");
  std::string rest = "t,x,y\n";
  for (int i = 0; i < 40; ++i) rest += std::to_string(i / 80.0) + ",0.1,0.2\n";
  write_text(still, rest);
  write_text(bad, "t,x,y\n0,0,0\n0.0125,zz,0\n");
  expect_error("incline analyze " + few + " --phi-deg 20", "points");
  expect_error("incline analyze " + still + " --phi-deg 20", "no motion");
  expect_error("incline mu-from-slide " + still + " --phi-deg 20", "stuck");
  expect_error("incline analyze " + bad + " --phi-deg 20", "bad.csv:3");
  expect_error("incline analyze " + dir + "/missing.csv --phi-deg 20", "missing.csv");
  const std::string run = dir + "/run.txt";
  run_json("incline synth" + kSeedRun + "--out " + run);
  expect_error("incline analyze " + run + " --phi-deg 20 --track nosuch", "nosuch");
  expect_error("incline analyze " + run + " --phi-deg 95", "--phi-deg");
  expect_error("incline analyze " + run, "phi-deg");
  expect_error("incline analyze " + run + " --phi-deg 20 --time-scale -1", "--time-scale");
  expect_error("incline synth" + kSeedRun + "--fps 0 --out " + dir + "/x.txt", "--fps");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.txt"));
  expect_error("incline synth" + kSeedRun + "--format xml --out " + dir + "/x.txt", "--format");
  expect_error("incline normal-friction-test", "--table");
  // Released from rest (--v0 0) the disc must slide (tan phi > mu) and follow model B.
  expect_error("incline synth --mu 0.634 --phi-deg 20 --v0 0 --out " + dir + "/x.txt", "stays");
  expect_error("incline synth --mu 0.634 --phi-deg 41 --v0 0 --normal-accel 0.3 --out " + dir + "/x.txt",
               "normal_accel");
  expect_error("incline synth --mu 0.634 --phi-deg 41 --v0 -1 --out " + dir + "/x.txt", "--v0");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.txt"));
}

}  // namespace
}  // namespace tribolab::cli::testing

namespace tribolab::cli::testing {
namespace {

/// The synthetic run `src` (Tracker Export Data text, t x y in s and m) rewritten as a plain
/// CSV t,x,y with the lengths multiplied by `factor` and no unit in its header.
void rewrite_lengths(const std::string& src, const std::string& dst, double factor) {
  std::ifstream in(src);
  std::ofstream out(dst);
  out << "t,x,y\n";
  out.precision(17);
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream cells(line);
    double t, x, y;
    if (!(cells >> t >> x >> y)) continue;  // the name and header rows
    out << t << ',' << factor * x << ',' << factor * y << '\n';
    ++rows;
  }
  ASSERT_GT(rows, 50);
}

TEST(InclineAnalysisCli, LengthUnitConvertsTheFilesLengths) {
  // The same run written in cm: read as metres it shows gravity 100x too strong (the warning);
  // with --length-unit cm it gives the metre file's fit to rounding (17 digits written).
  const std::string dir = temp_dir("incline_length_unit");
  run_json("incline synth" + kSeedRun + "--fps 120 --seed 11 --out " + dir + "/run.txt");
  rewrite_lengths(dir + "/run.txt", dir + "/m.csv", 1);
  rewrite_lengths(dir + "/run.txt", dir + "/cm.csv", 100);
  const json m = run_json("incline analyze " + dir + "/m.csv --phi-deg 20.96 --no-model-a");
  const json cm = run_json("incline analyze " + dir + "/cm.csv --phi-deg 20.96 --no-model-a --length-unit cm");
  EXPECT_NEAR(cm["mu"].get<double>(), m["mu"].get<double>(), 1e-9);
  EXPECT_NEAR(cm["v0"].get<double>(), m["v0"].get<double>(), 1e-9);
  EXPECT_NEAR(cm["gravity"]["g"].get<double>(), m["gravity"]["g"].get<double>(), 1e-9);
  const json as_m = run_json("incline analyze " + dir + "/cm.csv --phi-deg 20.96 --no-model-a");
  EXPECT_NEAR(as_m["gravity"]["g"].get<double>(), 100 * m["gravity"]["g"].get<double>(), 1e-6 * 980);
  expect_error(run_tribolab("incline analyze " + dir + "/cm.csv --phi-deg 20.96 --length-unit furlong"),
               "furlong");
}

TEST(InclineAnalysisCli, AWrongTimeScaleIsCalledOutNotAnalysedWithConfidence) {
  // Real-time data analysed as slow motion's opposite: --time-scale 8 makes every time 8x too
  // long, so the data show g/64. The analysis must say so (JSON, stderr), with the factor.
  const std::string dir = temp_dir("incline_time_scale");
  const std::string f = dir + "/run.txt";
  run_json("incline synth" + kSeedRun + "--fps 120 --seed 11 --out " + f);
  const json ok = run_json("incline analyze " + f + " --phi-deg 20.96 --no-model-a");
  EXPECT_TRUE(ok["warnings"].empty()) << ok["warnings"];
  EXPECT_LE(ok["gravity"]["g_ci95"][0].get<double>(), 9.8);
  EXPECT_GE(ok["gravity"]["g_ci95"][1].get<double>(), 9.8);

  const auto r = run_tribolab("incline analyze " + f + " --phi-deg 20.96 --no-model-a --time-scale 8 --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  // The gravity warning first (then theta_c's: the stretched run leaves 12 points in its window).
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("multiplied by 0.125"), std::string::npos) << j["warnings"];
  EXPECT_TRUE(j["gravity"]["implausible"].get<bool>());
  EXPECT_NEAR(j["gravity"]["g"].get<double>(), 9.8 / 64, 0.01);  // sigma ~0.001 m/s^2 here
  EXPECT_NE(r.err.find("tribolab: warning: the data show gravity g = 0.15"), std::string::npos) << r.err;
}

TEST(InclineAnalysisCli, NormalFrictionTestNamesAWrongTimeScale) {
  // Issue 27: three runs (10, 15, 20 deg) with --time-scale 8 or 16 where 1 is right: the
  // stretched runs lose their v_y extremum, and the error said only "needs at least 3 runs,
  // got 1" or "no v_y extremum found", never the factor each run's own analysis names.
  const std::string dir = temp_dir("nft_time_scale");
  std::string files;
  for (const char* phi : {"10", "15", "20"}) {
    const std::string f = dir + "/run" + phi + ".txt";
    run_json(std::string("incline synth --mu 0.634 --phi-deg ") + phi + " --v0 2.62 --fps 60 --seed " + phi + " --out " + f);
    files += " " + f;
  }
  for (const auto& [scale, factor] : {std::pair{"8", "0.12"}, std::pair{"16", "0.06"}}) {
    const auto r = run_tribolab("incline normal-friction-test" + files + " --phi-deg 10,15,20 --time-scale " + scale);
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.err.find(std::string("times must be multiplied by ") + factor), std::string::npos) << scale << ": " << r.err;
  }
}

TEST(InclineAnalysisCli, AThetaCFromFewPointsIsCalledOut) {
  // The seed's disc launched at 1.5 m/s and filmed at 60 fps: 17 points around the v_y
  // extremum, where the stated sigma was 1.4 times too small on average (docs/theory.md).
  const std::string dir = temp_dir("incline_theta_c_points");
  const std::string shortf = dir + "/short.txt", longf = dir + "/long.txt";
  run_json("incline synth --mu 0.634 --phi-deg 20.96 --v0 1.5 --fps 60 --seed 3 --out " + shortf);
  const auto r = run_tribolab("incline analyze " + shortf + " --phi-deg 20.96 --no-model-a --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j["theta_c"].is_object());
  const int n = j["theta_c"]["points"].get<int>();
  EXPECT_LT(n, 50);
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
  const std::string w = j["warnings"][0].get<std::string>();
  EXPECT_NE(w.find("theta_c rests on only " + std::to_string(n) + " points"), std::string::npos) << w;
  EXPECT_NE(w.find("higher frame rate"), std::string::npos) << w;
  EXPECT_NE(r.err.find("tribolab: warning: theta_c rests on only"), std::string::npos) << r.err;

  // The seed's launch at 240 fps: ~120 points, nothing to warn about.
  run_json("incline synth" + kSeedRun + "--fps 240 --seed 3 --out " + longf);
  const json ok = run_json("incline analyze " + longf + " --phi-deg 20.96 --no-model-a");
  EXPECT_GE(ok["theta_c"]["points"].get<int>(), 50);
  EXPECT_TRUE(ok["warnings"].empty()) << ok["warnings"];

  // normal-friction-test passes each run's warning on, prefixed by its file.
  std::string files;
  for (const char* phi : {"15", "20", "25"}) {
    const std::string f = dir + "/run" + phi + ".txt";
    run_json(std::string("incline synth --mu 0.634 --v0 1.5 --fps 60 --seed 4 --phi-deg ") + phi + " --out " + f);
    files += " " + f;
  }
  const json t = run_json("incline normal-friction-test" + files + " --phi-deg 15,20,25");
  ASSERT_FALSE(t["warnings"].empty());
  EXPECT_NE(t["warnings"][0].get<std::string>().find("run15.txt: theta_c rests on only"), std::string::npos)
      << t["warnings"];
}

// Regression (issue 26): one bad file among the runs lost every result (no JSON at all).
TEST(InclineAnalysisCli, NormalFrictionTestKeepsTheGoodRunsWhenOneFileIsBad) {
  const std::string dir = temp_dir("incline_nft_bad");
  std::string files;
  int seed = 40;
  for (const char* phi : {"10", "15", "20"}) {
    const std::string f = dir + "/run" + phi + ".txt";
    run_json(std::string("incline synth --mu 0.634 --v0 2.62 --fps 120 --phi-deg ") + phi + " --seed " +
             std::to_string(++seed) + " --out " + f);
    files += " " + f;
  }
  write_text(dir + "/bad.csv", "t,x,y\n0,0,0\n0.0125,zz,0\n");
  const auto r = run_tribolab("incline normal-friction-test" + files + " " + dir + "/bad.csv --phi-deg 10,15,20,25 --json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("tribolab: error: 1 of 4 runs failed (" + dir + "/bad.csv:3"), std::string::npos) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["n_runs"], 3);
  EXPECT_EQ(j["n_failed"], 1);
  EXPECT_TRUE(std::isfinite(j["mu"].get<double>()));
  ASSERT_EQ(j["runs"].size(), 4u);
  EXPECT_EQ(j["runs"][3]["source"], dir + "/bad.csv");
  EXPECT_NE(j["runs"][3]["error"].get<std::string>().find("bad.csv:3"), std::string::npos) << j["runs"][3];
}

// Regression (issue 26): one 1e308 in a good run gave mu 0.3996 (0.3001 clean), sigma null, exit 0.
TEST(InclineAnalysisCli, AValueNoRunHasIsRefusedWithItsLine) {
  const std::string dir = temp_dir("incline_huge");
  const std::string f = dir + "/run.csv";
  run_json("incline synth" + kSeedRun + "--fps 120 --format csv --out " + f);
  std::ifstream in(f);
  std::string text, line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 10) line = line.substr(0, line.rfind(',')) + ",1e308";  // y of the 9th point
    text += line + "\n";
  }
  write_text(f, text);
  const auto r = run_tribolab("incline analyze " + f + " --phi-deg 20.96");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(f + ":10: y = 1e+308 is beyond"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

// Regression (issue 26): one y 100 times off (a lost decimal point) in a good run was fitted
// without a word: mu 2.86 for a run of mu 0.634 (0.6350 from the clean file). Now the point is
// left out with a warning naming its track, frame and time, and mu is the clean file's.
TEST(InclineAnalysisCli, AValueAHundredTimesOffIsLeftOutWithAWarning) {
  const std::string dir = temp_dir("incline_outlier");
  const std::string f = dir + "/run.csv", clean = dir + "/clean.csv";
  run_json("incline synth --mu 0.634 --phi-deg 16 --v0 2.62 --fps 120 --seed 3 --format csv --out " + clean);
  std::ifstream in(clean);
  std::string text, line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 40) {  // y of a point mid-slide (track,frame,t,x,y)
      const auto comma = line.rfind(',');
      line = line.substr(0, comma + 1) + std::to_string(100 * std::stod(line.substr(comma + 1)));
    }
    text += line + "\n";
  }
  write_text(f, text);
  const json c = run_json("incline analyze " + clean + " --phi-deg 16");
  const auto r = run_tribolab("incline analyze " + f + " --phi-deg 16 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  // One point fewer of ~190 moves mu by a small part of its sigma (0.0008): 0.2 sigma bound.
  EXPECT_NEAR(j["mu"].get<double>(), c["mu"].get<double>(), 0.2 * c["sigma_mu"].get<double>());
  EXPECT_NE(r.err.find("tribolab: warning: track 'disc' frame 38 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("left out as a typo"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tribolab::cli::testing

namespace tribolab::cli::testing {
namespace {

TEST(InclineAnalysisCli, RadiansTypedAsDegreesAreCalledOutInJsonAndListing) {
  // Issue 27: the seed's 20.96 deg run with --phi-deg 0.3658 (radians) gave mu 0.398 and
  // "present" silently. The warning says it looks like radians, in the JSON and on stderr.
  const std::string dir = temp_dir("incline_radians");
  const std::string f = dir + "/run.txt";
  run_json("incline synth" + kSeedRun + "--fps 80 --seed 21 --out " + f);
  const auto r = run_tribolab("incline analyze " + f + " --phi-deg 0.3658 --no-model-a --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("looks like the angle in radians"), std::string::npos)
      << j["warnings"];
  const auto text = run_tribolab("incline analyze " + f + " --phi-deg 0.3658 --no-model-a");
  EXPECT_NE(text.err.find("tribolab: warning: the incline angle --phi-deg = 0.3658 deg contradicts the data"),
            std::string::npos) << text.err;
}

}  // namespace
}  // namespace tribolab::cli::testing
