// A Figure as Plotly.js input: {"data": [traces], "layout": {...}, "config": {...}}, the
// arguments of Plotly.newPlot. Text is escaped (Plotly decodes entities and accepts only
// its own small tag set), numbers keep full precision, NaN becomes null (a gap).
#pragma once

#include "report/report.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>

namespace tribolab::report {

/// One stop of a Plotly colour scale: position in [0, 1] and "rgb(r,g,b)".
struct ColorStop {
  double position;
  std::string rgb;
};

/// The colour scale a heat map is drawn with over [zmin, zmax] (its finite z): a sequential
/// scale as Plotly names it (one stop, empty rgb, holding the name) or, for a diverging scale,
/// explicit stops so that z_mid (default: the middle of the data) has the neutral colour.
std::vector<ColorStop> heatmap_colorscale(const HeatMap& h, double zmin, double zmax);

/// Fraction of the data's span added on each side of a figure's axis range.
inline constexpr double kAxisMargin = 0.04;

/// The range [lo, hi] of one axis of `figure` as drawn: every finite value of its series
/// (with error bars) and heat-map cells (half a cell beyond the outer centres, no margin),
/// plus kAxisMargin of the span on each side; in log10 units on a log axis (positive values
/// only). Zero span: ±5 % of the value (±1 at zero). Empty when there is nothing to draw.
std::optional<std::pair<double, double>> axis_range(const Figure& figure, bool y);

/// Plotly traces, layout and config for one figure. Each axis gets the range axis_range()
/// (not Plotly's autorange, which on an equal-aspect figure widens the range to fill the
/// plot's width: -10..13 for data in -2..3); equal-aspect figures shrink their plot area
/// instead (constrain "domain"). `file_name` names the PNG that the
/// mode bar's camera button saves (without extension).
nlohmann::json plotly_figure(const Figure& figure, const std::string& file_name);

}  // namespace tribolab::report
