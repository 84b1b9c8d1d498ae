// `tribolab incline analyze | mu-from-slide` as functions, for one tracked file or a series of
// them (seed 000, eqs a-c; docs/cli.md#incline-analyze, docs/cli.md#several-runs): option structs
// whose member initializers are the command line's defaults, results holding the command's JSON
// and the fitted and measured series. Several files are analysed in parallel; a failed run is a
// row with its error (Result::errors), the others still counted.
#pragma once

#include "analysis/incline_fit.hpp"
#include "analysis/incline_slide.hpp"
#include "analysis/series.hpp"
#include "app/incline/incline_analysis.hpp"
#include "report/plotly_script.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// Progress and threads of a series (several files): the front end's, not the analysis's.
struct InclineSeriesControl {
  int threads = 0;  ///< worker threads; 0 = all cores
  /// Called after each run of a series (serialised); empty = silent.
  std::function<void(const analysis::SeriesProgress&)> progress;
};

// ---- analyze --------------------------------------------------------------------------

struct InclineAnalyzeOptions {
  std::vector<std::string> files;  ///< Tracker .trk/.trz, Export Data text or CSV (required)
  /// Incline angle, degrees, in [0, 90): one for every file, or one per file (required).
  std::vector<double> phi_deg;
  double g = kDefaultG;            ///< gravitational acceleration, m/s^2
  /// Points per local fit of the a_N diagnostic, >= 5; unset = about 8 blocks.
  std::optional<int> block;
  bool no_model_a = false;         ///< skip model A (the verdict then comes from the a_N intercept)
  /// fit: fit the camera frame's rotation against the incline; none: the frame is known aligned.
  std::string frame_rotation = "fit";
  InclineTrackInput input;         ///< --track, --time-scale, --length-unit
  std::string report;              ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
  InclineSeriesControl series;     ///< several files only
};

/// The declaration of every option of `incline analyze` (the command line, Python and the
/// studio's form bind from it; series.threads stays a Python keyword of its own). The track
/// input is the shared incline_track_input_fields(). In incline_analyze.cpp.
const Fields<InclineAnalyzeOptions>& incline_analyze_fields();

/// One file of `incline analyze`.
struct InclineAnalyzeRun {
  std::string file;
  /// The fit: measured points (`data`), model B and A at them and on a fine grid, residuals,
  /// diagnostics. Unset when the run failed.
  std::optional<analysis::InclineAnalysis> analysis;
  std::string error;               ///< why it failed (series only; one file throws instead)
};

struct InclineAnalyzeResult {
  /// Exactly what `incline analyze --json` prints: the run's object for one file, else
  /// {"runs": [...], "summary": {...}}.
  nlohmann::json json;
  std::vector<InclineAnalyzeRun> runs;  ///< one per file, input order
  std::vector<std::string> errors;      ///< the failed runs' located errors (series)
};

InclineAnalyzeResult incline_analyze(const InclineAnalyzeOptions& o);

// ---- mu-from-slide --------------------------------------------------------------------

struct InclineMuFromSlideOptions {
  std::vector<std::string> files;  ///< Tracker .trk/.trz, Export Data text or CSV (required)
  /// Incline angle, degrees, in (0, 90): one, or one per file; empty = only a is reported.
  std::vector<double> phi_deg;
  /// Uncertainty of the angle, degrees: one, or one per file; empty = exact.
  std::vector<double> sigma_phi_deg;
  double g = kDefaultG;            ///< gravitational acceleration, m/s^2
  InclineTrackInput input;         ///< --track, --time-scale
  std::string report;              ///< HTML report to write; empty = none
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
  InclineSeriesControl series;     ///< several files only
};

struct InclineMuFromSlideRun {
  std::string file;
  /// a, mu and the measured points along the path (`t`, `s`, `v_t`, `v`); unset when it failed.
  std::optional<analysis::SlideResult> result;
  std::string error;
};

struct InclineMuFromSlideResult {
  nlohmann::json json;                     ///< exactly what `incline mu-from-slide --json` prints
  std::vector<InclineMuFromSlideRun> runs;  ///< one per file, input order
  std::vector<std::string> errors;         ///< the failed runs' located errors (series)
};

/// The declaration of every option of `incline mu-from-slide` (the command line and Python bind
/// from it; series.threads stays a Python keyword of its own). In incline_analyze.cpp.
const Fields<InclineMuFromSlideOptions>& incline_mu_from_slide_fields();

InclineMuFromSlideResult incline_mu_from_slide(const InclineMuFromSlideOptions& o);

/// The single-run JSON of `incline analyze` (without "track").
nlohmann::json incline_analysis_json(const analysis::InclineAnalysis& a);

}  // namespace tribolab::app
