// The JSON of a series of runs (several files given to one analysis command; docs/cli.md#several-runs):
// the `runs` array and the counts every summary starts with. CLI11-free: any front end builds
// the same objects.
#pragma once

#include "analysis/series.hpp"
#include "numerics/error.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// The `runs` array of the JSON: per outcome, {"file": source} followed by the keys of
/// `to_json(result)` (the single-file object), or {"file": source, "error": message}.
template <class Result, class ToJson>
nlohmann::json series_rows(const std::vector<analysis::RunOutcome<Result>>& runs, ToJson&& to_json) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : runs) {
    nlohmann::json row;
    row["file"] = r.source;
    if (r.ok()) {
      const nlohmann::json single = to_json(*r.result);  // a named object: items() refers to it
      for (const auto& [k, v] : single.items()) row[k] = v;
    } else {
      row["error"] = r.located_error();
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The keys every series summary starts with: n_runs, n_ok, n_failed, failed (the files).
template <class Result>
nlohmann::json series_counts(const std::vector<analysis::RunOutcome<Result>>& runs) {
  nlohmann::json failed = nlohmann::json::array();
  for (const auto& r : runs)
    if (!r.ok()) failed.push_back(r.source);
  return {{"n_runs", runs.size()}, {"n_ok", runs.size() - failed.size()}, {"n_failed", failed.size()},
          {"failed", failed}};
}

/// A per-file option: one value for every file, or exactly one per file (n_files of them);
/// none gives unset values. InputError naming `option` when the count differs.
inline std::vector<std::optional<double>> per_file(const std::vector<double>& values, std::size_t n_files,
                                                   const std::string& option) {
  if (values.empty()) return std::vector<std::optional<double>>(n_files);
  if (values.size() == 1) return std::vector<std::optional<double>>(n_files, values.front());
  if (values.size() != n_files)
    throw InputError(option, "gives " + std::to_string(values.size()) + " values for " + std::to_string(n_files) +
                                 (n_files == 1 ? " file" : " files") + " (give one value for all, or one per file)");
  return {values.begin(), values.end()};
}

/// The located errors of the failed runs (input order): what a front end reports after the output.
template <class Result>
std::vector<std::string> series_errors(const std::vector<analysis::RunOutcome<Result>>& runs) {
  std::vector<std::string> errors;
  for (const auto& r : runs)
    if (!r.ok()) errors.push_back(r.located_error());
  return errors;
}

}  // namespace tribolab::app
