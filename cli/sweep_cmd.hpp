// The progress line of a sweep on a terminal; the text of its ranges and shards is read by
// src/app/sweep/sweep_text.hpp. The workflow itself is app::bounce_sweep
// (src/app/bounce/bounce_sweep.hpp). docs/cli.md#bounce-sweep.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "app/sweep/sweep_text.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::cli {

// "lo:hi:count", a number or a range, "i/N" (src/app/sweep/sweep_text.hpp): what every
// declared range, number-or-range and shard option reads (cli/declared_options.hpp).
using app::parse_axis;
using app::parse_shard;
using app::parse_value_or_axis;

/// One progress line: "\rsweep: done/total cells (pct%)  rate cells/s  elapsed s  ETA s".
void print_progress(std::ostream& out, const sweep::Progress& p);

}  // namespace tribolab::cli
