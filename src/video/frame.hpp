// One decoded video frame as every part of src/video sees it: the colour image, its grey
// version (made only where a tracker reads it) and where it sits in the clip's time base.
// Image coordinates: x right, y down, pixels, origin at the top-left corner of the top-left
// pixel's centre (OpenCV's convention: pixel (i, j) is centred at x = j, y = i).
#pragma once

#include <opencv2/core.hpp>

namespace tribolab::video {

struct Frame {
  int index = 0;  ///< the video's frame index, from 0 (Tracker's frame number)
  double t = 0;   ///< time in the clip's time base, s (after any time scale)
  cv::Mat bgr;    ///< CV_8UC3, as decoded (CV_8UC1 for a grey image)
  /// CV_8UC1, cv::cvtColor(bgr, COLOR_BGR2GRAY) of the whole frame when made (make_gray), else
  /// empty: a tracker converts only the rectangles it reads (gray_region). FrameReader leaves it
  /// empty, since a tracker at 1080p reads windows around its object, not the frame.
  cv::Mat gray;
};

/// Fills frame.gray from frame.bgr (or copies a grey bgr).
void make_gray(Frame& frame);

/// The frame's size, px (of bgr, or of gray when there is no bgr).
cv::Size frame_size(const Frame& frame);

/// The grey image of `roi` (a rectangle inside the frame): a view of frame.gray when it is made,
/// else of a grey bgr, else bgr(roi) converted into `buf` (reallocated only when too small) and
/// a view of it. The values are make_gray's, pixel for pixel; empty when the frame has no image.
cv::Mat gray_region(const Frame& frame, const cv::Rect& roi, cv::Mat& buf);

}  // namespace tribolab::video
