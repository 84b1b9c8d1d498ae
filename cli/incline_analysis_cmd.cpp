// The commands on tracked incline runs (the incline study; docs/cli.md#incline-analyze): synth,
// mu-from-slide, analyze, normal-friction-test. Each binds its options to the application
// layer's struct (src/app/incline/incline_analysis.hpp, incline_analyze.hpp), calls the workflow and
// prints its JSON (a series: its table, then a non-zero exit if a run failed).
#include "incline_analysis_cmd.hpp"
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"

#include "app.hpp"
#include "help_explain.hpp"
#include "incline_options.hpp"
#include "app/incline/incline_analysis.hpp"
#include "app/incline/incline_analyze.hpp"
#include "report_option.hpp"
#include "series_cmd.hpp"

#include <memory>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

void set_types(CLI::App* cmd) {
  for (CLI::Option* o : cmd->get_options()) {
    if (o->get_lnames().empty()) {
      if (o->get_positional()) o->type_name("FILE");
      continue;
    }
    const std::string n = o->get_lnames().front();
    if (n == "help" || n == "json" || n == "no-model-a" || n == "report" || n == "plotly") continue;
    if (n == "out" || n == "table") o->type_name("FILE");
    else if (n == "track" || n == "track-name") o->type_name("NAME");
    else if (n == "length-unit") o->type_name("UNIT");
    else if (n == "format") o->type_name("export|csv");
    else o->type_name("NUM");
  }
}

// ---- synth ---------------------------------------------------------------------------

void add_synth(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "synth", "Synthetic tracked run from the simulators, with noise (test and demo data)");
  auto s = std::make_shared<InclineSynthOptions>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *s, incline_synth_fields(), incline_synth_result_keys());
  add_json_flag(*cmd, *as_json);
  set_types(cmd);
  cmd->callback([s, as_json, cmd] { print_declared(*cmd, incline_synth(*s).json, *as_json); });
}

// ---- mu-from-slide -------------------------------------------------------------------

/// A series' progress line on stderr when it is a terminal (cli_series_options).
InclineSeriesControl series_control() {
  InclineSeriesControl c;
  c.progress = cli_series_options().progress;
  return c;
}

/// Prints one file's object, or a series' table and summary; a failed run of a series then
/// makes the exit non-zero (finish_series).
void print_runs(const nlohmann::json& j, const std::vector<std::string>& errors, std::size_t n_files,
                bool as_json, const std::vector<std::string>& columns, const app::ResultKeys& keys,
                const app::ResultKeys& series_keys) {
  if (n_files == 1) return print_result(j, as_json, keys);
  print_series(j["runs"], j["summary"], as_json, columns, keys, series_keys);
  finish_series(n_files, errors);
}

void add_mu_from_slide(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "mu-from-slide", "Friction coefficient from a straight slide down the incline (incline study, equation a)");
  cmd->footer(help::kInclineMuFromSlide);
  auto s = std::make_shared<InclineMuFromSlideOptions>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *s, incline_mu_from_slide_fields(), incline_mu_from_slide_result_keys());
  add_json_flag(*cmd, *as_json);
  set_types(cmd);
  declare_series_results(*cmd, incline_mu_from_slide_series_result_keys());
  cmd->callback([s, as_json] {
    s->series = series_control();
    const InclineMuFromSlideResult r = incline_mu_from_slide(*s);
    print_runs(r.json, r.errors, s->files.size(), *as_json, {"phi_deg", "a", "sigma_a", "mu", "sigma_mu", "r_squared"},
               incline_mu_from_slide_result_keys(), incline_mu_from_slide_series_result_keys());
  });
}

// ---- analyze -------------------------------------------------------------------------

void add_analyze(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "analyze", "Fit models B and A to a tracked 2D run; test for a normal friction component");
  cmd->footer(std::string(help::kInclineModels) + help::kInclineAnalyze);
  auto s = std::make_shared<InclineAnalyzeOptions>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *s, incline_analyze_fields(), incline_analyze_result_keys());
  add_json_flag(*cmd, *as_json);
  set_types(cmd);
  cmd->get_option("--phi-deg")->type_name("NUM[,NUM...]");
  cmd->get_option("--frame-rotation")->type_name("fit|none");
  declare_series_results(*cmd, incline_analyze_series_result_keys());
  cmd->callback([s, as_json] {
    s->series = series_control();
    const InclineAnalyzeResult r = incline_analyze(*s);
    print_runs(r.json, r.errors, s->files.size(), *as_json,
               {"phi_deg", "mu", "sigma_mu", "v0", "rms_residual", "/normal_friction/verdict"}, incline_analyze_result_keys(),
               incline_analyze_series_result_keys());
  });
}

// ---- normal-friction-test ------------------------------------------------------------

void add_normal_friction_test(CLI::App* area) {
  auto* cmd = area->add_subcommand(
      "normal-friction-test",
      "cos(theta_c) against tan(phi) over runs at several angles (incline study, equation c): slope 1/mu");
  cmd->footer(std::string(help::kInclineModels) + help::kInclineNormalFrictionTest);
  auto s = std::make_shared<InclineNormalFrictionTestOptions>();
  auto as_json = std::make_shared<bool>(false);
  add_declared_options(*cmd, *s, incline_normal_friction_test_fields(), incline_normal_friction_test_result_keys());
  add_json_flag(*cmd, *as_json);
  set_types(cmd);
  cmd->get_option("--phi-deg")->type_name("NUM[,NUM...]");
  cmd->callback([s, as_json] {
    const InclineNormalFrictionTestResult r = incline_normal_friction_test(*s);
    print_result(r.json, *as_json, incline_normal_friction_test_result_keys());
    finish_series(s->files.size(), r.errors);  // exit 1 after the output when a run failed
  });
}

}  // namespace

void add_incline_analysis_commands(CLI::App* incline) {
  add_synth(incline);
  add_mu_from_slide(incline);
  add_analyze(incline);
  add_normal_friction_test(incline);
}

}  // namespace tribolab::cli
