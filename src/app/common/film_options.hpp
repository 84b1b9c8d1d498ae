// The camera options the render commands (`bounce render`, `incline render`) take as text, read
// into video::RenderOptions once for both (docs/cli.md#bounce-render, #incline-render). Errors
// are InputError naming the field.
#pragma once

#include "video/render.hpp"

#include <string>
#include <utility>

namespace tribolab::app {

/// "WIDTHxHEIGHT" in pixels (e.g. 640x480) -> {width, height}; the ranges are
/// RenderOptions::validate's.
std::pair<int, int> parse_frame_size(const std::string& text);

/// `background` (plain, gradient or texture) into r.background and the background colour the
/// renders use with it (grey 200; a slightly blue grey under the texture).
void apply_background(const std::string& background, video::RenderOptions& r);

}  // namespace tribolab::app
