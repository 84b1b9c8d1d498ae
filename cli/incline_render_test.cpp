// `tribolab incline render`: the real binary, as a user runs it; the video decoded back, the
// truth analysed, bad input refused with one line and no file.
#include "cli_test_util.hpp"

#include "video/codec.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>  // cv::CAP_PROP_*

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A short, small film: mu 0.45, phi 20 deg, v0 1.2 m/s (stops after 0.84 s), 0.5 s at 60 fps.
const std::string kSmall = "incline render --mu 0.45 --phi-deg 20 --v0 1.2 --size 320x240 --duration 0.5";

TEST(InclineRenderCli, VideoAndTruthAgreeWithTheJsonCalibration) {
  const std::string dir = temp_dir("incline_render");
  const std::string video = dir + "/run.avi", truth = dir + "/truth.csv";
  const json j = run_json(kSmall + " --background plain --noise 0 --shutter 0 --out " + video + " --truth " + truth);
  for (const char* k : {"frames", "fps", "scale_m_per_px", "origin_px", "disc_start_px", "disc_radius_px",
                        "track_video_options", "truth"})
    ASSERT_TRUE(j.contains(k)) << k << " missing: " << j.dump();
  for (const char* k : {"mu", "phi_deg", "v0", "g", "k", "t0", "t_stop", "x_stop", "y_stop"})
    EXPECT_TRUE(j["truth"].contains(k)) << k;
  EXPECT_EQ(j["truth"]["mu"].get<double>(), 0.45);
  const int frames = j["frames"];
  EXPECT_EQ(frames, 30);  // 0.5 s at 60 fps, the launch at most a frame before frame 0
  const double scale = j["scale_m_per_px"], ox = j["origin_px"][0], oy = j["origin_px"][1];
  const std::string opts = j["track_video_options"];
  EXPECT_NE(opts.find("--scale " + fmt::format("{}", scale)), std::string::npos) << opts;
  EXPECT_NE(opts.find("--origin " + fmt::format("{},{}", ox, oy)), std::string::npos) << opts;
  EXPECT_NE(opts.find("--ellipse disc="), std::string::npos) << opts;

  // The truth CSV: the disc's centre in metres and in pixels, one row per frame.
  std::istringstream in(slurp(truth));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "track,frame,t,x,y,x_px,y_px");
  std::vector<std::pair<double, double>> px;
  while (std::getline(in, line)) {
    std::vector<std::string> c;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) c.push_back(cell);
    ASSERT_EQ(c.size(), 7u) << line;
    EXPECT_NEAR(std::stod(c[5]), ox + std::stod(c[3]) / scale, 1e-6);
    EXPECT_NEAR(std::stod(c[6]), oy - std::stod(c[4]) / scale, 1e-6);
    px.emplace_back(std::stod(c[5]), std::stod(c[6]));
  }
  ASSERT_EQ(static_cast<int>(px.size()), frames);

  const auto cap = video::open_video_file(video);
  ASSERT_TRUE(cap);
  EXPECT_NEAR(cap->get(cv::CAP_PROP_FPS), 60, 1e-9);
  cv::Mat f;
  int k = 0;
  double worst = 0;
  while (cap->read(f)) {
    ASSERT_LT(k, frames);
    EXPECT_EQ(f.cols, 320);
    EXPECT_EQ(f.rows, 240);
    // Plain background (grey 200), no noise, no blur: the centroid of the darkening is the
    // disc's centre in pixels. JPEG adds errors of ~1 grey level that nearly cancel over the
    // disc; 0.25 px still tells a half-pixel convention slip or a frame-time shift (the disc
    // moves up to 8 px per frame here) from a correct mapping.
    cv::Mat g, dark;
    cv::cvtColor(f, g, cv::COLOR_BGR2GRAY);
    cv::subtract(cv::Scalar::all(200), g, dark, cv::noArray(), CV_64F);
    const cv::Moments m = cv::moments(dark, false);
    worst = std::max({worst, std::abs(m.m10 / m.m00 - px[k].first), std::abs(m.m01 / m.m00 - px[k].second)});
    ++k;
  }
  EXPECT_EQ(k, frames);
  EXPECT_LT(worst, 0.25);
  fs::remove_all(dir);
}

TEST(InclineRenderCli, TruthAnalysedGivesTheLaunch) {
  // The true path itself (no tracking, no noise) through `incline analyze`: mu and v0 exactly
  // (to the fit's convergence), t0 the launch's time in the video's clock.
  const std::string dir = temp_dir("incline_render_truth");
  const json j = run_json("incline render --mu 0.45 --phi-deg 20 --v0 1.2 --size 320x240 --supersample 1 --out " + dir +
                          "/run.avi --truth " + dir + "/truth.csv");  // to 0.3 s past the stop
  const json a = run_json("incline analyze " + dir + "/truth.csv --phi-deg 20 --no-model-a");
  EXPECT_NEAR(a["mu"].get<double>(), 0.45, 1e-6) << a.dump();
  EXPECT_NEAR(a["v0"].get<double>(), 1.2, 1e-6);
  EXPECT_NEAR(a["t0"].get<double>(), j["truth"]["t0"].get<double>(), 1e-6);
  fs::remove_all(dir);
}

TEST(InclineRenderCli, SameSeedSameTruthOtherSeedOtherPhase) {
  const std::string dir = temp_dir("incline_render_seed");
  auto truth_of = [&](int seed) {
    run_json("incline render --mu 0.45 --phi-deg 20 --v0 1.2 --size 160x120 --duration 0.2 --supersample 1 --seed " +
             std::to_string(seed) + " --out " + dir + "/v.mp4 --truth " + dir + "/t.csv");
    return slurp(dir + "/t.csv");
  };
  const std::string a = truth_of(3);
  EXPECT_EQ(a, truth_of(3));
  EXPECT_NE(a, truth_of(4));  // the launch falls at another phase of the frame period
  fs::remove_all(dir);
}

TEST(InclineRenderCli, BadInputIsOneLineAndNoFile) {
  const std::string dir = temp_dir("incline_render_bad");
  const std::string video = dir + "/v.avi", truth = dir + "/t.csv";
  const std::string out = " --out " + video + " --truth " + truth;
  expect_error(kSmall + " --size 320by240" + out, "--size");
  expect_error(kSmall + " --background stripes" + out, "--background");
  expect_error(kSmall + " --shutter 1.5" + out, "--shutter");
  expect_error(kSmall + " --radius 0" + out, "--radius");
  expect_error(kSmall + " --scale 0.02" + out, "--scale");  // a 2 cm disc of 1 px
  expect_error("incline render --phi-deg 20 --v0 1.2" + out, "--mu");
  expect_error("incline render --mu 0.45 --phi-deg 95 --v0 1.2" + out, "--phi-deg");
  expect_error("incline render --mu 0.45 --phi-deg 20 --v0 abc" + out, "--v0");
  expect_error(kSmall + " --out " + dir + "/v.gif --truth " + truth, "v.gif");
  expect_error(kSmall + " --out " + video + " --truth " + dir + "/missing/t.csv", "missing");
  expect_error(kSmall + " --out " + video + " --truth " + video, "--truth");
  EXPECT_TRUE(fs::is_empty(dir)) << "a failed command left a file";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli::testing
