#include "video/frame.hpp"
#include "video/ellipse_tracker.hpp"
#include "video/render.hpp"
#include "video/source.hpp"
#include "video/track_video.hpp"

#include <gtest/gtest.h>

namespace tribolab::video {
namespace {

TEST(Frame, GrayIsTheLuminanceOfTheColourImage) {
  Frame f;
  f.bgr = cv::Mat(2, 3, CV_8UC3, cv::Scalar(255, 0, 0));  // pure blue
  make_gray(f);
  ASSERT_EQ(f.gray.type(), CV_8UC1);
  // ITU-R BT.601 luma weight of blue, as OpenCV's COLOR_BGR2GRAY: 0.114 * 255 = 29.07.
  EXPECT_EQ(f.gray.at<unsigned char>(1, 2), 29);
}

}  // namespace
}  // namespace tribolab::video
