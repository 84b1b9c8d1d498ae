// `tribolab bounce sweep` / `bounce merge` wired to the bounce contact solver
// (docs/cli.md#bounce-sweep, docs/theory.md#sweeps).
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Adds `sweep` and `merge` under the `bounce` area command (app::bounce_sweep and
/// app::bounce_merge), each cell one whole impact from first touch (app/bounce/bounce_cell.hpp).
void register_bounce_sweep(CLI::App& bounce_area);

}  // namespace tribolab::cli
