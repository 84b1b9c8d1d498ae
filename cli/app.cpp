#include "app.hpp"

#include "command_line_check.hpp"
#include "help_placeholders.hpp"
#include "help_wrap.hpp"
#include "text_listing.hpp"

#include "app/common/spelled_json.hpp"
#include "numerics/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <new>
#include <ostream>
#include <string_view>

namespace tribolab::cli {
namespace {

bool secondary_mpi_rank() {
  // The launchers name each process's rank in its environment: Open MPI, MPICH (Hydra), PMIx.
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
    const char* rank = std::getenv(name);
    if (rank != nullptr && *rank != '\0') return std::string_view(rank) != "0";
  }
  return false;
}

}  // namespace

std::ostream& diagnostics() {
  // Under `mpirun -np N` every rank runs the same command line and meets the same error (or
  // warning): rank 0 alone says it, once; the others exit with the same status, silently.
  static std::ostream discard(nullptr);
  return secondary_mpi_rank() ? discard : std::cerr;
}

nlohmann::json spelled_for_cli(const nlohmann::json& j) { return app::spelled_json(j, flag_of); }

void print_result(const nlohmann::json& raw, bool as_json, const app::ResultKeys& keys) {
  const nlohmann::json result = spelled_for_cli(raw);
  // Data that contradict the physics are said on stderr too, whatever the output format.
  if (result.is_object() && result.contains("warnings") && result["warnings"].is_array()) {
    for (const auto& w : result["warnings"]) {
      if (w.is_string()) diagnostics() << "tribolab: warning: " << one_line(w.get<std::string>()) << '\n';
    }
  }
  if (as_json) {
    std::cout << result.dump() << '\n';
    return;
  }
  std::cout << text_listing(result, keys);
}

void add_json_flag(CLI::App& cmd, bool& flag) {
  cmd.add_flag("--json", flag, "Print the result as one JSON object on stdout");
}

std::string flag_of(std::string_view field) {
  std::string flag = "--" + std::string(field);
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

int run(int argc, char** argv) {
  CLI::App app{
      "tribolab: friction and impact experiments - simulate, predict, fit, analyse tracked video.\n"
      "SI units throughout; angles in degrees where an option says _deg/-deg.",
      "tribolab"};
  app.set_version_flag("--version", "tribolab 0.1.0");
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();  // help shows each default from its option struct
  register_incline(app);
  register_bounce(app);
  register_track(app);
  register_demo(app);
  register_schema(app);
  register_studio(app);
  tidy_placeholders(app);
  wrap_help(app);  // after the placeholders: they read the one-line help
  try {
    // A command that needs a subcommand and got nothing else: its help is the answer.
    if (CLI::App* bare = check_command_line(app, argc, argv)) {
      const CLI::App* parent = bare->get_parent();
      std::cout << bare->help(parent != nullptr ? full_name(*parent) : "");
      return 0;
    }
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const UsageError& e) {
    diagnostics() << "tribolab: error: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const CLI::ParseError& e) {
    diagnostics() << "tribolab: error: " << one_line(e.what()) << " (see --help)\n";
    return 2;
  } catch (const MissingOptionError& e) {  // a required option missing: a malformed command line
    diagnostics() << "tribolab: error: " << one_line(e.message(flag_of)) << '\n';
    return 2;
  } catch (const Error& e) {  // InputError, SolverError: the core's fields spelled as flags
    diagnostics() << "tribolab: error: " << one_line(e.message(flag_of)) << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    diagnostics() << "tribolab: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    diagnostics() << "tribolab: error: " << one_line(e.what()) << '\n';
    return 1;
  }
  return 0;
}

}  // namespace tribolab::cli
