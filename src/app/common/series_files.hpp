// The files of a series (several inputs, docs/cli.md#several-runs): where each run's own report
// and outputs go beside the series' one. Shared by the incline, bounce and track video series.
#pragma once

#include "report/plotly_script.hpp"
#include "report/report.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// Folder of the runs' own reports beside `report_path`: "DIR/<stem>_runs" for DIR/<stem>.html.
std::string series_runs_folder(const std::string& report_path);

/// The file name (inside series_runs_folder) of run `index` (0-based) from `source`:
/// "<NN>_<file stem>.html" with characters other than letters, digits, '.', '-' and '_'
/// replaced by '_' (NN = index + 1, zero-padded so the names sort in run order).
std::string series_run_file(std::size_t index, const std::string& source, std::size_t n_runs);

/// `path` with every byte a report's link does not take as it is (anything but letters, digits,
/// '.', '_', '-' and '/') percent-encoded: a folder named after "my series.html" still links.
std::string encode_link(const std::string& path);

/// The runs' own reports of a series: run i's, `report_of(i)` (nullopt: none, e.g. the run
/// failed), written into series_runs_folder(report_path) as series_run_file(i, sources[i], n);
/// returns the series report's links to them, relative to it and encoded ("" for a run without
/// one). With no report_path nothing is written and every link is "".
std::vector<std::string> write_run_reports(const std::vector<std::string>& sources, const std::string& report_path,
                                           report::PlotlyMode plotly,
                                           const std::function<std::optional<report::Report>(std::size_t)>& report_of);

}  // namespace tribolab::app
