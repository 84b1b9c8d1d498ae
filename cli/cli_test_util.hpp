// Runs the real `tribolab` binary for golden tests: exit code, stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace tribolab::cli::testing {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Runs `tribolab <args>` (args already shell-quoted where needed).
inline RunResult run_tribolab(const std::string& args) {
  static int counter = 0;
  const std::string base = (std::filesystem::temp_directory_path() /
                            ("tribolab_cli_" + std::to_string(::getpid()) + "_" +
                             std::to_string(counter++)))
                               .string();
  const std::string cmd = std::string("'") + TRIBOLAB_BINARY + "' " + args + " >'" + base +
                          ".out' 2>'" + base + ".err' </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

/// A fresh empty directory for one test's files.
inline std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tribolab_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

/// Number of lines in s.
/// How many times `what` occurs in `text` (overlapping occurrences counted).
inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

/// A path in single quotes for the shell of run_tribolab (paths made by the tests: no quote in them).
inline std::string q(const std::string& path) { return "'" + path + "'"; }

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

/// Runs `tribolab <args> --json` that must succeed: exit 0, nothing on stderr but the
/// result's own `warnings` (each as one "tribolab: warning: ..." line), and stdout either
/// empty (commands whose output is a file) or exactly one line of JSON.
inline nlohmann::json run_json(const std::string& args) {
  const auto r = run_tribolab(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  if (r.out.empty()) {
    EXPECT_TRUE(r.err.empty()) << args << "\n" << r.err;
    return nlohmann::json();
  }
  EXPECT_EQ(count_lines(r.out), 1) << args << "\n" << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  std::string expected_err;
  if (j.is_object() && j.contains("warnings") && j["warnings"].is_array()) {
    for (const auto& w : j["warnings"]) expected_err += "tribolab: warning: " + w.get<std::string>() + "\n";
  }
  // A series: each run's warnings prefixed by its file, then the summary's.
  if (j.is_object() && j.contains("runs") && j.contains("summary")) {
    for (const auto& run : j["runs"])
      if (run.contains("warnings"))
        for (const auto& w : run["warnings"])
          expected_err += "tribolab: warning: " + run.value("file", "") + ": " + w.get<std::string>() + "\n";
    if (j["summary"].contains("warnings"))
      for (const auto& w : j["summary"]["warnings"]) expected_err += "tribolab: warning: " + w.get<std::string>() + "\n";
  }
  EXPECT_EQ(r.err, expected_err) << args;
  return j;
}

/// Bad input as the user sees it: non-zero exit, exactly one line on stderr that contains
/// `must_mention`, and nothing on stdout.
inline void expect_error(const RunResult& r, const std::string& must_mention, const std::string& context = "") {
  EXPECT_NE(r.exit_code, 0) << context;
  EXPECT_EQ(count_lines(r.err), 1) << context << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << context << "\n" << r.out;
  EXPECT_NE(r.err.find(must_mention), std::string::npos)
      << context << "\nexpected '" << must_mention << "' in: " << r.err;
}

/// Runs `tribolab <args>` and checks it fails as `expect_error(result, ...)` describes.
inline void expect_error(const std::string& args, const std::string& must_mention) {
  expect_error(run_tribolab(args), must_mention, args);
}

/// `<command> --report BAD` for the bad report paths (wrong suffix, missing folder, a folder):
/// each fails as expect_error says, naming --report, and leaves no file; when `out_file` is
/// given, the command's other output must not appear either.
inline void expect_bad_report_paths(const std::string& command, const std::string& out_file = "") {
  const std::string dir = temp_dir("report_bad");
  for (const std::string& bad : {dir + "/r.txt", dir + "/missing/r.html", dir}) {
    expect_error(run_tribolab(command + " --report '" + bad + "'"), "--report", command + " --report " + bad);
    if (!out_file.empty()) {
      EXPECT_FALSE(std::filesystem::exists(out_file)) << command;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/r.txt")) << command;
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing")) << command;
}

}  // namespace tribolab::cli::testing
