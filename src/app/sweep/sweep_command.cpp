#include "app/sweep/sweep_command.hpp"

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>


#include "io/atomic_file.hpp"
#include "app/sweep/sweep_checkpoint.hpp"
#include "io/sweep_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"

namespace tribolab::app {
using namespace ::tribolab::io;
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// "theta_deg: message" (a core validation message) -> the same with the field marked
/// (numerics/error.hpp: the command line shows "--theta-deg: message").
std::string with_option_names(const std::string& message) {
  const auto colon = message.find(": ");
  if (colon != std::string::npos && sweep::quantity_from_name(std::string_view(message).substr(0, colon)))
    return field(message.substr(0, colon)) + message.substr(colon);
  return message;
}

std::string header_line_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line) || in.eof()) {
    throw InputError(path + ":1", "not a tribolab sweep file (no complete header line)");
  }
  return line;
}

}  // namespace

void write_derived_maps(const SweepCommandOptions& o, const sweep::CellModel& model,
                        SweepCommandResult& r) {
  const bool boundary = !o.contour_out.empty() || o.keep_derived;
  const bool thresholds = !o.threshold_out.empty() || o.keep_derived;
  if (!boundary && !thresholds && !o.keep_values && !o.visit_cells) return;
  // Checked again although the sweep just wrote or verified it: the maps index the values by
  // cell, and a file replaced meanwhile (by hand; a second sweep is refused by the lock)
  // must be an error, not a wrong map. The header first, the cell count after the stream.
  const SweepHeader header{o.grid, o.shard, model.output_names, model.description};
  auto changed = [&](std::int64_t cells) {
    return InputError(o.out, "changed while the contour/threshold maps were made (holds " + std::to_string(cells) +
                                 " of " + std::to_string(o.grid.cell_count()) + " cells of this sweep); rerun the sweep");
  };
  if (format_header(parse_header(header_line_of(o.out), o.out + ":1")) != format_header(header)) throw changed(0);
  sweep::ContourOptions co = o.contour;
  co.threads = o.threads;
  const int out = model.output_index(co.output);
  std::optional<sweep::MapTracer> tracer;
  if (boundary || thresholds) tracer.emplace(o.grid, model, co, boundary, thresholds);
  const std::int64_t n_spin = o.grid.axes.back().count, total = o.grid.cell_count();
  std::vector<double> row, values;
  const SweepFileScan scan = scan_sweep_file(o.out, [&](std::int64_t cell, const std::vector<double>& outputs) {
    if (cell >= total) throw changed(cell + 1);
    if (tracer) {
      row.push_back(outputs[static_cast<std::size_t>(out)]);
      if (static_cast<std::int64_t>(row.size()) == n_spin) {
        tracer->add_row(row);
        row.clear();
      }
    }
    if (o.keep_values) values.insert(values.end(), outputs.begin(), outputs.end());
    if (o.visit_cells) o.visit_cells(cell, outputs);
  });
  if (scan.complete_cells != total || scan.torn_tail) throw changed(scan.complete_cells);
  if (boundary) {
    sweep::ContourResult c = tracer->contour();
    if (!o.contour_out.empty()) {
      AtomicFile file(o.contour_out);
      write_contour_csv(file.stream(), c);
      file.commit();
    }
    r.contour_lines = static_cast<std::int64_t>(c.lines.size());
    for (const auto& l : c.lines) r.contour_points += static_cast<std::int64_t>(l.points.size());
    r.contour_evaluations = c.evaluations;
    if (o.keep_derived) r.boundary = std::move(c);
  }
  if (thresholds) {
    std::vector<sweep::Threshold> rows = tracer->thresholds();
    if (!o.threshold_out.empty()) {
      AtomicFile file(o.threshold_out);
      write_threshold_csv(file.stream(), o.grid, rows);
      file.commit();
    }
    for (const auto& t : rows) r.thresholds_found += t.status == sweep::Threshold::Status::found;
    if (o.keep_derived) r.thresholds = std::move(rows);
  }
  if (o.keep_values) r.values = std::move(values);
}

std::string to_string(SweepStatus s) {
  switch (s) {
    case SweepStatus::completed: return "completed";
    case SweepStatus::reused: return "reused";
    case SweepStatus::cancelled: return "cancelled";
    case SweepStatus::worker: return "worker";
  }
  return "completed";
}

std::string SweepCommandOptions::validate() const {
  if (auto e = grid.validate(); !e.empty()) return with_option_names(e);
  if (auto e = shard.validate(); !e.empty()) return field("shard") + ": " + e;
  if (out.empty()) return field("out") + ": an output file is required";
  if (auto e = sweep::threads_error(threads); !e.empty()) return field("threads") + ": " + e.substr(e.find("must"));
  if (chunk_cells < 0) return "chunk_cells must be >= 0";
  if (!(fsync_interval_s > 0)) return "fsync_interval_s must be > 0";
  const bool maps = !contour_out.empty() || !threshold_out.empty();
  if (maps && shard.count > 1) {
    return std::string(contour_out.empty() ? field("threshold") : field("contour")) +
           ": needs the whole grid, not one shard; merge the shards with `tribolab bounce merge`, "
           "then rerun the same sweep with " + field("out") + " set to the merged file";
  }
  if (auto e = contour.validate(); !e.empty()) return field("contour") + ": " + e;
  for (const std::string* p : {&contour_out, &threshold_out}) {
    if (!p->empty() && (*p == out || *p == out + ".partial")) {
      return field("contour") + "/" + field("threshold") + ": must not be the sweep output file " + out;
    }
  }
  if (!contour_out.empty() && contour_out == threshold_out) {
    return field("contour") + " and " + field("threshold") + " must be different files";
  }
  return {};
}

SweepCommandResult checked_sweep_start(const SweepCommandOptions& o, const sweep::CellModel& model) {
  if (auto e = o.validate(); !e.empty()) throw InputError(e);
  if (auto e = model.validate(); !e.empty()) throw InputError("cell model: " + e);
  SweepCommandResult r;
  r.out = o.out;
  r.cells_grid = o.grid.cell_count();
  r.cells_shard = o.shard.cells(r.cells_grid);
  r.threads = sweep::resolve_threads(o.threads);
  return r;
}

SweepCommandResult run_sweep_command(const SweepCommandOptions& o, const sweep::CellModel& model,
                                     const SweepProgressCallback& progress, const std::atomic<bool>* cancel) {
  SweepCommandResult r = checked_sweep_start(o, model);
  if ((!o.contour_out.empty() || !o.threshold_out.empty() || o.keep_derived) &&
      model.output_index(o.contour.output) < 0) {
    throw InputError(field("contour") + ": the cell model has no output '" + o.contour.output + "'");
  }
  {
    const fs::path target(o.out);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir)) throw InputError(o.out, "directory does not exist");
    if (fs::is_directory(target)) throw InputError(o.out, "is a directory, expected a file name");
  }
  const SweepHeader header{o.grid, o.shard, model.output_names, model.description};
  SweepCheckpoint file(o, header);
  if (file.reused()) {
    r.status = SweepStatus::reused;
    r.cells_resumed = r.cells_shard;
    write_derived_maps(o, model, r);
    return r;
  }
  r.cells_resumed = file.first_local();

  // Compute the missing cells; each chunk's lines are written as soon as every earlier
  // chunk is written, so the file is always a prefix of the final file.
  sweep::ResultSink sink;
  std::atomic<std::int64_t> with_result{0};  // computed cells with a finite output
  sink.encode = [&](const sweep::ChunkView& c, std::string& buf) {
    append_cell_lines(buf, o.grid, c);
    std::int64_t n = 0;
    for (std::int64_t i = 0; i < c.count; ++i)
      for (std::size_t k = 0; k < c.n_outputs; ++k)
        if (std::isfinite(c.outputs[static_cast<std::size_t>(i) * c.n_outputs + k])) {
          ++n;
          break;
        }
    with_result += n;
  };
  sink.commit = [&](const sweep::ChunkView&, const std::string& buf) { file.append(buf); };
  sweep::RunOptions ro;
  ro.threads = o.threads;
  ro.chunk_cells = o.chunk_cells;
  ro.cancel = cancel;
  ro.progress = progress;
  const sweep::RunSummary s = sweep::run_cells(o.grid, model, o.shard, file.first_local(), ro, sink);
  r.cells_computed = s.cells_computed;
  r.cells_computed_with_result = with_result.load();
  r.seconds = s.seconds;
  r.threads = s.threads;
  const bool complete = s.status == sweep::RunSummary::Status::completed;
  file.finish(complete);
  if (!complete) {
    r.status = SweepStatus::cancelled;
    r.out = file.partial_path();
    return r;
  }
  write_derived_maps(o, model, r);
  return r;
}

MergeResult run_merge_command(const std::vector<std::string>& inputs, const std::string& out) {
  if (inputs.empty()) throw InputError("merge: no input files given");
  if (out.empty()) throw InputError(field("out") + ": an output file is required");
  std::vector<SweepHeader> headers;
  for (const std::string& path : inputs) {
    if (!fs::exists(path)) throw InputError(path, "no such file");
    headers.push_back(parse_header(header_line_of(path), path + ":1"));
  }
  const std::int64_t n = headers[0].shard.count;
  std::vector<std::size_t> owner(static_cast<std::size_t>(n), inputs.size());
  for (std::size_t f = 0; f < inputs.size(); ++f) {
    const SweepHeader& h = headers[f];
    if (header_identity(h) != header_identity(headers[0]) || h.shard.count != n) {
      throw InputError(inputs[f] + ":1", "is a shard of a different sweep than " + inputs[0] +
                                             " (differs in " +
                                             header_difference(h, headers[0], false) +
                                             ")");
    }
    std::size_t& o = owner[static_cast<std::size_t>(h.shard.index)];
    if (o != inputs.size()) {
      throw InputError(inputs[f] + ":1", "shard " + std::to_string(h.shard.index) + "/" +
                                             std::to_string(n) + " given twice (also " +
                                             inputs[o] + ")");
    }
    o = f;
  }
  std::string missing;
  for (std::int64_t i = 0; i < n; ++i) {
    if (owner[static_cast<std::size_t>(i)] == inputs.size()) {
      missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(n);
    }
  }
  if (!missing.empty()) throw InputError("merge: missing shard(s) " + missing);

  const SweepHeader& h0 = headers[0];
  const sweep::GridSpec& grid = h0.grid;
  struct Input {
    std::string path;
    std::ifstream in;
    std::int64_t line = 2;
  };
  std::vector<Input> in(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    Input& x = in[static_cast<std::size_t>(i)];
    x.path = inputs[owner[static_cast<std::size_t>(i)]];
    x.in.open(x.path, std::ios::binary);
    std::string skip;
    std::getline(x.in, skip);
    if (!std::getline(x.in, skip) || x.in.eof() || skip + '\n' != format_columns(h0)) {
      throw InputError(x.path + ":2", "column names do not match the header");
    }
  }
  AtomicFile file(out);
  const SweepHeader merged{grid, sweep::Shard{}, h0.outputs, h0.model};
  std::string buf = format_header(merged) + format_columns(merged);
  std::string line;
  const std::int64_t total = grid.cell_count();
  for (std::int64_t g = 0; g < total; ++g) {
    Input& x = in[static_cast<std::size_t>(g % n)];
    ++x.line;
    const std::string where = x.path + ":" + std::to_string(x.line);
    if (!std::getline(x.in, line) || x.in.eof()) {
      const sweep::Shard sh{g % n, n};
      throw InputError(where, "incomplete shard: has " + std::to_string(g / n) + " of " +
                                  std::to_string(sh.cells(total)) +
                                  " cells; finish it by rerunning its sweep command");
    }
    check_cell_line(line, grid, grid.cell(g), h0.outputs.size(), nullptr, where);
    buf += line;
    buf += '\n';
    if (buf.size() > (1u << 20)) {
      file.stream() << buf;
      buf.clear();
    }
  }
  for (Input& x : in) {
    if (std::getline(x.in, line)) {
      throw InputError(x.path + ":" + std::to_string(x.line + 1), "more lines than the cells of its shard");
    }
  }
  file.stream() << buf;
  file.commit();
  return MergeResult{out, n, total};
}

std::string plain_csv_metadata_path(const std::string& plain_csv) { return plain_csv + ".meta.txt"; }

void write_plain_csv(const std::string& sweep_file, const std::string& plain_csv) {
  std::ifstream in(sweep_file, std::ios::binary);
  if (!in) throw InputError(sweep_file, "cannot be read");
  AtomicFile table(plain_csv);
  AtomicFile meta(plain_csv_metadata_path(plain_csv));
  bool columns = false;
  for (std::string line; std::getline(in, line);) {
    if (!columns && !line.empty() && line.front() == '#') {
      meta.stream() << line << '\n';
      continue;
    }
    columns = true;
    table.stream() << line << '\n';
  }
  if (!columns) throw InputError(sweep_file, "holds no column line");
  meta.commit();
  table.commit();
}

nlohmann::json sweep_result_json(const SweepCommandResult& r, const SweepCommandOptions& o) {
  nlohmann::json j;
  // Every cell computed gave NaN (no contact, failed solves): the file is complete but holds no
  // result, which is not what "completed" promises.
  const bool no_result = r.status == SweepStatus::completed && r.cells_resumed == 0 && r.cells_computed > 0 &&
                         r.cells_computed_with_result == std::int64_t{0};
  j["status"] = no_result ? std::string("no_result") : to_string(r.status);
  j["out"] = r.out;
  j["cells_grid"] = r.cells_grid;
  j["cells_shard"] = r.cells_shard;
  j["cells_resumed"] = r.cells_resumed;
  j["cells_computed"] = r.cells_computed;
  j["threads"] = r.threads;
  j["seconds"] = r.seconds;
  j["cells_per_second"] =
      r.seconds > 0 ? nlohmann::json(static_cast<double>(r.cells_computed) / r.seconds) : nlohmann::json();
  j["contour"] = o.contour_out.empty()
                     ? nlohmann::json()
                     : nlohmann::json{{"file", o.contour_out},
                                      {"lines", r.contour_lines},
                                      {"points", r.contour_points},
                                      {"evaluations", r.contour_evaluations}};
  j["threshold"] = o.threshold_out.empty()
                       ? nlohmann::json()
                       : nlohmann::json{{"file", o.threshold_out}, {"found", r.thresholds_found}};
  return j;
}

void write_contour_csv(std::ostream& out, const sweep::ContourResult& c) {
  std::string s = "line,closed,";
  for (sweep::Quantity q : c.slice_quantities) s += std::string(sweep::quantity_name(q)) + ",";
  s += "theta_deg," + std::string(sweep::quantity_name(c.spin_axis)) + ",refined\n";
  for (std::size_t l = 0; l < c.lines.size(); ++l) {
    const sweep::Polyline& line = c.lines[l];
    for (const sweep::ContourPoint& p : line.points) {
      s += std::to_string(l) + "," + (line.closed ? "1" : "0") + ",";
      for (double v : c.slice_values[static_cast<std::size_t>(line.slice)]) {
        append_number(s, v);
        s += ',';
      }
      append_number(s, p.theta_deg);
      s += ',';
      append_number(s, p.spin);
      s += p.refined ? ",1\n" : ",0\n";
    }
  }
  out << s;
}

void write_threshold_csv(std::ostream& out, const sweep::GridSpec& grid,
                         const std::vector<sweep::Threshold>& rows) {
  std::string s;
  const std::size_t lead = grid.axes.size() - 2;
  for (std::size_t k = 0; k < lead; ++k) s += std::string(sweep::quantity_name(grid.axes[k].quantity)) + ",";
  s += "theta_deg,status,omega,ratio,energy_ratio,refined\n";
  auto num = [&](double v) {
    if (!std::isnan(v)) append_number(s, v);  // empty field when there is no threshold
  };
  for (const sweep::Threshold& t : rows) {
    std::int64_t rest = t.slice;
    std::vector<double> lead_values(lead);
    for (std::size_t k = lead; k-- > 0;) {
      lead_values[k] = grid.axes[k].value(rest % grid.axes[k].count);
      rest /= grid.axes[k].count;
    }
    for (double v : lead_values) {
      append_number(s, v);
      s += ',';
    }
    append_number(s, t.theta_deg);
    s += "," + sweep::status_name(t.status) + ",";
    num(t.omega);
    s += ',';
    num(t.ratio);
    s += ',';
    num(t.energy_ratio);
    s += t.refined ? ",1\n" : ",0\n";
  }
  out << s;
}

}  // namespace tribolab::app
