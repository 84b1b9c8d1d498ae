// The declared JSON result keys (app/common/option_fields.hpp, ResultKey) of the commands whose options
// are not declared yet: their text listings print these units (cli/text_listing.hpp), and
// cli/schema_test.cpp requires every key their sample run prints to be declared here. Each
// table is defined beside the code that writes the keys; a command whose options get declared
// moves its declaration beside its options struct (as app/bounce/bounce_simulate.hpp's).
#pragma once

#include "app/common/option_fields.hpp"

namespace tribolab::app {

/// `bounce analyze FILE` (one file; docs/cli.md#bounce-analyze). In bounce_analyze.cpp.
const ResultKeys& bounce_analyze_result_keys();
/// `bounce render` (docs/cli.md#bounce-render). In bounce_render.cpp.
const ResultKeys& bounce_render_result_keys();
/// `track video` (docs/cli.md#track-video). In track_video.cpp.
const ResultKeys& track_video_result_keys();
/// `track kinematics` (docs/cli.md#track-kinematics). In track_kinematics.cpp.
const ResultKeys& track_kinematics_result_keys();
/// `incline mu-from-slide FILE` (one file; docs/cli.md#incline-mu-from-slide). In incline_analyze.cpp.
const ResultKeys& incline_mu_from_slide_result_keys();
/// `incline analyze FILE` (one file; docs/cli.md#incline-analyze). In incline_analyze.cpp.
const ResultKeys& incline_analyze_result_keys();
/// `incline normal-friction-test` (docs/cli.md#incline-normal-friction-test). In incline_analysis.cpp.
const ResultKeys& incline_normal_friction_test_result_keys();
/// `incline families` (docs/cli.md#incline-families). In incline_forward.cpp.
const ResultKeys& incline_families_result_keys();
/// `bounce fit` (docs/cli.md#bounce-fit). In bounce_analyze.cpp.
const ResultKeys& bounce_fit_result_keys();
/// `bounce sweep` (docs/cli.md#bounce-sweep). In bounce_sweep.cpp.
const ResultKeys& bounce_sweep_result_keys();
/// `track import` (docs/cli.md#track-import). In track_import.cpp.
const ResultKeys& track_import_result_keys();
/// `track rigid-body` (docs/cli.md#track-rigid-body). In track_rigid_body.cpp.
const ResultKeys& track_rigid_body_result_keys();
/// `track rotation` (docs/cli.md#track-rotation). In track_rotation.cpp.
const ResultKeys& track_rotation_result_keys();
/// The summaries of several files (docs/cli.md#several-runs): `incline analyze` and
/// `incline mu-from-slide` (in incline_series.cpp), `bounce analyze` (in bounce_series.cpp). Each
/// run's row is the one-file command's result (its keys above) with `file` and `error`.
const ResultKeys& incline_analyze_series_result_keys();
const ResultKeys& incline_mu_from_slide_series_result_keys();
const ResultKeys& bounce_analyze_series_result_keys();
/// `track video` on several videos (docs/cli.md#several-videos). In track_video.cpp.
const ResultKeys& track_video_series_result_keys();
/// `demo` (docs/cli.md#demo). In demo.cpp.
const ResultKeys& demo_result_keys();

}  // namespace tribolab::app
