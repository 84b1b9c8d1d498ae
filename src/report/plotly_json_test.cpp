// Axis ranges and colour scales of the figure JSON (report/plotly_json.hpp).
#include "report/plotly_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace tribolab::report {
namespace {

Figure measured_vs_fitted() {
  // The bounce-fit figure's shape: points in -2..3 on both axes, a 1:1 line, equal aspect,
  // in a plot far wider than high (Plotly's autorange made x span -10..13 here).
  Figure f;
  f.title = "measured vs fitted";
  f.equal_aspect = true;
  f.height_px = 380;
  Series pts;
  pts.x = {-2.0, -0.5, 1.0, 3.0};
  pts.y = {-1.8, -0.4, 1.1, 2.9};
  Series diag;
  diag.mode = Mode::Lines;
  diag.x = {-2.0, 3.0};
  diag.y = {-2.0, 3.0};
  f.series = {pts, diag};
  return f;
}

TEST(PlotlyFigure, AxesSpanTheDataWithASmallMarginOnAnEqualAspectPlot) {
  const auto layout = plotly_figure(measured_vs_fitted(), "f")["layout"];
  for (const char* axis : {"xaxis", "yaxis"}) {
    ASSERT_TRUE(layout[axis].contains("range")) << axis;
    const double lo = layout[axis]["range"][0], hi = layout[axis]["range"][1];
    // Covers the data (-2..3) and adds at most 10 % of its span (5) on each side.
    EXPECT_LE(lo, -2.0) << axis;
    EXPECT_GE(hi, 3.0) << axis;
    EXPECT_GE(lo, -2.0 - 0.5) << axis;
    EXPECT_LE(hi, 3.0 + 0.5) << axis;
    // The plot area shrinks to keep 1:1, the ranges stay the data's.
    EXPECT_EQ(layout[axis]["constrain"], "domain") << axis;
  }
  EXPECT_EQ(layout["yaxis"]["scaleanchor"], "x");
}

TEST(PlotlyFigure, RangesIncludeErrorBarsUseLog10OnLogAxesAndSkipGaps) {
  Figure f;
  f.y_axis.log = true;
  Series s;
  s.x = {0.0, 1.0, std::numeric_limits<double>::quiet_NaN(), 2.0};
  s.y = {10.0, 100.0, 5.0, 1000.0};
  s.x_error = {0.5, 0.0, 0.0, 0.0};
  f.series = {s};
  const auto r = axis_range(f, false);
  ASSERT_TRUE(r);
  const double span = 2.5;  // -0.5 (error bar) .. 2.0; the NaN point leaves x out
  EXPECT_DOUBLE_EQ(r->first, -0.5 - kAxisMargin * span);
  EXPECT_DOUBLE_EQ(r->second, 2.0 + kAxisMargin * span);
  const auto ry = axis_range(f, true);  // log10 of 5..1000
  ASSERT_TRUE(ry);
  EXPECT_NEAR(ry->first, std::log10(5.0) - kAxisMargin * (3 - std::log10(5.0)), 1e-12);
  EXPECT_NEAR(ry->second, 3 + kAxisMargin * (3 - std::log10(5.0)), 1e-12);
  EXPECT_FALSE(axis_range(Figure{}, false));  // nothing drawn: Plotly's default
}

TEST(PlotlyFigure, HeatMapAxesEndAtTheOuterCellEdges) {
  Figure f;
  HeatMap h;
  h.x = {30, 32, 34};
  h.y = {100, 110};
  h.z = {{0.5, 0.6, 0.7}, {0.8, 0.9, 1.0}};
  f.heatmap = h;
  Series inside;  // a boundary inside the map does not widen it
  inside.x = {31, 33};
  inside.y = {101, 109};
  f.series = {inside};
  const auto layout = plotly_figure(f, "m")["layout"];
  EXPECT_EQ(layout["xaxis"]["range"], nlohmann::json({29.0, 35.0}));
  EXPECT_EQ(layout["yaxis"]["range"], nlohmann::json({95.0, 115.0}));
}

TEST(PlotlyFigure, DivergingScaleThatTheDataReachOnOneSideOnlyHasNoBlue) {
  HeatMap h;
  h.colorscale = ColorScale::RdBu;
  h.z_mid = 1.0;
  // e from 0.4 to 0.9: all below 1, red shades that pale towards 0.9, no white, no blue.
  const auto stops = heatmap_colorscale(h, 0.4, 0.9);
  ASSERT_GE(stops.size(), 2u);
  EXPECT_EQ(stops.front().position, 0.0);
  EXPECT_EQ(stops.back().position, 1.0);
  EXPECT_EQ(stops.front().rgb, "rgb(103,0,31)");
  for (const auto& s : stops) {
    int r = 0, g = 0, b = 0;
    ASSERT_EQ(std::sscanf(s.rgb.c_str(), "rgb(%d,%d,%d)", &r, &g, &b), 3) << s.rgb;
    EXPECT_GE(r, b) << s.rgb;  // never bluer than red
    EXPECT_NE(s.rgb, "rgb(247,247,247)");
  }
  // Symmetric data about 1: the neutral in the middle, deepest red and blue at the ends.
  const auto both = heatmap_colorscale(h, 0.5, 1.5);
  EXPECT_EQ(both.front().rgb, "rgb(103,0,31)");
  EXPECT_EQ(both.back().rgb, "rgb(5,48,97)");
  bool mid = false;
  for (const auto& s : both) mid |= s.rgb == "rgb(247,247,247)" && std::abs(s.position - 0.5) < 1e-12;
  EXPECT_TRUE(mid);
}

}  // namespace
}  // namespace tribolab::report
