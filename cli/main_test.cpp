// Golden tests of the program's shared behaviour: help, unknown commands and options.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace tribolab::cli::testing {
namespace {

TEST(Cli, HelpListsTheAreas) {
  const auto r = run_tribolab("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* area : {"incline", "bounce", "track", "demo"}) {
    EXPECT_NE(r.out.find(area), std::string::npos) << area << " missing from:\n" << r.out;
  }
}

TEST(Cli, UnknownCommandIsOneErrorLine) {
  const auto r = run_tribolab("frobnicate");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("frobnicate"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(Cli, NoArgumentsPrintsTheHelp) {
  // A newcomer typing `tribolab` or `tribolab incline` wants to see what exists.
  for (const char* args : {"", "incline", "bounce", "track"}) {
    const auto r = run_tribolab(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find("Subcommands:"), std::string::npos) << args << ":\n" << r.out;
    EXPECT_NE(r.out.find("Usage: tribolab"), std::string::npos) << args << ":\n" << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
  }
}

TEST(Cli, UnknownCommandIsAMalformedCommandLineWithASuggestion) {
  const auto r = run_tribolab("incline simulat --mu 0.3");
  EXPECT_EQ(r.exit_code, 2);  // docs/cli.md#errors: 2 = malformed command line
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("unknown command 'simulat' for 'tribolab incline'; did you mean 'simulate'?"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(run_tribolab("frobnicate").exit_code, 2);
}

TEST(Cli, UnknownOptionNamesTheNearestOneBeforeAnyRequirement) {
  // `--vo` used to answer "--v0 is required"; `--mu-statc` listed the arguments backwards.
  const auto vo = run_tribolab("incline simulate --mu 0.3 --phi-deg 20 --vo 2.62 --out x.csv");
  EXPECT_EQ(vo.exit_code, 2);
  EXPECT_EQ(count_lines(vo.err), 1) << vo.err;
  EXPECT_NE(vo.err.find("unknown option '--vo' for 'tribolab incline simulate'; did you mean '--v0'?"),
            std::string::npos)
      << vo.err;
  const auto statc = run_tribolab("incline simulate --mu-statc=0.4");
  EXPECT_NE(statc.err.find("did you mean '--mu-static'?"), std::string::npos) << statc.err;
  // Far from every option: no guess, still one line.
  const auto far = run_tribolab("bounce simulate --zzzzzzzz 1");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_NE(far.err.find("unknown option '--zzzzzzzz'"), std::string::npos) << far.err;
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(Cli, OptionValuesThatLookLikeWordsAreNotMistakenForCommands) {
  // The pre-check must skip option values (negative numbers, words) as CLI11 does.
  const auto r = run_tribolab("bounce drop --height 1 --omega -20 --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

/// The help of every command of every area, concatenated.
std::string every_help() {
  std::string all;
  for (const char* area : {"incline", "bounce", "track"}) {
    const auto a = run_tribolab(std::string(area) + " --help");
    const std::string& out = a.out;
    const auto start = out.find("Subcommands:");
    EXPECT_NE(start, std::string::npos) << out;
    if (start == std::string::npos) continue;
    std::istringstream lines(out.substr(start));
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
      if (line.size() < 3 || line[2] == ' ') continue;  // a wrapped description's next line
      std::istringstream words(line);
      std::string name;
      if (!(words >> name)) continue;
      all += run_tribolab(std::string(area) + " " + name + " --help").out;
    }
  }
  return all;
}

TEST(Cli, EveryDefaultIsShownFromItsOptionStructNeverWrittenByHand) {
  const std::string all = every_help();
  ASSERT_GT(all.size(), 5000u);  // every command's help was collected
  std::istringstream lines(all);
  std::string line;
  int shown = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name, value;
    if (!(words >> name >> value) || name.rfind("--", 0) != 0) continue;
    // "--g NUM=9.8": the default CLI11 captured from the bound field of the option struct.
    if (value.find('=') != std::string::npos && value != "NAME=VALUE") {
      ++shown;
      EXPECT_EQ(line.find("default"), std::string::npos) << "a default written by hand beside the shown one: " << line;
    }
    // Nowhere a number typed into a help text as "(default 0.5)".
    static const std::regex typed(R"(\(default [-+]?[0-9.])");
    EXPECT_FALSE(std::regex_search(line, typed)) << line;
  }
  EXPECT_GT(shown, 100);  // the defaults are shown (the ball, the law, g, tolerances...)
}

TEST(Cli, EveryHelpUsesOnePlaceholderVocabulary) {
  const auto root = run_tribolab("--help");
  const std::string all = every_help();
  ASSERT_GT(all.size(), 5000u);  // every command's help was collected
  // Each option's placeholder says what the value is.
  const auto placeholder = [&](const std::string& help, const std::string& option) {
    std::istringstream lines(help);
    std::string line;
    while (std::getline(lines, line)) {
      std::istringstream words(line);
      std::string name, value;
      if (words >> name >> value && name == option) return value;
    }
    return std::string("(absent)");
  };
  const std::string analyze = run_tribolab("bounce analyze --help").out;
  EXPECT_EQ(placeholder(analyze, "--length-unit"), "UNIT");
  EXPECT_EQ(placeholder(analyze, "--floor-y"), "NUM[,NUM...]");
  EXPECT_EQ(placeholder(analyze, "--track-a"), "NAME");
  EXPECT_EQ(placeholder(analyze, "--report"), "FILE.html");
  const std::string sim = run_tribolab("bounce simulate --help").out;
  EXPECT_EQ(placeholder(sim, "--history"), "FILE");
  EXPECT_EQ(placeholder(sim, "--vy"), "NUM");
  EXPECT_EQ(placeholder(sim, "--friction"), "coulomb|regularized|spring=coulomb");  // with its default
  EXPECT_EQ(placeholder(sim, "--g"), "NUM=9.8");  // the default, from the option struct
  EXPECT_EQ(placeholder(sim, "--tol"), "NUM=1e-10");
  EXPECT_EQ(placeholder(run_tribolab("track import --help").out, "--entry"), "NAME");
  EXPECT_NE(placeholder(run_tribolab("track kinematics --help").out, "--impacts"), "NAME");
  for (const char* bad : {" FLOAT", " UINT", " TEXT TEXT", "FILE.html:FILE.html", "FILE FILE",
                          "FILE TEXT", "=[]", "=\"\"", "NUM=nan", "NUM=-inf", "NUM=inf"}) {
    EXPECT_EQ(all.find(bad), std::string::npos) << "'" << bad << "' in:\n" << all;
  }
}

TEST(Cli, AMissingOutputFolderIsTheSameClassForEveryOutput) {
  const std::string base = "incline simulate --mu 0.3 --phi-deg 20 --v0 2 ";
  const auto out = run_tribolab(base + "--out /nonexistent-folder/x.csv");
  const auto rep = run_tribolab(base + "--out x.csv --report /nonexistent-folder/x.html");
  EXPECT_EQ(out.exit_code, 1) << out.err;
  EXPECT_EQ(rep.exit_code, 1) << rep.err;
  // A wrong extension is a malformed command line.
  EXPECT_EQ(run_tribolab(base + "--out x.csv --report x.txt").exit_code, 2);
}

TEST(Cli, TwoOutputsIntoOneFileAreRefusedBeforeAnythingIsWritten) {
  // Used to leave CSV rows followed by the tail of the HTML report in same.html.
  const std::string dir = (std::filesystem::temp_directory_path() / "tribolab_same_output").string();
  std::filesystem::create_directories(dir);
  const std::string same = dir + "/same.html";
  std::filesystem::remove(same);
  const auto r = run_tribolab("incline simulate --mu 0.3 --phi-deg 20 --v0 2 --out '" + same +
                              "' --report '" + dir + "/./same.html'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--out and --report name the same file"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(same));
  // An output over the input file is refused too; the input is left untouched.
  const std::string input = dir + "/run.csv";
  { std::ofstream(input) << "track,frame,t,x,y\nA,0,0,0,0\nA,1,0.1,1,1\n"; }
  const auto over = run_tribolab("track import '" + input + "' --out '" + input + "'");
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("is also the input file"), std::string::npos) << over.err;
  EXPECT_EQ(slurp(input), "track,frame,t,x,y\nA,0,0,0,0\nA,1,0.1,1,1\n");
}

}  // namespace
}  // namespace tribolab::cli::testing
