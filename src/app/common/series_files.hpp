// The files of a series (several inputs, docs/cli.md#several-runs): where each run's own report
// and outputs go beside the series' one. Shared by the incline, bounce and track video series.
#pragma once

#include <cstddef>
#include <string>

namespace tribolab::app {

/// Folder of the runs' own reports beside `report_path`: "DIR/<stem>_runs" for DIR/<stem>.html.
std::string series_runs_folder(const std::string& report_path);

/// The file name (inside series_runs_folder) of run `index` (0-based) from `source`:
/// "<NN>_<file stem>.html" with characters other than letters, digits, '.', '-' and '_'
/// replaced by '_' (NN = index + 1, zero-padded so the names sort in run order).
std::string series_run_file(std::size_t index, const std::string& source, std::size_t n_runs);

}  // namespace tribolab::app
