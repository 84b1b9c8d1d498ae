// The command line's spelling of the option declarations (src/app/common/option_fields.hpp): one
// CLI11 option per declared field, so a command binds its options in one line,
//
//   add_declared_options(*cmd, o, bounce_simulate_fields(), bounce_simulate_result_keys());
//
// and prints with print_declared(*cmd, result.json, as_json). Flags are "--" + the field's name
// with dashes (flag_of), the help is "<help>[: a|b|c], <unit>", the default the member
// initializer (the help shows it), numbers read by add_number (cli/incline_options.hpp: one
// line naming the option for a malformed or empty number), `report`/`plotly` by
// add_report_option, a sweep's ranges and shards by add_range_option / add_shard_option
// (LO:HI:N, a number or LO:HI:N, I/N), fields for a notebook (FieldRole::notebook) left out. Each bound command
// is recorded for `tribolab schema` (cli/schema_cmd.cpp) with its fields and result keys.
#pragma once

#include "app.hpp"
#include "incline_options.hpp"
#include "report_option.hpp"

#include "app/common/option_fields.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <stdexcept>
#include <variant>
#include <string>
#include <type_traits>
#include <vector>

namespace tribolab::cli {

/// What `tribolab schema` knows of a command bound from its declaration.
struct DeclaredCommand {
  std::function<nlohmann::json()> fields;  ///< fields_schema of its options struct; empty: not declared
  const app::ResultKeys* results = nullptr;
  const app::ResultKeys* series_results = nullptr;  ///< the summary of several files, if it takes them
};

/// The commands bound by add_declared_options, by their CLI11 app.
std::map<const CLI::App*, DeclaredCommand>& declared_commands();

/// Records `keys` as the declared result keys of `cmd` (for a command whose options are not
/// declared yet; add_declared_options records both).
void declare_results(const CLI::App& cmd, const app::ResultKeys& keys);

/// Records `keys` as the declared keys of `cmd`'s summary of several files (print_series).
void declare_series_results(const CLI::App& cmd, const app::ResultKeys& keys);

/// "<help>[: a|b|c], <unit>": the help line of a declared field.
std::string declared_help(const app::FieldDecl& f);

/// `help` with every whole-word mention of one of `names` (the command's other fields, where a
/// declaration's help says "unset: from the flights and contact_duration") spelled as its flag
/// (--contact-duration). Only names with an underscore: a one-word name ("mass") is prose too;
/// a name in a CSV header (touching a comma without a space: "phi_deg,cos_theta_c") stays.
std::string flags_for_field_names(std::string help, const std::vector<std::string>& names);

/// Prints a declared command's result as print_result does, the listing's units from the
/// command's declared result keys.
void print_declared(const CLI::App& cmd, const nlohmann::json& result, bool as_json);

/// A sweep's range LO:HI:COUNT (`std::optional<sweep::Axis>`), or a number or a range
/// (`sweep::ValueOrAxis`), of the quantity named `field_name` (theta_deg, omega, ratio, speed,
/// mu), read by app::parse_axis / parse_value_or_axis as the option is parsed: a malformed
/// range is one line naming the option. A number-or-range shows its default number.
CLI::Option* add_range_option(CLI::App& cmd, const std::string& name, const std::string& field_name,
                              std::optional<sweep::Axis>& to, const std::string& help);
CLI::Option* add_range_option(CLI::App& cmd, const std::string& name, const std::string& field_name,
                              sweep::ValueOrAxis& to, const std::string& help);
/// A shard i/N (app::parse_shard).
CLI::Option* add_shard_option(CLI::App& cmd, const std::string& name, sweep::Shard& to, const std::string& help);

/// Adds one CLI11 option per declared field of `fields`, bound to `o` (which must outlive the
/// parse: the command's shared options), and records the command for the schema.
template <class O>
void add_declared_options(CLI::App& cmd, O& o, const app::Fields<O>& fields, const app::ResultKeys& results) {
  using app::FieldRole;
  std::vector<std::string> names;
  for (const app::Field<O>& f : fields) names.push_back(f.name);
  for (const app::Field<O>& f : fields) {
    if (f.role == FieldRole::notebook || f.role == FieldRole::plotly) continue;
    const std::string help = flags_for_field_names(declared_help(f), names);
    if (f.role == FieldRole::report) {
      const app::Field<O>* plotly = fields.find("plotly");
      const app::FieldRef path_ref = f.ref(o);
      const app::FieldRef mode_ref = plotly ? plotly->ref(o) : app::FieldRef{};
      auto* path = std::get_if<std::string*>(&path_ref);
      auto* mode = std::get_if<report::PlotlyMode*>(&mode_ref);
      if (!plotly || !mode || !path) throw std::logic_error("declared report without a plotly field: " + f.name);
      add_report_option(cmd, **path, **mode);
      continue;
    }
    std::string name = f.role == FieldRole::input_files ? f.name : flag_of(f.name);
    if (!f.cli_alias.empty()) name += "," + f.cli_alias;  // CLI11: the first long name is the option's name
    CLI::Option* opt = std::visit(
        [&](auto* p) -> CLI::Option* {
          using T = std::remove_cvref_t<decltype(*p)>;
          if constexpr (std::is_same_v<T, bool>) {
            return cmd.add_flag(name, *p, help);
          } else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::optional<std::string>> ||
                               std::is_same_v<T, std::vector<std::string>>) {
            return cmd.add_option(name, *p, help);
          } else if constexpr (std::is_same_v<T, report::PlotlyMode>) {
            throw std::logic_error("plotly outside a report pair: " + f.name);
          } else if constexpr (std::is_same_v<T, std::optional<sweep::Axis>> || std::is_same_v<T, sweep::ValueOrAxis>) {
            return add_range_option(cmd, name, f.name, *p, help);
          } else if constexpr (std::is_same_v<T, sweep::Shard>) {
            return add_shard_option(cmd, name, *p, help);
          } else {
            return add_number(cmd, name, *p, help);
          }
        },
        f.ref(o));
    if (f.required) opt->required();
  }
  declared_commands()[&cmd] = {[&fields] { return app::fields_schema(fields); }, &results};
}

}  // namespace tribolab::cli
