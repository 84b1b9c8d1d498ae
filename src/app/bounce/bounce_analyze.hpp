// `tribolab bounce analyze` (one file) and `bounce fit` as workflows of the application layer
// (docs/design.md, "Application layer: bounce"; docs/cli.md#bounce-analyze): seed 001's
// experiment 1 on two tracked tips, and the contact-law fit to a table of bounces. Errors are
// InputError naming the field (numerics/error.hpp field(): --time-scale on the command line,
// time_scale in Python); nothing is printed.
#pragma once

#include "app/bounce/bounce_options.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_series.hpp"
#include "track/track.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// `bounce analyze FILE` for one file (a series: the command line runs this per file).
struct BounceAnalyzeOptions {
  std::string file;          ///< Tracker .trk/.trz, Export Data text or tidy CSV (required)
  std::string track_a;       ///< name of the track of tip A (required)
  std::string track_b;       ///< name of the track of tip B (required)
  double time_scale = 1;     ///< real seconds per file second (240 fps shown at 30: 0.125)
  std::string length_unit;   ///< unit of the file's lengths, overriding the file; empty = the file's
  BallOptions ball;
  std::optional<double> floor_y;           ///< floor height in the file's frame, m; unset: from the flights
  double sigma_floor_y = 0;                ///< standard uncertainty of floor_y, m
  std::optional<double> contact_duration;  ///< contact duration, s (to half a frame); unset: located
  int exclude = analysis::BounceAnalyzeOptions{}.exclude;  ///< points always dropped on each side of the impact
  int impact = analysis::BounceAnalyzeOptions{}.impact;    ///< which detected impact to analyse (1 = first)
  std::string bounces_out;   ///< `bounce fit` table (CSV) of the analysed bounce; empty = none
  std::string report;        ///< HTML report path; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)

  /// The core's options after checking every field (InputError naming the option).
  analysis::BounceAnalyzeOptions checked() const;
};

/// The declaration of every option of `bounce analyze` for one file (app/common/option_fields.hpp):
/// the studio's form is made from it (src/studio/); the command line and Python bind from the
/// series' declaration built on it (bounce_analyze_series_fields, app/bounce/bounce_series.hpp).
inline const Fields<BounceAnalyzeOptions>& bounce_analyze_fields() {
  using O = BounceAnalyzeOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("file", &O::file, "", "Tracker .trk/.trz, Export Data text or tidy CSV").as(FieldRole::input_files).needed();
    d.add("track_a", &O::track_a, "", "name of the track of tip A").needed();
    d.add("track_b", &O::track_b, "", "name of the track of tip B").needed();
    d.add("time_scale", &O::time_scale, "", "real seconds per file second (240 fps shown at 30: 0.125)").in(ranges::time_scale);
    d.add("length_unit", &O::length_unit, "", "unit of the file's lengths, overriding the file (m, cm, mm, ...)");
    d.group(&O::ball, ball_fields());
    d.add("floor_y", &O::floor_y, "m", "floor height in the file's frame; unset: from the flights and contact_duration")
        .in(ranges::position);
    d.add("sigma_floor_y", &O::sigma_floor_y, "m", "standard uncertainty of floor_y").in(ranges::noise);
    d.add("contact_duration", &O::contact_duration, "s",
          "contact duration (to half a frame): enables mean_normal_force, and locates the floor without floor_y")
        .in(ranges::duration);
    d.add("exclude", &O::exclude, "", "points always dropped on each side of the impact (contact frames are dropped automatically)");
    d.add("impact", &O::impact, "", "which detected impact to analyse (1 = first)");
    d.add("bounces_out", &O::bounces_out, "", "also write the analysed bounce as a `bounce fit` table (CSV)")
        .as(FieldRole::output_path);
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}

struct BounceAnalyzeResult {
  nlohmann::json json;                 ///< exactly what `--json` prints
  track::Track tip_a, tip_b;           ///< the tracks as read (m, s)
  /// The analysis: body.rows (tips, centre, orientation, spin per frame), centre track,
  /// impacts, pre/post flight fits with their curves sampled on grid_t (grid_x, grid_y, grid_theta).
  analysis::BounceAnalysis analysis;
};

BounceAnalyzeResult bounce_analyze(const BounceAnalyzeOptions& o);

/// Reads `o.file` and analyses it with `checked` (= o.checked()), writing nothing: one run of
/// a series. Throws as bounce_analyze.
BounceAnalyzeResult bounce_analyze_run(const BounceAnalyzeOptions& o, const analysis::BounceAnalyzeOptions& checked);

/// The `bounce analyze` object of one run (docs/cli.md#bounce-analyze); a series' run rows
/// are this plus `file`.
nlohmann::json bounce_analysis_json(const analysis::BounceAnalysis& r);

/// The command line that analyses `o.file` alone (shown in its report).
std::string bounce_analyze_command(const BounceAnalyzeOptions& o);

/// Checks a --bounces-out path (not a folder, its folder exists): InputError otherwise.
void check_bounces_out_path(const std::string& path);

/// --bounces-out: the analysed runs as `bounce fit`'s table, each row's file in its last column `file`.
void write_bounces_out(const std::string& path, const std::vector<analysis::BounceSeriesPoint>& points,
                       const std::vector<std::string>& files);

/// `bounce fit FILE`: the contact law (K, n, D or e, mu) fitted to a table of bounces.
struct BounceFitOptions {
  std::string file;                    ///< CSV theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out (required)
  std::string model = "hunt-crossley";  ///< normal law
  bool restitution = false;            ///< fit the target restitution e instead of D
  std::string friction = "coulomb";    ///< coulomb|regularized|spring
  double slip_scale = analysis::BounceFitOptions{}.friction.slip_scale;  ///< v_s of the regularized law, m/s
  BallOptions ball;
  std::vector<std::string> fix;        ///< held parameters NAME=VALUE, NAME in K, n, D, e, mu
  std::string loss = "huber";          ///< robust loss: huber|cauchy|none
  double loss_scale = analysis::BounceFitOptions{}.loss_scale;  ///< residual where the loss bends, m/s
  double K0 = analysis::BounceFitOptions{}.K0;    ///< starting K, N/m^n
  double n0 = analysis::BounceFitOptions{}.n0;    ///< starting n
  double D0 = analysis::BounceFitOptions{}.D0;    ///< starting D, N s/m^(n+1)
  double e0 = analysis::BounceFitOptions{}.e0;    ///< starting e
  double mu0 = analysis::BounceFitOptions{}.mu0;  ///< starting mu
  std::string report;                  ///< HTML report path; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

struct BounceFitResult {
  nlohmann::json json;                        ///< exactly what `--json` prints (with "residuals")
  std::vector<analysis::BounceRow> rows;      ///< the table as read
  analysis::BounceFitResult fit;              ///< parameters, covariance and per-row predictions/residuals (fit.rows)
};

/// The declaration of every option of `bounce fit` (app/common/option_fields.hpp): the command
/// line and Python bind from it.
const Fields<BounceFitOptions>& bounce_fit_fields();

BounceFitResult bounce_fit(const BounceFitOptions& o);

}  // namespace tribolab::app
