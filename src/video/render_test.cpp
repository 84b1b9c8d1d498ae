#include "video/render.hpp"
#include "video/codec.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>  // cv::CAP_PROP_*

#include <cmath>
#include <filesystem>
#include <numbers>

namespace tribolab::video {
namespace {

RenderOptions plain_black(int w = 160, int h = 120) {
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.background = RenderOptions::Background::plain;
  o.background_colour = cv::Scalar(0, 0, 0);
  o.noise_sigma = 0;
  o.shutter_fraction = 0;
  return o;
}

ShapePose white_ellipse(double cx, double cy, double a, double b, double angle) {
  ShapePose s;
  s.cx_px = cx;
  s.cy_px = cy;
  s.a_px = a;
  s.b_px = b;
  s.angle_rad = angle;
  s.colour = cv::Scalar(255, 255, 255);
  return s;
}

// Sum of grey levels / 255 = the area the shapes cover, px^2; and the intensity centroid.
struct Moments {
  double area, cx, cy;
};
Moments moments(const cv::Mat& bgr) {
  cv::Mat g;
  cv::cvtColor(bgr, g, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(g, false);
  return {m.m00 / 255.0, m.m10 / m.m00, m.m01 / m.m00};
}

TEST(Render, EllipseAreaIsPiAB) {
  // A tilted ellipse, centre off the pixel grid. With 4x4 sub-pixels each boundary pixel's
  // coverage is known to 1/16; the errors along ~2 pi sqrt((a^2+b^2)/2) ~ 160 boundary
  // pixels have random signs, so the area error is ~ sqrt(160) * (1/16)/sqrt(12) ~ 0.25 px^2,
  // plus 8-bit rounding (< 0.5/255 per boundary pixel, ~0.3 px^2 at worst): 1 px^2 of
  // 1602 px^2 (0.06 %) is a bound of several sigma.
  const double a = 30, b = 17;
  const Scene scene = [&](double) { return std::vector<ShapePose>{white_ellipse(80.3, 60.7, a, b, 0.3)}; };
  const Moments m = moments(render_frame(scene, 0, plain_black(), 0));
  EXPECT_NEAR(m.area, std::numbers::pi * a * b, 1.0);
  // The centroid of a symmetric shape is its centre (sub-pixel to the same accuracy).
  EXPECT_NEAR(m.cx, 80.3, 0.01);
  EXPECT_NEAR(m.cy, 60.7, 0.01);
}

TEST(Render, RectangleOccludesTheEllipseBehindIt) {
  // A 20 x 20 black square (an occluder) in front of the centre of a white ellipse hides
  // 400 px^2 of it: the area seen is pi a b - 400 (to the same ~1 px^2 as above).
  ShapePose hand;
  hand.kind = ShapePose::Kind::rectangle;
  hand.cx_px = 80.37;  // off the pixel grid, like the ellipse: see EllipseAreaIsPiAB
  hand.cy_px = 60.21;
  hand.a_px = hand.b_px = 10;
  hand.colour = cv::Scalar(0, 0, 0);
  const Scene scene = [&](double) { return std::vector<ShapePose>{white_ellipse(80.37, 60.21, 30, 20, 0.1), hand}; };
  EXPECT_NEAR(moments(render_frame(scene, 0, plain_black(), 0)).area, std::numbers::pi * 600 - 400, 1.0);
}

TEST(Render, BlurredMovingEllipseCentroidIsItsPoseAtTheFrameTime) {
  // Moving at 2400 px/s and turning at 40 rad/s, filmed at 240 fps with the shutter open the
  // whole frame: each frame smears the ball over 10 px. The exposure is centred on the frame
  // time, so the intensity centroid is the centre at t (sub-frames symmetric about t; the
  // residual is anti-aliasing, ~0.01 px as above). An exposure starting at t would put it
  // 5 px further on: a 0.05 px tolerance tells the two apart by a factor 100.
  const double vx = 2400, vy = -1200, omega = 40;
  const Scene scene = [&](double t) {
    return std::vector<ShapePose>{white_ellipse(40 + vx * t, 80 + vy * t, 16, 10, omega * t)};
  };
  RenderOptions o = plain_black();
  o.fps = 240;
  o.shutter_fraction = 1;
  o.blur_samples = 16;
  for (int i = 1; i <= 3; ++i) {
    const double t = i / o.fps;
    const Moments m = moments(render_frame(scene, t, o, i));
    EXPECT_NEAR(m.cx, 40 + vx * t, 0.05) << "frame " << i;
    EXPECT_NEAR(m.cy, 80 + vy * t, 0.05) << "frame " << i;
    EXPECT_NEAR(m.area, std::numbers::pi * 160, 1.0);  // blur moves intensity, it keeps the total
  }
  // And the blur is there: the blurred frame differs from the sharp one.
  RenderOptions sharp = o;
  sharp.shutter_fraction = 0;
  EXPECT_GT(cv::norm(render_frame(scene, 1 / o.fps, o, 1), render_frame(scene, 1 / o.fps, sharp, 1), cv::NORM_L1),
            1000.0);
}

TEST(Render, NoiseHasTheRequestedStandardDeviation) {
  RenderOptions o = plain_black(320, 240);
  o.background_colour = cv::Scalar(128, 128, 128);  // far from 0 and 255: no clipping
  o.noise_sigma = 5;
  const Scene empty = [](double) { return std::vector<ShapePose>{}; };
  cv::Mat f;
  render_frame(empty, 0, o, 7).convertTo(f, CV_64FC3);
  cv::Scalar mean, sd;
  cv::meanStdDev(f.reshape(1), mean, sd);
  // Rounding to integers adds a uniform error of variance 1/12. With 230400 values the sd
  // is estimated to 1/sqrt(2N) = 0.15 % and the mean to sigma/sqrt(N) = 0.01: 1 % and 0.05
  // are five sigma or more.
  EXPECT_NEAR(sd[0], std::sqrt(25 + 1.0 / 12), 0.01 * 5);
  EXPECT_NEAR(mean[0], 128, 0.05);
}

TEST(Render, SameSeedSameFramesOtherSeedOtherNoise) {
  RenderOptions o = plain_black(64, 48);
  o.background = RenderOptions::Background::texture;
  o.background_colour = cv::Scalar(120, 140, 160);
  o.noise_sigma = 3;
  o.seed = 42;
  const Scene scene = [](double t) { return std::vector<ShapePose>{white_ellipse(30 + 100 * t, 20, 8, 5, t)}; };
  const cv::Mat a = render_frame(scene, 0.01, o, 3), b = render_frame(scene, 0.01, o, 3);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, render_frame(scene, 0.01, o, 4), cv::NORM_L1), 0.0);  // noise per frame
  RenderOptions other = o;
  other.seed = 43;
  EXPECT_GT(cv::norm(a, render_frame(scene, 0.01, other, 3), cv::NORM_L1), 0.0);
}

TEST(Render, TextureAndGradientBackgroundsVaryPlainDoesNot) {
  const Scene empty = [](double) { return std::vector<ShapePose>{}; };
  for (auto bg : {RenderOptions::Background::plain, RenderOptions::Background::gradient,
                  RenderOptions::Background::texture}) {
    RenderOptions o = plain_black(64, 48);
    o.background = bg;
    o.background_colour = cv::Scalar(150, 150, 150);
    cv::Scalar mean, sd;
    cv::meanStdDev(render_frame(empty, 0, o, 0).reshape(1), mean, sd);
    if (bg == RenderOptions::Background::plain) {
      EXPECT_EQ(sd[0], 0.0);
    } else {
      EXPECT_GT(sd[0], 3.0) << static_cast<int>(bg);  // visibly structured
    }
  }
}

TEST(Render, StickerIsACheckerInTheBodyFrame) {
  // A sticker of 3 x 12 px cells at (10, 0) in the body frame of an ellipse turned by 90
  // degrees counter-clockwise on screen: body +u points to screen up (image -y), so the
  // sticker centre is at image (cx, cy - 10); its centre cell is dark, its edge cells light.
  ShapePose s = white_ellipse(80, 60, 30, 25, std::numbers::pi / 2);
  s.colour = cv::Scalar(0, 0, 255);
  s.mark = true;
  s.mark_u_px = 10;
  s.mark_size_px = 12;
  const Scene scene = [&](double) { return std::vector<ShapePose>{s}; };
  const cv::Mat f = render_frame(scene, 0, plain_black(), 0);
  EXPECT_EQ(f.at<cv::Vec3b>(50, 80), cv::Vec3b(30, 30, 30));     // centre cell: dark
  EXPECT_EQ(f.at<cv::Vec3b>(46, 80), cv::Vec3b(235, 235, 235));  // the cell beyond it: light
  EXPECT_EQ(f.at<cv::Vec3b>(60, 80), cv::Vec3b(0, 0, 255));      // the body's own colour
}

TEST(Render, InvalidOptionsAreNamed) {
  RenderOptions o;
  EXPECT_EQ(o.validate(), "");
  o.blur_samples = 0;
  EXPECT_NE(o.validate().find("blur-samples"), std::string::npos);
  o = RenderOptions{};
  o.shutter_fraction = 1.5;
  EXPECT_NE(o.validate().find("shutter"), std::string::npos);
  o = RenderOptions{};
  o.fps = 0;
  EXPECT_THROW(render_frame([](double) { return std::vector<ShapePose>{}; }, 0, o, 0), InputError);
}

class WriteVideo : public ::testing::TestWithParam<const char*> {};

TEST_P(WriteVideo, DecodesToTheFramesSizeAndRateWritten) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("render_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  const fs::path path = dir / (std::string("clip") + GetParam());
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.fps = 30;
  o.blur_samples = 2;
  const Scene scene = [](double t) { return std::vector<ShapePose>{white_ellipse(50 + 600 * t, 120, 20, 12, 3 * t)}; };
  write_video(path.string(), scene, 12, o);
  const auto cap = open_video_file(path.string());
  ASSERT_TRUE(cap);
  EXPECT_NEAR(cap->get(cv::CAP_PROP_FPS), 30, 1e-6);
  int count = 0;
  cv::Mat frame;
  double err = 0;
  while (cap->read(frame)) {
    EXPECT_EQ(frame.cols, 320);
    EXPECT_EQ(frame.rows, 240);
    if (count == 5) err = cv::norm(frame, render_frame(scene, 5 / o.fps, o, 5), cv::NORM_L1) / frame.total() / 3;
    ++count;
  }
  EXPECT_EQ(count, 12);
  // Lossy compression: the decoded frame stays within a few grey levels of the rendered one
  // on average (MJPG ~ 1, mp4v ~ 2-3); 6 catches a wrong frame or colour order.
  EXPECT_LT(err, 6.0) << GetParam();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);  // no temporary left
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Containers, WriteVideo, ::testing::Values(".avi", ".mp4"));

TEST(WriteVideoErrors, UnwritablePathsThrowAndLeaveNoFile) {
  namespace fs = std::filesystem;
  const Scene empty = [](double) { return std::vector<ShapePose>{}; };
  RenderOptions o;
  o.width = 32;
  o.height = 32;
  EXPECT_THROW(write_video("/nonexistent-dir/x.avi", empty, 2, o), InputError);
  const fs::path bad = fs::temp_directory_path() / "render_test_clip.gif";
  EXPECT_THROW(write_video(bad.string(), empty, 2, o), InputError);
  EXPECT_FALSE(fs::exists(bad));
  EXPECT_THROW(write_video((fs::temp_directory_path() / "render_test_zero.avi").string(), empty, 0, o), InputError);
}

}  // namespace
}  // namespace tribolab::video
