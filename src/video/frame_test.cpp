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

TEST(Frame, GrayRegionIsTheSameAsTheWholeGrayImageThere) {
  // A frame without its grey image converts the rectangle asked for: the values must be
  // make_gray's exactly (trackers find the same peaks either way), also for rectangles of
  // odd sizes (SIMD tails) and when the buffer is reused for a smaller one.
  cv::Mat bgr(37, 53, CV_8UC3);
  cv::randu(bgr, cv::Scalar::all(0), cv::Scalar::all(256));
  Frame whole;
  whole.bgr = bgr;
  make_gray(whole);
  Frame lazy;
  lazy.bgr = bgr;
  cv::Mat buf;
  for (const cv::Rect r :
       {cv::Rect(0, 0, 53, 37), cv::Rect(3, 5, 31, 17), cv::Rect(50, 1, 3, 36), cv::Rect(7, 9, 1, 1)}) {
    const cv::Mat g = gray_region(lazy, r, buf);
    ASSERT_EQ(g.size(), r.size());
    EXPECT_EQ(cv::norm(g, whole.gray(r), cv::NORM_INF), 0) << r;
    EXPECT_EQ(cv::norm(gray_region(whole, r, buf), whole.gray(r), cv::NORM_INF), 0) << r;
  }
  EXPECT_TRUE(lazy.gray.empty());  // nothing kept in the frame
  EXPECT_EQ(frame_size(lazy), cv::Size(53, 37));
  EXPECT_TRUE(gray_region(Frame{}, cv::Rect(), buf).empty());
}

}  // namespace
}  // namespace tribolab::video
