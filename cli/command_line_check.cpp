#include "command_line_check.hpp"

#include "app.hpp"
#include "app/common/output_paths.hpp"
#include "numerics/error.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <filesystem>

namespace tribolab::cli {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  // Damerau–Levenshtein (optimal string alignment): a swapped pair of letters is one slip.
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end != nullptr && *end == '\0';
}

std::vector<std::string> long_option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
  }
  return names;
}

std::vector<std::string> subcommand_names(CLI::App& app) {
  std::vector<std::string> names;
  for (CLI::App* s : app.get_subcommands({})) names.push_back(s->get_name());
  return names;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = nearest_name(word, candidates);
  return near.empty() ? std::string() : "; did you mean '" + near + "'?";
}

/// Two outputs into one file (or an output over an input) would leave one of them holding
/// the other's tail after an error, against "no partial output": refuse them up front, as
/// the application layer does (app/common/output_paths.hpp), as a malformed command line.
void check_distinct_files(const std::vector<app::OutputPath>& files) {
  if (auto e = app::same_file_problem(files); !e.empty()) throw UsageError(spell_fields(e, flag_of));
}

}  // namespace

std::string empty_value_problem(const std::string& flag, const std::string& value) {
  if (value.find_first_not_of(" \t\n\r\v\f") != std::string::npos) return {};
  return "option '" + flag + "' is given an empty value; give a value, or leave the option out for its default";
}

std::string full_name(const CLI::App& app) {
  std::string name = app.get_name();
  for (const CLI::App* p = app.get_parent(); p != nullptr; p = p->get_parent()) {
    name = p->get_name() + " " + name;
  }
  return name;
}

std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  int prefix_matches = 0;
  std::string prefix_of;
  for (const std::string& c : candidates) {
    if (c.size() > word.size() && c.compare(0, word.size(), word) == 0) {
      ++prefix_matches;
      prefix_of = c;
    }
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // A slip is at most two edits, and fewer than a third of the word for short words
  // ("--vo" -> "--v0" is one edit of four letters).
  const std::size_t allowed = std::min<std::size_t>(2, std::max<std::size_t>(1, word.size() / 3));
  if (best_d <= allowed) return best;
  if (prefix_matches == 1 && word.size() >= 4) return prefix_of;
  return {};
}

CLI::App* check_command_line(CLI::App& root, int argc, char** argv) {
  CLI::App* level = &root;
  bool option_given = false;  // at the current level
  std::vector<app::OutputPath> files;  // file-valued options (by field) and positional inputs ("")
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
      option_given = true;
      const std::string name = arg.substr(0, arg.find('='));
      const CLI::Option* opt = level->get_option_no_throw(name);
      if (opt == nullptr) {
        throw UsageError("unknown option '" + name + "' for '" + full_name(*level) + "'" +
                         suggestion(name, long_option_names(*level)) + " (see " +
                         full_name(*level) + " --help)");
      }
      // Skip the option's value when it is the next argument.
      std::string value;
      bool has_value = false;
      if (const auto eq = arg.find('='); eq != std::string::npos) {
        value = arg.substr(eq + 1);
        has_value = true;
      } else if (opt->get_items_expected_max() > 0 && i + 1 < argc) {
        value = argv[++i];
        has_value = true;
      }
      if (has_value) {
        if (auto e = empty_value_problem(name, value); !e.empty()) throw UsageError(e);
      }
      if (opt->get_type_name().rfind("FILE", 0) == 0 && !value.empty()) {
        files.push_back({name.substr(2), value});  // "--bounces-out" -> "bounces-out" (flag_of spells it back)
      }
      continue;
    }
    if (arg.size() > 1 && arg[0] == '-' && !is_number(arg)) {
      option_given = true;  // a short option such as -h
      continue;
    }
    // A positional argument: a subcommand name where the level has subcommands.
    if (level->get_subcommands({}).empty()) {
      files.push_back({"", arg});
      continue;
    }
    CLI::App* sub = nullptr;
    for (CLI::App* s : level->get_subcommands({})) {
      if (s->check_name(arg)) sub = s;
    }
    if (sub == nullptr) {
      throw UsageError("unknown command '" + arg + "' for '" + full_name(*level) + "'" +
                       suggestion(arg, subcommand_names(*level)) + " (see " + full_name(*level) +
                       " --help)");
    }
    level = sub;
    option_given = false;
  }
  check_distinct_files(files);
  if (!option_given && !level->get_subcommands({}).empty()) return level;
  return nullptr;
}

}  // namespace tribolab::cli
