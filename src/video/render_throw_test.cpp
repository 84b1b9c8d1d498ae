#include "video/render_throw.hpp"
#include "video/codec.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>

namespace tribolab::video {
namespace {

ThrowFilmOptions small_film() {
  ThrowFilmOptions o;
  o.render.width = 320;
  o.render.height = 240;
  o.render.background = RenderOptions::Background::plain;
  o.render.noise_sigma = 0;
  o.motion.after = 0.05;
  return o;
}

TEST(ThrowFilm, TruthIsTheMotionAtEachFrameTime) {
  const ThrowFilm f = plan_throw_film(small_film());
  ASSERT_EQ(f.truth.tracks.size(), 3u);
  EXPECT_EQ(f.truth.tracks[0].name, "ball");
  EXPECT_EQ(f.truth.tracks[1].name, "ball.A");
  EXPECT_EQ(f.truth.tracks[2].name, "ball.B");
  const double fps = f.render.fps;
  EXPECT_GE(f.t0, 0);
  EXPECT_LT(f.t0, 1 / fps);
  // The video covers the throw to `after` s past the separation: ~ (t_end - t0) fps frames.
  EXPECT_EQ(f.frames, static_cast<int>(std::floor((f.motion.t_end - f.t0) * fps)) + 1);
  for (const auto& tr : f.truth.tracks) ASSERT_EQ(static_cast<int>(tr.points.size()), f.frames);
  for (int k : {0, f.frames / 2, f.frames - 1}) {
    const auto s = f.motion.state(k / fps + f.t0);
    const auto& c = f.truth.tracks[0].points[k];
    EXPECT_EQ(c.frame, k);
    EXPECT_DOUBLE_EQ(c.t, k / fps);
    EXPECT_DOUBLE_EQ(c.x, s.x);
    EXPECT_DOUBLE_EQ(c.y, s.y);
    // The tips are a apart from the centre along theta.
    const auto& a = f.truth.tracks[1].points[k];
    const auto& b = f.truth.tracks[2].points[k];
    EXPECT_NEAR(std::atan2(b.y - a.y, b.x - a.x), std::remainder(s.theta, 2 * M_PI), 1e-9);
    EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), 2 * small_film().motion.ball.a, 1e-12);
  }
  EXPECT_TRUE(f.ball_in_view);  // the default layout fits the whole throw
}

TEST(ThrowFilm, BallIsDrawnWhereTheTruthSaysInPixels) {
  // Plain background, no noise: the centroid of the darkening (background - image) is the
  // ball's centre in pixels. In flight the exposure-centred blur keeps it at the frame-time
  // pose to ~g T^2/24 ~ 2e-6 m (1e-3 px) plus anti-aliasing (~0.01 px, render_test): 0.05 px.
  // Every frame whose exposure misses the contact (inside it the motion is far from uniform
  // over the exposure, so the blurred centroid is not the pose at the frame time).
  ThrowFilmOptions o = small_film();
  o.floor_band = false;
  o.render.fps = 100;
  o.motion.height = 0.3;
  const ThrowFilm f = plan_throw_film(o);
  const double grey_bg = f.render.background_colour[0];
  const double half_exposure = 0.5 * f.render.shutter_fraction / f.render.fps;
  for (int k = 0; k < f.frames; ++k) {
    const double t = k / f.render.fps + f.t0;  // real time
    if (t + half_exposure > f.motion.truth.t_touch && t - half_exposure < f.motion.truth.t_separation) continue;
    cv::Mat g;
    cv::cvtColor(render_frame(f.scene, k / f.render.fps, f.render, k), g, cv::COLOR_BGR2GRAY);
    cv::Mat dark;
    cv::subtract(cv::Scalar::all(grey_bg), g, dark, cv::noArray(), CV_64F);
    const cv::Moments mo = cv::moments(dark, false);
    const auto& c = f.truth.tracks[0].points[k];
    const cv::Point2d px = f.view.to_px(c.x, c.y);
    EXPECT_NEAR(mo.m10 / mo.m00, px.x, 0.05) << "frame " << k;
    EXPECT_NEAR(mo.m01 / mo.m00, px.y, 0.05) << "frame " << k;
  }
}

TEST(ThrowFilm, FloorLineIsTheWorldOriginAndTheBandIsDark) {
  ThrowFilmOptions o = small_film();
  const ThrowFilm f = plan_throw_film(o);
  EXPECT_GT(f.view.origin_y_px, 0);
  EXPECT_LT(f.view.origin_y_px, o.render.height - 1);
  EXPECT_EQ(f.render.floor_y_px, f.view.origin_y_px);
  const cv::Mat img = render_frame([](double) { return std::vector<ShapePose>{}; }, 0, f.render, 0);
  const int below = static_cast<int>(std::ceil(f.view.origin_y_px)) + 1, above = below - 3;
  EXPECT_EQ(img.at<cv::Vec3b>(below, 10), cv::Vec3b(60, 60, 60));
  EXPECT_EQ(img.at<cv::Vec3b>(above, 10), cv::Vec3b(200, 200, 200));
}

TEST(ThrowFilm, InvalidOptionsNameTheOption) {
  ThrowFilmOptions o = small_film();
  o.scale_m_per_px = 0.05;  // 50 mm per px: the 95 mm semi-minor axis is ~1.9 px
  try {
    plan_throw_film(o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "scale");
  }
  o = small_film();
  o.render.blur_samples = 0;
  try {
    plan_throw_film(o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "blur_samples");
  }
}

}  // namespace
}  // namespace tribolab::video

namespace tribolab::video {
namespace {

TEST(ThrowFilm, WrittenVideoDecodesToTheRenderedFrames) {
  // Regression: OpenCV 4.6's own MJPEG writer (CAP_OPENCV_MJPEG) wrote a black 16x16 block
  // into frames 24 and 25 of exactly this film; write_video now encodes through FFmpeg.
  // Every decoded frame must be the rendered one up to compression: mean error ~1 grey
  // level (bound 3), largest error ~50 at sharp edges (bound 120; the block was 200).
  ThrowFilmOptions o = small_film();
  o.floor_band = false;
  o.render.fps = 100;
  o.motion.height = 0.3;
  const ThrowFilm f = plan_throw_film(o);
  namespace fs = std::filesystem;
  for (const char* ext : {".avi", ".mp4"}) {
    const fs::path path = fs::temp_directory_path() / ("render_throw_test_" + std::to_string(::getpid()) + ext);
    write_video(path.string(), f.scene, f.frames, f.render);
    const auto cap = open_video_file(path.string());
    ASSERT_TRUE(cap) << ext;
    cv::Mat frame;
    int k = 0;
    while (cap->read(frame)) {
      const cv::Mat direct = render_frame(f.scene, k / f.render.fps, f.render, k);
      EXPECT_LT(cv::norm(frame, direct, cv::NORM_L1) / frame.total() / 3, 3.0) << ext << " frame " << k;
      EXPECT_LT(cv::norm(frame, direct, cv::NORM_INF), 120.0) << ext << " frame " << k;
      ++k;
    }
    EXPECT_EQ(k, f.frames) << ext;
    fs::remove(path);
  }
}

}  // namespace
}  // namespace tribolab::video
