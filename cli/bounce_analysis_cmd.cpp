// `tribolab bounce analyze|fit|synth-video|synth-table`: the rugby-ball study's experiment 1 on tracked
// data, the contact-law fit to a table of bounces, and the synthetic data for both
// (docs/cli.md#bounce-analyze). The workflows are in src/app/bounce/bounce_analyze.*,
// src/app/bounce/bounce_series.* (several files) and src/app/bounce/bounce_synth.*; this file binds their
// options to flags and prints the results.
#include "bounce_analysis_cmd.hpp"
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"

#include "app.hpp"
#include "help_explain.hpp"
#include "series_cmd.hpp"

#include "app/bounce/bounce_analyze.hpp"
#include "app/bounce/bounce_series.hpp"
#include "app/bounce/bounce_synth.hpp"

#include "io/text.hpp"

#include <memory>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using nlohmann::json;

/// The summary for people: the bins and outliers as dotted keys, the per-run points left out
/// (they are the table above it).
json summary_for_text(json summary) {
  json bins = json::object();
  for (const auto& b : summary["bins"])
    bins[io::format_number(b["low_deg"].get<double>()) + "-" + io::format_number(b["high_deg"].get<double>())] = b;
  summary["bins"] = bins;
  json outliers = json::object();
  for (const auto& o : summary["outliers"]) outliers[o["file"].get<std::string>()] = o["reason"];
  summary["outliers"] = outliers;
  summary.erase("points");
  // A mean of runs that are not one value (e at different collision angles) is no headline:
  // the listing shows e_velocity_headline (the relation with the angle) instead.
  for (const char* key : {"e_velocity", "e_height"})
    if (!summary.value(std::string(key) + "_one_value", true)) summary.erase(key);
  return summary;
}

void add_analyze(CLI::App* area) {
  struct Opts {
    BounceAnalyzeSeriesOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& s = opts->o;
  auto* cmd = area->add_subcommand("analyze", "The rugby-ball study's experiment 1: v, omega, e and energies before/after one bounce from the two tracked tips");
  cmd->footer(help::kBounceAnalyze);
  add_declared_options(*cmd, s, bounce_analyze_series_fields(), bounce_analyze_result_keys());
  add_json_flag(*cmd, opts->json);
  declare_series_results(*cmd, bounce_analyze_series_result_keys());
  cmd->callback([opts] {
    opts->o.series = cli_series_options();
    const BounceAnalyzeSeriesResult r = bounce_analyze_series(opts->o);
    if (opts->o.files.size() == 1) return print_result(r.json, opts->json, bounce_analyze_result_keys());
    print_series(r.json["runs"], opts->json ? r.json["summary"] : summary_for_text(r.json["summary"]), opts->json,
                 {"collision_angle_deg", "e_velocity", "sigma_e_velocity", "e_height", "energy_pre", "energy_post",
                  "mean_normal_force"},
                 bounce_analyze_result_keys(), bounce_analyze_series_result_keys());
    finish_series(opts->o.files.size(), r.errors);
  });
}

void add_fit(CLI::App* area) {
  struct Opts {
    BounceFitOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& o = opts->o;
  auto* cmd = area->add_subcommand("fit", "fit the contact law (K, n, D or e, mu) to a table of measured bounces");
  cmd->footer(help::kBounceFit);
  add_declared_options(*cmd, o, bounce_fit_fields(), bounce_fit_result_keys());
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts] {
    json j = bounce_fit(opts->o).json;
    if (!opts->json) j.erase("residuals");  // the people's listing leaves the per-row table out
    print_result(j, opts->json, bounce_fit_result_keys());
  });
}

void add_synth_video(CLI::App* area) {
  struct Opts {
    BounceSynthVideoOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& o = opts->o;
  auto* cmd = area->add_subcommand("synth-video", "write a synthetic Tracker export of one bounce (tips A and B) with known truth");
  add_declared_options(*cmd, o, bounce_synth_video_fields(), bounce_synth_video_result_keys());
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts, cmd] { print_declared(*cmd, bounce_synth_video(opts->o).json, opts->json); });
}

void add_synth_table(CLI::App* area) {
  struct Opts {
    BounceSynthTableOptions o;
    bool json = false;
  };
  auto opts = std::make_shared<Opts>();
  auto& o = opts->o;
  auto* cmd = area->add_subcommand("synth-table", "write a synthetic bounce table for `bounce fit` with known truth");
  add_declared_options(*cmd, o, bounce_synth_table_fields(), bounce_synth_table_result_keys());
  add_json_flag(*cmd, opts->json);
  cmd->callback([opts, cmd] { print_declared(*cmd, bounce_synth_table(opts->o).json, opts->json); });
}

}  // namespace

void register_bounce_analysis(CLI::App* area) {
  add_analyze(area);
  add_fit(area);
  add_synth_video(area);
  add_synth_table(area);
}

}  // namespace tribolab::cli
