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

void add_input_options(CLI::App& cmd, TrackInputOptions& in) {
  cmd.add_option("FILE", in.file, "Tracker .trk/.trz, Tracker Export Data text, or CSV")->required();
  cmd.add_option("--time-scale", in.time_scale,
                 "Real seconds per file second: slow motion recorded at 240 fps and played at "
                 "30 fps is 0.125");
  cmd.add_option("--length-unit", in.length_unit,
                 "Unit of the file's lengths, overriding what the file says: m, cm, mm, km, um, "
                 "in, ft (when not given: the file's unit, else m)");
  cmd.add_option("--entry", in.entry, "For a .trz: the .trk inside to read (when not given: the first)");
}

/// --from/--to (also spelled --t-from/--t-to, the fields' names in messages and Python).
void add_time_range(CLI::App& cmd, double& t_from, double& t_to, const std::string& what) {
  cmd.add_option("--t-from,--from", t_from, "First time used, s (when not given: the first point): " + what);
  cmd.add_option("--t-to,--to", t_to, "Last time used, s (when not given: the last point)");
}

/// `keys`: the command's declared result keys (the listing's units).
template <class Options, class Run>
void bind(CLI::App& cmd, std::shared_ptr<Options> o, std::shared_ptr<bool> as_json, Run run,
          const app::ResultKeys& keys) {
  add_json_flag(cmd, *as_json);
  declare_results(cmd, keys);
  cmd.callback([o, as_json, run, &keys] { print_result(run(*o).json, *as_json, keys); });
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
    auto o = std::make_shared<TrackImportOptions>();
    add_input_options(*cmd, o->input);
    cmd->add_option("--track", o->track, "Keep only this track (repeatable; when not given: all)");
    cmd->add_option("--out", o->out, "Write the tidy CSV here (columns track,frame,t,x,y)");
    bind(*cmd, o, std::make_shared<bool>(false), track_import, track_import_result_keys());
  }

  // track kinematics
  {
    auto* cmd = area->add_subcommand(
        "kinematics", "Velocities and accelerations of one track (Tracker's stencils or "
                      "Savitzky-Golay with standard errors), never across impacts");
    auto o = std::make_shared<TrackKinematicsOptions>();
    auto as_json = std::make_shared<bool>(false);
    add_declared_options(*cmd, *o, track_kinematics_fields(), track_kinematics_result_keys());
    add_json_flag(*cmd, *as_json);
    cmd->callback([o, as_json, cmd] { print_declared(*cmd, track_kinematics(*o).json, *as_json); });
  }

  // track rigid-body
  {
    auto* cmd = area->add_subcommand(
        "rigid-body", "Centre, orientation and spin (with standard errors) of a body from two tracked "
                      "points on it (docs/theory.md#track-rigid-body)");
    auto o = std::make_shared<TrackRigidBodyOptions>();
    auto as_json = std::make_shared<bool>(false);
    add_declared_options(*cmd, *o, track_rigid_body_fields(), track_rigid_body_result_keys());
    add_json_flag(*cmd, *as_json);
    cmd->callback([o, as_json, cmd] { print_declared(*cmd, track_rigid_body(*o).json, *as_json); });
  }

  // track rotation
  {
    auto* cmd = area->add_subcommand(
        "rotation", "Spin (with standard errors) of ONE tracked point about a fixed, given or uniformly moving "
                    "pivot: a mark on a wheel, a pendulum bob (docs/theory.md#rotation-about-a-pivot)");
    auto o = std::make_shared<TrackRotationOptions>();
    add_input_options(*cmd, o->input);
    cmd->add_option("--track", o->track, "Track of the turning point (required when the file has several)");
    cmd->add_option("--pivot-x", o->pivot_x, "Pivot x, m, with --pivot-y (when not given: fitted to the track)");
    cmd->add_option("--pivot-y", o->pivot_y, "Pivot y, m, with --pivot-x");
    cmd->add_flag("--moving-pivot", o->moving_pivot, "Fit a pivot moving uniformly (a rolling wheel's axle)");
    cmd->add_option("--window", o->window, "Points per local linear fit of the angle (the spin at each frame), >= 3");
    add_time_range(*cmd, o->t_from, o->t_to, "only the part of the record that turns about the pivot");
    cmd->add_option("--out", o->out, "Output CSV: frame,t,x,y,theta,radius,omega,sigma_omega (s, m, rad, rad/s)");
    bind(*cmd, o, std::make_shared<bool>(false), track_rotation, track_rotation_result_keys());
  }
}

}  // namespace tribolab::cli
