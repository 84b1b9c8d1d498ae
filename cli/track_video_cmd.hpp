// `tribolab track video` (docs/cli.md#track-video), registered by register_track.
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Adds the `video` command to the `track` area.
void register_track_video(CLI::App& track_area);

}  // namespace tribolab::cli
