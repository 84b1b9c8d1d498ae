#include "sweep_cmd.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <unistd.h>

#include "app.hpp"
#include "io/sweep_command.hpp"
#include "io/sweep_file.hpp"
#include "io/sweep_mpi.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report_option.hpp"
#include "app/report_sweep.hpp"

namespace tribolab::cli {
namespace {

// Set by SIGINT/SIGTERM during a sweep: the runner stops starting work, writes what is
// finished and the command reports how to resume. A second signal kills at once.
// (Lock-free atomics, signal() and raise() are async-signal-safe.)
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int sig) {
  if (g_interrupted.exchange(true)) {
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

struct SweepArgs {
  std::string theta, omega, ratio, speed, mu, shard, out, contour, threshold, report;
  int threads = 0;
  bool restart = false, json = false;
  double contour_tol = 1e-9;
};

io::SweepCommandOptions to_options(const SweepArgs& a, const SweepPhysics& physics) {
  io::SweepCommandOptions o;
  o.grid.axes.push_back(io::parse_axis(a.theta, sweep::Quantity::theta_deg, "--theta-deg"));
  if (a.omega.empty() == a.ratio.empty()) {
    throw InputError("give exactly one of --omega (spin range) and --ratio (spin/speed range)");
  }
  if (!a.omega.empty()) o.grid.axes.push_back(io::parse_axis(a.omega, sweep::Quantity::omega, "--omega"));
  if (!a.ratio.empty()) o.grid.axes.push_back(io::parse_axis(a.ratio, sweep::Quantity::ratio, "--ratio"));
  o.grid.fixed_speed = physics.default_speed;
  o.grid.fixed_mu = physics.default_mu;
  if (!a.speed.empty()) {
    const io::ValueOrAxis v = io::parse_value_or_axis(a.speed, sweep::Quantity::speed, "--speed");
    if (v.axis) o.grid.axes.push_back(*v.axis);
    else o.grid.fixed_speed = v.value;
  }
  if (!a.mu.empty()) {
    const io::ValueOrAxis v = io::parse_value_or_axis(a.mu, sweep::Quantity::mu, "--mu");
    if (v.axis) o.grid.axes.push_back(*v.axis);
    else o.grid.fixed_mu = v.value;
  }
  // Physical ranges of the swept quantities (numerics/physical_range.hpp, docs/cli.md#physical-ranges).
  for (const sweep::Axis& ax : o.grid.axes) {
    const char* option = ax.quantity == sweep::Quantity::speed   ? "--speed"
                         : ax.quantity == sweep::Quantity::mu    ? "--mu"
                         : ax.quantity == sweep::Quantity::omega ? "--omega"
                         : ax.quantity == sweep::Quantity::ratio ? "--ratio"
                                                                 : nullptr;
    const PhysicalRange r = ax.quantity == sweep::Quantity::speed ? ranges::speed
                            : ax.quantity == sweep::Quantity::mu  ? ranges::friction
                            : ax.quantity == sweep::Quantity::ratio ? PhysicalRange{-1e5, 1e5, "rad/m"}
                                                                     : ranges::spin;
    if (option) for (double v : {ax.lo, ax.hi}) check_range(v, r, option);
  }
  check_range(o.grid.fixed_speed, ranges::speed, "--speed");
  check_range(o.grid.fixed_mu, ranges::friction, "--mu");
  sweep::sort_axes(o.grid.axes);
  if (!a.shard.empty()) o.shard = io::parse_shard(a.shard, "--shard");
  o.out = a.out;
  o.threads = a.threads;
  o.restart = a.restart;
  o.contour_out = a.contour;
  o.threshold_out = a.threshold;
  if (!(a.contour_tol > 0 && a.contour_tol < 1)) {
    throw InputError("--contour-tol", "must be in (0, 1) (a fraction of the grid spacing)");
  }
  o.contour.x_tol_rel = a.contour_tol;
  if (auto e = o.validate(); !e.empty()) throw InputError(e);
  if (!a.report.empty()) {
    // A shard holds every N-th cell of the grid: no map to draw. Checked before any work.
    if (o.shard.count > 1) {
      throw InputError("--report", "needs the whole grid, not one shard; merge the shards with `tribolab bounce "
                                   "merge ... --report FILE.html`");
    }
    for (const std::string* p : {&o.out, &o.contour_out, &o.threshold_out}) {
      if (!p->empty() && (a.report == *p || a.report == *p + ".partial")) {
        throw InputError("--report", "must not be the same file as --out, --contour or --threshold");
      }
    }
  }
  return o;
}

/// Number of ranks the MPI launcher started (1 when not under a launcher).
[[maybe_unused]] int launcher_ranks() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* v = std::getenv(var)) return std::atoi(v);
  }
  return 1;
}

void run_sweep(const SweepArgs& args, const SweepPhysics& physics) {
  int rank = 0;
  bool use_mpi = false;
#if TRIBOLAB_WITH_MPI
  if (io::launched_by_mpi_launcher()) {
    static io::MpiSession session;  // MPI_Finalize at exit
    rank = session.rank();
    use_mpi = true;
  }
#else
  if (launcher_ranks() > 1) {
    throw InputError("this tribolab was built without MPI (cmake -DTRIBOLAB_MPI=ON); run it "
                     "without mpirun, or split the grid with --shard");
  }
#endif
  try {
    const io::SweepCommandOptions o = to_options(args, physics);
    const sweep::CellModel model = physics.make_model();
    InterruptGuard guard;
    std::ostream* progress = rank == 0 && ::isatty(STDERR_FILENO) ? &std::cerr : nullptr;
    io::SweepCommandResult r;
#if TRIBOLAB_WITH_MPI
    if (use_mpi) {
      r = io::run_sweep_command_mpi(o, model, progress, &g_interrupted);
      if (rank != 0) return;  // rank 0 reports
    }
#endif
    if (!use_mpi) r = io::run_sweep_command(o, model, progress, &g_interrupted);
    if (r.status == "cancelled") {
      throw InputError("interrupted: " + std::to_string(r.cells_resumed + r.cells_computed) +
                       " of " + std::to_string(r.cells_shard) + " cells saved in " + r.out +
                       "; run the same command again to resume");
    }
    // Built from the completed file, read back: the same report for a fresh, resumed or
    // reused sweep, and the same boundary points as --contour.
    write_report_if_requested(args.report, [&] {
      sweep::ContourOptions co = o.contour;
      co.threads = o.threads;
      return sweep_report(sweep_report_data(o.out, model, co, "bounce sweep"));
    });
    print_result(io::sweep_result_json(r, o), args.json);
  } catch (...) {
    // Every rank sees the same error; only rank 0 prints it (one line, SPEC section 5).
    if (rank != 0) (void)std::freopen("/dev/null", "w", stderr);
    throw;
  }
}

/// The cell model that wrote the sweep file `path` (its header's physics description).
sweep::CellModel model_of_sweep_file(const std::string& path, const SweepPhysics& physics) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "no such file");
  std::string line;
  if (!std::getline(in, line) || in.eof()) {
    throw InputError(path + ":1", "not a tribolab sweep file (no complete header line)");
  }
  const io::SweepHeader h = io::parse_header(line, path + ":1");
  if (!physics.model_from_description) {
    throw InputError("--report", "this command cannot rebuild the physics of " + path);
  }
  return physics.model_from_description(h.model);
}

}  // namespace

void register_sweep_commands(CLI::App& bounce_area, SweepPhysics physics) {
  auto args = std::make_shared<SweepArgs>();
  auto shared_physics = std::make_shared<SweepPhysics>(std::move(physics));
  CLI::App* cmd = bounce_area.add_subcommand(
      "sweep",
      "Rebound over a grid of impact angle x spin (and speed, mu): CSV map, e = 1 boundary, "
      "spin thresholds; parallel, resumable, shardable");
  cmd->add_option("--theta-deg", args->theta, "Impact angle range lo:hi:count, deg (e.g. 100:170:71)")
      ->required();
  cmd->add_option("--omega", args->omega, "Spin range lo:hi:count, rad/s (e.g. 30:50:21)");
  cmd->add_option("--ratio", args->ratio,
                  "Instead of --omega: spin/speed range omega/|vy| lo:hi:count, rad/m");
  cmd->add_option("--speed", args->speed,
                  "Incoming vertical speed |vy|, m/s: a value or a range lo:hi:count (default " +
                      io::format_number_exact(shared_physics->default_speed) + ")");
  cmd->add_option("--mu", args->mu,
                  "Friction coefficient: a value or a range lo:hi:count (default " +
                      io::format_number_exact(shared_physics->default_mu) + ")");
  cmd->add_option("--out", args->out, "Output CSV (checkpoint while running: FILE.partial)")->required();
  cmd->add_option("--shard", args->shard, "Compute only shard i of N (cells with index % N == i), e.g. 0/4");
  cmd->add_option("--threads", args->threads, "Worker threads (default 0 = all cores)");
  cmd->add_flag("--restart", args->restart, "Discard an existing checkpoint or output and start afresh");
  cmd->add_option("--contour", args->contour, "Write the e = 1 boundary polylines to this CSV");
  cmd->add_option("--threshold", args->threshold,
                  "Write the spin threshold and energy ratio per angle to this CSV");
  cmd->add_option("--contour-tol", args->contour_tol,
                  "Root tolerance of boundary points, fraction of the grid spacing (default 1e-9)");
  add_report_option(*cmd, args->report);
  add_json_flag(*cmd, args->json);
  if (shared_physics->add_options) shared_physics->add_options(*cmd);
  cmd->callback([args, shared_physics] { run_sweep(*args, *shared_physics); });

  auto inputs = std::make_shared<std::vector<std::string>>();
  auto merge_out = std::make_shared<std::string>();
  auto merge_json = std::make_shared<bool>(false);
  auto merge_report = std::make_shared<std::string>();
  CLI::App* merge = bounce_area.add_subcommand(
      "merge", "Join the shard files of one `bounce sweep` into the full map, exactly");
  merge->add_option("files", *inputs, "Shard files (every shard i/N exactly once, any order)")
      ->required();
  merge->add_option("--out", *merge_out, "Merged output CSV")->required();
  add_report_option(*merge, *merge_report);
  add_json_flag(*merge, *merge_json);
  merge->callback([inputs, merge_out, merge_json, merge_report, shared_physics] {
    // The physics is rebuilt from the first shard's header before anything is written, so
    // a file this tribolab cannot report on fails without output.
    std::optional<sweep::CellModel> model;
    if (!merge_report->empty()) {
      if (*merge_report == *merge_out) throw InputError("--report", "must not be the same file as --out");
      if (!inputs->empty()) model = model_of_sweep_file(inputs->front(), *shared_physics);
    }
    const io::MergeResult r = io::run_merge_command(*inputs, *merge_out);
    if (model) {
      write_report_if_requested(*merge_report, [&] {
        return sweep_report(sweep_report_data(r.out, *model, sweep::ContourOptions{}, "bounce merge"));
      });
    }
    print_result(nlohmann::json{{"out", r.out}, {"shards", r.shards}, {"cells", r.cells}},
                 *merge_json);
  });
}

}  // namespace tribolab::cli
