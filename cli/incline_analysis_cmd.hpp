// `tribolab incline synth | mu-from-slide | analyze | normal-friction-test`: the analyses of
// tracked incline runs (docs/cli.md#incline-analyze). Registered by register_incline.
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Adds the analysis commands to the `incline` command.
void add_incline_analysis_commands(CLI::App* incline);

}  // namespace tribolab::cli
