// Where a tracked point should be in the next frame (docs/theory.md#point-tracking): a
// polynomial in the frame index fitted by least squares to the last few positions
// (constant acceleration from three positions on: a thrown object's parabola is predicted
// exactly) and a constant rate of turn fitted to the last few pattern angles (a mark on a
// wheel). Only accepted observations enter the model; lost frames are bridged by
// extrapolation from the last accepted ones.
#pragma once

#include <deque>

namespace tribolab::video {

struct MotionState {
  double x_px = 0, y_px = 0;  ///< position, px
  double angle_rad = 0;       ///< pattern rotation, rad (counter-clockwise on screen)
  double vx_px = 0, vy_px = 0;  ///< velocity, px per frame
  double turn_rad = 0;        ///< rotation rate, rad per frame
};

class MotionModel {
 public:
  /// Positions kept for the position fit (>= 3 fits a parabola) and angles for the rate.
  explicit MotionModel(int position_history = 4, int angle_history = 3);
  void reset();
  /// Records the accepted observation of `frame` (frames must increase).
  void add(int frame, double x_px, double y_px, double angle_rad);
  /// Extrapolation to `frame` (> the last added frame); requires at least one observation.
  MotionState predict(int frame) const;
  /// Number of observations held (at most the history length).
  int size() const { return static_cast<int>(history_.size()); }
  int last_frame() const;

 private:
  struct Sample {
    int frame;
    double x, y, angle;
  };
  int position_history_;
  int angle_history_;
  std::deque<Sample> history_;
};

}  // namespace tribolab::video
