// Several files at once for the analysis commands (`incline analyze`, `incline mu-from-slide`,
// `bounce analyze`; docs/cli.md#several-runs): the shared plumbing, so each command only says
// how one file is analysed and what its summary is.
//
//   cmd->add_option("FILE", files, "...")->required();             // a std::vector<std::string>
//   ...
//   if (files.size() == 1) { ...the single-file command, unchanged... }
//   const auto phi_text = per_file_values(phi_deg, files.size(), "--phi-deg");  // before any work
//   auto runs = run_files<MyRun>(files, [&](std::size_t i, const std::string& f) { ... });
//   json rows = series_rows(runs, [](const MyRun& r) { return r.json; });
//   print_series(rows, summary_json, as_json, {"phi_deg", "mu", "sigma_mu"});
//   finish_series(runs);                                   // non-zero exit if any run failed
//
// Runs are analysed in parallel (analysis::run_series); with a terminal on stderr a progress
// line is shown there. The output (JSON or text) is in input order whatever the threads.
#pragma once

#include "analysis/series.hpp"
#include "app/common/option_fields.hpp"
#include "app/common/series_json.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tribolab::cli {

/// `text` holds one value (used for every file) or a comma-separated list of exactly
/// n_files values; returns n_files strings (trimmed). Empty text gives n_files empty strings.
/// Throws InputError naming `option` when the count differs ("--phi-deg gives 2 values for 3 files").
std::vector<std::string> per_file_values(const std::string& text, std::size_t n_files, const std::string& option);

/// Series options for the CLI: all cores, and a progress line ("analysed 3/8 runs, 1
/// failed") on stderr, overwritten in place, when stderr is a terminal.
analysis::SeriesOptions cli_series_options(const std::string& what = "runs");

/// analysis::run_series with cli_series_options().
template <class Result, class Run>
std::vector<analysis::RunOutcome<Result>> run_files(const std::vector<std::string>& files, Run&& run) {
  return analysis::run_series<Result>(files, std::forward<Run>(run), cli_series_options());
}

using app::series_rows;  // the series JSON is the application layer's (app/common/series_json.hpp)
using app::series_counts;

/// Prints a series: with `as_json` one line {"runs": rows, "summary": summary}; else a table
/// of the runs (a column per entry of `columns`, each a key or a JSON pointer such as
/// "/normal_friction/verdict", and the error of a failed run; units in the header from
/// `row_keys`, the one-file command's declared keys) followed by the summary's keys as
/// print_result lists them (units from `summary_keys`).
void print_series(const nlohmann::json& rows, const nlohmann::json& summary, bool as_json,
                  const std::vector<std::string>& columns, const app::ResultKeys& row_keys,
                  const app::ResultKeys& summary_keys);

/// After the output: throws InputError ("2 of 8 runs failed: b.csv: ...; see their rows")
/// when any run failed, so the command exits non-zero with one line on stderr.
void finish_series(std::size_t n_runs, const std::vector<std::string>& errors);

template <class Result>
void finish_series(const std::vector<analysis::RunOutcome<Result>>& runs) {
  finish_series(runs.size(), app::series_errors(runs));
}

}  // namespace tribolab::cli
