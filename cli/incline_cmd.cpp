// `tribolab incline ...`: predict, simulate, mu-from-stop, families (docs/cli.md#incline),
// and the tracked-run analyses of incline_analysis_cmd.cpp. Each command binds its options
// to the application layer's option struct (src/app/incline_*.hpp), calls the workflow and
// prints its JSON; the library validates, computes and writes the files.
#include "app.hpp"
#include "help_explain.hpp"
#include "incline_analysis_cmd.hpp"
#include "incline_options.hpp"
#include "declared_options.hpp"
#include "report_option.hpp"

#include "app/incline/incline_forward.hpp"
#include "app/incline/incline_render.hpp"
#include "app/incline/incline_stop.hpp"
#include "app/common/result_keys.hpp"

#include <memory>
#include <string>

namespace tribolab::cli {
namespace {

/// Shows the choices instead of CLI11's TEXT in --help.
void name_option_types(CLI::App* cmd) {
  for (CLI::Option* o : cmd->get_options()) {
    if (o->get_lnames().empty()) continue;
    const std::string n = o->get_lnames().front();
    if (n == "out") o->type_name("FILE");
    else if (n == "values") o->type_name("LIST");
    else if (n == "model") o->type_name("A|B");
    else if (n == "method") o->type_name("analytic|numeric");
    else if (n == "vary") o->type_name("v0|phi|mu");
  }
}

/// Registers `name` bound from its declaration (app/common/option_fields.hpp, cli/declared_options.hpp).
template <class Options, class Run>
void add_declared_command(CLI::App* area, const std::string& name, const std::string& help,
                          const app::Fields<Options>& fields, const app::ResultKeys& keys, Run run,
                          const std::string& footer = "") {
  auto* cmd = area->add_subcommand(name, help);
  cmd->footer(footer);
  auto o = std::make_shared<Options>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *o, fields, keys);
  add_json_flag(*cmd, *as_json);
  name_option_types(cmd);
  cmd->callback([o, as_json, run, cmd] { print_declared(*cmd, run(*o).json, *as_json); });
}

void add_predict(CLI::App* area) {
  add_declared_command(area, "predict", "Closed-form prediction of a launch (model B)", incline_predict_fields(),
                       incline_predict_result_keys(), incline_predict, help::kInclineModels);
}

void add_simulate(CLI::App* area) {
  add_declared_command(area, "simulate", "Trajectory of a launch as CSV (t,x,y,vx,vy,ax,ay)", incline_simulate_fields(),
                       incline_simulate_result_keys(), incline_simulate, help::kInclineModels);
}

void add_render(CLI::App* area) {
  add_declared_command(area, "render", "Film a disc launched across the incline (model B) to a video with its truth",
                       incline_render_fields(), incline_render_result_keys(), incline_render);
}

void add_mu_from_stop(CLI::App* area) {
  add_declared_command(area, "mu-from-stop", "Friction coefficient from the stopping point alone (incline study, equation 10A (十A))",
                       incline_mu_from_stop_fields(), incline_mu_from_stop_result_keys(), incline_mu_from_stop,
                       help::kInclineMuFromStop);
}

void add_families(CLI::App* area) {
  add_declared_command(area, "families", "Closed-form curves for several values of v0, phi or mu (incline study, figures 5-7 (五-七))",
                       incline_families_fields(), incline_families_result_keys(), incline_families);
}

}  // namespace

void register_incline(CLI::App& root) {
  auto* area = root.add_subcommand("incline", "Disc launched across a rough incline (the incline study, Taiwan science fair 2017)");
  area->require_subcommand(1);
  add_predict(area);
  add_simulate(area);
  add_render(area);
  add_mu_from_stop(area);
  add_families(area);
  add_incline_analysis_commands(area);
}

}  // namespace tribolab::cli
