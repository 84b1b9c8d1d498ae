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
namespace {


/// theta_deg and the spin axis are always the last two axes (canonical order); the
/// leading axes (speed, mu) select a slice.
struct Layout {
  std::int64_t n_theta = 0, n_spin = 0, n_slices = 1;
  std::size_t lead = 0;  // number of leading axes
  int out = -1;
  std::size_t n_out = 0;

  Layout(const GridSpec& grid, const CellModel& model, const ContourOptions& options,
         const std::vector<double>& values) {
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
    TRIBOLAB_ASSERT(values.size() == static_cast<std::size_t>(grid.cell_count()) * n_out,
                    "values size " + std::to_string(values.size()));
  }
  std::int64_t cell(std::int64_t s, std::int64_t i, std::int64_t j) const {
    return (s * n_theta + i) * n_spin + j;
  }
};

/// A grid edge: from node (i, j) to (i, j+1) (along spin) or (i+1, j) (along theta).
struct Edge {
  std::int64_t s, i, j;
  bool along_spin;
};

class EdgeRefiner {
 public:
  EdgeRefiner(const GridSpec& grid, const CellModel& model, const ContourOptions& options,
              const Layout& layout, const std::vector<double>& values)
      : grid_(grid), model_(model), options_(options), layout_(layout), values_(values) {}

  double f_node(std::int64_t s, std::int64_t i, std::int64_t j) const {
    const auto idx = static_cast<std::size_t>(layout_.cell(s, i, j)) * layout_.n_out +
                     static_cast<std::size_t>(layout_.out);
    return values_[idx] - options_.level;
  }

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
    const double fa = f_node(e.s, e.i, e.j), fb = f_node(e.s, i1, j1);
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
  const std::vector<double>& values_;
};

}  // namespace

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

ContourResult trace_contour(const GridSpec& grid, const CellModel& model,
                            const std::vector<double>& values, const ContourOptions& options) {
  TRIBOLAB_ASSERT(options.validate().empty(), options.validate());
  const Layout L(grid, model, options, values);
  const EdgeRefiner refiner(grid, model, options, L, values);
  ContourResult result;
  result.spin_axis = grid.axes.back().quantity;
  for (std::size_t k = 0; k < L.lead; ++k) result.slice_quantities.push_back(grid.axes[k].quantity);
  for (std::int64_t s = 0; s < L.n_slices; ++s) {
    const std::vector<double> c = refiner.coords(s, 0, 0);
    result.slice_values.emplace_back(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(L.lead));
  }
  if (L.n_theta < 2 || L.n_spin < 2) return result;

  // Edge ids within a slice: along-spin edges (i, j)-(i, j+1) first, then along-theta.
  const std::int64_t n_h = L.n_theta * (L.n_spin - 1);
  const std::int64_t per_slice = n_h + (L.n_theta - 1) * L.n_spin;
  auto edge_id = [&](const Edge& e) {
    return e.s * per_slice + (e.along_spin ? e.i * (L.n_spin - 1) + e.j : n_h + e.i * L.n_spin + e.j);
  };
  auto inside = [](double f) { return f >= 0; };

  // 1. Marching squares: segments between crossed edges (ids), in square order.
  std::vector<std::array<std::int64_t, 2>> segments;
  std::map<std::int64_t, Edge> crossed;
  struct Saddle {
    std::int64_t s, i, j;
    std::array<std::int64_t, 4> e;
    bool a_in;
  };
  std::vector<Saddle> saddles;
  for (std::int64_t s = 0; s < L.n_slices; ++s) {
    for (std::int64_t i = 0; i + 1 < L.n_theta; ++i) {
      for (std::int64_t j = 0; j + 1 < L.n_spin; ++j) {
        // Corners a (i,j), b (i,j+1), c (i+1,j+1), d (i+1,j); edges ab, bc, dc, ad.
        const std::array<double, 4> f = {refiner.f_node(s, i, j), refiner.f_node(s, i, j + 1),
                                         refiner.f_node(s, i + 1, j + 1),
                                         refiner.f_node(s, i + 1, j)};
        if (std::any_of(f.begin(), f.end(), [](double v) { return std::isnan(v); })) continue;
        const std::array<Edge, 4> edges = {Edge{s, i, j, true}, Edge{s, i, j + 1, false},
                                           Edge{s, i + 1, j, true}, Edge{s, i, j, false}};
        std::array<std::int64_t, 4> ids{};
        std::vector<int> cut;
        for (int k = 0; k < 4; ++k) {
          ids[static_cast<std::size_t>(k)] = edge_id(edges[static_cast<std::size_t>(k)]);
          if (inside(f[static_cast<std::size_t>(k)]) != inside(f[static_cast<std::size_t>((k + 1) % 4)])) {
            cut.push_back(k);
            crossed.emplace(ids[static_cast<std::size_t>(k)], edges[static_cast<std::size_t>(k)]);
          }
        }
        if (cut.size() == 2) {
          segments.push_back({ids[static_cast<std::size_t>(cut[0])], ids[static_cast<std::size_t>(cut[1])]});
        } else if (cut.size() == 4) {
          saddles.push_back(Saddle{s, i, j, ids, inside(f[0])});
        }
      }
    }
  }
  // Saddles: the cell function at the square's centre decides which diagonal is connected.
  std::vector<char> centre_inside(saddles.size());
  std::vector<std::int64_t> evals(saddles.size() + crossed.size(), 0);
  parallel_for(static_cast<std::int64_t>(saddles.size()), options.threads, [&](std::int64_t q) {
    const Saddle& sd = saddles[static_cast<std::size_t>(q)];
    std::vector<double> c = refiner.coords(sd.s, sd.i, sd.j);
    const std::vector<double> c1 = refiner.coords(sd.s, sd.i + 1, sd.j + 1);
    c[L.lead] = 0.5 * (c[L.lead] + c1[L.lead]);
    c[L.lead + 1] = 0.5 * (c[L.lead + 1] + c1[L.lead + 1]);
    const double fc = refiner.f_at(c);
    evals[static_cast<std::size_t>(q)] = 1;
    // A NaN centre: fall back to the mean of the corners.
    if (std::isnan(fc)) {
      const double mean = 0.25 * (refiner.f_node(sd.s, sd.i, sd.j) + refiner.f_node(sd.s, sd.i, sd.j + 1) +
                                  refiner.f_node(sd.s, sd.i + 1, sd.j + 1) + refiner.f_node(sd.s, sd.i + 1, sd.j));
      centre_inside[static_cast<std::size_t>(q)] = inside(mean);
    } else {
      centre_inside[static_cast<std::size_t>(q)] = inside(fc);
    }
  });
  for (std::size_t q = 0; q < saddles.size(); ++q) {
    const Saddle& sd = saddles[q];
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
  for (const auto& [id, e] : crossed) {
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

std::vector<Threshold> spin_thresholds(const GridSpec& grid, const CellModel& model,
                                       const std::vector<double>& values,
                                       const ContourOptions& options) {
  TRIBOLAB_ASSERT(options.validate().empty(), options.validate());
  const Layout L(grid, model, options, values);
  const EdgeRefiner refiner(grid, model, options, L, values);
  const bool ratio_axis = grid.axes.back().quantity == Quantity::ratio;
  std::vector<Threshold> rows(static_cast<std::size_t>(L.n_slices * L.n_theta));
  parallel_for(static_cast<std::int64_t>(rows.size()), options.threads, [&](std::int64_t q) {
    const std::int64_t s = q / L.n_theta, i = q % L.n_theta;
    Threshold& t = rows[static_cast<std::size_t>(q)];
    t.slice = s;
    t.theta_deg = grid.axes[L.lead].value(i);
    t.omega = t.ratio = t.energy_ratio = kNaN;
    const double f0 = refiner.f_node(s, i, 0);
    if (!std::isnan(f0) && f0 >= 0) {
      t.status = Threshold::Status::below_grid;
      return;
    }
    for (std::int64_t j = 0; j + 1 < L.n_spin; ++j) {
      const double fa = refiner.f_node(s, i, j), fb = refiner.f_node(s, i, j + 1);
      if (std::isnan(fa) || std::isnan(fb) || !(fa < 0 && fb >= 0)) continue;
      std::int64_t evaluations = 0;
      const ContourPoint p = refiner.refine(Edge{s, i, j, true}, evaluations);
      const CellInput in = grid.at([&] {
        std::vector<double> c = refiner.coords(s, i, j);
        c[L.lead + 1] = p.spin;
        return c;
      }());
      t.status = Threshold::Status::found;
      t.refined = p.refined;
      t.omega = in.omega;
      t.ratio = ratio_axis ? p.spin : in.ratio;
      // Rotational / vertical translational kinetic energy, (I w^2/2) / (m vy^2/2).
      if (model.mass > 0 && model.inertia > 0) {
        t.energy_ratio = model.inertia * in.omega * in.omega / (model.mass * in.speed * in.speed);
      }
      return;
    }
  });
  return rows;
}

}  // namespace tribolab::sweep
