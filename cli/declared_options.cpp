#include "declared_options.hpp"

#include "text_listing.hpp"

#include "app/sweep/sweep_text.hpp"

#include <fmt/format.h>

#include <cctype>

namespace tribolab::cli {

std::map<const CLI::App*, DeclaredCommand>& declared_commands() {
  static std::map<const CLI::App*, DeclaredCommand> commands;
  return commands;
}

void declare_results(const CLI::App& cmd, const app::ResultKeys& keys) { declared_commands()[&cmd].results = &keys; }

void declare_series_results(const CLI::App& cmd, const app::ResultKeys& keys) {
  declared_commands()[&cmd].series_results = &keys;
}

std::string declared_help(const app::FieldDecl& f) {
  std::string h = f.help;
  if (!f.choices.empty()) {
    h += ": ";
    for (std::size_t i = 0; i < f.choices.size(); ++i) h += (i ? "|" : "") + f.choices[i];
  }
  if (!f.unit.empty()) h += ", " + f.unit;
  return h;
}

std::string flags_for_field_names(std::string help, const std::vector<std::string>& names) {
  const auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  for (const std::string& name : names) {
    if (name.find('_') == std::string::npos) continue;
    const std::string flag = flag_of(name);
    for (std::size_t at = help.find(name); at != std::string::npos; at = help.find(name, at)) {
      const std::size_t end = at + name.size();
      // a column of a CSV header ("columns phi_deg,cos_theta_c") is no flag: a comma without a space
      const bool in_header = (at > 0 && help[at - 1] == ',') ||
                             (end + 1 < help.size() && help[end] == ',' && !std::isspace(static_cast<unsigned char>(help[end + 1])));
      if (in_header || (at > 0 && word_char(help[at - 1])) || (end < help.size() && word_char(help[end]))) {
        at = end;
        continue;
      }
      help.replace(at, name.size(), flag);
      at += flag.size();
    }
  }
  return help;
}

namespace {

/// The quantity a declared range field is (its name: theta_deg, omega, ratio, speed, mu).
sweep::Quantity quantity_of_field(const std::string& field_name) {
  const auto q = sweep::quantity_from_name(field_name);
  if (!q) throw std::logic_error("declared range field is no sweep quantity: " + field_name);
  return *q;
}

/// "--t-from" of "--t-from,--from": the flag a message names.
std::string first_flag(const std::string& name) { return name.substr(0, name.find(',')); }

}  // namespace

CLI::Option* add_range_option(CLI::App& cmd, const std::string& name, const std::string& field_name,
                              std::optional<sweep::Axis>& to, const std::string& help) {
  const sweep::Quantity q = quantity_of_field(field_name);
  const std::string flag = first_flag(name);
  CLI::Option* opt = cmd.add_option_function<std::string>(
      name, [&to, q, flag](const std::string& text) { to = app::parse_axis(text, q, flag); }, help);
  opt->type_name("LO:HI:N");
  return opt;
}

CLI::Option* add_range_option(CLI::App& cmd, const std::string& name, const std::string& field_name,
                              sweep::ValueOrAxis& to, const std::string& help) {
  const sweep::Quantity q = quantity_of_field(field_name);
  const std::string flag = first_flag(name);
  CLI::Option* opt = cmd.add_option_function<std::string>(
      name,
      [&to, q, flag](const std::string& text) {
        // A range keeps the default value as the grid's fixed value (recorded in the file header).
        const sweep::ValueOrAxis v = app::parse_value_or_axis(text, q, flag);
        if (v.axis) to.axis = v.axis;
        else to.value = v.value;
      },
      help);
  opt->type_name("LO:HI:N");
  opt->default_str(fmt::format("{}", to.value));  // the help shows the default
  return opt;
}

CLI::Option* add_shard_option(CLI::App& cmd, const std::string& name, sweep::Shard& to, const std::string& help) {
  const std::string flag = first_flag(name);
  CLI::Option* opt = cmd.add_option_function<std::string>(
      name, [&to, flag](const std::string& text) { to = app::parse_shard(text, flag); }, help);
  opt->type_name("I/N");
  return opt;
}

void print_declared(const CLI::App& cmd, const nlohmann::json& result, bool as_json) {
  const auto it = declared_commands().find(&cmd);
  if (it == declared_commands().end() || !it->second.results) throw std::logic_error("print_declared: command not declared");
  print_result(result, as_json, *it->second.results);
}

}  // namespace tribolab::cli
