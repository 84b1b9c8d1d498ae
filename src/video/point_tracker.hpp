// Following a textured point from frame to frame, better than a template autotracker
// (docs/theory.md#video-tracking): a motion model predicts where to search (constant
// acceleration for a thrown object, a turning pattern for a mark on a wheel), the template
// is matched over a range of rotations around the predicted one and at a blurred scale as
// well as sharp, the correlation peak is refined to sub-pixel, and every point gets a score
// (normalised correlation, 1 = perfect). Below the score threshold the point is lost: the
// search widens along the motion model for a few frames (a hand passing) and the frames it
// could not bridge are reported, never silently replaced by another object; a match that shows
// what its place showed when the object was elsewhere (still texture) is lost too.
#pragma once

#include "video/frame.hpp"

#include <memory>
#include <string>

namespace tribolab::video {

struct PointTrackerOptions {
  int patch_px = 21;          ///< template side, px (odd, >= 7)
  int search_px = 0;          ///< search half-width around the prediction, px (0 = automatic)
  double min_score = 0.6;     ///< below this normalised correlation a point is lost
  double max_turn_deg = 40;   ///< largest pattern rotation searched per frame, degrees
  int max_gap_frames = 8;     ///< lost frames the motion model may bridge; beyond, the point is
                              ///< searched for afresh (wider, unambiguous matches only)
  /// Real time between two tracked frames, s (0: unknown): the earlier frames kept for the
  /// still-texture check are at least 1/30 s apart (SceneMemory::stride_for).
  double step_s = 0;
  std::string validate() const;
};

/// The tracker's answer for one frame.
struct Observation {
  int frame = 0;
  double x_px = 0, y_px = 0;  ///< position, px (image x right, y down)
  double score = 0;           ///< match quality in [0, 1]
  bool lost = false;          ///< true: no reliable position this frame (x_px, y_px = prediction)
  bool refound = false;       ///< true: found again after more than max_gap_frames lost in a row
  double angle_rad = 0;       ///< pattern rotation since the first frame (point) or major-axis
                              ///< direction (ellipse), image frame, counter-clockwise on screen, unwrapped
  double major_px = 0;        ///< ellipse semi-major axis, px (0 for a point)
  double minor_px = 0;        ///< ellipse semi-minor axis, px (0 for a point)
  bool manual = false;        ///< true: a manual mark (the user's position, score 1), not tracked
};

/// A position the user gave for one frame of a track (docs/theory.md#manual-marks): the
/// tracker reports it as it is (manual, score 1) and tracks on from it.
struct ManualMark {
  int frame = 0;              ///< video frame index
  double x_px = 0, y_px = 0;  ///< image px (x right, y down)
};

class PointTracker {
 public:
  explicit PointTracker(const PointTrackerOptions& options = {});
  ~PointTracker();
  PointTracker(PointTracker&&) noexcept;
  PointTracker& operator=(PointTracker&&) noexcept;
  /// Takes the template around (x_px, y_px) in `first`. Throws InputError when the point is
  /// outside the image or the patch has too little texture to follow (`name` in the message).
  /// Returns the observation for `first` (the start point refined to sub-pixel, score 1).
  Observation start(const Frame& first, double x_px, double y_px, const std::string& name);
  /// Finds the point in the next frame.
  Observation update(const Frame& frame);
  /// The user's mark for this frame (instead of update()): reported manual with score 1; the
  /// template is kept; the motion model goes on through the mark when it lies where the model
  /// predicts the point (within its gate), else restarts from it (as after a start).
  Observation mark(const Frame& frame, double x_px, double y_px);
  /// Why frames were lost since start() (for the message), "" when none was: the likely cause
  /// and the option that helps.
  std::string loss_hint() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribolab::video
