// The application of a sweep, for any cell model and any front end: checkpointed,
// resumable, shardable sweeps written to the sweep file format (io/sweep_file.hpp), the
// merge of shard files, and the derived maps. No command-line text is parsed here and
// nothing is printed: progress goes to a callback. The bounce workflow on top of it is
// app/bounce/bounce_sweep.hpp. See docs/design.md "Application layer: sweeps".
#pragma once

#include <atomic>
#include <functional>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/sweep_file.hpp"
#include "sweep/contour.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::app {

struct SweepCommandOptions {
  sweep::GridSpec grid;      ///< axes and fixed values
  sweep::Shard shard;        ///< --shard i/N; default 0/1 (the whole grid)
  std::string out;           ///< --out FILE.csv (required); checkpoint is FILE.csv.partial
  int threads = 0;           ///< --threads; 0 = all cores
  bool restart = false;      ///< --restart: discard an existing checkpoint or output
  std::int64_t chunk_cells = 0;  ///< cells per work unit; 0 = automatic
  double fsync_interval_s = 5.0;  ///< s between fsync() of the checkpoint (lines are written
                                  ///< to the file as each chunk completes, in cell order)
  std::string contour_out;    ///< --contour FILE.csv: the e = level polylines ("" = none)
  std::string threshold_out;  ///< --threshold FILE.csv: spin threshold per angle ("" = none)
  sweep::ContourOptions contour;  ///< output, level, tolerance of the derived maps
  /// Keep the finished file's values in the result (read back once: cells x outputs doubles).
  bool keep_values = false;
  /// Called with each cell (global index, outputs) of the finished file as the derived maps
  /// are made, the file read once and streamed (e.g. a report's bounded summary); may be empty.
  io::SweepCellVisitor visit_cells;
  /// Trace the boundary and thresholds (once, with `contour`) and keep them in the result,
  /// e.g. for a report, whether or not their CSV files are asked for.
  bool keep_derived = false;
  /// Empty when valid; messages name the command-line option.
  std::string validate() const;
};

/// How a sweep run ended.
enum class SweepStatus {
  completed,  ///< every cell of the shard is in the output file
  reused,     ///< the output file already held this complete sweep: nothing recomputed
  cancelled,  ///< stopped by the cancel flag; the cells done are saved in the checkpoint
  worker,     ///< an MPI rank other than 0: rank 0 owns the files and the result
};
/// "completed", "reused", "cancelled", "worker" (the JSON "status" of `bounce sweep`).
std::string to_string(SweepStatus s);

/// Called with the progress of a running sweep (from the calling thread); may be empty.
using SweepProgressCallback = std::function<void(const sweep::Progress&)>;

struct SweepCommandResult {
  SweepStatus status = SweepStatus::completed;
  std::string out;                   ///< the output file (or its checkpoint when cancelled)
  std::int64_t cells_grid = 0;       ///< cells in the whole grid
  std::int64_t cells_shard = 0;      ///< cells in this shard
  std::int64_t cells_resumed = 0;    ///< cells found in the checkpoint (not recomputed)
  std::int64_t cells_computed = 0;   ///< cells computed by this run
  /// Of those, cells with a finite output (counted by run_sweep_command; unset under MPI).
  std::optional<std::int64_t> cells_computed_with_result;
  int threads = 0;
  double seconds = 0;                ///< wall time of the computation, s
  std::int64_t contour_lines = 0, contour_points = 0, contour_evaluations = 0;
  std::int64_t thresholds_found = 0;
  // Kept when asked (SweepCommandOptions::keep_values, keep_derived) for a finished sweep:
  std::vector<double> values;  ///< cell_count x outputs, row-major, as in the file
  std::optional<sweep::ContourResult> boundary;             ///< the output = level polylines
  std::optional<std::vector<sweep::Threshold>> thresholds;  ///< per slice and angle
};

/// Runs (or resumes, or reuses) a sweep. Writes FILE.partial as it goes - complete lines
/// in cell order, fsync'ed every fsync_interval_s - and renames it to FILE when every cell
/// is done, so killing the process at any moment loses only unwritten cells and an
/// interrupted + resumed run gives the same bytes as an uninterrupted one. A FILE that
/// already holds this complete sweep is reused (status "reused"; only the derived maps are
/// computed); one holding another sweep is an error unless restart. `progress` (when not
/// empty) is called as chunks complete. Throws InputError for invalid options or files.
/// Checks the options and the cell model (InputError) and returns a result holding the sizes
/// (out, cells of the grid and of the shard, threads): the start the threaded and the MPI
/// sweep share.
SweepCommandResult checked_sweep_start(const SweepCommandOptions& options, const sweep::CellModel& model);

SweepCommandResult run_sweep_command(const SweepCommandOptions& options, const sweep::CellModel& model,
                                     const SweepProgressCallback& progress,
                                     const std::atomic<bool>* cancel = nullptr);

struct MergeResult {
  std::string out;
  std::int64_t shards = 0;
  std::int64_t cells = 0;
};

/// Joins the complete shard files of one sweep (any order, each shard exactly once) into
/// `out`, byte-identical to the unsharded run. Throws InputError naming the file on
/// different sweeps, missing/duplicate shards, incomplete or corrupt files.
MergeResult run_merge_command(const std::vector<std::string>& inputs, const std::string& out);

/// Writes the --contour / --threshold files of a finished sweep (streams o.out once, holding
/// two rows of the map and the crossings, not the map: sweep::MapTracer) and counts their
/// contents into r; keeps values, boundary and thresholds in r when o asks and gives each cell
/// to o.visit_cells. Each map is traced once. Needs the whole grid.
void write_derived_maps(const SweepCommandOptions& o, const sweep::CellModel& model,
                        SweepCommandResult& r);

/// The JSON result of `bounce sweep` (keys documented in docs/cli.md#bounce-sweep).
nlohmann::json sweep_result_json(const SweepCommandResult& r, const SweepCommandOptions& o);

/// Writes the polylines as CSV: line,closed,<slice quantities>,theta_deg,<omega|ratio>,refined.
void write_contour_csv(std::ostream& out, const sweep::ContourResult& contour);

/// The sidecar path of a plain CSV: "FILE.csv" -> "FILE.csv.meta.txt".
std::string plain_csv_metadata_path(const std::string& plain_csv);

/// Copies the finished sweep file `sweep_file` for spreadsheets and naive CSV readers: the
/// column line and the rows to `plain_csv` (no comment lines: its first row names the columns),
/// the `#` metadata lines (grid, shard, model: what resume and merge read) verbatim to the
/// sidecar plain_csv_metadata_path(plain_csv). Both written atomically; the sweep file itself
/// is left as it is (docs/design.md#spreadsheets).
void write_plain_csv(const std::string& sweep_file, const std::string& plain_csv);
/// Writes thresholds as CSV: <slice quantities>,theta_deg,status,omega,ratio,energy_ratio,refined.
void write_threshold_csv(std::ostream& out, const sweep::GridSpec& grid,
                         const std::vector<sweep::Threshold>& rows);

}  // namespace tribolab::app
