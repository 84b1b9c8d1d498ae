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

}  // namespace tribolab::video
