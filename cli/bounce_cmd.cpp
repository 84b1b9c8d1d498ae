// `tribolab bounce`: the spinning-ellipse bounce of the rugby-ball study (docs/cli.md#bounce).
//   contact-time  first contact after release from an apex (the study's experiment 3, table 4)
//   simulate      the impact from first touch to free flight (the study's experiment 4), every
//                 contact of it (docs/theory.md#bounce-contact, "whole impact")
//   drop          release -> flight -> contact -> ... several bounces
// The workflows are in src/app/bounce_simulate.*; this file binds their options to flags.
#include "app.hpp"
#include "bounce_analysis_cmd.hpp"
#include "bounce_options.hpp"
#include "bounce_render_cmd.hpp"
#include "bounce_sweep_cmd.hpp"
#include "report_option.hpp"

#include "app/bounce_simulate.hpp"

#include <memory>

namespace tribolab::cli {
namespace {

template <class Options>
struct Bound {
  Options o;
  bool json = false;
};

void add_contact_time(CLI::App* area) {
  auto b = std::make_shared<Bound<BounceContactTimeOptions>>();
  auto& o = b->o;
  auto* cmd = area->add_subcommand("contact-time", "First contact of a ball released at an apex (rugby-ball study, table 4)");
  cmd->add_option("--height", o.height, "centre height at the apex, m")->required();
  cmd->add_option("--omega", o.omega, "spin, rad/s, counter-clockwise positive");
  cmd->add_option("--theta-deg", o.theta_deg, "major axis from the horizontal at the apex, deg");
  cmd->add_option("--direction", o.direction, "direction of motion for the collision angle: 1 (+x) or -1");
  cmd->add_option("--g", o.g, "gravitational acceleration, m/s^2");
  add_ball_options(cmd, o.ball);
  add_json_flag(*cmd, b->json);
  add_report_option(*cmd, o.report, o.plotly);
  cmd->callback([b] { print_result(bounce_contact_time(b->o).json, b->json); });
}

void add_simulate(CLI::App* area) {
  auto b = std::make_shared<Bound<BounceSimulateOptions>>();
  auto& o = b->o;
  auto* cmd = area->add_subcommand("simulate", "The impact from first touch (gap 0) until the ball flies free to its apex: "
                                               "every contact of it (rugby-ball study, experiment 4)");
  cmd->add_option("--vx", o.vx, "centre velocity at first touch, m/s");
  cmd->add_option("--vy", o.vy, "centre velocity at first touch, m/s (< 0)")->required();
  cmd->add_option("--omega", o.omega, "spin at first touch, rad/s, CCW positive");
  cmd->add_option("--theta-deg", o.theta_deg, "major axis from the horizontal at first touch, deg");
  cmd->add_option("--g", o.g, "gravitational acceleration, m/s^2");
  cmd->add_option("--history", o.history, "write the time history to this CSV file");
  add_ball_options(cmd, o.ball);
  add_law_options(cmd, o.law);
  add_json_flag(*cmd, b->json);
  add_report_option(*cmd, o.report, o.plotly);
  cmd->callback([b] { print_result(bounce_simulate(b->o).json, b->json); });
}

void add_drop(CLI::App* area) {
  auto b = std::make_shared<Bound<BounceDropOptions>>();
  auto& o = b->o;
  auto* cmd = area->add_subcommand("drop", "Release, flight and several bounces until rest or --bounces");
  cmd->add_option("--height", o.height, "centre height at release, m")->required();
  cmd->add_option("--theta-deg", o.theta_deg, "major axis from the horizontal at release, deg");
  cmd->add_option("--omega", o.omega, "spin at release, rad/s, CCW positive");
  cmd->add_option("--vx", o.vx, "horizontal speed at release, m/s");
  cmd->add_option("--vy", o.vy, "vertical speed at release, m/s; 0: released at the apex");
  cmd->add_option("--bounces", o.bounces, "number of contacts to simulate");
  cmd->add_option("--rest-height", o.rest_height, "energy (as a height, m) below which the ball is at rest");
  cmd->add_option("--g", o.g, "gravitational acceleration, m/s^2");
  cmd->add_option("--trajectory", o.trajectory, "write the sampled trajectory to this CSV file");
  cmd->add_option("--sample-dt", o.sample_dt, "flight sampling step of --trajectory, s");
  add_ball_options(cmd, o.ball);
  add_law_options(cmd, o.law);
  add_json_flag(*cmd, b->json);
  add_report_option(*cmd, o.report, o.plotly);
  cmd->callback([b] { print_result(bounce_drop(b->o).json, b->json); });
}

}  // namespace

void register_bounce(CLI::App& root) {
  auto* area = root.add_subcommand("bounce", "spinning rugby ball (ellipse) bouncing on a floor (the rugby-ball study, Taiwan science fair 2021)");
  area->require_subcommand(1);
  add_contact_time(area);
  add_simulate(area);
  add_drop(area);
  register_bounce_analysis(area);
  register_bounce_sweep(*area);
  register_bounce_render(area);
}

}  // namespace tribolab::cli
