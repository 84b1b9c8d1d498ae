#include "sweep/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numerics/error.hpp"

namespace tribolab::sweep {
namespace {

constexpr std::array<std::string_view, kQuantityCount> kNames = {"speed", "mu", "theta_deg",
                                                                 "omega", "ratio"};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string_view quantity_name(Quantity q) { return kNames[static_cast<int>(q)]; }

std::optional<Quantity> quantity_from_name(std::string_view name) {
  for (int i = 0; i < kQuantityCount; ++i) {
    if (kNames[i] == name) return static_cast<Quantity>(i);
  }
  return std::nullopt;
}

double Axis::value(std::int64_t i) const {
  if (count <= 1 || i == 0) return lo;
  if (i == count - 1) return hi;
  return lo + (hi - lo) * (static_cast<double>(i) / static_cast<double>(count - 1));
}

std::string Axis::validate() const {
  const std::string name(quantity_name(quantity));
  if (count < 1) return name + ": count must be at least 1, got " + std::to_string(count);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return name + ": lo and hi must be finite";
  if (count == 1 && lo != hi) {
    return name + ": a single value (count 1) needs lo = hi, got " + num(lo) + " and " + num(hi);
  }
  if (count > 1 && lo == hi) return name + ": lo = hi with count " + std::to_string(count) +
                                        " would repeat one value; use count 1";
  if (quantity == Quantity::speed && (lo <= 0 || hi <= 0)) {
    return name + ": the incoming speed must be > 0 m/s";
  }
  if (quantity == Quantity::mu && (lo < 0 || hi < 0)) return name + ": mu must be >= 0";
  return {};
}

void sort_axes(std::vector<Axis>& axes) {
  std::stable_sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) {
    return static_cast<int>(a.quantity) < static_cast<int>(b.quantity);
  });
}

std::string GridSpec::validate() const {
  for (const Axis& a : axes) {
    if (auto e = a.validate(); !e.empty()) return e;
  }
  for (std::size_t i = 1; i < axes.size(); ++i) {
    if (axes[i - 1].quantity == axes[i].quantity) {
      return std::string(quantity_name(axes[i].quantity)) + ": axis given twice";
    }
    if (static_cast<int>(axes[i - 1].quantity) > static_cast<int>(axes[i].quantity)) {
      return "axes are not in canonical order (speed, mu, theta_deg, omega|ratio)";
    }
  }
  if (axis(Quantity::theta_deg) == nullptr) return "theta_deg: the impact-angle axis is required";
  const bool has_omega = axis(Quantity::omega) != nullptr;
  const bool has_ratio = axis(Quantity::ratio) != nullptr;
  if (has_omega == has_ratio) return "exactly one of omega and ratio must be swept";
  if (!(std::isfinite(fixed_speed) && fixed_speed > 0)) {
    return "speed: the incoming speed must be a finite number > 0 m/s, got " + num(fixed_speed);
  }
  if (!(std::isfinite(fixed_mu) && fixed_mu >= 0)) {
    return "mu: must be a finite number >= 0, got " + num(fixed_mu);
  }
  // Cell indices are int64 and coordinates are doubles: keep the count exactly
  // representable in both (2^53).
  constexpr std::int64_t kMaxCells = std::int64_t{1} << 53;
  std::int64_t n = 1;
  for (const Axis& a : axes) {
    if (n > kMaxCells / a.count) return "the grid has too many cells (more than 2^53)";
    n *= a.count;
  }
  return {};
}

std::int64_t GridSpec::cell_count() const {
  std::int64_t n = 1;
  for (const Axis& a : axes) n *= a.count;
  return n;
}

int GridSpec::axis_position(Quantity q) const {
  for (std::size_t i = 0; i < axes.size(); ++i) {
    if (axes[i].quantity == q) return static_cast<int>(i);
  }
  return -1;
}

const Axis* GridSpec::axis(Quantity q) const {
  const int p = axis_position(q);
  return p < 0 ? nullptr : &axes[static_cast<std::size_t>(p)];
}

std::vector<std::int64_t> GridSpec::indices(std::int64_t index) const {
  std::vector<std::int64_t> idx(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    idx[k] = index % axes[k].count;
    index /= axes[k].count;
  }
  return idx;
}

std::int64_t GridSpec::index_of(const std::vector<std::int64_t>& idx) const {
  TRIBOLAB_ASSERT(idx.size() == axes.size(), "indices size mismatch");
  std::int64_t index = 0;
  for (std::size_t k = 0; k < axes.size(); ++k) index = index * axes[k].count + idx[k];
  return index;
}

namespace {

/// Sets the field of `in` that `q` names.
void assign(CellInput& in, Quantity q, double v, bool& ratio_swept) {
  switch (q) {
    case Quantity::speed: in.speed = v; break;
    case Quantity::mu: in.mu = v; break;
    case Quantity::theta_deg: in.theta_deg = v; break;
    case Quantity::omega: in.omega = v; break;
    case Quantity::ratio: in.ratio = v; ratio_swept = true; break;
  }
}

/// omega and ratio = omega/speed determine each other: fill the one not swept.
void complete(CellInput& in, bool ratio_swept) {
  if (ratio_swept) {
    in.omega = in.ratio * in.speed;
  } else {
    in.ratio = in.omega / in.speed;
  }
}

}  // namespace

CellInput GridSpec::at(const std::vector<double>& coords) const {
  TRIBOLAB_ASSERT(coords.size() == axes.size(), "coordinate count mismatch");
  CellInput in;
  in.index = -1;
  in.speed = fixed_speed;
  in.mu = fixed_mu;
  bool ratio_swept = false;
  for (std::size_t k = 0; k < axes.size(); ++k) assign(in, axes[k].quantity, coords[k], ratio_swept);
  complete(in, ratio_swept);
  return in;
}

CellInput GridSpec::cell(std::int64_t index) const {
  // Same result as at() for the cell's coordinates, without allocating: this runs once per
  // cell in the hot loop.
  CellInput in;
  in.index = index;
  in.speed = fixed_speed;
  in.mu = fixed_mu;
  bool ratio_swept = false;
  std::int64_t rest = index;
  for (std::size_t k = axes.size(); k-- > 0;) {
    const Axis& a = axes[k];
    assign(in, a.quantity, a.value(rest % a.count), ratio_swept);
    rest /= a.count;
  }
  complete(in, ratio_swept);
  return in;
}

std::int64_t Shard::cells(std::int64_t total) const {
  if (index >= total) return 0;
  return (total - index + count - 1) / count;
}

std::string Shard::validate() const {
  if (count < 1) return "shard count must be at least 1, got " + std::to_string(count);
  if (index < 0 || index >= count) {
    return "shard index must be in 0.." + std::to_string(count - 1) + ", got " +
           std::to_string(index);
  }
  return {};
}

}  // namespace tribolab::sweep
