#include "app/sweep/report_map_caption.hpp"

#include "report/format.hpp"

#include <cmath>
#include <algorithm>
#include <cstddef>
#include <vector>

namespace tribolab::app {
namespace {

std::string v3(double x) { return report::format_value(x, 3); }

/// "collision angle (deg)" -> {"collision angle", "deg"}; no parentheses: {title, ""}.
std::pair<std::string, std::string> name_and_unit(const std::string& title) {
  const auto open = title.find(" (");
  const auto close = title.find(')', open == std::string::npos ? 0 : open);
  if (open == std::string::npos || close == std::string::npos) return {title, ""};
  return {title.substr(0, open), title.substr(open + 2, close - open - 2)};
}

std::string with_unit(double v, const std::string& unit) { return v3(v) + (unit.empty() ? "" : " " + unit); }

/// Mean of the finite values of row i (by_row) or column i.
double line_mean(const report::HeatMap& h, std::size_t i, bool by_row) {
  double sum = 0;
  int n = 0;
  const std::size_t len = by_row ? h.x.size() : h.y.size();
  for (std::size_t k = 0; k < len; ++k) {
    const double v = by_row ? h.z[i][k] : h.z[k][i];
    if (std::isfinite(v)) {
      sum += v;
      ++n;
    }
  }
  return n ? sum / n : NAN;
}

}  // namespace

std::string describe_heat_map(const report::Figure& f, const std::string& q, const std::string& unit) {
  const report::HeatMap& h = *f.heatmap;
  const auto [xn, xu] = name_and_unit(f.x_axis.title);
  const auto [yn, yu] = name_and_unit(f.y_axis.title);
  auto at = [&, &xn = xn, &xu = xu, &yn = yn, &yu = yu](std::size_t i, std::size_t j) {
    return "(" + yn + " " + with_unit(h.y[i], yu) + ", " + xn + " " + with_unit(h.x[j], xu) + ")";
  };
  std::size_t n = 0, blank = 0, above = 0, below = 0, imin = 0, jmin = 0, imax = 0, jmax = 0;
  double zmin = INFINITY, zmax = -INFINITY;
  const double mid = h.z_mid.value_or(NAN);
  for (std::size_t i = 0; i < h.z.size(); ++i)
    for (std::size_t j = 0; j < h.z[i].size(); ++j) {
      const double v = h.z[i][j];
      if (!std::isfinite(v)) {
        ++blank;
        continue;
      }
      ++n;
      if (v < zmin) zmin = v, imin = i, jmin = j;
      if (v > zmax) zmax = v, imax = i, jmax = j;
      above += v > mid ? 1 : 0;
      below += v < mid ? 1 : 0;
    }
  if (n == 0) return "No cell has a result: the map is blank.";
  std::string s = q + " runs from " + with_unit(zmin, unit) + " " + at(imin, jmin) + " to " + with_unit(zmax, unit) +
                  " " + at(imax, jmax) + ".";
  // Trends: the mean of the first and last column (x) and row (y).
  std::string trends;
  for (const bool by_row : {false, true}) {
    const std::size_t last = (by_row ? h.y.size() : h.x.size()) - 1;
    if (last == 0) continue;
    const double a = line_mean(h, 0, by_row), b = line_mean(h, last, by_row);
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    const std::string& name = by_row ? yn : xn;
    const std::string& u = by_row ? yu : xu;
    const std::vector<double>& axis = by_row ? h.y : h.x;
    const double change = b - a, scale = zmax - zmin;
    const std::string verb = std::abs(change) <= 0.05 * scale ? "hardly changes" : change > 0 ? "rises" : "falls";
    trends += (trends.empty() ? "On average it " : "; it ") + verb + " along " + name + " (mean " + v3(a) + " at " +
              with_unit(axis.front(), u) + ", " + v3(b) + " at " + with_unit(axis.back(), u) + ")";
  }
  if (!trends.empty()) s += " " + trends + ".";
  if (h.z_mid) {
    const std::string m = q + " = " + v3(mid);
    const double pct_above = 100.0 * static_cast<double>(above) / static_cast<double>(n);
    if (above > 0 && below > 0) {
      s += " The neutral colour is " + m + "; " + v3(pct_above) + " % of the cells with a result lie above it.";
    } else {
      s += std::string(" Every cell lies ") + (above > 0 ? "above " : below > 0 ? "below " : "at ") + m +
           ", so the colours stay on one side of the scale's neutral colour.";
    }
  }
  for (const report::Series& c : f.series) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    std::size_t pieces = 0;
    bool in_piece = false;
    for (std::size_t k = 0; k < c.x.size(); ++k) {
      const bool ok = std::isfinite(c.x[k]) && std::isfinite(c.y[k]);
      if (ok) {
        x0 = std::min(x0, c.x[k]), x1 = std::max(x1, c.x[k]), y0 = std::min(y0, c.y[k]), y1 = std::max(y1, c.y[k]);
        if (!in_piece) ++pieces;
      }
      in_piece = ok;
    }
    if (pieces == 0) continue;
    s += " The curve \"" + c.name + "\" (" + std::to_string(pieces) + (pieces == 1 ? " piece" : " pieces") +
         ") spans " + xn + " " + v3(x0) + "–" + with_unit(x1, xu) + " and " + yn + " " + v3(y0) + "–" +
         with_unit(y1, yu) + ".";
  }
  if (h.z_mid && above > 0 && below > 0 && f.series.empty())
    s += " No curve is drawn: the cells above and below " + v3(mid) + " are not separated by a traced boundary.";
  if (blank > 0) s += " " + std::to_string(blank) + " blank cells have no result.";
  return s;
}

}  // namespace tribolab::app
