// The command-line layer: each area registers its subcommands on the root CLI11 app.
// Commands parse options into the library's option structs, call the core, and print
// through print_result(); errors propagate as exceptions to main(), which turns them
// into one line on stderr and a non-zero exit (SPEC section 5).
#pragma once

#include "app/common/option_fields.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <string_view>

namespace tribolab::app {}  // the application layer (src/app): workflows, reports, the demo

namespace tribolab::cli {

/// The command line is one front end of the application layer; its names read unqualified.
using namespace ::tribolab::app;

/// Registers `tribolab incline ...`.
void register_incline(CLI::App& root);
/// Registers `tribolab bounce ...`.
void register_bounce(CLI::App& root);
/// Registers `tribolab track ...`.
void register_track(CLI::App& root);
/// Registers `tribolab demo`.
void register_demo(CLI::App& root);
/// Registers `tribolab schema` (cli/schema_cmd.cpp); after every other command.
void register_schema(CLI::App& root);
/// `tribolab studio` (cli/studio_cmd.cpp).
void register_studio(CLI::App& root);

/// Prints a command's result: the JSON object on one line of stdout with --json, else an
/// aligned "key  value" listing for people (nested objects as dotted keys), its units from
/// `keys` (the command's declared result keys). Fields the core names in the result's texts
/// (field("floor_y") in a warning) are spelled as flags (--floor-y).
void print_result(const nlohmann::json& result, bool as_json, const app::ResultKeys& keys);

/// `j` with every field mark in its strings spelled by the command line (--floor-y).
nlohmann::json spelled_for_cli(const nlohmann::json& j);

/// Adds the `--json` flag to a command.
void add_json_flag(CLI::App& cmd, bool& flag);

/// How the command line spells a field the core names (field("time_scale") in
/// numerics/error.hpp): "--time-scale".
/// Where the program's "tribolab: error:" and "tribolab: warning:" lines go: stderr, except
/// in an MPI rank other than 0 (the rank read from the launcher's environment), where they are
/// dropped so that `mpirun -np N` says each once.
std::ostream& diagnostics();
std::string flag_of(std::string_view field);

/// Runs the program; returns the process exit code. Exposed for in-process tests.
int run(int argc, char** argv);

}  // namespace tribolab::cli
