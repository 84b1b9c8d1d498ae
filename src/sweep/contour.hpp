// Derived maps of a finished sweep (seed 001, figures 53-56 and its "rotational to
// vertical kinetic energy ratio must exceed 2.56"): the e = 1 boundary by marching squares
// refined by root finding with the cell function itself, and the spin threshold per angle
// with its energy ratio. See docs/theory.md#sweeps.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::sweep {

struct ContourOptions {
  std::string output = "e";  ///< the output whose level set is traced (restitution)
  double level = 1.0;        ///< the level: e = 1 separates rebounds above the drop height
  /// Root tolerance along a grid edge, as a fraction of that edge's length (grid spacing).
  double x_tol_rel = 1e-9;
  /// Refine each crossing by root finding on the cell function (false: linear
  /// interpolation between the two grid values only; no extra cell evaluations).
  bool refine = true;
  int threads = 0;  ///< threads for refinement; 0 = all cores
  std::string validate() const;
};

/// One point of the boundary, in the slice's (theta_deg, spin) plane; spin is omega or
/// ratio, whichever the grid sweeps.
struct ContourPoint {
  double theta_deg = 0;  ///< deg
  double spin = 0;       ///< rad/s (omega axis) or rad/m (ratio axis)
  bool refined = false;  ///< root finding converged (else linear interpolation)
};

/// A connected piece of the boundary inside one slice.
struct Polyline {
  std::int64_t slice = 0;             ///< slice index (see ContourResult::slice_values)
  bool closed = false;                ///< a loop (first point repeated at the end)
  std::vector<ContourPoint> points;
};

struct ContourResult {
  Quantity spin_axis = Quantity::omega;  ///< omega or ratio
  /// For each slice, the values of the leading axes (speed and/or mu, canonical order);
  /// one slice with no values when neither is swept.
  std::vector<std::vector<double>> slice_values;
  std::vector<Quantity> slice_quantities;  ///< the leading axes' quantities
  std::vector<Polyline> lines;
  std::int64_t evaluations = 0;  ///< extra cell evaluations for refinement
  std::int64_t unrefined = 0;    ///< crossings where root finding did not converge
};

/// The level set output = level of the grid values `values` (cell_count x outputs,
/// row-major, as from evaluate_grid or a sweep file), per (speed, mu) slice.
/// Marching squares (Lorensen & Cline 1987, 2D case) with saddles resolved by evaluating
/// the cell function at the square's centre; each crossing on a grid edge is refined by
/// TOMS748 (numerics::find_root) on the cell function along that edge. Cells with a NaN
/// output are skipped. Deterministic: same points whatever the thread count.
ContourResult trace_contour(const GridSpec& grid, const CellModel& model,
                            const std::vector<double>& values, const ContourOptions& options);

/// The spin threshold at one angle: the first crossing of the level from below, scanning
/// the spin axis from lo to hi.
struct Threshold {
  enum class Status {
    found,       ///< output < level at lower spins, >= level from the threshold on
    below_grid,  ///< output >= level already at the first spin value
    none,        ///< output < level at every spin value of the grid (or NaN)
  };
  std::int64_t slice = 0;
  double theta_deg = 0;  ///< deg
  Status status = Status::none;
  double omega = 0;  ///< threshold spin, rad/s (NaN unless found)
  double ratio = 0;  ///< threshold omega / |vy|, rad/m (NaN unless found)
  /// Rotational over vertical translational kinetic energy at the threshold,
  /// (I omega^2 / 2) / (m vy^2 / 2) (seed 001: "must exceed 2.56"); NaN unless found and
  /// the model's mass and inertia are known.
  double energy_ratio = 0;
  bool refined = false;  ///< root finding converged
};

std::string status_name(Threshold::Status s);  ///< "found", "below_grid", "none"

/// One Threshold per slice and grid angle (slice-major, then theta order).
std::vector<Threshold> spin_thresholds(const GridSpec& grid, const CellModel& model,
                                       const std::vector<double>& values,
                                       const ContourOptions& options);

/// The boundary and the thresholds of a map whose values arrive one theta row at a time (the
/// grid's cell order: slice, then theta, then spin fastest), so a map of any size is traced
/// holding two rows, the crossings found and one Threshold per row, never the whole map
/// (`bounce sweep --contour/--threshold/--report` on a file; issue 26: 430 MB for 4e6 cells
/// before). trace_contour and spin_thresholds below are this tracer over a vector.
class MapTracer {
 public:
  /// Traces `options.output` = `options.level`; `boundary` / `thresholds` say which of the two
  /// maps are wanted (the other costs nothing).
  MapTracer(const GridSpec& grid, const CellModel& model, const ContourOptions& options, bool boundary = true,
            bool thresholds = true);
  ~MapTracer();
  MapTracer(const MapTracer&) = delete;
  MapTracer& operator=(const MapTracer&) = delete;
  /// The traced output's values of the next row (spin-axis count of them).
  void add_row(const std::vector<double>& row);
  std::int64_t rows_added() const;
  /// After every row: the polylines (refined by root finding, `options.threads`).
  ContourResult contour() const;
  /// After every row: one Threshold per slice and angle.
  std::vector<Threshold> thresholds() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace tribolab::sweep
