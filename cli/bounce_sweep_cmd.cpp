// `tribolab bounce sweep` and `tribolab bounce merge`: flags bound to app::BounceSweepOptions
// and app::BounceMergeOptions, the text of ranges and shards parsed (cli/sweep_cmd.hpp), the
// interrupt signal and the progress line handled here; the workflow is app::bounce_sweep
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

/// The text of the options that take ranges, before parsing into BounceSweepOptions.
struct SweepText {
  std::string theta, omega, ratio, speed, mu, shard;
  bool json = false;
};

/// Number of ranks the MPI launcher started (1 when not under a launcher).
int launcher_ranks() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* v = std::getenv(var)) return std::atoi(v);
  }
  return 1;
}

void run_sweep(app::BounceSweepOptions o, const SweepText& t) {
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
    o.theta_deg = parse_axis(t.theta, sweep::Quantity::theta_deg, "--theta-deg");
    if (!t.omega.empty()) o.omega = parse_axis(t.omega, sweep::Quantity::omega, "--omega");
    if (!t.ratio.empty()) o.ratio = parse_axis(t.ratio, sweep::Quantity::ratio, "--ratio");
    // A range keeps the default value as the grid's fixed value (recorded in the file header).
    auto value_or_axis = [](const std::string& text, sweep::Quantity q, const char* option, app::ValueOrAxis& to) {
      if (text.empty()) return;
      const app::ValueOrAxis v = parse_value_or_axis(text, q, option);
      if (v.axis) to.axis = v.axis;
      else to.value = v.value;
    };
    value_or_axis(t.speed, sweep::Quantity::speed, "--speed", o.speed);
    value_or_axis(t.mu, sweep::Quantity::mu, "--mu", o.mu);
    if (!t.shard.empty()) o.shard = parse_shard(t.shard, "--shard");
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
    print_result(r.json, t.json, app::bounce_sweep_result_keys());
  } catch (...) {
    // Every rank sees the same error; only rank 0 prints it (one line, SPEC section 5).
    if (rank != 0) (void)std::freopen("/dev/null", "w", stderr);
    throw;
  }
}

}  // namespace

void register_bounce_sweep(CLI::App& bounce_area) {
  auto opts = std::make_shared<app::BounceSweepOptions>();
  auto text = std::make_shared<SweepText>();
  text->speed = io::format_number_exact(opts->speed.value);  // the help shows the defaults
  text->mu = io::format_number_exact(opts->mu.value);
  CLI::App* cmd = bounce_area.add_subcommand(
      "sweep",
      "Rebound over a grid of impact angle x spin (and speed, mu): CSV map, e = 1 boundary, "
      "spin thresholds; parallel, resumable, shardable");
  cmd->add_option("--theta-deg", text->theta, "Impact angle range lo:hi:count, deg (e.g. 100:170:71)")
      ->required();
  cmd->add_option("--omega", text->omega, "Spin range lo:hi:count, rad/s, counter-clockwise positive (e.g. 30:50:21; the rugby-ball study's figure 53 spins clockwise for a ball moving to +x: -50:-30:21)");
  cmd->add_option("--ratio", text->ratio, "Instead of --omega: spin/speed range omega/|vy| lo:hi:count, rad/m");
  cmd->add_option("--speed", text->speed, "Incoming vertical speed |vy|, m/s: a value or a range lo:hi:count");
  cmd->add_option("--mu", text->mu, "Friction coefficient: a value or a range lo:hi:count");
  cmd->add_option("--out", opts->out, "Output CSV (checkpoint while running: FILE.partial)")->required();
  cmd->add_option("--shard", text->shard, "Compute only shard i of N (cells with index % N == i), e.g. 0/4");
  cmd->add_option("--threads", opts->threads, "Worker threads, 0 = all cores");
  cmd->add_flag("--restart", opts->restart, "Discard an existing checkpoint or output and start afresh");
  cmd->add_option("--contour", opts->contour, "Write the e = 1 boundary polylines to this CSV");
  cmd->add_option("--threshold", opts->threshold, "Write the spin threshold and energy ratio per angle to this CSV");
  cmd->add_option("--contour-tol", opts->contour_tol,
                  "Root tolerance of boundary points, fraction of the grid spacing");
  cmd->add_option("--plain-csv", opts->plain_csv,
                  "Also write the map for spreadsheets: no comment lines, the metadata in FILE.meta.txt");
  add_report_option(*cmd, opts->report, opts->plotly);
  add_json_flag(*cmd, text->json);
  // The physics of a cell: the options of `bounce simulate` except --mu (a sweep axis).
  app::BounceCellOptions& cell = opts->cell;
  cmd->add_option("--angle", cell.angle,
                  "meaning of --theta-deg: collision (the rugby-ball study's collision angle, 0..180 deg) | "
                  "orientation (major axis from the horizontal at first touch)");
  cmd->add_option("--vx", cell.vx, "horizontal centre velocity at first touch, m/s");
  add_ball_options(cmd, cell.ball);
  add_law_options(cmd, cell.law, /*with_mu=*/false);  // --mu belongs to the sweep (sweepable)
  cmd->add_option("--g", cell.g, "gravitational acceleration, m/s^2");
  declare_results(*cmd, app::bounce_sweep_result_keys());
  cmd->callback([opts, text] { run_sweep(*opts, *text); });

  auto merge_opts = std::make_shared<app::BounceMergeOptions>();
  auto merge_json = std::make_shared<bool>(false);
  CLI::App* merge = bounce_area.add_subcommand(
      "merge", "Join the shard files of one `bounce sweep` into the full map, exactly");
  add_declared_options(*merge, *merge_opts, app::bounce_merge_fields(), app::bounce_merge_result_keys());
  add_json_flag(*merge, *merge_json);
  merge->callback([merge_opts, merge_json, merge] { print_declared(*merge, app::bounce_merge(*merge_opts).json, *merge_json); });
}

}  // namespace tribolab::cli
