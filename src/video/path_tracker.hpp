// Offline point tracking for real film (docs/theory.md#tracking-on-real-film): the whole clip
// is used before any position is reported. The object is what the user clicked: its size
// comes from scale selection at the click (not a fixed square), its template from the first
// frame. Every frame gives a few candidates (normalised-correlation peaks near where the
// object could be), each scored by its likeness to the template and by how much it differs
// from the background (the per-pixel temporal median of frames sampled over the clip: a
// tripod camera's rail, wall and table). The track is the best path through the candidates
// under a smooth-motion prior (dynamic programming over pairs of candidates, i.e. a bounded
// acceleration), and a frame is reported only when the forward and backward passes agree:
// no path through another candidate farther away is nearly as good (min-marginals). A doubtful
// frame is reported lost with a low score, never a confident wrong point.
#pragma once

#include "video/frame.hpp"
#include "video/point_tracker.hpp"

#include <memory>
#include <string>
#include <vector>

namespace tribolab::video {

struct PathTrackerOptions {
  int patch_px = 0;           ///< template side, px (odd, >= 7; 0: from the object's size)
  int search_px = 0;          ///< largest motion between two tracked frames, px (0: automatic)
  double min_score = 0.6;     ///< a path point whose correlation is below this is lost
  int max_gap_frames = 8;     ///< frames the path may skip (an object hidden by a hand)
  /// Real time between two tracked frames, s (0: unknown). The automatic reach is a speed: a
  /// quarter of the image's smaller side per 1/30 s, per frame at 30 fps or fewer.
  double step_s = 0;
  std::string validate() const;
};

class PathTracker {
 public:
  explicit PathTracker(const PathTrackerOptions& options = {});
  ~PathTracker();
  PathTracker(PathTracker&&) noexcept;
  PathTracker& operator=(PathTracker&&) noexcept;
  /// Takes the object around (x_px, y_px) in `first`. Throws InputError when the point is
  /// outside the image (`name` in the message); a plain, low-texture object is not refused.
  Observation start(const Frame& first, double x_px, double y_px, const std::string& name);
  /// The user's marks (any order; frames after the start's), replacing any given before; at
  /// any time after start(). In finish(), a marked frame's only candidate is its mark and the
  /// best path passes through every mark (reported manual, score 1), so the path re-tracks
  /// from a mark backward as well as forward. The candidates collected by update() do not
  /// depend on the marks: finish() may be called again after new marks (a correction), which
  /// re-tracks without any frame among the candidates already found (a new mark's look, add_look(),
  /// needs the frames). Looks of marks removed or moved are dropped. Throws InputError for a mark outside the image or not after the start frame, or two
  /// on one frame.
  void set_marks(std::vector<ManualMark> marks);
  /// Shows the tracker the object as it looks at the mark of frame `frame` (set by set_marks()):
  /// `gray` is that frame's grey image or the part of it given by look_crop(), the mark at
  /// (x_px, y_px) in it. The frames from the nearest marks before to those after it are searched
  /// for this look as well as the start's, so a correction helps the frames around it, not only its
  /// own; to help frames before the mark it must be given before they are (track_video reads the
  /// marked frames first). A flat look (nothing to match) is not used; a mark of another frame, or
  /// after update() reached it, is an InputError.
  void add_look(int frame, const cv::Mat& gray, double x_px, double y_px);
  /// The part of an image of `image` size around a mark that holds every look add_look() may take
  /// (and the square it turns that look in).
  static cv::Rect look_crop(cv::Size image, double x_px, double y_px);
  /// Collects the candidates of the next frame (nothing is decided yet).
  void update(const Frame& frame);
  /// The track: one observation per frame given to update(), in order. May be called again
  /// (after set_marks()): the same candidates, the path chosen anew.
  std::vector<Observation> finish();
  /// The template side chosen at start(), px.
  int patch_px() const;
  /// Why frames were lost (for the message), "" when none was: the likely cause and the option
  /// that helps.
  std::string loss_hint() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribolab::video
