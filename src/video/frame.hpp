// One decoded video frame as every part of src/video sees it: the colour image, its grey
// version (computed once per frame) and where it sits in the clip's time base.
// Image coordinates: x right, y down, pixels, origin at the top-left corner of the top-left
// pixel's centre (OpenCV's convention: pixel (i, j) is centred at x = j, y = i).
#pragma once

#include <opencv2/core.hpp>

namespace tribolab::video {

struct Frame {
  int index = 0;  ///< the video's frame index, from 0 (Tracker's frame number)
  double t = 0;   ///< time in the clip's time base, s (after any time scale)
  cv::Mat bgr;    ///< CV_8UC3, as decoded
  cv::Mat gray;   ///< CV_8UC1, cv::cvtColor(bgr, COLOR_BGR2GRAY)
};

/// Fills frame.gray from frame.bgr (or copies a grey bgr).
void make_gray(Frame& frame);

}  // namespace tribolab::video
