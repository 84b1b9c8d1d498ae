// `tribolab bounce analyze|fit|synth-video|synth-table` (docs/cli.md#bounce-analyze).
#pragma once

#include "analysis/bounce_analyze.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace tribolab::cli {

/// Adds the analysis commands to the `bounce` area (called from register_bounce).
void register_bounce_analysis(CLI::App* area);

/// The `bounce analyze` object of one run (docs/cli.md#bounce-analyze); a series' run rows
/// are this plus `file`.
nlohmann::json bounce_analysis_json(const analysis::BounceAnalysis& r);

}  // namespace tribolab::cli
