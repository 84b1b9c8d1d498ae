// The checks of a command line before CLI11 parses it (cli/command_line_check.hpp), run over
// every command and option the program registers.
#include "app.hpp"
#include "cli_test_util.hpp"
#include "command_line_check.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

/// Every command that takes options (no subcommands), as its path of names from the root.
void leaves(CLI::App& app, std::vector<std::string> path, std::vector<std::pair<CLI::App*, std::vector<std::string>>>& out) {
  const auto subs = app.get_subcommands({});
  if (subs.empty()) out.emplace_back(&app, path);
  for (CLI::App* s : subs) {
    auto p = path;
    p.push_back(s->get_name());
    leaves(*s, p, out);
  }
}

/// check_command_line on `words` (argv[0] added); the UsageError's message, or "" if none.
std::string usage_error(CLI::App& root, std::vector<std::string> words) {
  words.insert(words.begin(), "tribolab");
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  try {
    check_command_line(root, static_cast<int>(argv.size()), argv.data());
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

// Regression (issue 26): `bounce simulate --mu ''` ran with mu = 0, `--g ''` with g = 0 (and
// drop, synth-video, synth-table, render); `incline synth --out ''` wrote nothing and exited
// 0. The rule is one check for every option of every command, whatever its type.
TEST(EmptyValue, IsRefusedForEveryOptionOfEveryCommand) {
  CLI::App root;
  register_incline(root);
  register_bounce(root);
  register_track(root);
  register_demo(root);
  std::vector<std::pair<CLI::App*, std::vector<std::string>>> commands;
  leaves(root, {}, commands);
  int checked = 0;
  for (auto& [cmd, path] : commands) {
    for (const CLI::Option* opt : cmd->get_options()) {
      if (opt->get_lnames().empty() || opt->get_items_expected_max() == 0) continue;  // flags, positionals
      const std::string flag = "--" + opt->get_lnames().front();
      for (const auto& given : {std::vector<std::string>{flag, ""}, std::vector<std::string>{flag + "=  "}}) {
        auto words = path;
        words.insert(words.end(), given.begin(), given.end());
        EXPECT_EQ(usage_error(root, words), "option '" + flag +
                                                "' is given an empty value; give a value, or leave the option out for its default")
            << words.front() << " " << flag;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);  // every command's options were walked
  EXPECT_EQ(usage_error(root, {"bounce", "simulate", "--mu", "0.3"}), "");  // a value is a value
}

TEST(EmptyValue, ExitsWithStatus2AndWritesNothing) {
  const std::string dir = testing::temp_dir("empty_value");
  for (const std::string& args : std::vector<std::string>{
           "bounce simulate --mu ''", "bounce simulate --g=", "incline synth --mu 0.6 --phi-deg 20 --v0 1 --out ''",
           "track video clip.avi --fps '' --out " + dir + "/t.csv"}) {
    const auto r = testing::run_tribolab(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("is given an empty value"), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace tribolab::cli
