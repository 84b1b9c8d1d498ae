// `tribolab bounce analyze|fit|synth-video|synth-table` (docs/cli.md#bounce-analyze).
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Adds the analysis commands to the `bounce` area (called from register_bounce).
void register_bounce_analysis(CLI::App* area);

}  // namespace tribolab::cli
