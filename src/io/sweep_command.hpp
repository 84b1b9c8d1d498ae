// What `bounce sweep` and `bounce merge` do, independent of the command-line parser:
// checkpointed, resumable, shardable sweeps written to the sweep file format
// (io/sweep_file.hpp), the merge of shard files, and the derived maps. The CLI layer only
// parses options into SweepCommandOptions and builds the CellModel. See docs/cli.md.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/contour.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::io {

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
  /// Empty when valid; messages name the command-line option.
  std::string validate() const;
};

struct SweepCommandResult {
  std::string status = "completed";  ///< "completed", "reused" (output already complete) or "cancelled"
  std::string out;                   ///< the output file (or its checkpoint when cancelled)
  std::int64_t cells_grid = 0;       ///< cells in the whole grid
  std::int64_t cells_shard = 0;      ///< cells in this shard
  std::int64_t cells_resumed = 0;    ///< cells found in the checkpoint (not recomputed)
  std::int64_t cells_computed = 0;   ///< cells computed by this run
  int threads = 0;
  double seconds = 0;                ///< wall time of the computation, s
  std::int64_t contour_lines = 0, contour_points = 0, contour_evaluations = 0;
  std::int64_t thresholds_found = 0;
};

/// Runs (or resumes, or reuses) a sweep. Writes FILE.partial as it goes - complete lines
/// in cell order, fsync'ed every fsync_interval_s - and renames it to FILE when every cell
/// is done, so killing the process at any moment loses only unwritten cells and an
/// interrupted + resumed run gives the same bytes as an uninterrupted one. A FILE that
/// already holds this complete sweep is reused (status "reused"; only the derived maps are
/// computed); one holding another sweep is an error unless restart. Progress lines go to
/// `progress` when it is not null. Throws InputError for invalid options or files.
SweepCommandResult run_sweep_command(const SweepCommandOptions& options, const sweep::CellModel& model,
                                     std::ostream* progress,
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

/// "lo:hi:count" -> Axis of quantity q; errors name `option`.
sweep::Axis parse_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// A single number ("4") or a range ("4:8:3"): nullopt axis and the value, or the axis.
struct ValueOrAxis {
  std::optional<sweep::Axis> axis;
  double value = 0;
};
ValueOrAxis parse_value_or_axis(std::string_view text, sweep::Quantity q, const std::string& option);
/// "i/N" -> Shard; errors name `option`.
sweep::Shard parse_shard(std::string_view text, const std::string& option);

/// Writes the --contour / --threshold files of a finished sweep (reads o.out) and counts
/// their contents into r. Needs the whole grid.
void write_derived_maps(const SweepCommandOptions& o, const sweep::CellModel& model,
                        SweepCommandResult& r);

/// One progress line: "\rsweep: done/total cells (pct%)  rate cells/s  elapsed s  ETA s".
void print_progress(std::ostream& out, const sweep::Progress& p);

/// The JSON result of `bounce sweep` (keys documented in docs/cli.md#bounce-sweep).
nlohmann::json sweep_result_json(const SweepCommandResult& r, const SweepCommandOptions& o);

/// Writes the polylines as CSV: line,closed,<slice quantities>,theta_deg,<omega|ratio>,refined.
void write_contour_csv(std::ostream& out, const sweep::ContourResult& contour);
/// Writes thresholds as CSV: <slice quantities>,theta_deg,status,omega,ratio,energy_ratio,refined.
void write_threshold_csv(std::ostream& out, const sweep::GridSpec& grid,
                         const std::vector<sweep::Threshold>& rows);

}  // namespace tribolab::io
