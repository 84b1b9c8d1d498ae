// Checks a command line against the registered commands and options before CLI11 parses it,
// so that a slip gets the answer a newcomer needs: `--vo 2.62` is "unknown option '--vo';
// did you mean '--v0'?" rather than "--v0 is required", `incline simulat` suggests
// `simulate`, and a command given without its subcommand prints its help.
#pragma once

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace tribolab::cli {

/// A malformed command line (exit status 2, docs/cli.md#errors).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The rule for every option's value, whatever its type (docs/cli.md#empty-values): an
/// option given is given something. An empty or blank value (`--mu ''`, `--out=`) is never
/// read as 0, as "unset" or as no file: it is a malformed command line (UsageError, exit 2).
/// Empty when `value` may be given to `flag`, else the message. (One function so that a
/// declaration mechanism for options can call it for each value it binds.)
std::string empty_value_problem(const std::string& flag, const std::string& value);

/// The command's whole path, e.g. "tribolab incline simulate".
std::string full_name(const CLI::App& app);

/// The candidate closest to `word` by edit distance (a prefix of exactly one candidate counts
/// as close), or "" when none is close enough to be a plausible slip.
std::string nearest_name(const std::string& word, const std::vector<std::string>& candidates);

/// Walks argv[1..] through the command tree of `root`. Throws UsageError naming the unknown
/// command or option (with the nearest valid one) for the command it was given to. Returns
/// the command that needs a subcommand but got none and no option (its help is then the
/// answer), or nullptr.
CLI::App* check_command_line(CLI::App& root, int argc, char** argv);

}  // namespace tribolab::cli
