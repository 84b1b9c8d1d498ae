// `track video` in the application layer (src/app/track/track_video.hpp), called directly on a tiny
// rendered clip (10 frames of 160x120: cheap under ASan): the tracked rows come back beside the
// JSON and equal the CSV, the sentinel options are optional, bad option text throws before any
// output exists.
#include "app/track/track_video.hpp"

#include "app/track/track_test_util.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "video/render.hpp"
#include "video/test_videos.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;
constexpr double kFps = 50;
constexpr int kFrames = 10;

/// A disc with a checker sticker crossing at 5 px per frame.
std::string film(const std::string& dir) {
  video::RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.fps = kFps;
  o.shutter_fraction = 0;
  o.background = video::RenderOptions::Background::plain;
  o.noise_sigma = 1;
  const auto scene = [](double t) {
    video::ShapePose disc;
    disc.cx_px = 30 + 5 * t * kFps;
    disc.cy_px = 60;
    disc.a_px = disc.b_px = 12;
    disc.colour = cv::Scalar(90, 160, 90);
    disc.mark = true;
    disc.mark_size_px = 15;
    return std::vector<video::ShapePose>{disc};
  };
  const std::string path = dir + "/film.avi";
  video::write_video(path, scene, kFrames, o);
  return path;
}

TEST(TrackVideo, RowsBesideTheJsonEqualTheCsv) {
  const std::string dir = testing::temp_dir("video");
  TrackVideoOptions o;
  o.input = film(dir);
  o.out = dir + "/t.csv";
  o.start = {"mark=30,60"};
  o.scale = 0.01;  // m per px
  const auto r = track_video(o);
  ASSERT_EQ(r.series.size(), 1u);
  const auto& rows = r.series[0].rows;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kFrames));
  EXPECT_EQ(r.json["frames"], kFrames);
  EXPECT_EQ(r.json["tracks"]["mark"]["tracked"], kFrames);
  EXPECT_TRUE(r.json["tracks"]["mark"]["exposure"].is_null());  // read for an ellipse only
  EXPECT_EQ(r.json["calibration"]["unit"], "m");
  EXPECT_EQ(r.json["out"], o.out);
  EXPECT_TRUE(r.json["report"].is_null());
  std::ifstream in(o.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "track,frame,t,x,y,x_px,y_px,score");
  for (const auto& row : rows) {
    ASSERT_TRUE(std::getline(in, line));
    const auto cells = io::split(line, ',');
    ASSERT_EQ(cells.size(), 8u) << line;
    EXPECT_EQ(std::stoi(cells[1]), row.frame);
    // the CSV holds shortest round-trip numbers: they read back to the same doubles
    EXPECT_EQ(std::stod(cells[3]), row.x) << line;
    EXPECT_EQ(std::stod(cells[6]), row.y_px) << line;
    // 5 px per frame at 0.01 m per px, to the tracker's sub-pixel accuracy (0.5 px at most
    // on this sharp, nearly noise-free clip)
    EXPECT_NEAR(row.x_px, 30 + 5 * row.frame, 0.5) << line;
  }
}

TEST(TrackVideo, ATrackWithNoMarkedFrameTrackedStatesNoDistanceFromTheMarks) {
  // CarInLoop's car from its first mark: no later frame is placed (docs/benchmarks.md#tracking-
  // on-real-film). Its distances from the human's marks are null, not 0 px (a perfect track).
  const std::string path = video::testing::tracker_project_path("CarInLoop.trz");
  if (path.empty()) GTEST_SKIP() << "../shared/data/tracker/CarInLoop.trz not found";
  TrackVideoOptions o;
  o.input = path;
  o.out = testing::temp_dir("video_car") + "/t.csv";
  o.from_track = {"masa A"};
  const auto r = track_video(o);
  const auto& h = r.json["tracks"]["masa A"]["vs_human"];
  ASSERT_EQ(h["frames"], 0) << "the car is placed in some frames now: choose another case";
  EXPECT_EQ(h["marks"], 52);
  EXPECT_EQ(h["to_correct"], 52);
  EXPECT_TRUE(h["median_px"].is_null());
  EXPECT_TRUE(h["p90_px"].is_null());
  EXPECT_TRUE(h["max_px"].is_null());
}

TEST(TrackVideo, BadOptionTextThrowsBeforeAnyOutput) {
  const std::string dir = testing::temp_dir("video_bad");
  TrackVideoOptions o;
  o.input = dir + "/not-read.avi";  // option errors come before the video is opened
  o.out = dir + "/never.csv";
  const auto message = [&](auto change) {
    auto c = o;
    change(c);
    try {
      track_video(c);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([](auto& c) { c.start = {"mark=30;60"}; }).find("start mark=30;60"), std::string::npos);
  EXPECT_NE(message([](auto& c) { c.calibrate = "1,2,3"; }).find("calibrate"), std::string::npos);
  EXPECT_NE(message([&](auto& c) {
              c.start = {"m=1,1"};
              c.write_trk = dir + "/x.txt";
            }).find(".trk"),
            std::string::npos);
  EXPECT_NE(message([](auto& c) {
              c.start = {"m=1,1"};
              c.fps = 0.1;
            }).find("fps"),
            std::string::npos);
  EXPECT_NE(message([](auto& c) { c.start = {"m=1,1"}; }).find("not-read.avi"), std::string::npos);
  EXPECT_FALSE(fs::exists(o.out));
}

}  // namespace
}  // namespace tribolab::app
