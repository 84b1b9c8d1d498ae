#include "io/sweep_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include "io/text.hpp"
#include "numerics/error.hpp"

namespace tribolab::io {
namespace {

constexpr std::string_view kMagic = "# tribolab-sweep v";
constexpr std::string_view kSep = " | ";

std::vector<std::string_view> split_view(std::string_view s, std::string_view sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto pos = s.find(sep, start);
    if (pos == std::string_view::npos) {
      out.push_back(s.substr(start));
      return out;
    }
    out.push_back(s.substr(start, pos - start));
    start = pos + sep.size();
  }
}

std::int64_t parse_int(std::string_view text, const std::string& where, const std::string& what) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || text.empty()) {
    throw InputError(where, "malformed " + what + " '" + std::string(text.substr(0, 40)) + "'");
  }
  return v;
}

/// A number written by append_number (finite or "nan", "inf", "-inf").
bool parse_any_double(std::string_view text, double& v) {
  if (text.empty()) return false;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return ec == std::errc() && ptr == text.data() + text.size();
}

std::string_view strip_prefix(std::string_view field, std::string_view prefix,
                              const std::string& where) {
  if (field.substr(0, prefix.size()) != prefix) {
    throw InputError(where, "malformed sweep header: expected '" + std::string(prefix) +
                                "...', found '" + std::string(field.substr(0, 40)) + "'");
  }
  return field.substr(prefix.size());
}

/// Extra columns: swept axes other than theta_deg and omega, canonical order.
bool is_extra(sweep::Quantity q) {
  return q != sweep::Quantity::theta_deg && q != sweep::Quantity::omega;
}

double quantity_value(const sweep::CellInput& in, sweep::Quantity q) {
  switch (q) {
    case sweep::Quantity::speed: return in.speed;
    case sweep::Quantity::mu: return in.mu;
    case sweep::Quantity::theta_deg: return in.theta_deg;
    case sweep::Quantity::omega: return in.omega;
    case sweep::Quantity::ratio: return in.ratio;
  }
  return 0;
}

std::string format_grid(const sweep::GridSpec& g) {
  std::string s = "grid";
  for (const sweep::Axis& a : g.axes) {
    s += ' ';
    s += sweep::quantity_name(a.quantity);
    s += '=';
    append_number(s, a.lo);
    s += ':';
    append_number(s, a.hi);
    s += ':';
    s += std::to_string(a.count);
  }
  return s;
}

std::string format_fixed(const sweep::GridSpec& g) {
  std::string s = "fixed";
  if (!g.axis(sweep::Quantity::speed)) {
    s += " speed=";
    append_number(s, g.fixed_speed);
  }
  if (!g.axis(sweep::Quantity::mu)) {
    s += " mu=";
    append_number(s, g.fixed_mu);
  }
  return s;
}

}  // namespace

void append_number(std::string& out, double v) {
  if (std::isnan(v)) {
    out += "nan";
    return;
  }
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  TRIBOLAB_ASSERT(ec == std::errc(), "to_chars failed");
  out.append(buf, ptr);
}

std::string format_number_exact(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

std::string header_identity(const SweepHeader& h) {
  std::string s = format_grid(h.grid);
  s += kSep;
  s += format_fixed(h.grid);
  s += kSep;
  s += "outputs";
  for (const std::string& o : h.outputs) s += ' ' + o;
  s += kSep;
  s += "model ";
  s += h.model;
  return s;
}

std::string format_header(const SweepHeader& h) {
  std::string s(kMagic);
  s += std::to_string(kSweepFormatVersion);
  s += kSep;
  s += "shard " + std::to_string(h.shard.index) + "/" + std::to_string(h.shard.count);
  s += kSep;
  s += header_identity(h);
  s += '\n';
  return s;
}

std::string format_columns(const SweepHeader& h) {
  std::string s = "theta_deg,omega";
  for (const std::string& o : h.outputs) s += ',' + o;
  for (const sweep::Axis& a : h.grid.axes) {
    if (is_extra(a.quantity)) {
      s += ',';
      s += sweep::quantity_name(a.quantity);
    }
  }
  s += '\n';
  return s;
}

SweepHeader parse_header(std::string_view line, const std::string& where) {
  if (line.substr(0, kMagic.size()) != kMagic) {
    throw InputError(where, "not a tribolab sweep file (the first line must start with '" +
                                std::string(kMagic) + "')");
  }
  const std::vector<std::string_view> f = split_view(line, kSep);
  const std::int64_t version = parse_int(f[0].substr(kMagic.size()), where, "format version");
  if (version < kOldestSweepFormatVersion || version > kSweepFormatVersion) {
    throw InputError(where, "sweep format version " + std::to_string(version) +
                                " is not supported (this tribolab reads versions " +
                                std::to_string(kOldestSweepFormatVersion) + " to " +
                                std::to_string(kSweepFormatVersion) + ")");
  }
  if (f.size() < 6) throw InputError(where, "malformed sweep header: missing fields");
  SweepHeader h;
  // shard i/N
  {
    const std::string_view s = strip_prefix(f[1], "shard ", where);
    const auto slash = s.find('/');
    if (slash == std::string_view::npos) throw InputError(where, "malformed shard in header");
    h.shard.index = parse_int(s.substr(0, slash), where, "shard index");
    h.shard.count = parse_int(s.substr(slash + 1), where, "shard count");
    if (auto e = h.shard.validate(); !e.empty()) throw InputError(where, e);
  }
  // grid name=lo:hi:count ...
  {
    const std::string_view s = strip_prefix(f[2], "grid", where);
    for (const std::string& item : split(trim(s), ' ')) {
      const auto eq = item.find('=');
      const auto q = sweep::quantity_from_name(std::string_view(item).substr(0, eq));
      if (eq == std::string::npos || !q) throw InputError(where, "malformed grid axis '" + item + "'");
      const std::vector<std::string> p = split(std::string_view(item).substr(eq + 1), ':');
      if (p.size() != 3) throw InputError(where, "malformed grid axis '" + item + "'");
      sweep::Axis a;
      a.quantity = *q;
      a.lo = parse_double(p[0], where);
      a.hi = parse_double(p[1], where);
      a.count = parse_int(p[2], where, "axis count");
      h.grid.axes.push_back(a);
    }
  }
  // fixed speed=.. mu=..
  {
    const std::string_view s = strip_prefix(f[3], "fixed", where);
    for (const std::string& item : split(trim(s), ' ')) {
      if (item.empty()) continue;
      const auto eq = item.find('=');
      const std::string name = item.substr(0, eq);
      if (eq == std::string::npos) throw InputError(where, "malformed fixed value '" + item + "'");
      const double v = parse_double(std::string_view(item).substr(eq + 1), where);
      if (name == "speed") {
        h.grid.fixed_speed = v;
      } else if (name == "mu") {
        h.grid.fixed_mu = v;
      } else {
        throw InputError(where, "unknown fixed quantity '" + name + "'");
      }
    }
  }
  if (auto e = h.grid.validate(); !e.empty()) throw InputError(where, "grid in header: " + e);
  {
    const std::string_view s = strip_prefix(f[4], "outputs", where);
    for (const std::string& item : split(trim(s), ' ')) {
      if (!item.empty()) h.outputs.push_back(item);
    }
    const std::size_t max_outputs = version == 1 ? 8 : sweep::kMaxOutputs;
    if (h.outputs.empty() || h.outputs.size() > max_outputs) {
      throw InputError(where, "malformed sweep header: 1 to " + std::to_string(max_outputs) +
                                  " outputs expected (format version " + std::to_string(version) + ")");
    }
  }
  // The model description is the rest of the line (it may itself contain " | ").
  const auto model_pos = line.find(std::string(kSep) + "model ");
  if (model_pos == std::string_view::npos) {
    throw InputError(where, "malformed sweep header: no 'model' field");
  }
  h.model = std::string(line.substr(model_pos + kSep.size() + 6));
  // Canonical form; an older version's header differs only in its version number.
  const std::string canonical = format_header(h);
  const auto after_version = [](std::string_view l) { return l.substr(std::min(l.size(), l.find(kSep))); };
  if (after_version(canonical) != std::string(after_version(line)) + '\n') {
    throw InputError(where, "malformed sweep header (not in canonical form)");
  }
  return h;
}

void append_cell_lines(std::string& out, const sweep::GridSpec& grid, const sweep::ChunkView& c) {
  for (std::int64_t k = 0; k < c.count; ++k) {
    const sweep::CellInput& in = c.inputs[k];
    append_number(out, in.theta_deg);
    out += ',';
    append_number(out, in.omega);
    const double* o = c.outputs + static_cast<std::size_t>(k) * c.n_outputs;
    for (std::size_t j = 0; j < c.n_outputs; ++j) {
      out += ',';
      append_number(out, o[j]);
    }
    for (const sweep::Axis& a : grid.axes) {
      if (!is_extra(a.quantity)) continue;
      out += ',';
      append_number(out, quantity_value(in, a.quantity));
    }
    out += '\n';
  }
}

void check_cell_line(std::string_view line, const sweep::GridSpec& grid, const sweep::CellInput& cell,
                     std::size_t n_outputs, double* values, const std::string& where) {
  const std::vector<std::string_view> f = split_view(line, ",");
  std::size_t n_extra = 0;
  for (const sweep::Axis& a : grid.axes) n_extra += is_extra(a.quantity) ? 1 : 0;
  const std::size_t expected = 2 + n_outputs + n_extra;
  if (f.size() != expected) {
    throw InputError(where, "expected " + std::to_string(expected) + " fields, found " +
                                std::to_string(f.size()));
  }
  auto check = [&](std::string_view field, double v, std::string_view name) {
    if (field != format_number_exact(v)) {
      throw InputError(where, std::string(name) + " = '" + std::string(field.substr(0, 40)) +
                                  "' does not match cell " + std::to_string(cell.index) +
                                  " of the grid in the header (expected " +
                                  format_number_exact(v) + ")");
    }
  };
  check(f[0], cell.theta_deg, "theta_deg");
  check(f[1], cell.omega, "omega");
  for (std::size_t j = 0; j < n_outputs; ++j) {
    double v = 0;
    if (!parse_any_double(f[2 + j], v)) {
      throw InputError(where, "malformed number '" + std::string(f[2 + j].substr(0, 40)) + "'");
    }
    if (values != nullptr) values[j] = v;
  }
  std::size_t col = 2 + n_outputs;
  for (const sweep::Axis& a : grid.axes) {
    if (!is_extra(a.quantity)) continue;
    check(f[col++], quantity_value(cell, a.quantity), sweep::quantity_name(a.quantity));
  }
}

SweepFileScan scan_sweep_file(const std::string& path, std::vector<double>* values) {
  if (values != nullptr) values->clear();
  return scan_sweep_file(path, [&](std::int64_t, const std::vector<double>& row) {
    if (values != nullptr) values->insert(values->end(), row.begin(), row.end());
  });
}

SweepFileScan scan_sweep_file(const std::string& path, const SweepCellVisitor& visit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open");
  SweepFileScan scan;
  std::string line;
  if (!std::getline(in, line) || in.eof()) {
    throw InputError(path + ":1", "not a tribolab sweep file (no complete header line)");
  }
  scan.header = parse_header(line, path + ":1");
  scan.valid_bytes = line.size() + 1;
  if (!std::getline(in, line) || in.eof()) {
    throw InputError(path + ":2", "no complete column line");
  }
  if (line + '\n' != format_columns(scan.header)) {
    throw InputError(path + ":2", "column names do not match the header");
  }
  scan.valid_bytes += line.size() + 1;
  const sweep::GridSpec& grid = scan.header.grid;
  const std::size_t n_out = scan.header.outputs.size();
  scan.expected_cells = scan.header.shard.cells(grid.cell_count());
  std::vector<double> row(n_out);
  std::int64_t line_no = 2;
  while (std::getline(in, line)) {
    ++line_no;
    if (in.eof()) {  // no '\n': an interrupted write
      scan.torn_tail = !line.empty();
      break;
    }
    const std::string where = path + ":" + std::to_string(line_no);
    if (scan.complete_cells >= scan.expected_cells) {
      throw InputError(where, "more lines than the " + std::to_string(scan.expected_cells) +
                                  " cells of the shard");
    }
    const sweep::CellInput cell = grid.cell(scan.header.shard.global(scan.complete_cells));
    check_cell_line(line, grid, cell, n_out, row.data(), where);
    if (visit) visit(scan.complete_cells, row);
    ++scan.complete_cells;
    scan.valid_bytes += line.size() + 1;
  }
  if (in.bad()) throw InputError(path, "read error");
  return scan;
}

}  // namespace tribolab::io
