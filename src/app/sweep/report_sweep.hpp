// Report pages of phase-diagram sweeps: the theta x spin heat map with the e = 1 boundary
// drawn over it (shared by the demo's figures 53-55 and `bounce sweep/merge --report`), and
// the whole report of a finished sweep file. docs/cli.md#bounce-sweep, docs/theory.md#sweeps.
#pragma once

#include "io/sweep_file.hpp"
#include "report/report.hpp"
#include "sweep/contour.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tribolab::app {

/// Labels and colours of one sweep heat map.
struct SweepMapStyle {
  std::string title;
  std::string x_title;                            ///< the spin axis with its unit
  std::string y_title = "collision angle (deg)";  ///< the theta_deg axis with its unit
  std::string colorbar_title = "e";
  std::string quantity = "e";  ///< the mapped quantity's name in the computed caption
  std::string unit;            ///< its unit there ("" when dimensionless)
  report::ColorScale colorscale = report::ColorScale::RdBu;
  std::optional<double> z_mid = 1.0;  ///< centre of a diverging scale (restitution: 1)
  /// Draw at most this many grid values along each axis (every k-th row and column, the
  /// first always included); 0 = all. Bounds the size of a report of a huge grid.
  std::int64_t max_side = 0;
  int height_px = 420;
};

/// The polylines of `boundary` in slice `slice` as one black series "e = 1 boundary",
/// x = spin, y = theta_deg, NaN between polylines (empty when the slice has none).
report::Series boundary_series(const sweep::ContourResult& boundary, std::int64_t slice);

/// Heat map of output `output` over spin (x) x theta_deg (y) for slice `slice` of `values`
/// (cell_count x n_outputs, row-major, as from sweep::evaluate_grid or a sweep file), with
/// boundary_series(*boundary, slice) drawn over it when boundary is not null and the slice
/// has a boundary. The caption describes what the map shows (describe_heat_map).
report::Figure sweep_heat_map(const sweep::GridSpec& grid, const std::vector<double>& values,
                              std::size_t n_outputs, int output, std::int64_t slice,
                              const sweep::ContourResult* boundary, const SweepMapStyle& style);

/// Bounds of a sweep report (docs/cli.md#bounce-sweep, "Report").
inline constexpr std::int64_t kReportMaxSlices = 6;    ///< slices drawn as maps
inline constexpr std::int64_t kReportMaxSide = 201;    ///< grid values per map axis

/// Counts of e over some cells of a map.
struct SweepCellStats {
  std::int64_t cells = 0, finite = 0, above = 0;  ///< cells; with a result; with e > 1
  double e_max = std::numeric_limits<double>::quiet_NaN();  ///< largest e (NaN: none)
  std::int64_t at = -1;                                      ///< global index of the largest e
  void add(double e, std::int64_t cell);
};

/// What a sweep report shows of the map, gathered cell by cell (add) as the finished file is
/// read: the counts of the whole grid and per slice (the first 200 and the drawn ones), and
/// the drawn values of e and omega_out (every k-th row and column, at most kReportMaxSide per
/// axis, on at most kReportMaxSlices slices). Bounded by those, not by the grid: the report
/// of a 4e6-cell sweep holds no more than one of 40,000 (issue 26: the whole map was loaded).
class SweepMapSummary {
 public:
  explicit SweepMapSummary(const io::SweepHeader& header);
  /// The cell of global index `cell` (in order or not) with its outputs (header.outputs).
  void add(std::int64_t cell, const std::vector<double>& outputs);

  SweepCellStats all;                         ///< e over the whole grid
  SweepCellStats first_phase;                 ///< e_first over the whole grid (when present)
  std::int64_t several_contacts = 0;          ///< cells whose impact has several contacts
  std::int64_t first_phase_differs = 0;       ///< cells where e_first is on the other side of 1
  std::map<std::int64_t, SweepCellStats> slices;  ///< per slice: the first 200 and the drawn
  std::vector<std::int64_t> drawn_slices;     ///< the slices drawn as maps
  std::vector<std::int64_t> rows, cols;       ///< the drawn theta and spin indices
  /// Per drawn slice, e and omega_out (empty when absent) at rows x cols.
  std::map<std::int64_t, std::vector<std::vector<double>>> e_map, omega_out_map;

 private:
  int e_ = -1, omega_out_ = -1, contacts_ = -1, e_first_ = -1;
  std::int64_t per_slice_ = 1, n_spin_ = 1;
  std::vector<std::int64_t> row_at_, col_at_;  // drawn position of each index, or -1
};

/// The summary of a whole map held in memory (cell_count x outputs), e.g. from evaluate_grid.
SweepMapSummary summarize_sweep_map(const io::SweepHeader& header, const std::vector<double>& values);

/// Everything a sweep report shows: a complete sweep file's summary and the boundary and
/// thresholds the sweep traced (the report builder traces nothing itself).
struct SweepReportData {
  io::SweepHeader header;  ///< grid, outputs and physics of the file (shard 0/1)
  std::optional<SweepMapSummary> map;  ///< the file's values as the report shows them
  sweep::ContourResult boundary;           ///< the e = 1 polylines
  std::vector<sweep::Threshold> thresholds;  ///< per slice and angle
  double contour_tol = 1e-9;  ///< ContourOptions::x_tol_rel used
  std::string command;        ///< "bounce sweep" or "bounce merge", for the subtitle
};

/// The report: parameters, summary numbers, e (and omega_out when present) maps of up to
/// kReportMaxSlices slices with the boundary, the threshold curve and energy ratio.
report::Report sweep_report(const SweepReportData& d);

}  // namespace tribolab::app
