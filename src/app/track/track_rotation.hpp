// `tribolab track rotation` (docs/cli.md#track-rotation): the spin of ONE tracked point about a
// fixed (given or fitted) or uniformly moving pivot, with standard errors: a mark on a wheel, a
// pendulum bob, a point on a diabolo (docs/theory.md#rotation-about-a-pivot). Two points of one
// body are `track rigid-body`.
#pragma once

#include "app/track/track_import.hpp"
#include "app/track/track_time_range.hpp"
#include "track/pivot.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace tribolab::app {

struct TrackRotationOptions {
  TrackInputOptions input;
  std::string track;            ///< the turning point's track; empty: the file's only track
  /// Pivot x, m (with pivot_y; not given: fitted to the track), e.g. 0.41
  double pivot_x = track::kNotGiven;
  /// Pivot y, m (with pivot_x; not given: fitted to the track), e.g. 0.52
  double pivot_y = track::kNotGiven;
  bool moving_pivot = false;    ///< fit a pivot moving uniformly (a rolling wheel's axle)
  int window = track::PivotOptions{}.window;  ///< points per local linear fit of theta(t) (the spin at each frame), >= 3
  /// First time used, s (--from: only the part of the record that turns about the pivot)
  double t_from = -kNoTimeLimit;
  /// Last time used, s (--to)
  double t_to = kNoTimeLimit;
  std::string out;              ///< CSV frame,t,x,y,theta,radius,omega,sigma_omega; empty: not written
};

/// The declaration of every option of `track rotation` (app/common/option_fields.hpp): the
/// command line and Python bind from it.
inline const Fields<TrackRotationOptions>& track_rotation_fields() {
  using O = TrackRotationOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::input, track_input_fields());
    d.add("track", &O::track, "", "track of the turning point (required when the file has several)");
    d.add("pivot_x", &O::pivot_x, "m", "pivot x, with pivot_y (when not given: fitted to the track)");
    d.add("pivot_y", &O::pivot_y, "m", "pivot y, with pivot_x");
    d.add("moving_pivot", &O::moving_pivot, "", "fit a pivot moving uniformly (a rolling wheel's axle)");
    d.add("window", &O::window, "", "points per local linear fit of the angle (the spin at each frame), >= 3");
    d.add("t_from", &O::t_from, "s",
          "first time used (when not given: the first point): only the part of the record that turns about the pivot")
        .also_spelled("--from");
    d.add("t_to", &O::t_to, "s", "last time used (when not given: the last point)").also_spelled("--to");
    d.add("out", &O::out, "", "output CSV: frame,t,x,y,theta,radius,omega,sigma_omega (s, m, rad, rad/s)")
        .as(FieldRole::output_path);
    return d;
  }();
  return f;
}

struct TrackRotationResult {
  nlohmann::json json;          ///< what `track rotation --json` prints
  /// Per point: frame, t (s), x, y (m), theta about the pivot (rad, unwrapped), radius (m),
  /// local omega and sigma_omega (rad/s); the joint fit's pivot, radius, omega, alpha, sigmas.
  track::PivotRotation rotation;
};

/// Validates (InputError naming --track, --pivot-x/--pivot-y, --moving-pivot, --window, --from/--to
/// or the file), fits the rotation, says what the data cannot carry (an aliased spin, a point off its
/// circle, a spin that is not uniformly accelerated), writes the CSV when asked.
TrackRotationResult track_rotation(const TrackRotationOptions& options);

}  // namespace tribolab::app
