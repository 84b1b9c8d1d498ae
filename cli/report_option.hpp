// `--report FILE.html` for any analysis or simulation command, in two lines:
//
//   std::string report_path;                       // next to the command's other options
//   report::PlotlyMode plotly;                     // how the page gets Plotly.js
//   add_report_option(*cmd, report_path, plotly);  // --report and --plotly
//   ...
//   write_report_if_requested(report_path, plotly, [&] { return build_report(result); });
//
// The option is checked while parsing (ends in .html or .htm, not a directory, its folder
// exists), so a bad name fails before any computation; the report is built only when asked
// for and written atomically (no partial file if anything fails).
#pragma once

#include "report/plotly_script.hpp"
#include "report/report.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace tribolab::cli {

/// Adds `--report FILE.html` to `cmd`, storing the path in `path` (empty = not requested),
/// and `--plotly embed|cdn|file` storing how the page gets Plotly.js in `plotly`
/// (docs/cli.md#plotly-in-reports). Returns the --report option.
CLI::Option* add_report_option(CLI::App& cmd, std::string& path, report::PlotlyMode& plotly);

/// Checks a report path as --report does: empty string when valid, else the reason.
std::string check_report_path(const std::string& path);

/// When `path` is not empty, builds the report with `build` and writes it to `path`.
/// Returns true when a report was written.
bool write_report_if_requested(const std::string& path, report::PlotlyMode plotly,
                               const std::function<report::Report()>& build);

}  // namespace tribolab::cli
