// The text of a sweep's ranges and shards: "lo:hi:count", a number or a range, "i/N". The
// command line reads every such option with these (cli/declared_options.hpp, `bounce sweep`),
// Python a shard given as "i/N" (python/src/bind.hpp); the workflows take them parsed
// (sweep::Axis, sweep::ValueOrAxis, sweep::Shard). docs/cli.md#bounce-sweep.
#pragma once

#include "sweep/grid.hpp"

#include <string>
#include <string_view>

namespace tribolab::app {

/// "lo:hi:count" -> Axis of quantity q; errors name `option` (a flag, or field(name)).
sweep::Axis parse_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// A single number ("4") or a range ("4:8:3"): the value, or the axis.
sweep::ValueOrAxis parse_value_or_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// "i/N" -> Shard; errors name `option`.
sweep::Shard parse_shard(std::string_view text, const std::string& option);

}  // namespace tribolab::app
