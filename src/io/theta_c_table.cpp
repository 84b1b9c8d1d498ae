#include "io/theta_c_table.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <algorithm>

namespace tribolab::io {

std::vector<analysis::ThetaCPoint> parse_theta_c_table(const std::string& text, const std::string& name) {
  std::vector<analysis::ThetaCPoint> pts;
  int line_no = 0, col_phi = -1, col_cos = -1, col_sigma = -1;
  std::size_t pos = 0;
  bool header = false;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string line(trim(std::string_view(text).substr(pos, end - pos)));
    pos = end + 1;
    ++line_no;
    const std::string where = name + ":" + std::to_string(line_no);
    if (line.empty() || line[0] == '#') {
      if (end == text.size()) break;
      continue;
    }
    const auto cells = split(line, ',');
    if (!header) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const std::string c(trim(cells[i]));
        if (c == "phi_deg") col_phi = static_cast<int>(i);
        else if (c == "cos_theta_c") col_cos = static_cast<int>(i);
        else if (c == "sigma_cos_theta_c") col_sigma = static_cast<int>(i);
      }
      if (col_phi < 0 || col_cos < 0)
        throw InputError(where, "header must name the columns phi_deg and cos_theta_c (comma separated)");
      header = true;
    } else {
      const int need = std::max({col_phi, col_cos, col_sigma});
      if (static_cast<int>(cells.size()) <= need)
        throw InputError(where, "expected " + std::to_string(need + 1) + " cells, got " + std::to_string(cells.size()));
      analysis::ThetaCPoint p;
      const double phi_deg = parse_double(trim(cells[col_phi]), where);
      if (!(phi_deg > 0 && phi_deg < 90)) throw InputError(where, "phi_deg must be in (0, 90)");
      p.phi = to_rad(phi_deg);
      p.cos_theta_c = parse_double(trim(cells[col_cos]), where);
      if (col_sigma >= 0) p.sigma_cos_theta_c = parse_double(trim(cells[col_sigma]), where);
      // cos(theta_c) = |v_y|/|v| lies in [0, 1]; a value outside (1e308: a typo) is no
      // measurement, and the fit cannot carry it.
      if (!(p.cos_theta_c >= 0 && p.cos_theta_c <= 1))
        throw InputError(where, "cos_theta_c must be in [0, 1], got " + format_number(p.cos_theta_c));
      if (!(p.sigma_cos_theta_c >= 0 && p.sigma_cos_theta_c <= 1))
        throw InputError(where, "sigma_cos_theta_c must be in [0, 1], got " + format_number(p.sigma_cos_theta_c));
      p.source = where;
      pts.push_back(p);
    }
    if (end == text.size()) break;
  }
  if (!header) throw InputError(name, "is empty; expected a header phi_deg,cos_theta_c");
  return pts;
}

std::vector<analysis::ThetaCPoint> read_theta_c_table(const std::string& path) {
  return parse_theta_c_table(read_file(path), path);
}

}  // namespace tribolab::io
