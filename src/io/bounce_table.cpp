#include "io/bounce_table.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tribolab::io {

namespace {
/// Shortest text that reads back to the same double.
std::string shortest(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

constexpr std::array<const char*, 7> kColumns = {"theta_deg", "vx_in", "vy_in", "omega_in",
                                                 "vx_out", "vy_out", "omega_out"};
/// Optional columns: the standard uncertainties of the seven above (bounce analyze's
/// bounces_out writes them; tables without them stay unweighted in bounce fit).
constexpr std::array<const char*, 7> kSigmaColumns = {"sigma_theta_deg", "sigma_vx_in", "sigma_vy_in", "sigma_omega_in",
                                                      "sigma_vx_out", "sigma_vy_out", "sigma_omega_out"};
constexpr std::array<double analysis::BounceRow::*, 7> kSigmaFields = {
    &analysis::BounceRow::sigma_theta_deg, &analysis::BounceRow::sigma_vx_in,  &analysis::BounceRow::sigma_vy_in,
    &analysis::BounceRow::sigma_omega_in,  &analysis::BounceRow::sigma_vx_out, &analysis::BounceRow::sigma_vy_out,
    &analysis::BounceRow::sigma_omega_out};

/// The cells of one CSV line (RFC 4180): a cell in double quotes may hold commas and doubled
/// quotes; other cells are split on commas as they are.
std::vector<std::string> bounce_table_cells(std::string_view line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') cells.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
      else quoted = false;
    } else if (c == '"' && trim(cells.back()).empty()) {
      cells.back().clear();
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}
}

std::vector<analysis::BounceRow> parse_bounce_table(std::string_view text, const std::string& source) {
  std::vector<analysis::BounceRow> rows;
  std::array<int, 7> col{}, sigma_col{};
  col.fill(-1);
  sigma_col.fill(-1);
  std::size_t n_fields = 0;
  bool have_header = false;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    const std::string where = source + ":" + std::to_string(line_no);
    const auto fields = bounce_table_cells(line);
    if (!have_header) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        const auto name = trim(fields[i]);
        for (std::size_t c = 0; c < kColumns.size(); ++c) {
          if (name == kColumns[c]) col[c] = static_cast<int>(i);
          if (name == kSigmaColumns[c]) sigma_col[c] = static_cast<int>(i);
        }
      }
      for (std::size_t c = 0; c < kSigmaColumns.size(); ++c) {
        if ((sigma_col[c] < 0) != (sigma_col[0] < 0))
          throw InputError(where, std::string("column '") + kSigmaColumns[c] +
                                      (sigma_col[c] < 0 ? "' missing" : "' without the other sigma columns") +
                                      ": give all seven sigma_ columns or none");
      }
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        if (col[c] < 0) {
          throw InputError(where, std::string("missing column '") + kColumns[c] +
                                      "' (header must name theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out)");
        }
      }
      n_fields = fields.size();
      have_header = true;
      continue;
    }
    if (fields.size() != n_fields) {
      throw InputError(where, "expected " + std::to_string(n_fields) + " fields, found " + std::to_string(fields.size()));
    }
    std::array<double, 7> v{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      v[c] = parse_double(trim(fields[col[c]]), where + " (" + kColumns[c] + ")");
      if (!std::isfinite(v[c])) throw InputError(where, std::string(kColumns[c]) + " is not finite");
      // A value no bounce has (1e308: a typo, a lost decimal point) is refused here: the fit
      // cannot carry it (docs/cli.md#physical-ranges).
      const PhysicalRange& r = c == 0 ? ranges::angle_deg : (c == 3 || c == 6) ? ranges::spin : ranges::velocity;
      if (auto e = range_error(v[c], r, kColumns[c]); !e.empty()) throw InputError(where, e);
    }
    analysis::BounceRow row{v[0], v[1], v[2], v[3], v[4], v[5], v[6]};
    for (std::size_t c = 0; c < kSigmaColumns.size() && sigma_col[0] >= 0; ++c) {
      const double sv = parse_double(trim(fields[sigma_col[c]]), where + " (" + kSigmaColumns[c] + ")");
      if (!(std::isfinite(sv) && sv >= 0)) throw InputError(where, std::string(kSigmaColumns[c]) + " must be a finite number >= 0");
      row.*kSigmaFields[c] = sv;
    }
    if (sigma_col[0] >= 0 && !row.has_sigmas())
      throw InputError(where, "sigma_vx_out, sigma_vy_out and sigma_omega_out must be positive");
    rows.push_back(row);
  }
  if (!have_header) throw InputError(source, "empty table (no header)");
  if (rows.empty()) throw InputError(source, "no data rows after the header");
  return rows;
}

std::vector<analysis::BounceRow> read_bounce_table(const std::string& path) {
  return parse_bounce_table(read_file(path), path);
}

std::string write_bounce_table(const std::vector<analysis::BounceRow>& rows, const std::vector<std::string>& files) {
  if (!files.empty() && files.size() != rows.size())
    throw std::logic_error("write_bounce_table: " + std::to_string(files.size()) + " files for " +
                           std::to_string(rows.size()) + " rows");
  std::ostringstream out;
  // The sigma columns when every row has its sigmas (tables without them read as before).
  bool sigmas = !rows.empty();
  for (const auto& r : rows) sigmas = sigmas && r.has_sigmas();
  out << "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out";
  if (sigmas)
    for (const char* c : kSigmaColumns) out << ',' << c;
  if (!files.empty()) out << ",file";
  out << '\n';
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    out << shortest(r.theta_deg) << ',' << shortest(r.vx_in) << ',' << shortest(r.vy_in) << ','
        << shortest(r.omega_in) << ',' << shortest(r.vx_out) << ',' << shortest(r.vy_out) << ','
        << shortest(r.omega_out);
    if (sigmas)
      for (auto f : kSigmaFields) out << ',' << shortest(r.*f);
    if (!files.empty()) out << ',' << csv_quote(files[i]);
    out << '\n';
  }
  return out.str();
}

}  // namespace tribolab::io
