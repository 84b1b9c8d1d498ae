#include "app/common/study_citation.hpp"
#include "app/common/result_keys.hpp"
#include "app/bounce/bounce_sweep.hpp"

#include "app/common/output_paths.hpp"

#include "app/sweep/report_sweep.hpp"
#include "app/sweep/sweep_mpi.hpp"
#include "io/sweep_file.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/html.hpp"

#include <fstream>
#include <utility>

namespace tribolab::app {
namespace {

/// The axis of `option` with its quantity set (the caller may leave it at its default).
sweep::Axis axis_of(sweep::Axis a, sweep::Quantity q) {
  a.quantity = q;
  return a;
}

/// The grid and run options of the sweep, checked; messages name the option.
SweepCommandOptions to_run_options(const BounceSweepOptions& a) {
  SweepCommandOptions o;
  if (!a.theta_deg) throw MissingOptionError(field("theta_deg") + " is required");
  o.grid.axes.push_back(axis_of(*a.theta_deg, sweep::Quantity::theta_deg));
  if (a.omega.has_value() == a.ratio.has_value()) {
    throw InputError("give exactly one of " + field("omega") + " (spin range) and " + field("ratio") + " (spin/speed range)");
  }
  if (a.omega) o.grid.axes.push_back(axis_of(*a.omega, sweep::Quantity::omega));
  if (a.ratio) o.grid.axes.push_back(axis_of(*a.ratio, sweep::Quantity::ratio));
  o.grid.fixed_speed = a.speed.value;
  o.grid.fixed_mu = a.mu.value;
  if (a.speed.axis) o.grid.axes.push_back(axis_of(*a.speed.axis, sweep::Quantity::speed));
  if (a.mu.axis) o.grid.axes.push_back(axis_of(*a.mu.axis, sweep::Quantity::mu));
  // Physical ranges of the swept quantities (numerics/physical_range.hpp, docs/cli.md#physical-ranges).
  for (const sweep::Axis& ax : o.grid.axes) {
    const char* name = ax.quantity == sweep::Quantity::speed   ? "speed"
                       : ax.quantity == sweep::Quantity::mu    ? "mu"
                       : ax.quantity == sweep::Quantity::omega ? "omega"
                       : ax.quantity == sweep::Quantity::ratio ? "ratio"
                                                               : nullptr;
    const PhysicalRange r = ax.quantity == sweep::Quantity::speed   ? ranges::speed
                            : ax.quantity == sweep::Quantity::mu    ? ranges::friction
                            : ax.quantity == sweep::Quantity::ratio ? PhysicalRange{-1e5, 1e5, "rad/m"}
                                                                    : ranges::spin;
    if (name) for (double v : {ax.lo, ax.hi}) check_range(v, r, field(name));
  }
  check_range(o.grid.fixed_speed, ranges::speed, field("speed"));
  check_range(o.grid.fixed_mu, ranges::friction, field("mu"));
  sweep::sort_axes(o.grid.axes);
  o.shard = a.shard;
  o.out = a.out;
  o.threads = a.threads;
  o.restart = a.restart;
  o.contour_out = a.contour;
  o.threshold_out = a.threshold;
  if (!(a.contour_tol > 0 && a.contour_tol < 1)) {
    throw InputError(field("contour_tol"), "must be in (0, 1) (a fraction of the grid spacing)");
  }
  o.contour.x_tol_rel = a.contour_tol;
  if (auto e = o.validate(); !e.empty()) throw InputError(e);
  if (!a.report.empty()) {
    // A shard holds every N-th cell of the grid: no map to draw. Checked before any work.
    if (o.shard.count > 1) {
      throw InputError(field("report"), "needs the whole grid, not one shard; merge the shards with `tribolab bounce "
                                   "merge ... --report FILE.html`");
    }
    for (const std::string* p : {&o.out, &o.contour_out, &o.threshold_out}) {
      if (!p->empty() && (a.report == *p || a.report == *p + ".partial")) {
        throw InputError(field("report"), "must not be the same file as " + field("out") + ", " + field("contour") + " or " + field("threshold"));
      }
    }
  }
  o.keep_values = a.return_map;  // the report streams a bounded summary instead (visit_cells)
  o.keep_derived = !a.report.empty();
  return o;
}

/// The collision angle is defined on [0, 180] deg: checks the swept range once.
void check_theta_range(const BounceCell& cell, const sweep::Axis& theta) {
  if (cell.convention != AngleConvention::collision) return;
  for (double v : {theta.lo, theta.hi}) {
    if (!(v >= 0 && v <= 180)) {
      throw InputError(field("theta_deg"), "a collision angle lies in 0..180 deg, got " + io::format_number_exact(v) +
                                          " (use " + field("angle") + " orientation for the orientation at impact)");
    }
  }
}

SweepMap map_of(const sweep::GridSpec& grid, const sweep::CellModel& model, const std::vector<double>& values) {
  SweepMap m;
  for (const sweep::Axis& ax : grid.axes) {
    m.axis_names.emplace_back(sweep::quantity_name(ax.quantity));
    std::vector<double> v(static_cast<std::size_t>(ax.count));
    for (std::int64_t i = 0; i < ax.count; ++i) v[static_cast<std::size_t>(i)] = ax.value(i);
    m.axis_values.push_back(std::move(v));
  }
  m.output_names = model.output_names;
  const std::size_t n = model.output_names.size(), cells = n == 0 ? 0 : values.size() / n;
  m.outputs.assign(n, std::vector<double>(cells));
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t j = 0; j < n; ++j) m.outputs[j][c] = values[c * n + j];
  }
  return m;
}

/// The first line of the sweep file `path`.
std::string header_line_of_sweep_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "no such file");
  std::string line;
  if (!std::getline(in, line) || in.eof()) {
    throw InputError(path + ":1", "not a tribolab sweep file (no complete header line)");
  }
  return line;
}

/// The cell model that wrote the sweep file `path` (its header's physics description).
sweep::CellModel model_of_sweep_file(const std::string& path) {
  return bounce_cell_model_from_description(io::parse_header(header_line_of_sweep_file(path), path + ":1").model);
}

}  // namespace

BounceSweepResult bounce_sweep(const BounceSweepOptions& a) {
  check_output_paths({}, {{"out", a.out}, {"contour", a.contour}, {"threshold", a.threshold}, {"report", a.report},
                          {"plain_csv", a.plain_csv}});  // before any work (app/common/output_paths.hpp)
  if (!a.plain_csv.empty() && a.plain_csv == a.out)
    throw InputError(field("plain_csv"), "must not be the same file as " + field("out"));
  SweepCommandOptions o = to_run_options(a);
  const BounceCell cell = make_bounce_cell(a.cell);
  check_theta_range(cell, *a.theta_deg);
  const sweep::CellModel model = bounce_cell_model(cell);
  const io::SweepHeader header{o.grid, sweep::Shard{}, model.output_names, model.description};
  std::optional<SweepMapSummary> summary;  // what the report shows of the map, streamed
  if (!a.report.empty()) {
    summary.emplace(header);
    o.visit_cells = [&](std::int64_t c, const std::vector<double>& v) { summary->add(c, v); };
  }
  BounceSweepResult result;
  if (a.mpi) {
    if (!built_with_mpi()) {
      throw InputError("this tribolab was built without MPI (cmake -DTRIBOLAB_MPI=ON); run it "
                       "without mpirun, or split the grid with " + field("shard"));
    }
    result.run = run_sweep_command_mpi(o, model, a.progress, a.cancel);
  } else {
    result.run = run_sweep_command(o, model, a.progress, a.cancel);
  }
  SweepCommandResult& r = result.run;
  if (r.status == SweepStatus::worker) {
    result.is_reporting_rank = false;
    return result;
  }
  if (r.status == SweepStatus::cancelled) {
    throw InputError("interrupted: " + std::to_string(r.cells_resumed + r.cells_computed) + " of " +
                     std::to_string(r.cells_shard) + " cells saved in " + r.out +
                     "; run the same command again to resume");
  }
  // Built from the completed file read back and the boundary and thresholds the sweep traced
  // (the same points as --contour/--threshold): the same report for a fresh, resumed or
  // reused sweep.
  if (!a.report.empty()) {
    SweepReportData d;
    d.header = header;
    d.map = std::move(summary);
    d.boundary = r.boundary.value_or(sweep::ContourResult{});
    d.thresholds = r.thresholds.value_or(std::vector<sweep::Threshold>{});
    d.contour_tol = o.contour.x_tol_rel;
    d.command = "bounce sweep";
    report::write_html(with_study_source(sweep_report(d), Study::rugby_ball), a.report, a.plotly);
  }
  if (!a.plain_csv.empty() && !o.out.empty()) write_plain_csv(o.out, a.plain_csv);
  if (a.return_map) result.map = map_of(o.grid, model, r.values);
  r.values = {};
  r.boundary.reset();
  r.thresholds.reset();
  result.json = sweep_result_json(r, o);
  if (result.json["status"] == "no_result")
    result.json["warnings"] = {"no cell of the sweep gave a result: every value in " + r.out +
                               " is NaN (no contact or a failed solve in every cell; see the cell model's inputs)"};
  return result;
}

BounceMergeResult bounce_merge(const BounceMergeOptions& a) {
  check_output_paths(a.files, {{"out", a.out}, {"report", a.report}, {"plain_csv", a.plain_csv}});  // before any work (app/common/output_paths.hpp)
  if (!a.plain_csv.empty() && a.plain_csv == a.out)
    throw InputError(field("plain_csv"), "must not be the same file as " + field("out"));
  // The physics is rebuilt from the first shard's header before anything is written, so a
  // file this tribolab cannot report on fails without output.
  std::optional<sweep::CellModel> model;
  if (!a.report.empty()) {
    if (a.report == a.out) throw InputError(field("report"), "must not be the same file as " + field("out"));
    if (!a.files.empty()) model = model_of_sweep_file(a.files.front());
  }
  const MergeResult r = run_merge_command(a.files, a.out);
  if (model) {
    // The merged file streamed once into the boundary, the thresholds and the report's
    // bounded summary (write_derived_maps), as `bounce sweep --report` does.
    SweepCommandOptions o;
    o.out = r.out;
    o.grid = io::parse_header(header_line_of_sweep_file(r.out), r.out + ":1").grid;
    o.keep_derived = true;
    if (model->output_index(o.contour.output) < 0) {
      throw InputError(field("report") + ": the cell model has no output '" + o.contour.output + "'");
    }
    SweepReportData d;
    d.header = io::SweepHeader{o.grid, sweep::Shard{}, model->output_names, model->description};
    SweepMapSummary summary(d.header);
    o.visit_cells = [&](std::int64_t c, const std::vector<double>& v) { summary.add(c, v); };
    SweepCommandResult run;
    write_derived_maps(o, *model, run);
    d.map = std::move(summary);
    d.boundary = std::move(*run.boundary);
    d.thresholds = std::move(*run.thresholds);
    d.contour_tol = o.contour.x_tol_rel;
    d.command = "bounce merge";
    report::write_html(with_study_source(sweep_report(d), Study::rugby_ball), a.report, a.plotly);
  }
  if (!a.plain_csv.empty()) write_plain_csv(r.out, a.plain_csv);
  BounceMergeResult result;
  result.json = nlohmann::json{{"out", r.out}, {"shards", r.shards}, {"cells", r.cells}};
  return result;
}

const ResultKeys& bounce_merge_result_keys() {
  static const ResultKeys k = {{"out", "", ""}, {"shards", "", "shard files joined"}, {"cells", "", "cells of the map"}};
  return k;
}


const Fields<BounceSweepOptions>& bounce_sweep_fields() {
  using O = BounceSweepOptions;
  using C = BounceCellOptions;
  static const Fields<C> cell = [] {
    Fields<C> d;
    d.add("angle", &C::angle, "",
          "meaning of theta_deg: the rugby-ball study's collision angle (0..180 deg), or the orientation (major "
          "axis from the horizontal at first touch)")
        .one_of({"collision", "orientation"});
    d.add("vx", &C::vx, "m/s", "horizontal centre velocity at first touch");
    d.group(&C::ball, ball_fields());
    d.group(&C::law, law_fields(), {"mu"});  // mu is the sweep's (a value or an axis)
    d.add("g", &C::g, "m/s^2", "gravitational acceleration (0 allowed: cells start at touch)");
    return d;
  }();
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("theta_deg", &O::theta_deg, "deg", "impact angle range lo:hi:count (e.g. 100:170:71)").needed();
    d.add("omega", &O::omega, "rad/s",
          "spin range lo:hi:count, counter-clockwise positive (e.g. 30:50:21; the rugby-ball study's figure 53 "
          "spins clockwise for a ball moving to +x: -50:-30:21)");
    d.add("ratio", &O::ratio, "rad/m", "instead of the spin range: spin/speed range omega/|vy| lo:hi:count");
    d.add("speed", &O::speed, "m/s", "incoming vertical speed |vy|: a value or a range lo:hi:count");
    d.add("mu", &O::mu, "", "friction coefficient: a value or a range lo:hi:count");
    d.add("out", &O::out, "",
          "output CSV (checkpoint while running: FILE.partial)")
        .as(FieldRole::output_path)
        .needed();
    d.add("shard", &O::shard, "", "compute only shard i of N (cells with index % N == i), e.g. 0/4");
    d.add("threads", &O::threads, "", "worker threads, 0 = all cores");
    d.add("restart", &O::restart, "", "discard an existing checkpoint or output and start afresh");
    d.add("contour", &O::contour, "", "write the e = 1 boundary polylines to this CSV").as(FieldRole::output_path);
    d.add("threshold", &O::threshold, "", "write the spin threshold and energy ratio per angle to this CSV")
        .as(FieldRole::output_path);
    d.add("contour_tol", &O::contour_tol, "", "root tolerance of boundary points, fraction of the grid spacing");
    d.add("plain_csv", &O::plain_csv, "",
          "also write the map for spreadsheets: no comment lines, the metadata in FILE.meta.txt")
        .as(FieldRole::output_path);
    d.add_report(&O::report, &O::plotly);
    d.group(&O::cell, cell);
    return d;
  }();
  return f;
}

const ResultKeys& bounce_sweep_result_keys() {
  static const ResultKeys k = {
      {"status", "", ""}, {"out", "", ""}, {"cells_grid", "", ""}, {"cells_shard", "", ""}, {"cells_resumed", "", ""},
      {"cells_computed", "", ""}, {"threads", "", ""}, {"seconds", "s", "wall time"}, {"cells_per_second", "1/s", ""},
      {"contour", "", "null: no --contour"}, {"contour.file", "", ""}, {"contour.lines", "", ""},
      {"contour.points", "", ""}, {"contour.evaluations", "", ""}, {"threshold", "", "null: no --threshold"},
      {"threshold.file", "", ""}, {"threshold.found", "", ""},
      {"warnings", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
