// The command-line text of a sweep: axis ranges "lo:hi:count", "value or range", shards
// "i/N", and the progress line on a terminal. The workflow itself is app::bounce_sweep
// (src/app/bounce/bounce_sweep.hpp). docs/cli.md#bounce-sweep.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "app/bounce/bounce_sweep.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::cli {

/// "lo:hi:count" -> Axis of quantity q; errors name `option`.
sweep::Axis parse_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// A single number ("4") or a range ("4:8:3"): the value, or the axis.
app::ValueOrAxis parse_value_or_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// "i/N" -> Shard; errors name `option`.
sweep::Shard parse_shard(std::string_view text, const std::string& option);

/// One progress line: "\rsweep: done/total cells (pct%)  rate cells/s  elapsed s  ETA s".
void print_progress(std::ostream& out, const sweep::Progress& p);

}  // namespace tribolab::cli
