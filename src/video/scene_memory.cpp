#include "video/scene_memory.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace tribolab::video {

int SceneMemory::stride_for(double step_s) {
  constexpr double kMinGapS = 1.0 / 30;
  return step_s > 0 ? std::max(1, static_cast<int>(kMinGapS / step_s + 1e-9)) : 1;
}

void SceneMemory::reset(int stride) {
  kept_.clear();
  stride_ = std::max(1, stride);
  seen_ = 0;
}

void SceneMemory::remember(const Frame& f, std::optional<cv::Point2d> object) {
  const unsigned block = static_cast<unsigned>(seen_ / stride_);
  const int place = static_cast<int>(((block * 2654435761u) >> 8) % static_cast<unsigned>(stride_));
  if (seen_++ % stride_ != place) return;
  cv::Mat own;
  const cv::Mat g = gray_region(f, cv::Rect(cv::Point(), frame_size(f)), own);
  if (g.empty()) return;
  kept_.push_back({g.data == own.data ? own : g.clone(), object});
  if (kept_.size() >= kMaxSamples) {
    std::vector<Kept> thinned;
    for (std::size_t i = 0; i < kept_.size(); i += 2) thinned.push_back(std::move(kept_[i]));
    kept_ = std::move(thinned);
    stride_ *= 2;
  }
}

std::optional<double> SceneMemory::least_difference(const cv::Mat& patch, cv::Point2d at, double away) const {
  std::optional<double> least;
  cv::Mat now, then;
  patch.convertTo(now, CV_32F);
  now -= cv::mean(now)[0];
  for (const Kept& k : kept_) {
    if (!k.object || std::hypot(k.object->x - at.x, k.object->y - at.y) <= away) continue;
    cv::getRectSubPix(k.gray, patch.size(), cv::Point2f(at), then, CV_32F);
    then -= cv::mean(then)[0];
    const double d = cv::norm(now, then, cv::NORM_L1) / static_cast<double>(patch.total());
    least = least ? std::min(*least, d) : d;
  }
  return least;
}

}  // namespace tribolab::video
