// Small helpers shared by the report pages of the commands and the demo.
#pragma once

#include "report/report.hpp"

#include <string>
#include <utility>

namespace tribolab::cli {

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

}  // namespace tribolab::cli
