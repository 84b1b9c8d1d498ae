// Small helpers shared by the report pages of the commands and the demo.
#pragma once

#include "report/format.hpp"
#include "report/report.hpp"

#include <string>
#include <utility>
#include <vector>

namespace tribolab::app {

/// A series with a legend name and the defaults of report::Series otherwise.
inline report::Series named(std::string name, report::Mode mode = report::Mode::Markers) {
  report::Series s;
  s.name = std::move(name);
  s.mode = mode;
  return s;
}

/// An empty figure with its title, axis titles and height (px).
inline report::Figure make_figure(std::string title, std::string x_title, std::string y_title, int height_px) {
  report::Figure f;
  f.title = std::move(title);
  f.x_axis.title = std::move(x_title);
  f.y_axis.title = std::move(y_title);
  f.height_px = height_px;
  return f;
}

/// A line series with a legend name, its points, dash and colour (empty: Plotly's default).
inline report::Series make_line(std::string name, std::vector<double> x, std::vector<double> y,
                                report::Dash dash = report::Dash::Solid, std::string color = {}) {
  report::Series s = named(std::move(name), report::Mode::Lines);
  s.x = std::move(x);
  s.y = std::move(y);
  s.dash = dash;
  s.color = std::move(color);
  return s;
}

/// "[lo, hi]" with five significant digits: an interval in a report's table.
inline std::string interval_cell(double lo, double hi) {
  return "[" + report::format_value(lo, 5) + ", " + report::format_value(hi, 5) + "]";
}

/// "yes" or "no" in a report's table.
inline std::string yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace tribolab::app
