#include "declared_options.hpp"

#include "text_listing.hpp"

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

void print_declared(const CLI::App& cmd, const nlohmann::json& result, bool as_json) {
  const auto it = declared_commands().find(&cmd);
  if (it == declared_commands().end() || !it->second.results) throw std::logic_error("print_declared: command not declared");
  print_result(result, as_json, *it->second.results);
}

}  // namespace tribolab::cli
