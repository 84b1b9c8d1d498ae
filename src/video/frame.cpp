#include "video/frame.hpp"

#include <opencv2/imgproc.hpp>

namespace tribolab::video {

void make_gray(Frame& frame) {
  if (frame.bgr.channels() == 1) {
    frame.gray = frame.bgr.clone();
  } else {
    cv::cvtColor(frame.bgr, frame.gray, cv::COLOR_BGR2GRAY);
  }
}

cv::Size frame_size(const Frame& frame) { return frame.bgr.empty() ? frame.gray.size() : frame.bgr.size(); }

cv::Mat gray_region(const Frame& frame, const cv::Rect& roi, cv::Mat& buf) {
  if (!frame.gray.empty()) return frame.gray(roi);
  if (frame.bgr.empty()) return cv::Mat();
  if (frame.bgr.channels() == 1) return frame.bgr(roi);
  // cvtColor writes into buf's own size: a view of a larger buffer would be reallocated.
  if (buf.type() != CV_8UC1 || buf.cols < roi.width || buf.rows < roi.height) {
    buf.create(std::max(roi.height, buf.rows), std::max(roi.width, buf.cols), CV_8UC1);
  }
  cv::Mat out = buf(cv::Rect(0, 0, roi.width, roi.height));
  cv::cvtColor(frame.bgr(roi), out, cv::COLOR_BGR2GRAY);
  return out;
}

}  // namespace tribolab::video
