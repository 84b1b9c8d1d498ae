#include "sweep/contour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "numerics/error.hpp"
#include "numerics/roots.hpp"
#include "sweep/runner.hpp"
#include "numerics/units.hpp"

namespace tribolab::sweep {
// Named, not anonymous: MapTracer::State, a member of a class of the header, holds them.
namespace detail {


/// theta_deg and the spin axis are always the last two axes (canonical order); the
/// leading axes (speed, mu) select a slice.
struct Layout {
  std::int64_t n_theta = 0, n_spin = 0, n_slices = 1;
  std::size_t lead = 0;  // number of leading axes
  int out = -1;
  std::size_t n_out = 0;

  Layout(const GridSpec& grid, const CellModel& model, const ContourOptions& options) {
    TRIBOLAB_ASSERT(grid.validate().empty(), grid.validate());
    TRIBOLAB_ASSERT(model.validate().empty(), model.validate());
    const std::size_t n = grid.axes.size();
    lead = n - 2;
    n_theta = grid.axes[n - 2].count;
    n_spin = grid.axes[n - 1].count;
    for (std::size_t k = 0; k < lead; ++k) n_slices *= grid.axes[k].count;
    out = model.output_index(options.output);
    if (out < 0) throw InputError("the cell model has no output '" + options.output + "'");
    n_out = model.output_names.size();
  }
};

/// A grid edge: from node (i, j) to (i, j+1) (along spin) or (i+1, j) (along theta), with
/// the output minus the level at its two ends.
struct Edge {
  std::int64_t s, i, j;
  bool along_spin;
  double fa, fb;
};

class EdgeRefiner {
 public:
  EdgeRefiner(const GridSpec& grid, const CellModel& model, const ContourOptions& options, const Layout& layout)
      : grid_(grid), model_(model), options_(options), layout_(layout) {}

  /// Coordinates (one per axis) of node (s, i, j), with the moving coordinate replaced.
  std::vector<double> coords(std::int64_t s, std::int64_t i, std::int64_t j) const {
    std::vector<double> c(grid_.axes.size());
    std::int64_t rest = s;
    for (std::size_t k = layout_.lead; k-- > 0;) {
      c[k] = grid_.axes[k].value(rest % grid_.axes[k].count);
      rest /= grid_.axes[k].count;
    }
    c[layout_.lead] = grid_.axes[layout_.lead].value(i);
    c[layout_.lead + 1] = grid_.axes[layout_.lead + 1].value(j);
    return c;
  }

  double f_at(const std::vector<double>& c) const {
    return model_.evaluate(grid_.at(c))[static_cast<std::size_t>(layout_.out)] - options_.level;
  }

  /// The crossing on edge e as (theta_deg, spin), refined when asked; evaluations counted.
  ContourPoint refine(const Edge& e, std::int64_t& evaluations) const {
    const std::int64_t i1 = e.along_spin ? e.i : e.i + 1;
    const std::int64_t j1 = e.along_spin ? e.j + 1 : e.j;
    const double fa = e.fa, fb = e.fb;
    std::vector<double> c = coords(e.s, e.i, e.j);
    const std::size_t k = layout_.lead + (e.along_spin ? 1 : 0);
    const double a = c[k], b = grid_.axes[k].value(e.along_spin ? j1 : i1);
    double x = fa == fb ? a : a + (b - a) * (fa / (fa - fb));  // linear interpolation
    bool refined = false;
    if (options_.refine) {
      numerics::RootOptions ro;
      ro.x_tol = options_.x_tol_rel * std::abs(b - a);
      const numerics::RootResult r = numerics::find_root(
          [&](double xv) {
            ++evaluations;
            c[k] = xv;
            return f_at(c);
          },
          a, b, ro);
      if (r.converged) {
        x = r.x;
        refined = true;
      }
    }
    ContourPoint p;
    p.theta_deg = e.along_spin ? grid_.axes[layout_.lead].value(e.i) : x;
    p.spin = e.along_spin ? x : grid_.axes[layout_.lead + 1].value(e.j);
    p.refined = refined;
    return p;
  }

 private:
  const GridSpec& grid_;
  const CellModel& model_;
  const ContourOptions& options_;
  const Layout& layout_;
};

bool inside(double f) { return f >= 0; }

}  // namespace detail

using detail::Edge;
using detail::EdgeRefiner;
using detail::inside;
using detail::Layout;

std::string ContourOptions::validate() const {
  if (output.empty()) return "contour output name is empty";
  if (!std::isfinite(level)) return "contour level must be finite";
  if (!(x_tol_rel > 0 && x_tol_rel < 1)) return "x_tol_rel must be in (0, 1)";
  if (auto e = threads_error(threads); !e.empty()) return e;
  return {};
}

std::string status_name(Threshold::Status s) {
  switch (s) {
    case Threshold::Status::found: return "found";
    case Threshold::Status::below_grid: return "below_grid";
    case Threshold::Status::none: return "none";
  }
  return "none";
}

/// What the tracer keeps: the previous row, the crossings and segments of the squares seen,
/// the saddles, and the thresholds' rows with their crossing edge when found.
struct MapTracer::State {
  GridSpec grid;
  CellModel model;
  ContourOptions options;
  Layout L;
  EdgeRefiner refiner;
  bool boundary, thresholds;
  std::int64_t rows = 0;
  std::vector<double> prev;  // the previous row of this slice, minus the level
  // Boundary: segments between crossed edges (ids), in square order; saddles apart.
  std::vector<std::array<std::int64_t, 2>> segments;
  std::map<std::int64_t, Edge> crossed;
  struct Saddle {
    std::int64_t s, i, j;
    std::array<std::int64_t, 4> e;
    bool a_in;
    double corner_mean;  // fallback when the centre is NaN
  };
  std::vector<Saddle> saddles;
  // Thresholds: one per row; `pending` holds the rows whose crossing is still to refine.
  std::vector<Threshold> rows_out;
  std::vector<std::pair<std::size_t, Edge>> pending;

  State(const GridSpec& g, const CellModel& m, const ContourOptions& o, bool b, bool t)
      : grid(g), model(m), options(o), L(grid, model, options), refiner(grid, model, options, L), boundary(b),
        thresholds(t) {}

  std::int64_t edge_id(const Edge& e) const {
    const std::int64_t n_h = L.n_theta * (L.n_spin - 1);
    const std::int64_t per_slice = n_h + (L.n_theta - 1) * L.n_spin;
    return e.s * per_slice + (e.along_spin ? e.i * (L.n_spin - 1) + e.j : n_h + e.i * L.n_spin + e.j);
  }

  /// Marching squares over the squares between the previous row (i - 1) and `cur` (i).
  void squares(std::int64_t s, std::int64_t i0, const std::vector<double>& cur) {
    for (std::int64_t j = 0; j + 1 < L.n_spin; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      // Corners a (i,j), b (i,j+1), c (i+1,j+1), d (i+1,j); edges ab, bc, dc, ad.
      const std::array<double, 4> f = {prev[ju], prev[ju + 1], cur[ju + 1], cur[ju]};
      if (std::any_of(f.begin(), f.end(), [](double v) { return std::isnan(v); })) continue;
      const std::array<Edge, 4> edges = {Edge{s, i0, j, true, f[0], f[1]}, Edge{s, i0, j + 1, false, f[1], f[2]},
                                         Edge{s, i0 + 1, j, true, f[3], f[2]}, Edge{s, i0, j, false, f[0], f[3]}};
      std::array<std::int64_t, 4> ids{};
      std::vector<int> cut;
      for (int k = 0; k < 4; ++k) {
        const auto ku = static_cast<std::size_t>(k);
        ids[ku] = edge_id(edges[ku]);
        if (inside(f[ku]) != inside(f[(ku + 1) % 4])) {
          cut.push_back(k);
          crossed.emplace(ids[ku], edges[ku]);
        }
      }
      if (cut.size() == 2) {
        segments.push_back({ids[static_cast<std::size_t>(cut[0])], ids[static_cast<std::size_t>(cut[1])]});
      } else if (cut.size() == 4) {
        saddles.push_back(Saddle{s, i0, j, ids, inside(f[0]), 0.25 * (f[0] + f[1] + f[2] + f[3])});
      }
    }
  }

  /// The threshold of row (s, i): the first crossing from below along spin.
  void threshold_row(std::int64_t s, std::int64_t i, const std::vector<double>& cur) {
    Threshold t;
    t.slice = s;
    t.theta_deg = grid.axes[L.lead].value(i);
    t.omega = t.ratio = t.energy_ratio = kNaN;
    if (!std::isnan(cur[0]) && cur[0] >= 0) {
      t.status = Threshold::Status::below_grid;
    } else {
      for (std::int64_t j = 0; j + 1 < L.n_spin; ++j) {
        const double fa = cur[static_cast<std::size_t>(j)], fb = cur[static_cast<std::size_t>(j) + 1];
        if (std::isnan(fa) || std::isnan(fb) || !(fa < 0 && fb >= 0)) continue;
        pending.emplace_back(rows_out.size(), Edge{s, i, j, true, fa, fb});
        break;
      }
    }
    rows_out.push_back(t);
  }
};

MapTracer::MapTracer(const GridSpec& grid, const CellModel& model, const ContourOptions& options, bool boundary,
                     bool thresholds) {
  TRIBOLAB_ASSERT(options.validate().empty(), options.validate());
  state_ = std::make_unique<State>(grid, model, options, boundary, thresholds);
}

MapTracer::~MapTracer() = default;

std::int64_t MapTracer::rows_added() const { return state_->rows; }

void MapTracer::add_row(const std::vector<double>& row) {
  State& st = *state_;
  const Layout& L = st.L;
  TRIBOLAB_ASSERT(static_cast<std::int64_t>(row.size()) == L.n_spin, "row of " + std::to_string(row.size()));
  TRIBOLAB_ASSERT(st.rows < L.n_slices * L.n_theta, "more rows than the grid's");
  const std::int64_t s = st.rows / L.n_theta, i = st.rows % L.n_theta;
  std::vector<double> cur(row.size());
  for (std::size_t j = 0; j < row.size(); ++j) cur[j] = row[j] - st.options.level;
  if (st.thresholds) st.threshold_row(s, i, cur);
  if (st.boundary && i > 0 && L.n_spin >= 2) st.squares(s, i - 1, cur);
  st.prev = std::move(cur);
  ++st.rows;
}

ContourResult MapTracer::contour() const {
  const State& st = *state_;
  const Layout& L = st.L;
  TRIBOLAB_ASSERT(st.boundary && st.rows == L.n_slices * L.n_theta, "contour() before every row");
  const ContourOptions& options = st.options;
  const EdgeRefiner& refiner = st.refiner;
  ContourResult result;
  result.spin_axis = st.grid.axes.back().quantity;
  for (std::size_t k = 0; k < L.lead; ++k) result.slice_quantities.push_back(st.grid.axes[k].quantity);
  for (std::int64_t s = 0; s < L.n_slices; ++s) {
    const std::vector<double> c = refiner.coords(s, 0, 0);
    result.slice_values.emplace_back(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(L.lead));
  }
  if (L.n_theta < 2 || L.n_spin < 2) return result;

  // 1. Marching squares (done row by row): segments between crossed edges, in square order.
  std::vector<std::array<std::int64_t, 2>> segments = st.segments;
  const auto& saddles = st.saddles;
  // Saddles: the cell function at the square's centre decides which diagonal is connected.
  std::vector<char> centre_inside(saddles.size());
  std::vector<std::int64_t> evals(saddles.size() + st.crossed.size(), 0);
  parallel_for(static_cast<std::int64_t>(saddles.size()), options.threads, [&](std::int64_t q) {
    const State::Saddle& sd = saddles[static_cast<std::size_t>(q)];
    std::vector<double> c = refiner.coords(sd.s, sd.i, sd.j);
    const std::vector<double> c1 = refiner.coords(sd.s, sd.i + 1, sd.j + 1);
    c[L.lead] = 0.5 * (c[L.lead] + c1[L.lead]);
    c[L.lead + 1] = 0.5 * (c[L.lead + 1] + c1[L.lead + 1]);
    const double fc = refiner.f_at(c);
    evals[static_cast<std::size_t>(q)] = 1;
    // A NaN centre: fall back to the mean of the corners.
    centre_inside[static_cast<std::size_t>(q)] = inside(std::isnan(fc) ? sd.corner_mean : fc);
  });
  for (std::size_t q = 0; q < saddles.size(); ++q) {
    const State::Saddle& sd = saddles[q];
    if (static_cast<bool>(centre_inside[q]) == sd.a_in) {
      // a and c connected through the centre: cut off corners b (edges ab, bc) and d (dc, ad).
      segments.push_back({sd.e[0], sd.e[1]});
      segments.push_back({sd.e[2], sd.e[3]});
    } else {
      // cut off corners a (ad, ab) and c (bc, dc).
      segments.push_back({sd.e[3], sd.e[0]});
      segments.push_back({sd.e[1], sd.e[2]});
    }
  }

  // 2. Refine every crossing once (shared by the two squares on either side of an edge).
  std::vector<std::int64_t> ids;
  std::vector<Edge> edges;
  for (const auto& [id, e] : st.crossed) {
    ids.push_back(id);
    edges.push_back(e);
  }
  std::vector<ContourPoint> points(edges.size());
  parallel_for(static_cast<std::int64_t>(edges.size()), options.threads, [&](std::int64_t q) {
    const auto u = static_cast<std::size_t>(q);
    points[u] = refiner.refine(edges[u], evals[saddles.size() + u]);
  });
  for (std::int64_t e : evals) result.evaluations += e;
  for (const ContourPoint& p : points) result.unrefined += p.refined ? 0 : 1;
  auto point_of = [&](std::int64_t id) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    return static_cast<std::size_t>(it - ids.begin());
  };

  // 3. Join segments into polylines: each crossing has one neighbour (on the grid border
  // or next to a skipped NaN square) or two. Open chains first from their lowest end,
  // then loops from their lowest id, so the output order is deterministic.
  std::vector<std::array<std::int64_t, 2>> nbr(ids.size(), {-1, -1});
  for (const auto& seg : segments) {
    const std::size_t u = point_of(seg[0]), v = point_of(seg[1]);
    auto link = [&](std::size_t from, std::size_t to) {
      auto& n = nbr[from];
      (n[0] < 0 ? n[0] : n[1]) = static_cast<std::int64_t>(to);
    };
    link(u, v);
    link(v, u);
  }
  std::vector<char> used(ids.size(), 0);
  auto walk = [&](std::size_t start, bool closed) {
    Polyline line;
    line.slice = edges[start].s;
    line.closed = closed;
    std::int64_t prev = -1;
    std::size_t cur = start;
    while (true) {
      used[cur] = 1;
      line.points.push_back(points[cur]);
      const auto& n = nbr[cur];
      std::int64_t next = n[0] != prev && n[0] >= 0 && !used[static_cast<std::size_t>(n[0])] ? n[0] : -1;
      if (next < 0 && n[1] != prev && n[1] >= 0 && !used[static_cast<std::size_t>(n[1])]) next = n[1];
      if (next < 0) break;
      prev = static_cast<std::int64_t>(cur);
      cur = static_cast<std::size_t>(next);
    }
    if (closed) line.points.push_back(points[start]);
    result.lines.push_back(std::move(line));
  };
  for (std::size_t u = 0; u < ids.size(); ++u) {
    if (!used[u] && nbr[u][1] < 0) walk(u, false);
  }
  for (std::size_t u = 0; u < ids.size(); ++u) {
    if (!used[u]) walk(u, true);
  }
  std::stable_sort(result.lines.begin(), result.lines.end(),
                   [](const Polyline& a, const Polyline& b) { return a.slice < b.slice; });
  return result;
}

std::vector<Threshold> MapTracer::thresholds() const {
  const State& st = *state_;
  const Layout& L = st.L;
  TRIBOLAB_ASSERT(st.thresholds && st.rows == L.n_slices * L.n_theta, "thresholds() before every row");
  const bool ratio_axis = st.grid.axes.back().quantity == Quantity::ratio;
  std::vector<Threshold> rows = st.rows_out;
  parallel_for(static_cast<std::int64_t>(st.pending.size()), st.options.threads, [&](std::int64_t q) {
    // Named members, not a structured binding: clang before 16 cannot capture a binding in the
    // lambda below (the sanitizer tree is built with clang, docs/design.md#build-and-ci).
    const auto& pending = st.pending[static_cast<std::size_t>(q)];
    const auto& edge = pending.second;
    Threshold& t = rows[pending.first];
    std::int64_t evaluations = 0;
    const ContourPoint p = st.refiner.refine(edge, evaluations);
    const CellInput in = st.grid.at([&] {
      std::vector<double> c = st.refiner.coords(edge.s, edge.i, edge.j);
      c[L.lead + 1] = p.spin;
      return c;
    }());
    t.status = Threshold::Status::found;
    t.refined = p.refined;
    t.omega = in.omega;
    t.ratio = ratio_axis ? p.spin : in.ratio;
    // Rotational / vertical translational kinetic energy, (I w^2/2) / (m vy^2/2).
    if (st.model.mass > 0 && st.model.inertia > 0) {
      t.energy_ratio = st.model.inertia * in.omega * in.omega / (st.model.mass * in.speed * in.speed);
    }
  });
  return rows;
}

namespace {

/// Feeds the whole vector `values` (cell_count x outputs) to a tracer, row by row.
void feed(MapTracer& tracer, const GridSpec& grid, const CellModel& model, const ContourOptions& options,
          const std::vector<double>& values) {
  const Layout L(grid, model, options);
  TRIBOLAB_ASSERT(values.size() == static_cast<std::size_t>(grid.cell_count()) * L.n_out,
                  "values size " + std::to_string(values.size()));
  std::vector<double> row(static_cast<std::size_t>(L.n_spin));
  for (std::int64_t r = 0; r < L.n_slices * L.n_theta; ++r) {
    for (std::int64_t j = 0; j < L.n_spin; ++j)
      row[static_cast<std::size_t>(j)] =
          values[static_cast<std::size_t>(r * L.n_spin + j) * L.n_out + static_cast<std::size_t>(L.out)];
    tracer.add_row(row);
  }
}

}  // namespace

ContourResult trace_contour(const GridSpec& grid, const CellModel& model,
                            const std::vector<double>& values, const ContourOptions& options) {
  MapTracer tracer(grid, model, options, true, false);
  feed(tracer, grid, model, options, values);
  return tracer.contour();
}

std::vector<Threshold> spin_thresholds(const GridSpec& grid, const CellModel& model,
                                       const std::vector<double>& values,
                                       const ContourOptions& options) {
  MapTracer tracer(grid, model, options, false, true);
  feed(tracer, grid, model, options, values);
  return tracer.thresholds();
}

}  // namespace tribolab::sweep
