// The text listing of a command's result, for people (docs/cli.md#output). `--json` prints
// the result object itself; without it the same object is laid out as:
//
//   * one aligned "name  value unit" row per number, string or flag;
//   * a value with a standard uncertainty beside it (`sigma_X` next to `X`) as one rounded
//     "0.6331 ± 0.0004" (report/format.hpp's rule), its 95 % interval (`ci95.X`, `X_ci95`,
//     `X_ci95_deg` for `X_deg`) on the same row;
//   * units from the command's declared result keys (app/option_fields.hpp); for commands
//     not yet declared, from the key's name (docs/cli.md#units-in-the-text-listing: `_deg` degrees, `t_`
//     seconds, `v`/`vx` metres per second, `omega` radians per second, energies in joules...);
//   * a nested object as an indented block under its name, a list of objects (bounces,
//     members, phases, runs) as a sub-table with one row per element and units in the header;
//   * null explained ("does not stop", "never") instead of a bare dash, empty lists as "none".
#pragma once

#include "app/option_fields.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace tribolab::cli {

/// The listing of `result` (an object; anything else is printed as one value), ending in '\n'.
/// With `keys` (a command's declared result keys, app/option_fields.hpp) each unit is the
/// declared one (none for an undeclared key); without, the older rules of unit_of (for the
/// commands not yet declared).
std::string text_listing(const nlohmann::json& result, const app::ResultKeys* keys = nullptr);

/// The unit of a result key from its name ("" when dimensionless or unknown); `parent` is the
/// enclosing object's key (energies inside an `energy_in_parts` object are joules).
std::string unit_of(const std::string& key, const std::string& parent = "");

}  // namespace tribolab::cli
