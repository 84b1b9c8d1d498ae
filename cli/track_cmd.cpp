// `tribolab track`: read tracked video data (Tracker .trk/.trz, Export Data text, CSV),
// differentiate it, follow two points of one body. Options are documented in docs/cli.md#track;
// the workflows live in src/app/track_*.hpp, this file only binds options to them.
#include "app.hpp"
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"
#include "report_option.hpp"
#include "track_video_cmd.hpp"

#include "app/track/track_import.hpp"
#include "app/track/track_kinematics.hpp"
#include "app/track/track_rigid_body.hpp"
#include "app/track/track_rotation.hpp"

#include <memory>

namespace tribolab::cli {

namespace {

/// A command bound from its declaration: its options, --json, and the listing of `run`'s JSON.
template <class Options, class Run>
void add_declared_track_command(CLI::App& cmd, const app::Fields<Options>& fields, const app::ResultKeys& keys, Run run) {
  auto o = std::make_shared<Options>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(cmd, *o, fields, keys);
  add_json_flag(cmd, *as_json);
  cmd.callback([o, as_json, run, &cmd] { print_declared(cmd, run(*o).json, *as_json); });
}

}  // namespace

void register_track(CLI::App& root) {
  auto* area = root.add_subcommand(
      "track", "Tracked video data: track points and balls in video, read Tracker files and exports, "
               "velocities and accelerations, the motion of a body from two of its points, the spin of one "
               "point about a pivot");
  area->require_subcommand(1);

  // track video (cli/track_video_cmd.cpp)
  register_track_video(*area);

  // track import
  {
    auto* cmd = area->add_subcommand(
        "import", "Read tracked points into a tidy table track,frame,t,x,y (s, m) and summarise them");
    add_declared_track_command(*cmd, track_import_fields(), track_import_result_keys(), track_import);
  }

  // track kinematics
  {
    auto* cmd = area->add_subcommand(
        "kinematics", "Velocities and accelerations of one track (Tracker's stencils or "
                      "Savitzky-Golay with standard errors), never across impacts");
    add_declared_track_command(*cmd, track_kinematics_fields(), track_kinematics_result_keys(), track_kinematics);
  }

  // track rigid-body
  {
    auto* cmd = area->add_subcommand(
        "rigid-body", "Centre, orientation and spin (with standard errors) of a body from two tracked "
                      "points on it (docs/theory.md#track-rigid-body)");
    add_declared_track_command(*cmd, track_rigid_body_fields(), track_rigid_body_result_keys(), track_rigid_body);
  }

  // track rotation
  {
    auto* cmd = area->add_subcommand(
        "rotation", "Spin (with standard errors) of ONE tracked point about a fixed, given or uniformly moving "
                    "pivot: a mark on a wheel, a pendulum bob (docs/theory.md#rotation-about-a-pivot)");
    add_declared_track_command(*cmd, track_rotation_fields(), track_rotation_result_keys(), track_rotation);
  }
}

}  // namespace tribolab::cli
