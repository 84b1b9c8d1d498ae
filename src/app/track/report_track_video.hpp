// Report page of `track video` (docs/cli.md#track-video): what was decoded (size, frames, frame
// rate and time base, time scale, calibration and its unit), every track's summary (tracked,
// lost frame ranges, median score, distance to a Tracker project's human marks), the warnings,
// thumbnails of frames with the tracks drawn, and x, y, orientation and score against time.
#pragma once

#include "report/report.hpp"
#include "video/track_video.hpp"

#include <string>

namespace tribolab::app {

/// Appends the sections of the tracking report to `r`, their headings starting with `prefix`
/// (e.g. "" for the command's own page, "Tracking: " inside another report). Returns the number
/// of figures added.
int add_track_video_sections(report::Report& r, const video::TrackVideoResult& result, const std::string& prefix = {});

/// `track video --report`: the whole page.
report::Report track_video_report(const video::TrackVideoResult& result);

}  // namespace tribolab::app
