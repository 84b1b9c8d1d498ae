// SceneMemory: still texture told from an object that comes to its place.
#include "video/scene_memory.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <random>

namespace tribolab::video {
namespace {

// A 160x120 grey frame of fixed random texture with a bright 9 px square centred at (cx, 60),
// its grey levels `offset` brighter everywhere (a camera's exposure drifting).
Frame textured(int index, int cx, int offset = 0) {
  cv::Mat g(120, 160, CV_8U);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> level(60, 180);
  for (int y = 0; y < g.rows; ++y) {
    for (int x = 0; x < g.cols; ++x) g.at<unsigned char>(y, x) = static_cast<unsigned char>(level(rng) / 8 * 8);
  }
  cv::GaussianBlur(g, g, cv::Size(0, 0), 1.0);
  cv::rectangle(g, cv::Rect(cx - 4, 56, 9, 9), cv::Scalar(250), cv::FILLED);
  g += cv::Scalar(offset);
  Frame f;
  f.index = index;
  f.bgr = g;
  return f;
}

cv::Mat square(const Frame& f, cv::Point2d at) {
  cv::Mat p;
  cv::getRectSubPix(f.bgr, cv::Size(15, 15), cv::Point2f(at), p, CV_32F);
  return p;
}

TEST(SceneMemory, TellsStillTextureFromTheObjectThatCameThere) {
  SceneMemory m;
  // The object moves right 10 px per frame from x = 30.
  for (int k = 0; k < 6; ++k) m.remember(textured(k, 30 + 10 * k), cv::Point2d(30 + 10 * k, 60));
  const Frame now = textured(6, 90);
  // Texture at (120, 60), where the object never was: as every kept frame showed it.
  const std::optional<double> still = m.least_difference(square(now, {120, 60}), {120, 60}, 15);
  ASSERT_TRUE(still.has_value());
  EXPECT_LT(*still, 0.5);
  // The object at (90, 60): frames 0-4 had it 20 px or more away and showed texture there.
  const std::optional<double> object = m.least_difference(square(now, {90, 60}), {90, 60}, 15);
  ASSERT_TRUE(object.has_value());
  EXPECT_GT(*object, 20);
  // Near the start, no kept frame had the object farther than 60 px: nothing to compare with.
  EXPECT_FALSE(m.least_difference(square(now, {35, 60}), {35, 60}, 60).has_value());
}

TEST(SceneMemory, IgnoresAnExposureDriftAndFramesWhereTheObjectWasLost) {
  SceneMemory m;
  m.remember(textured(0, 30), std::nullopt);  // lost: says nothing of where the object was
  EXPECT_FALSE(m.least_difference(square(textured(1, 30), {120, 60}), {120, 60}, 15).has_value());
  m.remember(textured(1, 30), cv::Point2d(30, 60));
  const Frame brighter = textured(2, 30, 20);
  const std::optional<double> d = m.least_difference(square(brighter, {120, 60}), {120, 60}, 15);
  ASSERT_TRUE(d.has_value());
  EXPECT_LT(*d, 0.5);
}

TEST(SceneMemory, KeepsAtMostItsSamplesSpreadOverTheClip) {
  SceneMemory m;
  for (int k = 0; k < 100; ++k) {
    m.remember(textured(k, 30), cv::Point2d(30, 60));
    EXPECT_LE(m.size(), SceneMemory::kMaxSamples);
    // Every frame kept until 16 are, then one of every 2, 4, 8 (100 frames: three thinnings).
    if (k >= 16) {
      EXPECT_GE(m.size(), SceneMemory::kMaxSamples / 2);
    }
  }
  EXPECT_EQ(m.gray(0).type(), CV_8U);
  EXPECT_EQ(m.gray(0).size(), cv::Size(160, 120));
  m.reset(4);
  EXPECT_EQ(m.size(), 0U);
  for (int k = 0; k < 8; ++k) m.remember(textured(k, 30), std::nullopt);
  EXPECT_EQ(m.size(), 2U);  // one of each block of 4
}

TEST(SceneMemory, KeepsFramesAtLeastAThirtiethOfASecondApart) {
  EXPECT_EQ(SceneMemory::stride_for(1 / 240.0), 8);
  EXPECT_EQ(SceneMemory::stride_for(1 / 60.0), 2);
  EXPECT_EQ(SceneMemory::stride_for(1 / 30.0), 1);
  EXPECT_EQ(SceneMemory::stride_for(1 / 15.0), 1);
  EXPECT_EQ(SceneMemory::stride_for(0), 1);  // the time base unknown: every frame at first
}

}  // namespace
}  // namespace tribolab::video
