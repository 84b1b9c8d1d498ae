// Report page of `bounce analyze` over several files: seed 001's figures rebuilt from the runs
// (figure 32: e against the collision angle with error bars and the e = 1 line; figures 49, 50:
// energies and the mean normal force per run; figure 52: the contact-point speed against the
// angle), the summary, the outliers named, and a table of every run linking to its own report
// written beside the series report (docs/cli.md#bounce-analyze). Every number is the summary's
// own (the JSON's values).
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_series.hpp"
#include "report/plotly_script.hpp"
#include "report/report.hpp"

#include <functional>
#include <string>
#include <vector>

namespace tribolab::app {

/// One run of a `bounce analyze` series as the report sees it.
struct BounceSeriesRun {
  std::string source;                                  ///< the file
  const analysis::BounceAnalysis* analysis = nullptr;  ///< null when the run failed
  std::string error;                                   ///< why it failed (empty when it did not)
};

/// Adds the series content (summary, figures 32, 49, 50, 52, run table) to `r`, each section
/// heading starting with `prefix` (e.g. "Bounce series: "). `points` are the analysed runs'
/// points (point_of) in run order; `links` one per run (empty: none). Returns the number of
/// figures added.
int add_bounce_series(report::Report& r, const std::string& prefix, const std::vector<BounceSeriesRun>& runs,
                      const std::vector<analysis::BounceSeriesPoint>& points,
                      const analysis::BounceSeriesSummary& summary,
                      const analysis::BounceSeriesOptions& options, const std::vector<std::string>& links);

/// `bounce analyze --report` over several files. Writes each analysed run's own report
/// (bounce_analyze_report, with `run_command(i)` under its title) into
/// series_runs_folder(report_path) and returns the series report linking to them.
report::Report bounce_analyze_series_report(const std::string& command, const bounce::Ball& ball,
                                            const std::vector<BounceSeriesRun>& runs,
                                            const std::vector<analysis::BounceSeriesPoint>& points,
                                            const analysis::BounceSeriesSummary& summary,
                                            const analysis::BounceSeriesOptions& options,
                                            const std::string& report_path,
                                            const std::function<std::string(std::size_t)>& run_command,
                                            report::PlotlyMode plotly);

}  // namespace tribolab::app
