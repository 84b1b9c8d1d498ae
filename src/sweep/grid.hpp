// The parameter grid of a phase-diagram sweep (SPEC section 3.5, seed 001 figures 53-56):
// named axes lo:hi:count, a deterministic cell order and cell index <-> coordinates.
// See docs/theory.md#sweeps.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::sweep {

/// The quantities a sweep can vary. The enumerator order is the canonical axis order of a
/// grid: cells are numbered row-major over (speed, mu, theta_deg, omega | ratio), absent
/// axes skipped, the LAST axis varying fastest. Each (speed, mu) slice is therefore one
/// contiguous theta x spin heat map, stored row by row (constant theta_deg per row).
enum class Quantity : int {
  speed = 0,      ///< incoming vertical speed |vy|, m/s (seed figure 53: 4, figure 54: 8)
  mu = 1,         ///< Coulomb friction coefficient, dimensionless, usually 0.3-0.7
  theta_deg = 2,  ///< impact angle, degrees (seed: collision angle 100-170 deg)
  omega = 3,      ///< incoming spin, rad/s, counter-clockwise positive (seed: 30-50)
  ratio = 4,      ///< spin/speed ratio omega/|vy|, rad/m (seed figure 55); omega = ratio*speed
};
inline constexpr int kQuantityCount = 5;

/// "speed", "mu", "theta_deg", "omega", "ratio" (also the CSV column names).
std::string_view quantity_name(Quantity q);
/// Inverse of quantity_name; nullopt for an unknown name.
std::optional<Quantity> quantity_from_name(std::string_view name);

/// One axis: `count` equally spaced values from lo to hi inclusive; count = 1 is the single
/// value lo (hi must then equal lo). lo > hi is allowed (values then decrease).
struct Axis {
  Quantity quantity = Quantity::theta_deg;
  double lo = 0;           ///< first value, in the quantity's unit
  double hi = 0;           ///< last value (exactly), in the quantity's unit
  std::int64_t count = 1;  ///< number of values, >= 1

  /// Value i in [0, count): lo + (hi - lo) * i / (count - 1); the last one is exactly hi.
  double value(std::int64_t i) const;
  /// Empty when valid, else a message naming the quantity.
  std::string validate() const;
  bool operator==(const Axis&) const = default;
};

/// A quantity that is either one value or an axis lo:hi:count (`bounce sweep --speed`, `--mu`).
struct ValueOrAxis {
  double value = 0;          ///< the value, or the grid's fixed value when swept (file header)
  std::optional<Axis> axis;  ///< its quantity is set by the workflow
};

/// A cell's inputs, handed to the cell function. Every field is always set: quantities
/// that are not swept take the grid's fixed value.
struct CellInput {
  std::int64_t index = 0;  ///< global cell index in the grid's cell order
  double theta_deg = 0;    ///< impact angle, deg (typically 100-170)
  double omega = 0;        ///< incoming spin, rad/s (typically 30-50); ratio*speed if ratio swept
  double speed = 0;        ///< incoming vertical speed |vy|, m/s (typically 4)
  double mu = 0;           ///< friction coefficient (typically 0.5)
  double ratio = 0;        ///< omega / speed, rad/m (always set, swept or derived)
};

/// The whole grid: swept axes in canonical order plus the fixed values of the quantities
/// that are not swept.
struct GridSpec {
  std::vector<Axis> axes;    ///< canonical order (see Quantity); theta_deg and one of omega/ratio required
  double fixed_speed = 4.0;  ///< m/s, used when speed is not an axis (seed figure 53: 4 m/s)
  double fixed_mu = 0.5;     ///< used when mu is not an axis (SPEC section 3 default)

  /// Empty when valid. Checks each axis, the canonical order, no duplicate, theta_deg
  /// present, exactly one of omega and ratio, speed > 0, mu >= 0, and the cell count fits.
  std::string validate() const;
  /// Product of the axis counts.
  std::int64_t cell_count() const;
  /// The axis of quantity q, or nullptr if q is not swept.
  const Axis* axis(Quantity q) const;
  /// Position of q's axis in `axes`, or -1.
  int axis_position(Quantity q) const;
  /// Inputs of cell `index` (0 <= index < cell_count()).
  CellInput cell(std::int64_t index) const;
  /// Inputs at arbitrary (not necessarily grid) coordinates, one value per axis in order;
  /// used to refine boundaries between grid points. index is set to -1.
  CellInput at(const std::vector<double>& coords) const;
  /// Per-axis indices of cell `index` (last axis fastest).
  std::vector<std::int64_t> indices(std::int64_t index) const;
  /// Inverse of indices().
  std::int64_t index_of(const std::vector<std::int64_t>& indices) const;
  bool operator==(const GridSpec&) const = default;
};

/// Puts axes into canonical order (stable); does not validate.
void sort_axes(std::vector<Axis>& axes);

/// A part of the grid: shard `index` of `count` holds the cells whose global index g has
/// g % count == index (interleaved, so slow regions of the grid spread over all shards).
/// Its local cell k is global cell index + k * count.
struct Shard {
  std::int64_t index = 0;  ///< 0 <= index < count
  std::int64_t count = 1;  ///< number of shards, >= 1
  /// Number of cells of a grid of `total` cells in this shard.
  std::int64_t cells(std::int64_t total) const;
  std::int64_t global(std::int64_t local) const { return index + local * count; }
  std::string validate() const;
  bool operator==(const Shard&) const = default;
};

}  // namespace tribolab::sweep
