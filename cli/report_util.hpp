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

}  // namespace tribolab::cli
