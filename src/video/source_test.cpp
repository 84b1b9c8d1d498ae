#include "video/source.hpp"

#include "io/track_import.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"
#include "numerics/source_dir_test_util.hpp"
#include "video/test_videos.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace tribolab::video {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::TestVideo;

/// A fresh directory for one test's files.
std::string source_temp_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("tribolab_source_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// MJPG is lossy: a flat 8x8 block keeps its level within a few grey levels at the default
/// quality; the levels of neighbouring frames differ by 9.
constexpr double kCodeTolerance = 3;

std::vector<Frame> read_all(const VideoInput& in) {
  FrameReader reader(in);
  std::vector<Frame> frames;
  Frame f;
  while (reader.next(f)) frames.push_back(f);
  return frames;
}

io::TrkWriteSpec project_spec(const std::string& video) {
  io::TrkWriteSpec s;
  s.coords = {{0, 20, 100, 10, 200, 200}, {6, 25, 98, 12, 210, 205}};
  s.start_frame = 3;
  s.step_size = 2;
  s.step_count = 5;
  s.start_time_ms = 40;
  s.frame_duration_ms = 1000.0 / 240;
  s.length_unit = "cm";
  s.video_path = video;
  s.video_frame_count = 20;
  return s;
}

/// One human-marked track (world units of the spec) on frames 3, 5, 7.
std::vector<track::Track> human_marks() {
  track::Track t{"mark", {}};
  for (int f : {3, 5, 7}) t.points.push_back({f, 0, 0.1 * f, 0.2 - 0.01 * f});
  return {t};
}

TEST(Source, PlainVideoReportsTheContainersFacts) {
  const std::string dir = source_temp_dir("plain");
  const TestVideo v;
  write_test_video(dir + "/v.avi", v);
  const VideoInput in = open_input(dir + "/v.avi", {});
  EXPECT_EQ(in.info.width, 160);
  EXPECT_EQ(in.info.height, 120);
  EXPECT_EQ(in.info.frame_count, 20);
  EXPECT_DOUBLE_EQ(in.info.fps, 25);
  EXPECT_EQ(in.info.codec, "MJPG");
  EXPECT_DOUBLE_EQ(in.time.t(10), 10.0 / 25);
  EXPECT_FALSE(in.calibration.calibrated);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_THAT(in.warnings[0], HasSubstr("pixels"));
  EXPECT_TRUE(in.marks_px.empty());
  EXPECT_TRUE(in.project_video.empty());
}

TEST(Source, FrameReaderStreamsEveryFrameInOrderWithItsTime) {
  const std::string dir = source_temp_dir("stream");
  const TestVideo v;
  write_test_video(dir + "/v.avi", v);
  SourceOptions o;
  o.fps = 100;          // overrides the container's 25
  o.time_scale = 0.5;   // and real time runs at half the video's
  const VideoInput in = open_input(dir + "/v.avi", o);
  FrameReader reader(in);
  EXPECT_EQ(reader.expected_steps(), 20);
  const auto frames = read_all(in);
  ASSERT_EQ(frames.size(), 20u);
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(frames[i].index, i);
    EXPECT_DOUBLE_EQ(frames[i].t, i / 100.0 * 0.5);
    EXPECT_NEAR(testing::read_code(frames[i].bgr), testing::code_level(i), kCodeTolerance) << i;
    // the grey image is left to the trackers (gray_region converts the windows they read)
    EXPECT_TRUE(frames[i].gray.empty());
    EXPECT_EQ(frame_size(frames[i]), cv::Size(frames[i].bgr.cols, frames[i].bgr.rows));
  }
  // every frame owns its pixels: a tracker may keep earlier frames
  EXPECT_NE(frames[0].bgr.data, frames[1].bgr.data);
}

TEST(Source, TrkProjectGivesItsClipTimeBaseCalibrationAndMarks) {
  const std::string dir = source_temp_dir("trk");
  fs::create_directories(dir + "/videos");
  write_test_video(dir + "/videos/v.avi", TestVideo{});
  const io::TrkWriteSpec spec = project_spec("videos/v.avi");
  spit(dir + "/p.trk", io::write_trk(human_marks(), spec));
  const VideoInput in = open_input(dir + "/p.trk", {});
  EXPECT_EQ(in.project_video, "videos/v.avi");
  EXPECT_EQ(in.clip.start_frame, 3);
  EXPECT_EQ(in.clip.step_size, 2);
  EXPECT_EQ(in.clip.step_count, 5);
  EXPECT_TRUE(in.calibration.calibrated);
  EXPECT_DOUBLE_EQ(in.calibration.metres_per_unit, 0.01);
  EXPECT_EQ(in.calibration.at(7).frame, 6);  // the second key frame holds from frame 6
  const auto frames = read_all(in);
  ASSERT_EQ(frames.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    const int f = 3 + 2 * k;
    EXPECT_EQ(frames[k].index, f);
    EXPECT_NEAR(frames[k].t, (40 + (f - 3) * 1000.0 / 240) / 1000, 1e-15);
    EXPECT_NEAR(testing::read_code(frames[k].bgr), testing::code_level(f), kCodeTolerance) << f;
  }
  // the human marks, back in world units, are the numbers `track import` reads
  const track::TrackSet imported = io::read_tracks(dir + "/p.trk");
  ASSERT_EQ(in.marks_px.size(), 1u);
  ASSERT_EQ(in.marks_px[0].points.size(), 3u);
  for (std::size_t j = 0; j < 3; ++j) {
    const auto& px = in.marks_px[0].points[j];
    const auto& want = imported.tracks[0].points[j];
    const auto [x, y] = in.calibration.to_world(px.frame, px.x, px.y);
    EXPECT_EQ(x, want.x);  // the same arithmetic as the importer: bit for bit
    EXPECT_EQ(y, want.y);
    EXPECT_NEAR(px.t, want.t, 1e-15);  // seconds here, ms in the importer: one rounding apart
  }
}

TEST(Source, TrzHoldsTheVideoAsATemporaryCopyRemovedAfterUse) {
  const std::string dir = source_temp_dir("trz");
  write_test_video(dir + "/v.avi", TestVideo{});
  const io::TrkWriteSpec spec = project_spec("videos/clip.avi");
  spit(dir + "/p.trz", io::write_trz(io::write_trk(human_marks(), spec), "p.trk",
                                     {{"videos/clip.avi", slurp(dir + "/v.avi")}}));
  fs::remove(dir + "/v.avi");
  std::string temp;
  {
    const VideoInput in = open_input(dir + "/p.trz", {});
    temp = in.info.path;
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_NE(temp.find(".avi"), std::string::npos);
    FrameReader reader(in);
    Frame f;
    ASSERT_TRUE(reader.next(f));
    EXPECT_EQ(f.index, 3);
  }
  EXPECT_FALSE(fs::exists(temp)) << temp;
}

TEST(Source, ProjectMarksLandOnTrackImportsNumbersForBallToss) {
  // Tracker's own example project (not in the repository: see docs/theory.md#tracker-files)
  const std::string path = video::testing::ball_toss_path();
  if (path.empty()) GTEST_SKIP() << "BallToss.trz not found beside the repository";
  const VideoInput in = open_input(path, {});
  EXPECT_EQ(in.info.width, 640);
  EXPECT_EQ(in.info.height, 480);
  EXPECT_EQ(in.clip.step_count, 13);
  const track::TrackSet imported = io::read_tracks(path);
  const track::Track& human = imported.find("ball");
  const auto it = std::find_if(in.marks_px.begin(), in.marks_px.end(),
                               [](const auto& t) { return t.name == "ball"; });
  ASSERT_NE(it, in.marks_px.end());
  ASSERT_EQ(it->points.size(), human.points.size());
  for (std::size_t j = 0; j < human.points.size(); ++j) {
    const auto [x, y] = in.calibration.to_world(it->points[j].frame, it->points[j].x, it->points[j].y);
    EXPECT_EQ(x, human.points[j].x);
    EXPECT_EQ(y, human.points[j].y);
    // the time base is kept in seconds, the importer computes in ms: one rounding apart
    EXPECT_NEAR(it->points[j].t, human.points[j].t, 1e-15);
  }
  EXPECT_EQ(read_all(in).size(), 13u);
}

TEST(Source, PlainVideoCalibrationFromScaleStickOriginAndAxes) {
  const std::string dir = source_temp_dir("cal");
  write_test_video(dir + "/v.avi", TestVideo{});
  SourceOptions o;
  o.calibrate_points = std::make_pair(cv::Point2d(10, 100), cv::Point2d(110, 100));
  o.calibrate_length_m = 0.5;  // 100 px = 0.5 m
  o.origin_px = cv::Point2d(10, 100);
  o.axes_deg = 90;             // world x points up the image
  const VideoInput in = open_input(dir + "/v.avi", o);
  EXPECT_TRUE(in.calibration.calibrated);
  EXPECT_TRUE(in.warnings.empty());
  const auto [x, y] = in.calibration.to_world(5, 10, 80);  // 20 px above the origin
  EXPECT_NEAR(x, 0.1, 1e-15);
  EXPECT_NEAR(y, 0, 1e-15);
  const auto [px, py] = in.calibration.to_image(5, x, y);
  EXPECT_NEAR(px, 10, 1e-12);
  EXPECT_NEAR(py, 80, 1e-12);
  SourceOptions s;
  s.scale_m_per_px = 0.002;
  const VideoInput in2 = open_input(dir + "/v.avi", s);
  // default origin: the centre of the bottom-left pixel (0, 119), y up
  const auto [x2, y2] = in2.calibration.to_world(0, 50, 19);
  EXPECT_NEAR(x2, 0.1, 1e-15);
  EXPECT_NEAR(y2, 0.2, 1e-15);
}

TEST(Source, CalibrationOptionsOverrideAProjectWithAWarning) {
  const std::string dir = source_temp_dir("override");
  write_test_video(dir + "/v.avi", TestVideo{});
  spit(dir + "/p.trk", io::write_trk(human_marks(), project_spec("v.avi")));
  SourceOptions o;
  o.scale_m_per_px = 0.001;
  o.fps = 50;
  const VideoInput in = open_input(dir + "/p.trk", o);
  EXPECT_DOUBLE_EQ(in.time.frame_duration_s, 0.02);
  EXPECT_EQ(in.calibration.coords.size(), 1u);
  EXPECT_EQ(in.warnings.size(), 2u);
}

void expect_input_error(const std::string& path, const SourceOptions& o, const std::string& fragment) {
  try {
    const VideoInput in = open_input(path, o);
    read_all(in);
    FAIL() << "no error for " << path << " (" << fragment << ")";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(fragment)) << path;
    if (std::getenv("TRIBOLAB_SHOW_ERRORS")) std::printf("%s\n", e.what());
  }
}

TEST(Source, BadInputIsOneClearError) {
  const std::string dir = source_temp_dir("bad");
  write_test_video(dir + "/v.avi", TestVideo{});
  expect_input_error(dir + "/missing.avi", {}, "no such file");
  expect_input_error(dir, {}, "directory");
  spit(dir + "/text.mp4", "this is not a video at all\n");
  expect_input_error(dir + "/text.mp4", {}, "text.mp4");
  spit(dir + "/empty.avi", "");
  expect_input_error(dir + "/empty.avi", {}, "empty.avi");
  // a .trz without its video
  spit(dir + "/novideo.trz", io::write_trz(io::write_trk(human_marks(), project_spec("gone.avi")), "p.trk"));
  expect_input_error(dir + "/novideo.trz", {}, "no video");
  // a project naming no video at all
  spit(dir + "/none.trk", io::write_trk(human_marks(), project_spec("")));
  expect_input_error(dir + "/none.trk", {}, "names no video");
  // a .trk whose video is missing
  spit(dir + "/lost.trk", io::write_trk(human_marks(), project_spec("videos/lost.avi")));
  expect_input_error(dir + "/lost.trk", {}, "lost.avi");
  // a clip longer than the video
  io::TrkWriteSpec longer = project_spec("v.avi");
  longer.step_count = 15;  // frames 3..31 of a 20-frame video
  spit(dir + "/long.trk", io::write_trk(human_marks(), longer));
  expect_input_error(dir + "/long.trk", {}, "clip needs frame 21");
  SourceOptions o;
  o.scale_m_per_px = -1;
  expect_input_error(dir + "/v.avi", o, "scale");
  SourceOptions both;
  both.scale_m_per_px = 0.001;
  both.calibrate_points = std::make_pair(cv::Point2d(0, 0), cv::Point2d(10, 0));
  both.calibrate_length_m = 1;
  expect_input_error(dir + "/v.avi", both, "not both");
}

TEST(Source, TruncatedVideoIsAnErrorNotAShortTrack) {
  const std::string dir = source_temp_dir("trunc");
  TestVideo v;
  v.frames = 60;
  write_test_video(dir + "/v.avi", v);
  const std::string bytes = slurp(dir + "/v.avi");
  spit(dir + "/cut.avi", bytes.substr(0, bytes.size() / 2));
  expect_input_error(dir + "/cut.avi", {}, "cut.avi");
  spit(dir + "/head.avi", bytes.substr(0, 2000));
  expect_input_error(dir + "/head.avi", {}, "head.avi");
}

// Regression (issue 26): a variable-frame-rate video was timed by one average frame time
// (frame 39 at t = 1.973 s, its real timestamp 1.27 s), without a warning.
TEST(FrameReader, VariableFrameRateTakesTheTimestamps) {
  const std::string path = test_source_dir() + "/src/video/testdata/vfr.mkv";  // make_vfr.sh
  const VideoInput in = open_input(path, SourceOptions{});
  FrameReader reader(in);
  std::vector<double> t;
  Frame f;
  while (reader.next(f)) t.push_back(f.t);
  ASSERT_EQ(t.size(), 14u);
  // Frames 0-10 on the 30 fps grid (their 1 ms-rounded timestamps are within a quarter frame).
  for (int k = 0; k <= 10; ++k) EXPECT_DOUBLE_EQ(t[k], k / 30.0) << k;
  // Then the timestamps, 2/30 s apart, to Matroska's 1 ms.
  for (int k = 11; k < 14; ++k) EXPECT_NEAR(t[k], (10 + 2 * (k - 10)) / 30.0, 1e-3) << k;
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_THAT(reader.warnings()[0], HasSubstr("variable frame rate: 3 frame(s) take their timestamps"));
  EXPECT_THAT(reader.warnings()[0], HasSubstr("from frame 11 at t = 0.4 s, not 0.366666666667 s"));

  // --fps imposes a constant rate: the grid everywhere, no warning.
  SourceOptions fixed;
  fixed.fps = 30;
  FrameReader grid(open_input(path, fixed));
  for (int k = 0; grid.next(f); ++k) EXPECT_DOUBLE_EQ(f.t, k / 30.0) << k;
  EXPECT_TRUE(grid.warnings().empty());
}
}  // namespace
}  // namespace tribolab::video
