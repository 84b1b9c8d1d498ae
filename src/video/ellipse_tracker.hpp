// Following a ball or disc that contrasts with its background as an ellipse
// (docs/theory.md#ellipse-tracking): the object is found near its predicted position by its
// colour, edge points are located to sub-pixel along the normals of the expected outline (the
// mean edge over the exposure), an ellipse is fitted to them robustly, and the two ends of the
// major axis are labelled A and B continuously in time (the end nearest the direction
// predicted from the spin of the past frames), so `bounce analyze --track-a NAME.A --track-b
// NAME.B` reads them directly.
#pragma once

#include "video/frame.hpp"
#include "video/point_tracker.hpp"

#include <memory>
#include <string>
#include <vector>

namespace tribolab::video {

struct EllipseTrackerOptions {
  double min_score = 0.55;     ///< below this edge-fit quality (fraction of the normals in
                               ///< view giving a kept edge point, times shape agreement, in
                               ///< [0, 1]) the object is lost
  int max_gap_frames = 8;      ///< frames the motion model may bridge before giving up
  std::string validate() const;
};

/// One frame of an ellipse: centre and both ends of the major axis.
struct EllipseObservation {
  Observation centre;          ///< centre, orientation (angle_rad: direction centre->A), axes
  double ax_px = 0, ay_px = 0; ///< end A of the major axis, px
  double bx_px = 0, by_px = 0; ///< end B, px
  /// The axes differ by less than 5 %: no measurable orientation, so angle_rad and the ends
  /// A, B follow the spin predicted from earlier frames (constant for an object always round).
  bool round = false;
  double rms_px = 0;           ///< rms distance of the edge points from the fitted ellipse, px
};

class EllipseTracker {
 public:
  explicit EllipseTracker(const EllipseTrackerOptions& options = {});
  ~EllipseTracker();
  EllipseTracker(EllipseTracker&&) noexcept;
  EllipseTracker& operator=(EllipseTracker&&) noexcept;
  /// Segments the object containing (x_px, y_px) in `first`. Throws InputError when the
  /// point is outside the image or no contrasting object surrounds it (`name` in the message).
  /// Returns the ellipse fitted in `first`.
  EllipseObservation start(const Frame& first, double x_px, double y_px, const std::string& name);
  EllipseObservation update(const Frame& frame);
  /// Why frames were lost, and the option that helps, for the warning listing them (empty
  /// when none was lost): a weak edge fit (blur, lossy video: field("ellipse_min_score")) or nothing
  /// found near the prediction (hidden: field("max_gap")); and whether the tracker gave up.
  std::string loss_hint() const;
  /// The user's mark of the centre for this frame (instead of update()): reported at the mark,
  /// manual, score 1, with the running axes and the predicted orientation; the motion model
  /// goes on through the mark when it lies where the model predicts the centre (as an accepted
  /// centre would), else restarts from it (a lost object is searched for there again).
  EllipseObservation mark(const Frame& frame, double x_px, double y_px);
  /// After the last frame: the accepted frames at their time (mid-exposure) rather than as
  /// their blurred outlines show them, for the frames that move by 0.01 px or more, and the
  /// exposure read (FrameTimePass, fed with every accepted frame as it comes: the motion at
  /// each frame from its neighbours on both sides within its flight, the exposure from the
  /// edge ramps of all frames, each elongated frame refitted from its edge points). No poses
  /// when the exposure cannot be read (a slow or round object, whose blur biases no velocity).
  /// update() reports what decided each frame; these replace it in the track
  /// (docs/theory.md#ellipse-tracking, item 4).
  struct AtFrameTime {
    double exposure = 0;                   ///< read from the edge ramps, frame periods (0: not read)
    std::vector<EllipseObservation> poses;  ///< the frames that changed
  };
  AtFrameTime at_frame_time() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribolab::video
