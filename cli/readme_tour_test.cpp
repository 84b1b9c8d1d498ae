// The README's tour, run exactly as printed: every `tribolab ...` command of its "A short
// tour" section, in order, in a fresh folder where `demo-out/data` holds the demo's data files
// (as `make demo` leaves them). A newcomer copies these lines first; each must work.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

/// The commands of the tour: indented lines starting with `tribolab `, joined over trailing
/// backslashes, in README order.
std::vector<std::string> tour_commands() {
  std::istringstream in(slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/README.md"));
  std::vector<std::string> commands;
  std::string line;
  bool in_tour = false;
  std::string pending;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_tour = line == "## A short tour";
    if (!in_tour) continue;
    if (!pending.empty()) {
      pending += "\n" + line;
    } else if (line.rfind("    tribolab ", 0) == 0) {
      pending = line;
    } else {
      continue;
    }
    // A continuation ends in a backslash before any comment.
    std::string last = line;
    if (const auto hash = last.find(" #"); hash != std::string::npos) last = last.substr(0, hash);
    while (!last.empty() && last.back() == ' ') last.pop_back();
    if (!last.empty() && last.back() == '\\') continue;
    commands.push_back(pending);
    pending.clear();
  }
  return commands;
}

TEST(ReadmeTour, EveryCommandRunsAsPrinted) {
  namespace fs = std::filesystem;
  const std::vector<std::string> commands = tour_commands();
  ASSERT_GE(commands.size(), 20u) << "the tour's commands were not found in README.md";
  const std::string dir = (fs::temp_directory_path() / ("tribolab_tour_" + std::to_string(::getpid()))).string();
  fs::remove_all(dir);
  fs::create_directories(dir + "/demo-out");
  fs::create_directory_symlink(std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo", dir + "/demo-out/data");
  const std::string bin_dir = fs::path(TRIBOLAB_BINARY).parent_path().string();
  for (const std::string& command : commands) {
    // The README's text verbatim, with comments, through the shell as a user pastes it.
    const std::string script = dir + "/cmd.sh";
    std::ofstream(script) << "cd '" << dir << "' && PATH='" << bin_dir << "':\"$PATH\"\n" << command << "\n";
    const int status = std::system(("sh '" + script + "' > '" + dir + "/out.txt' 2> '" + dir + "/err.txt'").c_str());
    EXPECT_EQ(status, 0) << command << "\n" << slurp(dir + "/err.txt");
  }
  // Each report the tour names is written once (the tour once wrote fit.html twice).
  std::vector<std::string> reports;
  for (const std::string& c : commands) {
    for (auto at = c.find("--report "); at != std::string::npos; at = c.find("--report ", at + 1)) {
      const std::string name = c.substr(at + 9, c.find_first_of(" \n", at + 9) - at - 9);
      EXPECT_EQ(std::count(reports.begin(), reports.end(), name), 0) << name << " written twice by the tour";
      reports.push_back(name);
      EXPECT_TRUE(fs::exists(dir + "/" + name)) << name;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli::testing
