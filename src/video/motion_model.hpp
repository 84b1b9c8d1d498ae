// Where a tracked point should be in the next frame (docs/theory.md#point-tracking). The
// pattern angle follows a constant rate of turn fitted to the last few angles. The position
// follows the better (least squares) of two models over the last few positions: a parabola in
// the frame index (a thrown object's flight is predicted exactly), and, once the pattern has
// turned by 15 degrees or more over them, a point on a turning body whose centre moves
// uniformly (p = c0 + c1 t + R(theta) r, with the measured angles: a mark on a wheel, which a
// parabola predicts poorly when it turns 20+ degrees per frame). Only accepted observations
// enter the model; lost frames are bridged by extrapolation from the last accepted ones.
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
  /// Positions kept for the position fits (>= 3 fits a parabola, >= 4 the turning body) and
  /// angles for the rate of turn.
  explicit MotionModel(int position_history = 5, int angle_history = 3);
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
