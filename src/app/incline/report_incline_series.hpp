// Report pages of `incline analyze` and `incline mu-from-slide` over several files: the series
// drawn as seed 000 drew it (mu per run with the weighted mean, figure 八's stop-point scaling,
// cos theta_c against tan phi, model A's normal friction pooled), a table of every run with
// its outliers named, each row linking to the run's own report written beside the series
// report (docs/cli.md#several-runs). Every number is the summary's own (the JSON's values).
#pragma once

#include "analysis/incline_fit.hpp"
#include "analysis/incline_series.hpp"
#include "analysis/incline_slide.hpp"
#include "report/plotly_script.hpp"
#include "report/report.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

/// One run of an `incline analyze` series as the report sees it.
struct InclineSeriesRun {
  std::string source;                                ///< the file
  const analysis::InclineAnalysis* analysis = nullptr;  ///< null when the run failed
  double phi = 0;                                    ///< rad
  std::string error;                                 ///< why it failed (empty when it did not)
};

/// One run of a `mu-from-slide` series.
struct SlideSeriesRun {
  std::string source;
  const analysis::SlideResult* result = nullptr;  ///< null when the run failed
  analysis::SlideOptions options;
  std::string error;
};

/// `incline analyze --report` over several files. Writes each analysed run's own report
/// (incline_analyze_report) into series_runs_folder(report_path) and returns the series
/// report linking to them. `report_path` empty: no run reports, no links (for the demo's
/// inline use). `plotly`: how every page gets Plotly.js (with PlotlyMode::file the runs'
/// reports share the one script beside the series report).
report::Report incline_analyze_series_report(const std::vector<InclineSeriesRun>& runs,
                                             const analysis::InclineSeriesSummary& summary,
                                             const std::string& report_path,
                                             report::PlotlyMode plotly);

/// Adds the series content (summary, run table, figures) to `r`; `links` per run (empty
/// strings: none). Returns the number of figures added. For the demo's case study.
int add_incline_series(report::Report& r, const std::string& title, const std::vector<InclineSeriesRun>& runs,
                       const analysis::InclineSeriesSummary& summary, const std::vector<std::string>& links);

/// `incline mu-from-slide --report` over several files (runs' own reports as above).
report::Report incline_slide_series_report(const std::vector<SlideSeriesRun>& runs,
                                           const analysis::SlideSeriesSummary& summary,
                                           const std::string& report_path,
                                           report::PlotlyMode plotly);

}  // namespace tribolab::app
