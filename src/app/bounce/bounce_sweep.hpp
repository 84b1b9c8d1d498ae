// `bounce sweep` and `bounce merge` as library functions (the application-layer contract of
// docs/design.md "Application layer: sweeps"): plain option structs in, the JSON the command
// prints plus the map as arrays out. The grid axes arrive parsed (sweep::Axis); nothing is
// printed, progress goes to a callback. docs/cli.md#bounce-sweep.
#pragma once

#include "app/common/option_fields.hpp"
#include "app/bounce/bounce_cell.hpp"
#include "app/sweep/sweep_command.hpp"
#include "report/plotly_script.hpp"

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tribolab::app {

/// A quantity that is either one value or an axis lo:hi:count (--speed, --mu; sweep/grid.hpp).
using ValueOrAxis = sweep::ValueOrAxis;

struct BounceSweepOptions {
  /// --theta-deg: impact angle axis lo:hi:count, deg (required)
  std::optional<sweep::Axis> theta_deg;
  std::optional<sweep::Axis> omega;  ///< --omega: spin axis, rad/s (exactly one of omega, ratio)
  std::optional<sweep::Axis> ratio;  ///< --ratio: spin/speed omega/|vy| axis, rad/m
  ValueOrAxis speed{4.0, std::nullopt};  ///< --speed: incoming vertical speed |vy|, m/s (seed 001 figure 53)
  ValueOrAxis mu{0.5, std::nullopt};     ///< --mu: friction coefficient (docs/cli.md, default of every --mu)
  std::string out;         ///< --out: the output CSV (required by the command; Python without it returns the map only); FILE.partial while running
  sweep::Shard shard;      ///< --shard i/N: only cells with index % N == i; default the whole grid
  int threads = 0;         ///< --threads: worker threads, 0 = all cores
  bool restart = false;    ///< --restart: discard an existing checkpoint or output
  std::string contour;     ///< --contour: the e = 1 boundary polylines CSV ("" = none)
  std::string threshold;   ///< --threshold: spin threshold per angle CSV ("" = none)
  /// --contour-tol: root tolerance of boundary points, fraction of the grid spacing
  double contour_tol = 1e-9;
  /// --plain-csv: also the map for spreadsheets, no comment lines (its metadata in FILE.meta.txt)
  std::string plain_csv;
  std::string report;      ///< --report: HTML report ("" = none)
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
  BounceCellOptions cell;  ///< the physics of a cell (--angle --vx ball, law, --g)

  // Not command-line options:
  /// Keep the map in the result (axes, outputs as arrays): cells x outputs doubles, read back
  /// from the finished file, so memory is bounded by the map itself.
  bool return_map = false;
  SweepProgressCallback progress;             ///< called as chunks complete (may be empty)
  const std::atomic<bool>* cancel = nullptr;  ///< set to stop; the cells done stay saved
  bool mpi = false;  ///< run over MPI_COMM_WORLD (a -DTRIBOLAB_MPI=ON build under a launcher)
};

/// The declaration of every option of `bounce sweep` (app/common/option_fields.hpp): the
/// command line and Python bind from it. The axes are ranges (sweep::Axis: LO:HI:COUNT on the
/// command line, (lo, hi, count) in Python), speed and mu a number or a range, the shard i/N
/// or (i, N); the cell's physics are `bounce simulate`'s options but mu (an axis here).
/// In bounce_sweep.cpp.
const Fields<BounceSweepOptions>& bounce_sweep_fields();

/// The map of a finished sweep for a notebook: axis k has axis_values[k] (the grid order:
/// the last axis varies fastest), output j is outputs[j] with one value per cell in that
/// order, so numpy's reshape(axis counts) gives an array shaped by the axes.
struct SweepMap {
  std::vector<std::string> axis_names;          ///< e.g. "theta_deg", "omega"
  std::vector<std::vector<double>> axis_values;
  std::vector<std::string> output_names;        ///< the cell model's outputs
  std::vector<std::vector<double>> outputs;     ///< [output][cell]
};

struct BounceSweepResult {
  nlohmann::json json;  ///< exactly what `bounce sweep --json` prints
  SweepCommandResult run;
  bool is_reporting_rank = true;  ///< false on MPI ranks other than 0 (json empty)
  std::optional<SweepMap> map;    ///< when options.return_map and the sweep completed
};

/// Validates (InputError naming the field), runs, resumes or
/// reuses the sweep, writes --contour/--threshold/--report from what it computed, returns the
/// result. A cancelled run throws InputError("interrupted: ... run the same command again to
/// resume") after saving its cells, as the command reports it.
BounceSweepResult bounce_sweep(const BounceSweepOptions& options);

struct BounceMergeOptions {
  std::vector<std::string> files;  ///< shard files, every shard i/N exactly once, any order
  std::string out;                 ///< --out: merged output CSV
  /// --plain-csv: also the merged map for spreadsheets, no comment lines (metadata in FILE.meta.txt)
  std::string plain_csv;
  std::string report;              ///< --report: HTML report ("" = none)
  report::PlotlyMode plotly = report::PlotlyMode::embed;  ///< --plotly: how the report gets Plotly.js (embed, cdn, file)
};

/// The declaration of every option of `bounce merge` (app/common/option_fields.hpp).
inline const Fields<BounceMergeOptions>& bounce_merge_fields() {
  using O = BounceMergeOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("files", &O::files, "", "shard files (every shard i/N exactly once, any order)").as(FieldRole::input_files).needed();
    d.add("out", &O::out, "", "merged output CSV").as(FieldRole::output_path).needed();
    d.add("plain_csv", &O::plain_csv, "",
          "also write the merged map for spreadsheets: no comment lines, the metadata in FILE.meta.txt")
        .as(FieldRole::output_path);
    d.add_report(&O::report, &O::plotly);
    return d;
  }();
  return f;
}
/// The keys of `bounce merge --json`: the merged file, its shards and cells. In bounce_sweep.cpp.
const ResultKeys& bounce_merge_result_keys();

struct BounceMergeResult {
  nlohmann::json json;  ///< exactly what `bounce merge --json` prints
};

/// Joins the shards (byte-identical to the unsharded run); with a report, the physics is
/// rebuilt from the first shard's header before anything is written.
BounceMergeResult bounce_merge(const BounceMergeOptions& options);

}  // namespace tribolab::app
