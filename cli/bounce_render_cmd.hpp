// `tribolab bounce render`: a simulated throw filmed to a video with its truth
// (docs/cli.md#bounce-render).
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Adds `render` under the `bounce` area command.
void register_bounce_render(CLI::App* bounce_area);

}  // namespace tribolab::cli
