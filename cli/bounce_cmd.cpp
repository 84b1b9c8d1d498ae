// `tribolab bounce`: the spinning-ellipse bounce of the rugby-ball study (docs/cli.md#bounce).
//   contact-time  first contact after release from an apex (the study's experiment 3, table 4)
//   simulate      the impact from first touch to free flight (the study's experiment 4), every
//                 contact of it (docs/theory.md#bounce-contact, "whole impact")
//   drop          release -> flight -> contact -> ... several bounces
// The workflows and their option declarations are in src/app/bounce/bounce_simulate.*; this file
// binds the declarations to flags (cli/declared_options.hpp).
#include "app.hpp"
#include "bounce_analysis_cmd.hpp"
#include "bounce_options.hpp"
#include "bounce_render_cmd.hpp"
#include "bounce_sweep_cmd.hpp"
#include "declared_options.hpp"
#include "report_option.hpp"

#include "app/bounce/bounce_simulate.hpp"

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
  auto* cmd = area->add_subcommand("contact-time", "First contact of a ball released at an apex (rugby-ball study, table 4)");
  add_declared_options(*cmd, b->o, bounce_contact_time_fields(), bounce_contact_time_result_keys());
  add_json_flag(*cmd, b->json);
  cmd->callback([b, cmd] { print_declared(*cmd, bounce_contact_time(b->o).json, b->json); });
}

void add_simulate(CLI::App* area) {
  auto b = std::make_shared<Bound<BounceSimulateOptions>>();
  auto* cmd = area->add_subcommand("simulate", "The impact from first touch (gap 0) until the ball flies free to its apex: "
                                               "every contact of it (rugby-ball study, experiment 4)");
  add_declared_options(*cmd, b->o, bounce_simulate_fields(), bounce_simulate_result_keys());
  add_json_flag(*cmd, b->json);
  cmd->callback([b, cmd] { print_declared(*cmd, bounce_simulate(b->o).json, b->json); });
}

void add_drop(CLI::App* area) {
  auto b = std::make_shared<Bound<BounceDropOptions>>();
  auto* cmd = area->add_subcommand("drop", "Release, flight and several bounces until rest or --bounces");
  add_declared_options(*cmd, b->o, bounce_drop_fields(), bounce_drop_result_keys());
  add_json_flag(*cmd, b->json);
  cmd->callback([b, cmd] { print_declared(*cmd, bounce_drop(b->o).json, b->json); });
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
