// `tribolab track rigid-body` (docs/cli.md#track-rigid-body): the planar motion of a body from
// two tracked points on it (a spinning diabolo's two ends, a falling toast's corners, two marks
// on a wheel): centre, orientation and spin with standard errors against time, and a check that
// the distance between the points stays constant (docs/theory.md#track-rigid-body). The same
// two-point body (src/track/rigid_body.hpp) is what `bounce analyze` builds from the tips.
#pragma once

#include "app/track/track_import.hpp"
#include "track/rigid_body.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace tribolab::app {

struct TrackRigidBodyOptions {
  TrackInputOptions input;
  std::string track_a;           ///< track of point A; required
  std::string track_b;           ///< track of point B on the same body; required
  int window = track::RigidBodyOptions{}.window;  ///< points per local linear fit of theta(t), >= 3
  /// Warning threshold, fraction of the mean A-B distance, for its drift over the record and
  /// its frame-to-frame scatter (a rigid body keeps the distance)
  double max_drift = 0.03;
  std::string out;               ///< CSV frame,t,x,y,theta,omega,sigma_omega,length; empty: not written
  std::string report;            ///< HTML report; empty: not written
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `track rigid-body` (app/common/option_fields.hpp): the
/// command line and Python bind from it.
inline const Fields<TrackRigidBodyOptions>& track_rigid_body_fields() {
  using O = TrackRigidBodyOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::input, track_input_fields());
    d.add("track_a", &O::track_a, "", "track of point A on the body").needed();
    d.add("track_b", &O::track_b, "", "track of point B on the same body").needed();
    d.add("window", &O::window, "", "points per local linear fit of the orientation (the spin at each frame), >= 3");
    d.add("max_drift", &O::max_drift, "",
          "warn when the A-B distance drifts or scatters by more than this fraction of its mean, in (0, 1] (a rigid "
          "body keeps it; more means a wrong calibration or a mislabelled track)");
    d.add("out", &O::out, "", "output CSV: frame,t,x,y,theta,omega,sigma_omega,length (s, m, rad, rad/s)")
        .as(FieldRole::output_path);
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

/// The A-B distance over the record: a straight-line fit length = l0 + l1 t.
struct LengthCheck {
  double mean = 0;               ///< m
  double sd = 0;                 ///< frame-to-frame standard deviation, m
  double min = 0, max = 0;       ///< m
  double drift = 0;              ///< l1 (t_last - t_first): change over the record, m
  double sigma_drift = 0;        ///< its standard error, m
};

struct TrackRigidBodyResult {
  nlohmann::json json;           ///< what `track rigid-body --json` prints
  /// Per frame with both points: frame, t (s), centre xc, yc (m), theta (rad, unwrapped),
  /// length (m), omega and sigma_omega (rad/s); the global spin fit.
  track::RigidBody body;
  LengthCheck length;
};

/// The least number of frames with both points: a spin with a standard error needs 3.
inline constexpr int kRigidBodyMinFrames = 3;

/// Validates (InputError naming --track-a, --track-b, --window, --max-drift or the file),
/// builds the body, checks its length, writes the CSV and the report when asked.
TrackRigidBodyResult track_rigid_body(const TrackRigidBodyOptions& options);

/// The length check of a body with at least 3 rows (least squares, docs/theory.md#track-rigid-body).
LengthCheck check_length(const track::RigidBody& body);

}  // namespace tribolab::app
