// A Figure as Plotly.js input: {"data": [traces], "layout": {...}, "config": {...}}, the
// arguments of Plotly.newPlot. Text is escaped (Plotly decodes entities and accepts only
// its own small tag set), numbers keep full precision, NaN becomes null (a gap).
#pragma once

#include "report/report.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace tribolab::report {

/// Plotly traces, layout and config for one figure. `file_name` names the PNG that the
/// mode bar's camera button saves (without extension).
nlohmann::json plotly_figure(const Figure& figure, const std::string& file_name);

}  // namespace tribolab::report
