// `tribolab incline synth | normal-friction-test` as functions (seed 000, eq c; docs/cli.md#incline,
// docs/design.md "Application layer: incline"): option structs whose member initializers are the
// command line's defaults, results holding the command's JSON and the arrays a notebook wants.
#pragma once

#include "app/common/option_fields.hpp"
#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/incline_synthetic.hpp"
#include "numerics/units.hpp"
#include "track/track.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// Which track of a tracked file, and its time scale (`--track`, `--time-scale`).
struct InclineTrackInput {
  std::string track;        ///< track to analyse; empty = the only one with points
  double time_scale = 1;    ///< real seconds per file second (240 fps shown at 30 fps: 0.125)
  /// Unit of the file's lengths (m, cm, mm, km, um, in, ft), overriding the file's; empty: the
  /// file's, else m (as `track kinematics --length-unit`).
  std::string length_unit;
};

/// The declarations of --track --time-scale --length-unit (app/common/option_fields.hpp), the
/// shared input options of the incline commands that read tracked runs. In incline_analysis.cpp.
const Fields<InclineTrackInput>& incline_track_input_fields();

/// Reads the one track `in` selects from `file` (Tracker .trk/.trz, Export Data text, CSV);
/// InputError naming the file when it holds several and none is chosen.
track::Track read_incline_track(const std::string& file, const InclineTrackInput& in);

// ---- synth ----------------------------------------------------------------------------

struct InclineSynthOptions {
  std::optional<double> mu;       ///< kinetic friction coefficient, > 0 (required)
  std::optional<double> phi_deg;  ///< incline angle, degrees, in [0, 90) (required)
  /// Launch speed along +x, m/s, >= 0; 0 releases the disc from rest (a straight slide) (required).
  std::optional<double> v0;
  double g = kDefaultG;           ///< gravitational acceleration, m/s^2
  /// Model A: normal friction / mass, m/s^2, positive left of the velocity; 0 is model B.
  double normal_accel = 0;
  double fps = 80;                ///< frame rate, 1/s
  double noise = 0.001;           ///< standard deviation of the position noise, m
  std::uint64_t seed = 1;         ///< noise seed: the same seed gives the same run
  double t_offset = 0.1;          ///< launch instant in the file's time, s
  double x0 = 0.05;               ///< launch point x, m
  double y0 = 0;                  ///< launch point y, m
  /// Recording length, s; unset = until 0.3 s after the stop, or 1.5 s after the launch.
  std::optional<double> duration;
  std::string format = "export";  ///< export (Tracker Export Data text) or csv (track,frame,t,x,y)
  std::string track_name = "disc";  ///< name of the track
  /// Camera axes turned against the incline: points rotated CCW about the launch point, deg, within +-20.
  double frame_rotation_deg = 0;
  std::string out;                ///< file to write; empty = none
};

/// The declaration of every option of `incline synth` (app/common/option_fields.hpp).
inline const Fields<InclineSynthOptions>& incline_synth_fields() {
  using O = InclineSynthOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("mu", &O::mu, "", "kinetic friction coefficient (> 0)").in(ranges::friction).needed();
    d.add("phi_deg", &O::phi_deg, "deg", "incline angle, in [0, 90)").needed();
    d.add("v0", &O::v0, "m/s", "launch speed along +x (>= 0; 0 = released from rest: a straight slide down the slope)")
        .in(ranges::speed).needed();
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.add("normal_accel", &O::normal_accel, "m/s^2",
          "model A: normal friction / mass, positive left of the velocity (0 = model B; see incline analyze --help)")
        .in(ranges::accel);
    d.add("fps", &O::fps, "1/s", "frame rate").in(ranges::frame_rate);
    d.add("noise", &O::noise, "m", "standard deviation of the position noise").in(ranges::noise);
    d.add("seed", &O::seed, "", "noise seed, integer >= 0");
    d.add("t_offset", &O::t_offset, "s", "launch instant in the file's time").in(ranges::duration);
    d.add("x0", &O::x0, "m", "launch point x").in(ranges::position);
    d.add("y0", &O::y0, "m", "launch point y").in(ranges::position);
    d.add("duration", &O::duration, "s", "recording length (unset: until 0.3 s after the stop, or 1.5 s after the launch)")
        .in(ranges::duration);
    d.add("format", &O::format, "", "export (Tracker Export Data text, tab delimited) or csv (track,frame,t,x,y)")
        .one_of({"export", "csv"});
    d.add("track_name", &O::track_name, "", "name of the track");
    d.add("frame_rotation_deg", &O::frame_rotation_deg, "deg",
          "camera axes turned against the incline: points rotated CCW about the launch point (within +-20)");
    d.add("out", &O::out, "", "output file").as(FieldRole::output_path).needed();
    return d;
  }();
  return f;
}
/// The keys of `incline synth --json` (docs/cli.md#incline-synth). In incline_analysis.cpp.
const ResultKeys& incline_synth_result_keys();

struct InclineSynthResult {
  nlohmann::json json;                ///< exactly what `incline synth --json` prints
  analysis::InclineSynthRun run;      ///< the noisy track, the noise-free truth at each point, t_stop
};

InclineSynthResult incline_synth(const InclineSynthOptions& o);

// ---- normal-friction-test -------------------------------------------------------------

struct InclineNormalFrictionTestOptions {
  std::vector<std::string> files;  ///< tracked runs, one per angle (with phi_deg); or use table
  std::vector<double> phi_deg;     ///< incline angles, degrees, in (0, 90), one per file
  std::string table;               ///< CSV phi_deg,cos_theta_c[,sigma_cos_theta_c] instead of files
  double g = kDefaultG;            ///< gravitational acceleration, m/s^2
  InclineTrackInput input;         ///< --track, --time-scale
  std::string report;              ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

struct InclineNormalFrictionTestResult {
  nlohmann::json json;                   ///< exactly what `incline normal-friction-test --json` prints
  analysis::NormalFrictionTest test;     ///< the fit of eq c and its points
  /// Per point: tan(phi) and cos(theta_c), the line the fit draws through them.
  std::vector<double> tan_phi, cos_theta_c;
  /// The failed runs' located errors (files given; docs/cli.md#several-runs): their rows in
  /// json["runs"] hold "error", the fit used the other runs.
  std::vector<std::string> errors;
};

/// The declaration of every option of `incline normal-friction-test` (the command line and
/// Python bind from it). In incline_analysis.cpp.
const Fields<InclineNormalFrictionTestOptions>& incline_normal_friction_test_fields();

InclineNormalFrictionTestResult incline_normal_friction_test(const InclineNormalFrictionTestOptions& o);

}  // namespace tribolab::app
