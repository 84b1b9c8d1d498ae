#include "app/sweep/report_sweep.hpp"

#include "numerics/error.hpp"
#include "report/format.hpp"
#include "app/sweep/report_map_caption.hpp"
#include "app/common/report_util.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribolab::app {
namespace {

using report::format_value;

/// seed 001: "rotational to vertical kinetic energy ratio must exceed 2.56" (see the erratum
/// in docs/theory.md#errata-in-the-seeds).
constexpr double kSeedEnergyRatio = 2.56;


/// Every k-th index of 0..n-1 (k the smallest stride giving at most max_side values); the
/// last index is added when the stride skips it, so the map spans the whole axis.
std::vector<std::int64_t> drawn_indices(std::int64_t n, std::int64_t max_side) {
  std::int64_t stride = 1;
  if (max_side > 1 && n > max_side) stride = (n - 1 + max_side - 2) / (max_side - 1);
  std::vector<std::int64_t> out;
  for (std::int64_t i = 0; i < n; i += stride) out.push_back(i);
  if (out.back() != n - 1) out.push_back(n - 1);
  return out;
}

std::string unit_of(sweep::Quantity q) {
  switch (q) {
    case sweep::Quantity::speed: return "m/s";
    case sweep::Quantity::mu: return "";
    case sweep::Quantity::theta_deg: return "deg";
    case sweep::Quantity::omega: return "rad/s";
    case sweep::Quantity::ratio: return "rad/m";
  }
  return "";
}

std::string spin_title(sweep::Quantity q) {
  // The sign is said: the seed's figures 53-56 use clockwise spin for a ball moving to +x
  // (negative here; docs/theory.md, errata 討論 四), as the demo's maps do.
  return q == sweep::Quantity::ratio ? "spin/speed ω/|v_y| (rad/m, counter-clockwise positive)"
                                     : "incoming spin ω (rad/s, counter-clockwise positive)";
}

/// The theta axis title from the physics description ("angle=collision" of the bounce cell,
/// docs/cli.md#bounce-sweep).
std::string theta_title(const std::string& model) {
  if (model.find(" angle=collision") != std::string::npos) return "collision angle (deg)";
  if (model.find(" angle=orientation") != std::string::npos) return "orientation θ at first touch (deg)";
  return "theta_deg (deg)";
}

/// "speed = 4 m/s, mu = 0.5" for a slice (empty when there are no leading axes).
std::string slice_label(const sweep::ContourResult& c, std::int64_t slice) {
  std::string s;
  const auto& v = c.slice_values[static_cast<std::size_t>(slice)];
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string unit = unit_of(c.slice_quantities[k]);
    s += (k ? ", " : "") + std::string(sweep::quantity_name(c.slice_quantities[k])) + " = " +
         io::format_number_exact(v[k]) + (unit.empty() ? "" : " " + unit);
  }
  return s;
}

/// The slices drawn: all when at most kReportMaxSlices, else that many evenly spaced ones,
/// first and last included.
std::vector<std::int64_t> drawn_slices(std::int64_t n) {
  std::vector<std::int64_t> out;
  if (n <= kReportMaxSlices) {
    for (std::int64_t s = 0; s < n; ++s) out.push_back(s);
    return out;
  }
  for (std::int64_t k = 0; k < kReportMaxSlices; ++k) {
    const std::int64_t s = (k * (n - 1) + (kReportMaxSlices - 1) / 2) / (kReportMaxSlices - 1);
    if (out.empty() || out.back() != s) out.push_back(s);
  }
  return out;
}

using SliceStats = SweepCellStats;

std::string percent(std::int64_t part, std::int64_t whole) {
  return whole > 0 ? format_value(100.0 * static_cast<double>(part) / static_cast<double>(whole), 4) + " %" : "—";
}

std::string where(const sweep::GridSpec& grid, std::int64_t cell) {
  if (cell < 0) return "—";
  const sweep::CellInput in = grid.cell(cell);
  const sweep::Quantity spin = grid.axes.back().quantity;
  std::string s = "theta_deg = " + io::format_number_exact(in.theta_deg) + ", " +
                  std::string(sweep::quantity_name(spin)) + " = " +
                  io::format_number_exact(spin == sweep::Quantity::ratio ? in.ratio : in.omega);
  if (grid.axis(sweep::Quantity::speed)) s += ", speed = " + io::format_number_exact(in.speed);
  if (grid.axis(sweep::Quantity::mu)) s += ", mu = " + io::format_number_exact(in.mu);
  return s;
}

report::Table parameters_table(const SweepReportData& d) {
  const sweep::GridSpec& g = d.header.grid;
  report::Table t;
  t.caption = "Parameters of the sweep (from the header of the sweep file)";
  t.header = {"parameter", "value"};
  for (const sweep::Axis& a : g.axes) {
    const std::string unit = unit_of(a.quantity);
    t.rows.push_back({std::string(sweep::quantity_name(a.quantity)) + (unit.empty() ? "" : " (" + unit + ")"),
                      "swept " + io::format_number_exact(a.lo) + " to " + io::format_number_exact(a.hi) + ", " +
                          std::to_string(a.count) + " values"});
  }
  if (!g.axis(sweep::Quantity::speed)) t.rows.push_back({"speed (m/s)", io::format_number_exact(g.fixed_speed)});
  if (!g.axis(sweep::Quantity::mu)) t.rows.push_back({"mu", io::format_number_exact(g.fixed_mu)});
  // The physics: "bounce-contact angle=collision vx=0 a=0.145 ..." -> one row per key=value.
  const std::vector<std::string> words = [&] {
    std::vector<std::string> w;
    std::size_t p = 0;
    while (p < d.header.model.size()) {
      const std::size_t q = std::min(d.header.model.find(' ', p), d.header.model.size());
      if (q > p) w.push_back(d.header.model.substr(p, q - p));
      p = q + 1;
    }
    return w;
  }();
  // K and D take their unit from the law (docs/theory.md#bounce-normal-laws): N/m and N s/m
  // for Hooke, N/m^n and N s/m^(n+1) for Hunt–Crossley; the other keys' units come from the
  // report's unit column (report/units.hpp).
  std::string law, n = "n";
  for (const std::string& w : words) {
    if (w.rfind("law=", 0) == 0) law = w.substr(4);
    if (w.rfind("n=", 0) == 0) n = w.substr(2);
  }
  const bool hooke = law == "hooke";
  std::string other;
  for (const std::string& w : words) {
    const auto eq = w.find('=');
    if (eq == std::string::npos || eq == 0) {
      other += (other.empty() ? "" : " ") + w;
    } else {
      std::string key = w.substr(0, eq);
      if (key == "K" && !law.empty()) key += hooke ? " (N/m)" : " (N/m^" + n + ")";
      if (key == "D" && !law.empty()) key += hooke ? " (N s/m)" : " (N s/m^(" + n + "+1))";
      t.rows.push_back({key, w.substr(eq + 1)});
    }
  }
  if (!other.empty()) t.rows.insert(t.rows.begin(), {"cell model", other});
  t.rows.push_back({"boundary root tolerance (fraction of the grid spacing)", io::format_number_exact(d.contour_tol)});
  return t;
}

}  // namespace

report::Series boundary_series(const sweep::ContourResult& boundary, std::int64_t slice) {
  report::Series b = named("e = 1 boundary", report::Mode::Lines);
  b.color = "black";
  for (const auto& line : boundary.lines) {
    if (line.slice != slice) continue;
    if (!b.x.empty()) {
      b.x.push_back(kNaN);
      b.y.push_back(kNaN);
    }
    for (const auto& p : line.points) {
      b.x.push_back(p.spin);
      b.y.push_back(p.theta_deg);
    }
  }
  return b;
}

namespace {

/// The heat map of z (rows: theta indices `rows`, columns: spin indices `cols` of the grid)
/// with the slice's boundary drawn over it.
report::Figure heat_map_of(const sweep::GridSpec& grid, const std::vector<std::int64_t>& rows,
                           const std::vector<std::int64_t>& cols, std::vector<std::vector<double>> z,
                           std::int64_t slice, const sweep::ContourResult* boundary, const SweepMapStyle& style) {
  const sweep::Axis& th = grid.axes[grid.axes.size() - 2];
  const sweep::Axis& sp = grid.axes.back();
  report::HeatMap h;
  for (std::int64_t j : cols) h.x.push_back(sp.value(j));
  for (std::int64_t i : rows) h.y.push_back(th.value(i));
  h.z = std::move(z);
  h.colorbar_title = style.colorbar_title;
  h.colorscale = style.colorscale;
  h.z_mid = style.z_mid;
  report::Figure f;
  f.title = style.title;
  f.x_axis.title = style.x_title;
  f.y_axis.title = style.y_title;
  f.heatmap = std::move(h);
  if (boundary != nullptr) {
    report::Series b = boundary_series(*boundary, slice);
    if (!b.x.empty()) f.series.push_back(std::move(b));
  }
  f.height_px = style.height_px;
  f.caption = describe_heat_map(f, style.quantity, style.unit);
  return f;
}

}  // namespace

report::Figure sweep_heat_map(const sweep::GridSpec& grid, const std::vector<double>& values,
                              std::size_t n_outputs, int output, std::int64_t slice,
                              const sweep::ContourResult* boundary, const SweepMapStyle& style) {
  TRIBOLAB_ASSERT(grid.axes.size() >= 2 && output >= 0 && static_cast<std::size_t>(output) < n_outputs,
                  "sweep_heat_map: bad grid or output");
  const sweep::Axis& th = grid.axes[grid.axes.size() - 2];
  const sweep::Axis& sp = grid.axes.back();
  const std::int64_t per_slice = th.count * sp.count;
  TRIBOLAB_ASSERT(values.size() >= static_cast<std::size_t>((slice + 1) * per_slice) * n_outputs,
                  "sweep_heat_map: too few values for the slice");
  const std::vector<std::int64_t> rows = drawn_indices(th.count, style.max_side);
  const std::vector<std::int64_t> cols = drawn_indices(sp.count, style.max_side);
  std::vector<std::vector<double>> z;
  for (std::int64_t i : rows) {
    std::vector<double> row;
    row.reserve(cols.size());
    for (std::int64_t j : cols)
      row.push_back(values[static_cast<std::size_t>(slice * per_slice + i * sp.count + j) * n_outputs +
                           static_cast<std::size_t>(output)]);
    z.push_back(std::move(row));
  }
  return heat_map_of(grid, rows, cols, std::move(z), slice, boundary, style);
}

void SweepCellStats::add(double e, std::int64_t cell) {
  ++cells;
  if (!std::isfinite(e)) return;
  ++finite;
  above += e > 1 ? 1 : 0;
  if (at < 0 || e > e_max) {
    e_max = e;
    at = cell;
  }
}

SweepMapSummary::SweepMapSummary(const io::SweepHeader& header) {
  const auto index_of = [&](const std::string& name) {
    const auto it = std::find(header.outputs.begin(), header.outputs.end(), name);
    return it == header.outputs.end() ? -1 : static_cast<int>(it - header.outputs.begin());
  };
  e_ = index_of("e");
  omega_out_ = index_of("omega_out");
  contacts_ = index_of("contacts");
  e_first_ = index_of("e_first");
  TRIBOLAB_ASSERT(e_ >= 0, "sweep report: no output e");
  const sweep::GridSpec& grid = header.grid;
  const sweep::Axis& th = grid.axes[grid.axes.size() - 2];
  const sweep::Axis& sp = grid.axes.back();
  per_slice_ = th.count * sp.count;
  n_spin_ = sp.count;
  drawn_slices = ::tribolab::app::drawn_slices(grid.cell_count() / per_slice_);
  rows = drawn_indices(th.count, kReportMaxSide);
  cols = drawn_indices(sp.count, kReportMaxSide);
  row_at_.assign(static_cast<std::size_t>(th.count), -1);
  col_at_.assign(static_cast<std::size_t>(sp.count), -1);
  for (std::size_t k = 0; k < rows.size(); ++k) row_at_[static_cast<std::size_t>(rows[k])] = static_cast<std::int64_t>(k);
  for (std::size_t k = 0; k < cols.size(); ++k) col_at_[static_cast<std::size_t>(cols[k])] = static_cast<std::int64_t>(k);
  const std::vector<std::vector<double>> blank(rows.size(), std::vector<double>(cols.size(), kNaN));
  for (std::int64_t s = 0; s < std::min<std::int64_t>(200, grid.cell_count() / per_slice_); ++s) slices[s];
  for (std::int64_t s : drawn_slices) {
    slices[s];
    e_map[s] = blank;
    if (omega_out_ >= 0) omega_out_map[s] = blank;
  }
}

void SweepMapSummary::add(std::int64_t cell, const std::vector<double>& v) {
  const double e = v[static_cast<std::size_t>(e_)];
  all.add(e, cell);
  if (contacts_ >= 0 && e_first_ >= 0) {
    const double ef = v[static_cast<std::size_t>(e_first_)];
    first_phase.add(ef, cell);
    several_contacts += v[static_cast<std::size_t>(contacts_)] > 1 ? 1 : 0;
    first_phase_differs += std::isfinite(e) && std::isfinite(ef) && (e > 1) != (ef > 1) ? 1 : 0;
  }
  const std::int64_t s = cell / per_slice_;
  const auto it = slices.find(s);
  if (it == slices.end()) return;
  it->second.add(e, cell);
  const auto m = e_map.find(s);
  if (m == e_map.end()) return;
  const std::int64_t r = row_at_[static_cast<std::size_t>((cell % per_slice_) / n_spin_)];
  const std::int64_t c = col_at_[static_cast<std::size_t>(cell % n_spin_)];
  if (r < 0 || c < 0) return;
  m->second[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = e;
  if (omega_out_ >= 0)
    omega_out_map[s][static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = v[static_cast<std::size_t>(omega_out_)];
}

SweepMapSummary summarize_sweep_map(const io::SweepHeader& header, const std::vector<double>& values) {
  SweepMapSummary m(header);
  const std::size_t n_out = header.outputs.size();
  TRIBOLAB_ASSERT(values.size() == static_cast<std::size_t>(header.grid.cell_count()) * n_out,
                  "summarize_sweep_map: values size " + std::to_string(values.size()));
  std::vector<double> row(n_out);
  for (std::int64_t c = 0; c < header.grid.cell_count(); ++c) {
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(c) * n_out),
                static_cast<std::ptrdiff_t>(n_out), row.begin());
    m.add(c, row);
  }
  return m;
}

namespace {

/// What every section of the sweep report reads: the grid, its two map axes, the slices drawn.
struct SweepReportView {
  const SweepReportData& d;
  const sweep::GridSpec& grid;
  const SweepMapSummary& map;
  const sweep::Axis& th;  ///< the impact angle axis (the maps' y)
  const sweep::Axis& sp;  ///< the spin axis (the maps' x)
  std::int64_t n_slices;
  const std::vector<std::int64_t>& shown;
  std::string x_title, y_title;

  explicit SweepReportView(const SweepReportData& data)
      : d(data),
        grid(data.header.grid),
        map(*data.map),
        th(grid.axes[grid.axes.size() - 2]),
        sp(grid.axes.back()),
        n_slices(grid.cell_count() / (th.count * sp.count)),
        shown(map.drawn_slices),
        x_title(spin_title(sp.quantity)),
        y_title(theta_title(data.header.model)) {}

  /// The column of output `name` in the sweep file, or -1.
  int index_of(const std::string& name) const {
    const auto it = std::find(d.header.outputs.begin(), d.header.outputs.end(), name);
    return it == d.header.outputs.end() ? -1 : static_cast<int>(it - d.header.outputs.begin());
  }
};

void add_parameters_section(report::Report& r, const SweepReportView& v) {
  const SweepReportData& d = v.d;
  auto& p = r.add_section("Parameters");
  p.add_paragraph(v.index_of("contacts") >= 0
                      ? "Each cell is one whole impact from first touch with incoming v_y = −speed and the cell's "
                        "spin: every contact until the ball flies free to its apex (docs/theory.md#bounce-contact); "
                        "e = −v_y,out/v_y,in with v_y,out after the last contact. Values as written in the sweep file "
                        "(its header records the grid and every physical option)."
                      : "Each cell is one contact from first touch (the first contact phase only: a sweep file "
                        "written before whole impacts) with incoming v_y = −speed and the cell's spin; "
                        "e = −v_y,out/v_y,in. Values as written in the sweep file (its header records the grid and "
                        "every physical option).");
  p.add_equation("e = −v_{y,out} / v_{y,in}", "rugby-ball study, figures 53–56; docs/theory.md#sweeps",
                 "e > 1: the ball rises above the height it fell from");
  p.add_equation("E_{rot}/E_y = I ω^2 / (m v_y^2)", "rugby-ball study (\"must exceed 2.56\"); docs/theory.md#sweeps",
                 "rotational over vertical translational kinetic energy at the spin threshold");
  p.add_table(parameters_table(d));

}

// Summary numbers.
void add_summary_section(report::Report& r, const SweepReportView& v) {
  const SweepReportData& d = v.d;
  const sweep::GridSpec& grid = v.grid;
  const SweepMapSummary& map = v.map;
  const std::int64_t n_slices = v.n_slices;
  auto& s = r.add_section("Summary");
  const SliceStats& all = map.all;
  std::int64_t points = 0, found = 0;
  for (const auto& l : d.boundary.lines) points += static_cast<std::int64_t>(l.points.size());
  double er_min = kNaN;
  const sweep::Threshold* er_at = nullptr;
  for (const auto& t : d.thresholds) {
    if (t.status != sweep::Threshold::Status::found) continue;
    ++found;
    if (std::isfinite(t.energy_ratio) && (er_at == nullptr || t.energy_ratio < er_min)) {
      er_min = t.energy_ratio;
      er_at = &t;
    }
  }
  report::Table sum;
  sum.caption = "Summary of the whole grid";
  sum.header = {"quantity", "value"};
  sum.rows = {
      {"cells", std::to_string(all.cells)},
      {"cells without a result (no contact or failed: nan)", std::to_string(all.cells - all.finite)},
      {"largest e", format_value(all.e_max)},
      {"largest e at", where(grid, all.at)},
      {"cells with e > 1 (of the cells with a result)", std::to_string(all.above) + " (" + percent(all.above, all.finite) + ")"},
      {"e = 1 boundary", std::to_string(d.boundary.lines.size()) +
                             (d.boundary.lines.size() == 1 ? " polyline, " : " polylines, ") + std::to_string(points) +
                             " points (" + std::to_string(d.boundary.unrefined) + " not refined by root finding)"},
      {"angles with a spin threshold (e reaches 1 inside the grid)",
       std::to_string(found) + " of " + std::to_string(d.thresholds.size())},
      {"smallest energy ratio E_rot/E_y at a threshold (the study: 2.56)",
       er_at ? format_value(er_min) + " at theta_deg = " + io::format_number_exact(er_at->theta_deg) : "—"},
  };
  const int contacts = v.index_of("contacts"), e_first = v.index_of("e_first");
  if (contacts >= 0 && e_first >= 0) {
    // The whole impact against its first contact phase (docs/theory.md#sweeps).
    const std::int64_t several = map.several_contacts, differ = map.first_phase_differs;
    const SliceStats& first = map.first_phase;
    sum.rows.push_back({"cells whose impact has several contacts", std::to_string(several)});
    sum.rows.push_back({"largest e of the first contact phase alone", format_value(first.e_max)});
    sum.rows.push_back({"cells where the first phase alone is on the other side of e = 1", std::to_string(differ)});
  }
  s.add_table(std::move(sum));
  if (n_slices > 1) {
    report::Table per;
    per.caption = "Per slice";
    per.header = {"slice", "largest e", "at", "cells with e > 1"};
    for (std::int64_t k = 0; k < n_slices && k < 200; ++k) {
      const SliceStats& st = map.slices.at(k);
      per.rows.push_back({slice_label(d.boundary, k), format_value(st.e_max), where(grid, st.at),
                          std::to_string(st.above) + " (" + percent(st.above, st.finite) + ")"});
    }
    if (n_slices > 200) per.caption += " (the first 200 of " + std::to_string(n_slices) + ")";
    s.add_table(std::move(per));
  }

}

void add_e_maps_section(report::Report& r, const SweepReportView& v) {
  const SweepReportData& d = v.d;
  const sweep::GridSpec& grid = v.grid;
  const SweepMapSummary& map = v.map;
  const sweep::Axis& th = v.th;
  const sweep::Axis& sp = v.sp;
  const std::int64_t n_slices = v.n_slices;
  const std::vector<std::int64_t>& shown = v.shown;
  const std::string& x_title = v.x_title;
  const std::string& y_title = v.y_title;
  auto& m = r.add_section("Maps of e with the e = 1 boundary");
  std::string bound = "Blue: e > 1 (the ball rises above its drop height), red: e < 1, blank: no result. The black "
                      "curve is the e = 1 boundary, traced by marching squares and refined by root finding on the "
                      "cell function (the points of --contour).";
  if (shown.size() < static_cast<std::size_t>(n_slices)) {
    bound += " " + std::to_string(shown.size()) + " of the " + std::to_string(n_slices) +
             " slices are drawn, evenly spaced (first and last included); the summary covers all.";
  }
  if (th.count > kReportMaxSide || sp.count > kReportMaxSide) {
    bound += " The maps draw every k-th grid value (at most " + std::to_string(kReportMaxSide) +
             " per axis); the boundary uses the whole grid.";
  }
  m.add_paragraph(bound);
  for (std::int64_t slice : shown) {
    const std::string label = slice_label(d.boundary, slice);
    SweepMapStyle st;
    st.title = "Restitution e" + (label.empty() ? std::string() : ", " + label);
    st.x_title = x_title;
    st.y_title = y_title;
    st.max_side = kReportMaxSide;
    report::Figure f = heat_map_of(grid, map.rows, map.cols, map.e_map.at(slice), slice, &d.boundary, st);
    const SliceStats& ss = map.slices.at(slice);
    if (ss.finite > 0 && (th.count > kReportMaxSide || sp.count > kReportMaxSide))
      f.caption += " Over the whole grid of this slice: largest e " + format_value(ss.e_max) +
                   (ss.at >= 0 ? " at " + where(grid, ss.at) : "") + "; e > 1 in " + percent(ss.above, ss.finite) +
                   " of the cells with a result.";
    m.add_figure(std::move(f));
  }
}

void add_spin_maps_section(report::Report& r, const SweepReportView& v) {
  const SweepReportData& d = v.d;
  const sweep::GridSpec& grid = v.grid;
  const SweepMapSummary& map = v.map;
  const std::vector<std::int64_t>& shown = v.shown;
  const std::string& x_title = v.x_title;
  const std::string& y_title = v.y_title;
  auto& o = r.add_section("Maps of the outgoing spin");
  o.add_paragraph("ω_out after the contact (rad/s, counter-clockwise positive), with the e = 1 boundary: where "
                  "e > 1 the contact turned spin into vertical speed.");
  for (std::int64_t slice : shown) {
    const std::string label = slice_label(d.boundary, slice);
    SweepMapStyle st;
    st.title = "Outgoing spin ω_out" + (label.empty() ? std::string() : ", " + label);
    st.x_title = x_title;
    st.y_title = y_title;
    st.colorbar_title = "ω_{out} (rad/s)";
    st.quantity = "ω_out";
    st.unit = "rad/s";
    st.colorscale = report::ColorScale::PuOr;  // the sign is the spin's sense: white at no spin
    st.z_mid = 0.0;
    st.max_side = kReportMaxSide;
    o.add_figure(heat_map_of(grid, map.rows, map.cols, map.omega_out_map.at(slice), slice, &d.boundary, st));
  }
}

void add_thresholds_section(report::Report& r, const SweepReportView& v) {
  const SweepReportData& d = v.d;
  const sweep::Axis& th = v.th;
  const sweep::Axis& sp = v.sp;
  const std::vector<std::int64_t>& shown = v.shown;
  const std::string& y_title = v.y_title;
  auto& t = r.add_section("Spin threshold per angle");
  t.add_paragraph("At each angle, the smallest spin at which e reaches 1, scanning the spin axis upwards (refined by "
                  "root finding between grid values; the rows of --threshold), and the energy ratio E_rot/E_y there. "
                  "The study says the ratio must exceed 2.56; see the errata (docs/theory.md).");
  report::Figure thr, er;
  thr.title = "Spin threshold for e ≥ 1";
  thr.x_axis.title = y_title;
  thr.y_axis.title = sp.quantity == sweep::Quantity::ratio ? "threshold ω/|v_y| (rad/m)" : "threshold ω (rad/s)";
  er.title = "Energy ratio E_rot/E_y at the threshold";
  er.x_axis.title = y_title;
  er.y_axis.title = "I ω² / (m v_y²)";
  bool any_found = false, any_ratio = false;
  for (std::int64_t slice : shown) {
    const std::string label = slice_label(d.boundary, slice);
    report::Series a = named(label.empty() ? "threshold" : label, report::Mode::LinesMarkers);
    report::Series b = named(label.empty() ? "energy ratio" : label, report::Mode::LinesMarkers);
    for (const auto& row : d.thresholds) {
      if (row.slice != slice) continue;
      const bool ok = row.status == sweep::Threshold::Status::found;
      a.x.push_back(row.theta_deg);
      a.y.push_back(ok ? (sp.quantity == sweep::Quantity::ratio ? row.ratio : row.omega) : kNaN);
      b.x.push_back(row.theta_deg);
      b.y.push_back(ok ? row.energy_ratio : kNaN);
      any_found = any_found || ok;
      any_ratio = any_ratio || (ok && std::isfinite(row.energy_ratio));
    }
    thr.series.push_back(std::move(a));
    er.series.push_back(std::move(b));
  }
  if (any_found) {
    thr.caption = "Gaps: angles where e stays below 1 over the whole spin range, or is already ≥ 1 at its lowest value.";
    t.add_figure(std::move(thr));
  } else {
    t.add_paragraph("No angle has a spin threshold inside the grid: e never crosses 1 from below along the spin axis.");
  }
  if (any_ratio) {
    report::Series seed = named("the study's 2.56", report::Mode::Lines);
    seed.dash = report::Dash::Dash;
    seed.color = "#d62728";
    seed.x = {th.value(0), th.value(th.count - 1)};
    seed.y = {kSeedEnergyRatio, kSeedEnergyRatio};
    er.series.push_back(std::move(seed));
    er.caption = "Dashed: the ratio the study quotes as necessary.";
    t.add_figure(std::move(er));
  }
}

}  // namespace

report::Report sweep_report(const SweepReportData& d) {
  TRIBOLAB_ASSERT(d.map.has_value(), "sweep_report: no map summary");
  const SweepReportView v(d);
  TRIBOLAB_ASSERT(v.index_of("e") >= 0, "sweep_report: no output e");
  report::Report r;
  r.title = "Phase diagram of the bounce: e over impact angle × spin";
  r.subtitle = "tribolab " + d.command + ": " + std::to_string(v.grid.cell_count()) + " cells, " +
               std::to_string(v.n_slices) + (v.n_slices == 1 ? " slice" : " slices");
  add_parameters_section(r, v);
  add_summary_section(r, v);
  add_e_maps_section(r, v);
  if (v.index_of("omega_out") >= 0) add_spin_maps_section(r, v);
  add_thresholds_section(r, v);
  return r;
}

}  // namespace tribolab::app
