// An ellipse track's frames put at their time (docs/theory.md#ellipse-tracking, item 4): the
// blurred outline a frame shows is not the ellipse at the frame's time, where it slides along
// itself (the tips of a falling ball). A pass over the whole track corrects each elongated
// frame from its edge points, with the motion taken from its neighbours on both sides within
// its flight and the exposure read from the edge ramps. It runs as the frames come, a few
// frames behind them, so it holds the edge points of a few frames only.
#pragma once

#include "video/ellipse_fit.hpp"

#include <deque>
#include <vector>

namespace tribolab::video {

/// One accepted frame of an ellipse track, as the pass takes it.
struct FittedFrame {
  int index = 0;                 ///< frame index (one per frame period of the video)
  int piece = 0;                 ///< the motion model's piece: a restart (a bounce) begins the next
  Ellipse found;                 ///< the fit to the blurred outline
  double a0 = 0, b0 = 0;         ///< the semi-axes its shape was tied to, px
  double phi = 0;                ///< orientation of end A (screen, counter-clockwise, unwrapped), rad
  double score = 0, rms = 0;     ///< the fit's score and rms distance, px
  bool round = false;            ///< no orientation: never refitted
  std::vector<EdgePoint> edges;  ///< the fit's edge points (empty: not refitted)
};

/// A frame refitted at its time.
struct RetimedFrame {
  FittedFrame frame;  ///< as it was fitted (its edge points dropped)
  Ellipse at;         ///< the ellipse at the frame's time
  double phi = 0;     ///< its orientation, continuing the frame's
};

class FrameTimePass {
 public:
  /// The next accepted frame: indices increasing, pieces not decreasing.
  void add(FittedFrame frame);

  struct Result {
    double exposure = 0;                ///< read from the edge ramps, frame periods (0: not read)
    std::vector<RetimedFrame> frames;   ///< the frames that moved by 0.01 px or more
  };
  /// The frames refitted so far and those still held, finished as if the track ended here (on
  /// a copy: add() may go on). Empty frames when the exposure cannot be read (fewer than 10
  /// head-on ramps: a slow object, whose blur biases nothing measurable).
  Result result() const;
  /// Frames held now: the neighbours the next frame's motion needs, and frames waiting for the
  /// exposure to be read (at most 240), not the whole track.
  std::size_t held_frames() const { return held_.size(); }

 private:
  struct Held {
    FittedFrame f;
    bool read = false;  ///< its motion is known and its ramps are read
    FrameMotion motion;
  };
  /// Reads the motion and ramps of the frames whose neighbours are known (all of them when the
  /// track has ended), refits those it can, and drops what no later frame needs.
  void advance(bool track_ended);
  bool motion_of(std::size_t i, bool track_ended);
  std::deque<Held> held_;
  std::vector<double> readings_;
  std::vector<RetimedFrame> done_;
};

}  // namespace tribolab::video
