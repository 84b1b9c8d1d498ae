// The text listing of a command's result, for people (docs/cli.md#output). `--json` prints
// the result object itself; without it the same object is laid out as:
//
//   * one aligned "name  value unit" row per number, string or flag;
//   * a value with a standard uncertainty beside it (`sigma_X` next to `X`) as one rounded
//     "0.6331 ± 0.0004" (report/format.hpp's rule), its 95 % interval (`ci95.X`, `X_ci95`,
//     `X_ci95_deg` for `X_deg`) on the same row;
//   * units from the command's declared result keys (app/common/option_fields.hpp, ResultKey),
//     never from a key's name: an undeclared key prints without a unit (cli/schema_test.cpp
//     fails when a command prints one);
//   * a nested object as an indented block under its name, a list of objects (bounces,
//     members, phases, runs) as a sub-table with one row per element and units in the header;
//   * null explained ("does not stop", "never") instead of a bare dash, empty lists as "none".
#pragma once

#include "app/common/option_fields.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace tribolab::cli {

/// The listing of `result` (an object; anything else is printed as one value), ending in '\n'.
/// Each unit is the one `keys` (the command's declared result keys) give its path.
std::string text_listing(const nlohmann::json& result, const app::ResultKeys& keys);

/// The label of a column of a table of runs or elements: "name (unit)", the bare name when the
/// unit is empty or the name already says it (`_deg`, `_px`).
std::string column_label(const std::string& name, const std::string& unit);

}  // namespace tribolab::cli
