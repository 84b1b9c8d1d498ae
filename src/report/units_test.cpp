// Units from labels and keys (report/units.hpp), and the unit column of parameter tables.
#include "report/units.hpp"

#include "report/html.hpp"

#include <gtest/gtest.h>

namespace tribolab::report {
namespace {

TEST(Units, LabelsGiveTheirWrittenUnitOrTheirSymbolsUnit) {
  using P = std::pair<std::string, std::string>;
  EXPECT_EQ(split_unit("v_x (m/s)"), P("v_x", "m/s"));
  EXPECT_EQ(split_unit("a (semi-major axis), m"), P("a (semi-major axis)", "m"));
  EXPECT_EQ(split_unit("I (about the centre), kg m^2"), P("I (about the centre)", "kg m^2"));
  EXPECT_EQ(split_unit("D (N s/m^(n+1))"), P("D", "N s/m^(n+1)"));
  EXPECT_EQ(split_unit("K (N/m^1.5)"), P("K", "N/m^1.5"));
  EXPECT_EQ(split_unit("ω (rad/s, CCW positive)"), P("ω (CCW positive)", "rad/s"));
  // No written unit: from the leading symbol or key, dimensionless marked as such.
  EXPECT_EQ(split_unit("μ (kinetic friction coefficient)"), P("μ (kinetic friction coefficient)", kDimensionless));
  EXPECT_EQ(split_unit("e = −v_y,out / v_y,in"), P("e = −v_y,out / v_y,in", kDimensionless));
  EXPECT_EQ(split_unit("a"), P("a", "m"));  // a sweep file's ball semi-axis key
  EXPECT_EQ(split_unit("mass"), P("mass", "kg"));
  EXPECT_EQ(split_unit("inertia"), P("inertia", "kg m^2"));
  EXPECT_EQ(split_unit("vx"), P("vx", "m/s"));
  EXPECT_EQ(split_unit("g"), P("g", "m/s^2"));
  EXPECT_EQ(split_unit("boundary root tolerance (fraction of the grid spacing)").second, kDimensionless);
  EXPECT_EQ(split_unit("cell model"), P("cell model", ""));  // text: no unit
  // Qualifiers before the symbol, statistics and the stop-point slopes.
  EXPECT_EQ(split_unit("slope t_stop_v0").second, "s^2/m");
  EXPECT_EQ(split_unit("slope y_stop_x_stop").second, kDimensionless);
  EXPECT_EQ(split_unit("weighted f_N/m (m/s^2) (inverse-variance)").second, "m/s^2");
  EXPECT_EQ(split_unit("truth μ (make.sh)").second, kDimensionless);
  EXPECT_EQ(split_unit("p value").second, kDimensionless);
  EXPECT_EQ(split_unit("largest e of the first contact phase alone").second, kDimensionless);
  EXPECT_EQ(split_unit("r = |x_stop / y_stop|").second, kDimensionless);
  // A note in parentheses is not a unit.
  EXPECT_FALSE(looks_like_unit("fraction of the grid spacing"));
  EXPECT_TRUE(looks_like_unit("m/s^2"));
  // The text listing's key rules are the same function.
  EXPECT_EQ(unit_of_key("t_stop"), "s");
  EXPECT_EQ(unit_of_key("mean", "mean_normal_force"), "N");
}

TEST(Units, ParameterTablesGetAUnitColumn) {
  Report r;
  r.title = "t";
  Table t;
  t.caption = "Ball";
  t.header = {"quantity", "value"};
  t.rows = {{"mass, kg", "0.4"}, {"μ", "0.5"}, {"law", "hooke"}};
  Table other;
  other.caption = "Runs";
  other.header = {"run", "e"};
  other.rows = {{"1", "0.8"}};
  r.add_section("s").add_table(t).add_table(other);
  const std::string html = to_html(r, PlotlyMode::cdn);
  EXPECT_NE(html.find("<th>quantity</th><th>unit</th><th>value</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>mass</td><td>kg</td><td>0.4</td></tr>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>μ</td><td>dimensionless</td>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>law</td><td></td><td>hooke</td></tr>"), std::string::npos);
  EXPECT_NE(html.find("<th>run</th><th>e</th>"), std::string::npos);  // other tables unchanged
}

}  // namespace
}  // namespace tribolab::report
