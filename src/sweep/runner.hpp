// Evaluates a cell function over the cells of a grid (or of one shard of it) on N threads,
// handing results to a sink strictly in cell order. Each cell is a pure function of its
// inputs, so the results - and any file written from them - are identical whatever the
// thread count. See docs/theory.md#sweeps.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sweep/grid.hpp"

namespace tribolab::sweep {

/// Largest number of outputs of one cell.
inline constexpr std::size_t kMaxOutputs = 16;
/// A cell's outputs; only the first output_names.size() entries are used.
using CellOutputs = std::array<double, kMaxOutputs>;

/// What is computed in every cell: the physics behind a sweep (e.g. one bounce contact).
struct CellModel {
  /// Names of the outputs, in order, 1..kMaxOutputs of them; used as CSV column names.
  /// The derived maps need one named "e" (restitution). Bounce: vx, vy, omega_out, e,
  /// contacts, contact_duration, then the first contact phase's vx_first ... duration_first.
  std::vector<std::string> output_names;
  /// The cell function. Must be a pure function of its input (same input, same bits out)
  /// and safe to call concurrently from many threads. May throw (e.g. InputError).
  std::function<CellOutputs(const CellInput&)> evaluate;
  /// One line describing every physical option (law, K, n, D, ball, g...). Recorded in
  /// the header of every sweep file so that a resume or merge of files computed with other
  /// physics is refused. No newline.
  std::string description;
  /// Ball mass, kg (rugby ball: 0.435); needed only for the energy-ratio threshold.
  double mass = std::numeric_limits<double>::quiet_NaN();
  /// Moment of inertia about the centre, kg m^2 (rugby ball: 4.1e-3); energy ratio only.
  double inertia = std::numeric_limits<double>::quiet_NaN();

  /// Empty when valid: 1..kMaxOutputs distinct, non-empty names of letters, digits and
  /// '_', an evaluate function, a description without newline.
  std::string validate() const;
  /// Position of output `name`, or -1.
  int output_index(const std::string& name) const;
};

/// Progress of a run, reported to RunOptions::progress.
struct Progress {
  std::int64_t done = 0;   ///< cells of the shard finished and committed (resumed ones included)
  std::int64_t total = 0;  ///< cells in the shard
  double elapsed_s = 0;    ///< wall time since the run started, s
  double rate = 0;         ///< cells per second computed in this run
};

struct RunOptions {
  /// Worker threads, 0 to kMaxThreads; 0 = std::thread::hardware_concurrency() (all cores).
  int threads = 0;
  /// Cells per work unit; 0 = automatic (enough units for load balance, at most 1024 cells).
  std::int64_t chunk_cells = 0;
  /// When set and it becomes true, no new work is started; finished work is still
  /// committed in order and run_cells returns with status cancelled.
  const std::atomic<bool>* cancel = nullptr;
  /// Called on the calling thread about every progress_interval_s and once at the end.
  std::function<void(const Progress&)> progress;
  double progress_interval_s = 0.2;  ///< s
  std::string validate() const;
};

/// A run of consecutive cells of a shard, in local order (local k = global shard.global(k)).
struct ChunkView {
  std::int64_t first_local = 0;          ///< local index of the first cell
  std::int64_t count = 0;                ///< cells in the chunk
  const CellInput* inputs = nullptr;     ///< count inputs
  const double* outputs = nullptr;       ///< count x n_outputs values, row-major
  std::size_t n_outputs = 0;
};

/// Where results go. encode() runs on worker threads, concurrently for different chunks,
/// and turns a chunk into bytes (e.g. CSV lines) in `buffer` (cleared before, capacity
/// kept). commit() runs on the calling thread, one chunk at a time, in cell order.
/// Either may be empty. Exceptions from either end the run and are rethrown.
struct ResultSink {
  std::function<void(const ChunkView&, std::string& buffer)> encode;
  std::function<void(const ChunkView&, const std::string& buffer)> commit;
};

struct RunSummary {
  enum class Status { completed, cancelled };
  Status status = Status::completed;
  std::int64_t cells_computed = 0;  ///< cells computed and committed in this call
  int threads = 0;                  ///< worker threads used
  double seconds = 0;               ///< wall time, s
};

/// Computes local cells [first_local, end_local) of `shard` (end_local < 0: to the end of
/// the shard, shard.cells(grid.cell_count())) and commits them in order. Grid, model,
/// shard and options must be valid (asserted).
RunSummary run_cells(const GridSpec& grid, const CellModel& model, const Shard& shard,
                     std::int64_t first_local, const RunOptions& options, const ResultSink& sink,
                     std::int64_t end_local = -1);

/// Every cell of the grid in memory: cell_count() x output_names.size() values, row-major.
std::vector<double> evaluate_grid(const GridSpec& grid, const CellModel& model,
                                  const RunOptions& options = {});

/// Calls f(i) for i in [0, n) on `threads` threads (0 = all cores); rethrows the first
/// exception. For small independent jobs such as refining contour points.
void parallel_for(std::int64_t n, int threads, const std::function<void(std::int64_t)>& f);

/// The most worker threads a run may ask for. More gain nothing on any machine tribolab
/// targets, and each costs a stack (8 MiB of address space by default): 100000 exhausted it.
inline constexpr int kMaxThreads = 1024;
/// Empty when 0 <= threads <= kMaxThreads, else the message ("threads must be 0 (all cores)
/// to 1024, got 100000"). Every option struct with a thread count validates with it.
std::string threads_error(int threads);

/// threads, or hardware_concurrency() (at least 1) when threads <= 0.
int resolve_threads(int threads);

}  // namespace tribolab::sweep
