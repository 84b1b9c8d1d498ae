// `tribolab track kinematics` (docs/cli.md#track): velocities and accelerations of one track,
// Tracker's stencils or Savitzky-Golay with standard errors, never across impacts
// (docs/theory.md#kinematics).
#pragma once

#include "app/common/option_fields.hpp"
#include "app/track/track_import.hpp"
#include "app/track/track_time_range.hpp"
#include "track/free_flight.hpp"
#include "track/kinematics.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace tribolab::app {

struct TrackKinematicsOptions {
  TrackInputOptions input;
  std::string track;             ///< track to differentiate; empty: the file's only track
  std::string method = "tracker";  ///< tracker (Tracker's finite differences) or savgol
  int window = 7;                ///< savgol: points per local fit
  int order = 2;                 ///< savgol: polynomial degree 1..6
  std::string impacts = "auto";  ///< auto: never difference across detected impacts; none: straight through
  /// Gravity a free-flight segment is held against, m/s^2 (docs/theory.md#free-flight-check)
  double g = kDefaultG;
  /// First time used, s (--from: fit only part of a record, e.g. the free fall before a landing)
  double t_from = -kNoTimeLimit;
  /// Last time used, s (--to)
  double t_to = kNoTimeLimit;
  std::string out;               ///< CSV t,x,y,vx,vy,ax,ay (+ sigmas for savgol); required
  std::string report;            ///< HTML report; empty: not written
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `track kinematics` (app/common/option_fields.hpp): the studio's
/// form is made from it (src/studio/); the command line does not bind from it yet (its
/// --from/--to spellings need aliases the declarations do not have).
inline const Fields<TrackKinematicsOptions>& track_kinematics_fields() {
  using O = TrackKinematicsOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.group(&O::input, track_input_fields());
    d.add("track", &O::track, "", "track to differentiate (required when the file has several)");
    d.add("method", &O::method, "", "Tracker's finite differences, or Savitzky-Golay with standard errors")
        .one_of({"tracker", "savgol"});
    d.add("window", &O::window, "", "savgol: points per local fit");
    d.add("order", &O::order, "", "savgol: polynomial degree 1..6");
    d.add("impacts", &O::impacts, "", "auto: never difference across detected impacts; none: straight through")
        .one_of({"auto", "none"});
    d.add("g", &O::g, "m/s^2", "gravitational acceleration free-flight segments are checked against").in(ranges::gravity);
    d.add("t_from", &O::t_from, "s", "first time used (when not given: the first point): e.g. only the free fall before a landing")
        .also_spelled("--from");
    d.add("t_to", &O::t_to, "s", "last time used (when not given: the last point)").also_spelled("--to");
    d.add("out", &O::out, "", "output CSV: t,x,y,vx,vy,ax,ay (+ sigma columns for savgol)").as(FieldRole::output_path).needed();
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

struct TrackKinematicsResult {
  nlohmann::json json;           ///< what `track kinematics --json` prints
  /// Per point: frame, t (s), x, y (m), vx, vy (m/s), ax, ay (m/s^2) and their standard errors
  /// (savgol; NaN for tracker and where a derivative is undefined), the impacts.
  track::Kinematics kinematics;
  /// Constant-acceleration fit of every flight segment and its comparison with g.
  std::vector<track::SegmentAcceleration> segment_fits;
  std::vector<std::string> warnings;  ///< the JSON's "warnings": importer's, then the g check's
};

/// Validates (InputError naming --method, --window/--order, --impacts, --g, --from/--to, --out
/// or the file), keeps the points from t_from to t_to, differentiates, checks the free-flight segments against g, writes the CSV (and the
/// report when asked) and summarises.
TrackKinematicsResult track_kinematics(const TrackKinematicsOptions& options);

}  // namespace tribolab::app
