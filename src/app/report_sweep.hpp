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

/// Everything a sweep report shows: a complete sweep file read back and the boundary and
/// thresholds the sweep traced (the report builder traces nothing itself).
struct SweepReportData {
  io::SweepHeader header;     ///< grid, outputs and physics of the file (shard 0/1)
  std::vector<double> values;  ///< cell_count x outputs
  sweep::ContourResult boundary;           ///< the e = 1 polylines
  std::vector<sweep::Threshold> thresholds;  ///< per slice and angle
  double contour_tol = 1e-9;  ///< ContourOptions::x_tol_rel used
  std::string command;        ///< "bounce sweep" or "bounce merge", for the subtitle
};

/// The report: parameters, summary numbers, e (and omega_out when present) maps of up to
/// kReportMaxSlices slices with the boundary, the threshold curve and energy ratio.
report::Report sweep_report(const SweepReportData& d);

}  // namespace tribolab::app
