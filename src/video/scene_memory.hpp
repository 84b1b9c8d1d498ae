// Frames a tracker has seen, kept spread over the clip, and where it had the object in each
// (docs/theory.md#point-tracking, "still texture"). The path tracker's background is their
// per-pixel median. For the frame tracker, a match that shows exactly what its place showed in
// a kept frame, when the object was elsewhere, is the still background (texture on a wall, a
// rail's bolt), not the object: the object changes the place it comes to, still texture does not.
#pragma once

#include "video/frame.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace tribolab::video {

class SceneMemory {
 public:
  /// At most this many frames are kept (grey, whole): when full, every other one is dropped and
  /// the stride between kept frames doubles, so they stay spread over the clip.
  static constexpr std::size_t kMaxSamples = 16;

  /// The first stride for frames `step_s` s of real time apart (0: unknown, 1): at least 1/30 s
  /// between kept frames. Frames closer hold a moving object at nearly the same place, so they
  /// add conversions of whole frames, not information (at 240 fps the first 16 frames kept one by
  /// one were the clip's first 1/15 s).
  static int stride_for(double step_s);
  /// Forgets every frame (a new track); one frame per block of `stride` frames is kept at first.
  void reset(int stride = 1);
  /// Frame `f` was followed with the object at `object` (none: lost there, or not known). One
  /// frame per block of the stride is kept, at a scrambled place in the block: a regular stride
  /// aliases with a periodic motion (a pendulum of period 15 frames sampled every 15 frames puts
  /// the bob into every kept frame at one place). Only a kept frame's grey image is made whole.
  void remember(const Frame& f, std::optional<cv::Point2d> object);
  /// The least difference, grey levels, between `patch` (CV_32F or CV_8U, odd side, one channel)
  /// centred at `at` and the same square of every kept frame in which the object was farther
  /// than `away` px from `at`: the mean absolute difference after each square's mean is taken
  /// away (a camera's exposure drifting leaves it 0). Empty when no kept frame had the object
  /// that far away.
  std::optional<double> least_difference(const cv::Mat& patch, cv::Point2d at, double away) const;
  /// The frames kept, oldest first, and each one's grey image (CV_8U, whole).
  std::size_t size() const { return kept_.size(); }
  const cv::Mat& gray(std::size_t i) const { return kept_[i].gray; }

 private:
  struct Kept {
    cv::Mat gray;                       // CV_8U, the whole frame
    std::optional<cv::Point2d> object;  // where the tracker had the object
  };
  std::vector<Kept> kept_;
  int stride_ = 1, seen_ = 0;
};

}  // namespace tribolab::video
