#include "app.hpp"

#include "numerics/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <new>

namespace tribolab::cli {
namespace {

void flatten(const nlohmann::json& j, const std::string& prefix,
             std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
    return;
  }
  std::string value;
  if (j.is_number_float()) {
    value = fmt::format("{:.6g}", j.get<double>());
  } else if (j.is_string()) {
    value = j.get<std::string>();
  } else if (j.is_null()) {
    value = "-";
  } else {
    value = j.dump();
  }
  out.emplace_back(prefix, value);
}

/// One line, whatever the message holds: newlines would break "one clear line".
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

/// CLI11 reports "a subcommand is required" for `tribolab frobnicate`; name the culprit.
void check_command_names(CLI::App& app, int argc, char** argv) {
  CLI::App* level = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.empty() || arg[0] == '-') return;
    if (level->get_subcommands({}).empty()) return;
    CLI::App* sub = nullptr;
    for (CLI::App* s : level->get_subcommands({})) {
      if (s->check_name(arg)) sub = s;
    }
    if (sub == nullptr) {
      throw InputError("unknown command '" + arg + "' for '" + level->get_display_name(true) +
                       "' (see --help)");
    }
    level = sub;
  }
}

}  // namespace

void print_result(const nlohmann::json& result, bool as_json) {
  if (as_json) {
    std::cout << result.dump() << '\n';
    return;
  }
  std::vector<std::pair<std::string, std::string>> rows;
  flatten(result, "", rows);
  std::size_t width = 0;
  for (const auto& r : rows) width = std::max(width, r.first.size());
  for (const auto& [k, v] : rows) std::cout << fmt::format("{:<{}}  {}\n", k, width, v);
}

void add_json_flag(CLI::App& cmd, bool& flag) {
  cmd.add_flag("--json", flag, "Print the result as one JSON object on stdout");
}

int run(int argc, char** argv) {
  CLI::App app{
      "tribolab: friction and impact experiments - simulate, predict, fit, analyse tracked video.\n"
      "SI units throughout; angles in degrees where an option says _deg/-deg.",
      "tribolab"};
  app.set_version_flag("--version", "tribolab 0.1.0");
  app.require_subcommand(1);
  register_incline(app);
  register_bounce(app);
  register_track(app);
  register_demo(app);
  try {
    check_command_names(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tribolab: error: " << one_line(e.what()) << " (see --help)\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "tribolab: error: " << one_line(e.what()) << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "tribolab: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "tribolab: error: " << one_line(e.what()) << '\n';
    return 1;
  }
  return 0;
}

}  // namespace tribolab::cli
