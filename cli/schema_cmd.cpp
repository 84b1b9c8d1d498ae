// `tribolab schema [--json]`: every command with its options as the command line has them
// (CLI11's own list: flag, help, default, required) and, for a command bound from its option
// declaration (cli/declared_options.hpp), the declared fields (type, unit, range, choices,
// group, Python keyword) and result keys with units. A browser form, docs/cli.md's check
// (cli/schema_test.cpp) and the Python parity test (python/tests/test_schema.py) read it.
#include "app.hpp"
#include "command_line_check.hpp"
#include "declared_options.hpp"
#include "text_listing.hpp"

#include <iostream>
#include <memory>

namespace tribolab::cli {
namespace {

using nlohmann::json;

/// A help text on one line: the 80-column wrapping (cli/help_wrap.hpp) undone.
std::string one_line_help(const std::string& text) {
  std::string out;
  bool space = false;
  for (char c : text) {
    if (c == '\n' || c == ' ') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

json options_of(const CLI::App& cmd) {
  json a = json::array();
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt == cmd.get_help_ptr() || opt == cmd.get_help_all_ptr()) continue;
    a.push_back({{"name", opt->get_name()},
                 {"positional", !opt->nonpositional()},
                 {"help", one_line_help(opt->get_description())},
                 {"default", opt->get_default_str()},
                 {"required", opt->get_required()}});
  }
  return a;
}

void collect(const CLI::App& app, const std::string& prefix, json& out) {
  for (const CLI::App* sub : app.get_subcommands({})) {
    const std::string name = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    if (!sub->get_subcommands({}).empty()) {
      collect(*sub, name, out);
      continue;
    }
    json c = {{"command", name}, {"description", one_line_help(sub->get_description())}, {"options", options_of(*sub)}};
    const auto it = declared_commands().find(sub);
    const bool has_fields = it != declared_commands().end() && it->second.fields;
    c["declared"] = has_fields;
    if (it != declared_commands().end() && it->second.results) c["results"] = app::result_keys_schema(*it->second.results);
    if (it != declared_commands().end() && it->second.series_results)
      c["series_results"] = app::result_keys_schema(*it->second.series_results);
    if (has_fields) {
      json fields = it->second.fields();
      for (json& f : fields) {
        const std::string role = f["role"];
        f["flag"] = role == "notebook" ? json(nullptr) : role == "input_files" ? json(f["name"]) : json(flag_of(f["name"].get<std::string>()));
        f["python_keyword"] = f["name"];
      }
      c["fields"] = fields;
    }
    out.push_back(c);
  }
}

std::string text_of(const json& commands) {
  std::string s;
  for (const json& c : commands) {
    s += c["command"].get<std::string>() + "\n";
    for (const json& f : c.value("fields", json::array())) {
      const std::string flag = f["flag"].is_null() ? f["name"].get<std::string>() + " (Python only)" : f["flag"].get<std::string>();
      s += "  " + flag + "  " + f["type"].get<std::string>() +
           (f["unit"].get<std::string>().empty() ? "" : ", " + f["unit"].get<std::string>()) + "  default " +
           (f["default"].is_null() ? std::string("none") : f["default"].dump()) + (f["required"].get<bool>() ? ", required" : "") +
           "  " + f["help"].get<std::string>() + "\n";
    }
    if (!c.contains("results") || c["results"].empty()) continue;  // studio prints no result
    s += "  result keys:";
    for (const json& k : c["results"])
      s += " " + k["key"].get<std::string>() + (k["unit"].get<std::string>().empty() ? "" : " (" + k["unit"].get<std::string>() + ")");
    s += "\n";
    if (!c.contains("series_results")) continue;
    s += "  summary keys of several files:";
    for (const json& k : c["series_results"])
      s += " " + k["key"].get<std::string>() + (k["unit"].get<std::string>().empty() ? "" : " (" + k["unit"].get<std::string>() + ")");
    s += "\n";
  }
  return s;
}

/// `schema` has no option of its own but --json: an empty declaration, so that it is listed as
/// declared like every other command, and its one result key.
struct SchemaOptions {};

const app::Fields<SchemaOptions>& schema_fields() {
  static const app::Fields<SchemaOptions> f;
  return f;
}

const app::ResultKeys& schema_result_keys() {
  static const app::ResultKeys k = {
      {"commands.*", "", "each command: its options, declared fields with types, units, defaults and ranges, result keys"},
  };
  return k;
}

}  // namespace

void register_schema(CLI::App& root) {
  auto json_out = std::make_shared<bool>(false);
  auto* cmd = root.add_subcommand("schema", "Every command's options and result keys, with types, units, defaults and ranges "
                                            "(for forms and documentation)");
  static SchemaOptions none;
  add_declared_options(*cmd, none, schema_fields(), schema_result_keys());
  add_json_flag(*cmd, *json_out);
  cmd->callback([json_out, &root] {
    json commands = json::array();
    collect(root, "", commands);
    if (*json_out) {
      std::cout << json{{"commands", commands}}.dump() << '\n';
    } else {
      std::cout << text_of(commands);
    }
  });
}

}  // namespace tribolab::cli
