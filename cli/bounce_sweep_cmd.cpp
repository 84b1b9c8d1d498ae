// `tribolab bounce sweep` and `tribolab bounce merge`: flags bound from the declarations of
// app::BounceSweepOptions and app::BounceMergeOptions (the text of ranges and shards read by
// src/app/sweep/sweep_text.hpp as the options are parsed), the interrupt signal and the progress line handled here; the workflow is app::bounce_sweep
// (src/app/bounce/bounce_sweep.hpp), each cell the one bounce cell model (src/app/bounce/bounce_cell.hpp).
// docs/cli.md#bounce-sweep, docs/theory.md#sweeps.
#include "declared_options.hpp"
#include "app/common/result_keys.hpp"
#include "bounce_sweep_cmd.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "app.hpp"
#include "app/bounce/bounce_sweep.hpp"
#include "app/sweep/sweep_mpi.hpp"
#include "bounce_options.hpp"
#include "io/sweep_file.hpp"
#include "io/temp_files.hpp"
#include "numerics/error.hpp"
#include "report_option.hpp"
#include "sweep_cmd.hpp"

namespace tribolab::cli {
namespace {

// Set by SIGINT/SIGTERM during a sweep: the runner stops starting work, writes what is
// finished and the command reports how to resume. A second signal kills at once.
// (Lock-free atomics, signal() and raise() are async-signal-safe.)
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int sig) {
  if (g_interrupted.exchange(true)) {
    io::remove_registered_temps();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

/// Installs the interrupt handler for the lifetime of the object.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupted = false;
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~InterruptGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

/// Ends the progress line (if one was printed) however the sweep ends.
struct ProgressLine {
  bool printed = false;
  ~ProgressLine() {
    if (printed) std::cerr << '\n' << std::flush;
  }
};

/// Number of ranks the MPI launcher started (1 when not under a launcher).
int launcher_ranks() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* v = std::getenv(var)) return std::atoi(v);
  }
  return 1;
}

void run_sweep(app::BounceSweepOptions o, const CLI::App& cmd, bool as_json) {
  int rank = 0;
  if (app::launched_by_mpi_launcher() && app::built_with_mpi()) {
    static app::MpiSession session;  // MPI_Finalize at exit
    rank = session.rank();
    o.mpi = true;
  } else if (launcher_ranks() > 1) {
    throw InputError("this tribolab was built without MPI (cmake -DTRIBOLAB_MPI=ON); run it "
                     "without mpirun, or split the grid with --shard");
  }
  try {
    InterruptGuard guard;
    ProgressLine line;
    if (rank == 0 && ::isatty(STDERR_FILENO)) {
      o.progress = [&line](const sweep::Progress& p) {
        print_progress(std::cerr, p);
        line.printed = true;
      };
    }
    o.cancel = &g_interrupted;
    const app::BounceSweepResult r = app::bounce_sweep(o);
    if (!r.is_reporting_rank) return;  // rank 0 reports
    print_declared(cmd, r.json, as_json);
  } catch (...) {
    // Every rank sees the same error; only rank 0 prints it (one line, SPEC section 5).
    if (rank != 0) (void)std::freopen("/dev/null", "w", stderr);
    throw;
  }
}

}  // namespace

void register_bounce_sweep(CLI::App& bounce_area) {
  auto opts = std::make_shared<app::BounceSweepOptions>();
  auto as_json = std::make_shared<bool>(false);
  CLI::App* cmd = bounce_area.add_subcommand(
      "sweep",
      "Rebound over a grid of impact angle x spin (and speed, mu): CSV map, e = 1 boundary, "
      "spin thresholds; parallel, resumable, shardable");
  // The ranges (LO:HI:N), a number or a range, the shard (I/N) read by app/sweep/sweep_text.hpp.
  add_declared_options(*cmd, *opts, app::bounce_sweep_fields(), app::bounce_sweep_result_keys());
  add_json_flag(*cmd, *as_json);
  cmd->callback([opts, as_json, cmd] { run_sweep(*opts, *cmd, *as_json); });

  auto merge_opts = std::make_shared<app::BounceMergeOptions>();
  auto merge_json = std::make_shared<bool>(false);
  CLI::App* merge = bounce_area.add_subcommand(
      "merge", "Join the shard files of one `bounce sweep` into the full map, exactly");
  add_declared_options(*merge, *merge_opts, app::bounce_merge_fields(), app::bounce_merge_result_keys());
  add_json_flag(*merge, *merge_json);
  merge->callback([merge_opts, merge_json, merge] { print_declared(*merge, app::bounce_merge(*merge_opts).json, *merge_json); });
}

}  // namespace tribolab::cli
