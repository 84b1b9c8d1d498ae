// Unit tests of the sweep report builder (src/app/sweep/report_sweep.hpp) on the analytic cell models
// of sweep/synthetic.hpp: the heat map holds the grid's values, the boundary drawn is the
// traced contour, the size bounds hold, and the figures present match what the data allow.
#include "app/sweep/report_sweep.hpp"

#include "report/format.hpp"
#include "report/html.hpp"
#include "sweep/synthetic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <unistd.h>

namespace tribolab::app {
namespace {

/// The report's data with the whole map kept beside it, for the tests to compare against.
struct TestData : SweepReportData {
  std::vector<double> values;  ///< cell_count x outputs
};

TestData data_for(const sweep::GridSpec& grid, const sweep::CellModel& model) {
  TestData d;
  d.header = io::SweepHeader{grid, sweep::Shard{}, model.output_names, model.description};
  d.values = sweep::evaluate_grid(grid, model);
  d.map = summarize_sweep_map(d.header, d.values);
  const sweep::ContourOptions co;
  d.boundary = sweep::trace_contour(grid, model, d.values, co);
  d.thresholds = sweep::spin_thresholds(grid, model, d.values, co);
  d.command = "test";
  return d;
}

sweep::GridSpec seed_window(std::int64_t n_theta = 8, std::int64_t n_omega = 5) {
  sweep::GridSpec g;
  g.axes = {{sweep::Quantity::theta_deg, 100, 170, n_theta}, {sweep::Quantity::omega, 30, 50, n_omega}};
  return g;
}

int figures(const report::Report& r) { return r.figure_count(); }

const report::Table* find_table(const report::Report& r, const std::string& caption) {
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* t = std::get_if<report::Table>(&b); t && t->caption == caption) return t;
  return nullptr;
}

std::string row_value(const report::Table& t, const std::string& name) {
  for (const auto& row : t.rows)
    if (row[0] == name) return row[1];
  return "(no row '" + name + "')";
}

TEST(SweepReport, MapCaptionIsComputedFromTheCellsAndTheBoundary) {
  const sweep::GridSpec g = seed_window();
  const TestData d = data_for(g, sweep::synthetic::wave_model());
  SweepMapStyle style;
  style.title = "e";
  style.x_title = "incoming spin ω (rad/s)";
  const report::Figure f = sweep_heat_map(g, d.values, 4, 3, 0, &d.boundary, style);
  // The extremes of the slice, recomputed here, and where they are.
  double lo = INFINITY, hi = -INFINITY;
  int above = 0, n = 0;
  for (const auto& row : f.heatmap->z)
    for (double v : row) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      above += v > 1 ? 1 : 0;
      ++n;
    }
  ASSERT_LT(lo, 1.0);
  ASSERT_GT(hi, 1.0);
  EXPECT_NE(f.caption.find("e runs from " + report::format_value(lo, 3) + " "), std::string::npos) << f.caption;
  EXPECT_NE(f.caption.find(" to " + report::format_value(hi, 3) + " "), std::string::npos) << f.caption;
  EXPECT_NE(f.caption.find("The neutral colour is e = 1; " + report::format_value(100.0 * above / n, 3) + " %"),
            std::string::npos)
      << f.caption;
  // The boundary's extent along the spin axis, from the drawn series.
  double x0 = INFINITY, x1 = -INFINITY;
  for (double x : f.series.at(0).x)
    if (std::isfinite(x)) x0 = std::min(x0, x), x1 = std::max(x1, x);
  EXPECT_NE(f.caption.find("\"e = 1 boundary\""), std::string::npos) << f.caption;
  EXPECT_NE(f.caption.find("incoming spin ω " + report::format_value(x0, 3) + "–" + report::format_value(x1, 3) + " rad/s"),
            std::string::npos)
      << f.caption;
  // Every cell below 1: said so, and no blue in the scale (report/plotly_json_test.cpp).
  std::vector<double> low = d.values;
  for (double& v : low) v = std::min(v, 0.9);
  const report::Figure g2 = sweep_heat_map(g, low, 4, 3, 0, nullptr, style);
  EXPECT_NE(g2.caption.find("Every cell lies below e = 1"), std::string::npos) << g2.caption;
}

TEST(SweepReport, HeatMapHoldsTheGridValuesAndTheBoundary) {
  const sweep::GridSpec g = seed_window();
  const TestData d = data_for(g, sweep::synthetic::wave_model());
  ASSERT_FALSE(d.boundary.lines.empty()) << "the wave model crosses e = 1 near 40 rad/s";
  SweepMapStyle style;
  style.title = "e";
  const report::Figure f = sweep_heat_map(g, d.values, 4, 3, 0, &d.boundary, style);
  EXPECT_TRUE(f.validate().empty()) << f.validate();
  ASSERT_TRUE(f.heatmap.has_value());
  ASSERT_EQ(f.heatmap->y.size(), 8u);
  ASSERT_EQ(f.heatmap->x.size(), 5u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(f.heatmap->y[i], g.axes[0].value(static_cast<std::int64_t>(i)));
    for (std::size_t j = 0; j < 5; ++j) EXPECT_EQ(f.heatmap->z[i][j], d.values[(i * 5 + j) * 4 + 3]);
  }
  // The series is every contour point in order, polylines separated by one NaN.
  ASSERT_EQ(f.series.size(), 1u);
  const report::Series& b = f.series[0];
  std::size_t k = 0;
  for (std::size_t l = 0; l < d.boundary.lines.size(); ++l) {
    if (l > 0) {
      ASSERT_LT(k, b.x.size());
      EXPECT_TRUE(std::isnan(b.x[k]) && std::isnan(b.y[k]));
      ++k;
    }
    for (const auto& p : d.boundary.lines[l].points) {
      ASSERT_LT(k, b.x.size());
      EXPECT_EQ(b.x[k], p.spin);
      EXPECT_EQ(b.y[k], p.theta_deg);
      ++k;
    }
  }
  EXPECT_EQ(k, b.x.size());
}

TEST(SweepReport, LargeMapsAreThinnedToTheBound) {
  // Rows drawn: all up to 201; else every k-th (k the smallest stride that fits) plus the
  // last: 1001 rows -> every 5th = 201; 1002 -> every 6th (167) + the last = 168;
  // 202 -> every 2nd (101) + the last = 102.
  for (const auto& [n, drawn] : {std::pair<std::int64_t, std::size_t>{1001, 201}, {1002, 168}, {202, 102},
                                 {201, 201}, {2, 2}}) {
    sweep::GridSpec g = seed_window(n, 3);
    const TestData d = data_for(g, sweep::synthetic::trivial_model());
    SweepMapStyle style;
    style.max_side = kReportMaxSide;
    const report::Figure f = sweep_heat_map(g, d.values, 4, 0, 0, nullptr, style);
    const auto& y = f.heatmap->y;
    EXPECT_LE(y.size(), static_cast<std::size_t>(kReportMaxSide)) << n;
    EXPECT_EQ(y.size(), drawn) << n;
    EXPECT_EQ(y.front(), 100) << n;
    EXPECT_EQ(y.back(), 170) << n;  // the whole axis spanned
    // The trivial model's output 0 is theta_deg itself: each drawn row holds its own angle.
    for (std::size_t i = 0; i < y.size(); ++i) EXPECT_EQ(f.heatmap->z[i][0], y[i]);
  }
}

TEST(SweepReport, OneSliceHasEMapSpinMapThresholdAndEnergyRatio) {
  const sweep::GridSpec g = seed_window();
  const TestData d = data_for(g, sweep::synthetic::wave_model());
  const report::Report r = sweep_report(d);
  EXPECT_TRUE(r.validate().empty()) << r.validate();
  EXPECT_EQ(figures(r), 4);
  const report::Table* sum = find_table(r, "Summary of the whole grid");
  ASSERT_NE(sum, nullptr);
  EXPECT_EQ(row_value(*sum, "cells"), "40");
  double e_max = -1;
  int above = 0;
  for (std::size_t c = 0; c < 40; ++c) {
    e_max = std::max(e_max, d.values[c * 4 + 3]);
    above += d.values[c * 4 + 3] > 1;
  }
  EXPECT_EQ(row_value(*sum, "largest e"), report::format_value(e_max, 4));
  const std::string share = row_value(*sum, "cells with e > 1 (of the cells with a result)");
  EXPECT_EQ(share.substr(0, share.find(' ')), std::to_string(above)) << share;
  EXPECT_GT(above, 0);
  EXPECT_LT(above, 40);
  const report::Table* params = find_table(r, "Parameters of the sweep (from the header of the sweep file)");
  ASSERT_NE(params, nullptr);
  EXPECT_EQ(row_value(*params, "speed (m/s)"), "4");
  EXPECT_EQ(row_value(*params, "omega (rad/s)"), "swept 30 to 50, 5 values");
}

TEST(SweepReport, WithoutSpinOutputOrMassOnlyEMapAndThreshold) {
  // The ellipse model has only "e" and no mass or inertia: no omega_out map, no energy ratio.
  const TestData d = data_for(seed_window(15, 11), sweep::synthetic::ellipse_model());
  const report::Report r = sweep_report(d);
  EXPECT_TRUE(r.validate().empty()) << r.validate();
  EXPECT_EQ(figures(r), 2);
}

TEST(SweepReport, ThirdAxisDrawsAtMostSixSlices) {
  for (const auto& [n_speed, expected] : {std::pair{4, 4 + 4 + 2}, std::pair{9, 6 + 6 + 2}}) {
    sweep::GridSpec g = seed_window();
    g.axes.insert(g.axes.begin(), sweep::Axis{sweep::Quantity::speed, 3, 5, n_speed});
    const TestData d = data_for(g, sweep::synthetic::wave_model());
    const report::Report r = sweep_report(d);
    EXPECT_TRUE(r.validate().empty()) << r.validate();
    EXPECT_EQ(figures(r), expected) << n_speed << " speeds";
    const report::Table* per = find_table(r, "Per slice");
    ASSERT_NE(per, nullptr);
    EXPECT_EQ(per->rows.size(), static_cast<std::size_t>(n_speed));  // the table covers every slice
    EXPECT_EQ(per->rows.front()[0], "speed = 3 m/s");
    EXPECT_EQ(per->rows.back()[0], "speed = 5 m/s");
  }
}

// The size bound of docs/cli.md#bounce-sweep: a grid far larger than what is drawn (7
// slices of 401 x 401) gives 6 slices of 201 x 201 values and a file under 15 MB.
TEST(SweepReport, HugeGridStaysUnderTheDocumentedSize) {
  sweep::GridSpec g = seed_window(401, 401);
  g.axes.insert(g.axes.begin(), sweep::Axis{sweep::Quantity::speed, 3, 5, 7});
  const TestData d = data_for(g, sweep::synthetic::wave_model());
  const report::Report r = sweep_report(d);
  EXPECT_EQ(figures(r), 6 + 6 + 2);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("tribolab_sweep_report_size_" + std::to_string(::getpid()) + ".html"))
          .string();
  report::write_html(r, path);
  const auto bytes = std::filesystem::file_size(path);
  std::filesystem::remove(path);
  EXPECT_LT(bytes, 15'000'000u);
  EXPECT_GT(bytes, 10'000'000u) << "12 maps of 201 x 201 full-precision values are drawn";
}

// Issue 26: the report of a big sweep loaded its whole map. Its summary, gathered cell by
// cell, holds the drawn values only: for a 2001 x 2001 grid (4e6 cells) at most 201 x 201 per
// map, whatever the grid; and cells given in any order land in the same place.
TEST(SweepMapSummary, HoldsTheDrawnValuesOnlyAndTakesCellsInAnyOrder) {
  const sweep::CellModel model = sweep::synthetic::wave_model();
  sweep::GridSpec big;
  big.axes = {{sweep::Quantity::theta_deg, 100, 170, 2001}, {sweep::Quantity::omega, 30, 50, 2001}};
  const SweepMapSummary s(io::SweepHeader{big, sweep::Shard{}, model.output_names, model.description});
  ASSERT_EQ(s.e_map.size(), 1u);
  EXPECT_LE(s.e_map.at(0).size(), static_cast<std::size_t>(kReportMaxSide));
  EXPECT_LE(s.e_map.at(0).front().size(), static_cast<std::size_t>(kReportMaxSide));
  const sweep::GridSpec g = seed_window(9, 7);
  const TestData d = data_for(g, model);
  SweepMapSummary reversed(d.header);
  const std::size_t n_out = model.output_names.size();
  for (std::int64_t c = g.cell_count(); c-- > 0;) {
    reversed.add(c, std::vector<double>(d.values.begin() + static_cast<std::ptrdiff_t>(c * n_out),
                                        d.values.begin() + static_cast<std::ptrdiff_t>((c + 1) * n_out)));
  }
  EXPECT_EQ(reversed.e_map.at(0), d.map->e_map.at(0));
  EXPECT_EQ(reversed.all.above, d.map->all.above);
  EXPECT_EQ(reversed.all.e_max, d.map->all.e_max);
}

}  // namespace
}  // namespace tribolab::app
