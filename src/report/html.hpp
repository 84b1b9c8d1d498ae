// Writes a Report as one self-contained HTML file: the text, the tables, the equations, and
// interactive Plotly figures, with Plotly.js itself embedded, so the file opens offline on
// any machine. The page reports whether it rendered in a hidden status element:
//
//   <div id="tribolab-status" hidden>ok 3</div>          every one of 3 plots drawn
//   <div id="tribolab-status" hidden>error: ...</div>    a script error or a failed plot
//
// ("pending" until the plots finish). tests/browser/check_report.sh reads it in headless
// Chromium.
#pragma once

#include "report/plotly_script.hpp"
#include "report/report.hpp"

#include <ostream>
#include <string>

namespace tribolab::report {

/// Id of the hidden status element and of the JSON block holding the figures' data.
inline constexpr const char* kStatusId = "tribolab-status";
inline constexpr const char* kFiguresId = "tribolab-figures";

/// The whole page. Throws std::invalid_argument with Report::validate()'s message when the
/// report is malformed (a programming error in the code that built it). `plotly` says how the
/// page gets Plotly.js (plotly_script.hpp); for PlotlyMode::file, `script_src` is the relative
/// URL of the shared script (default: plotly_file_name(), beside the page).
std::string to_html(const Report& report, PlotlyMode plotly = PlotlyMode::embed,
                    const std::string& script_src = {});

/// Writes the page to `path` through io::AtomicFile: the file appears whole or not at all.
/// Throws InputError naming the path when it cannot be written. With PlotlyMode::file the
/// shared script is written (once, write_plotly_script) into `script_dir`, default the
/// page's own folder, and the page links to it by a relative path (e.g. "../plotly-X.min.js"
/// for the run reports of a series in a sub-folder).
void write_html(const Report& report, const std::string& path, PlotlyMode plotly = PlotlyMode::embed,
                const std::string& script_dir = {});

}  // namespace tribolab::report
