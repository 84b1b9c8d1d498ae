// `--plotly embed|cdn|file`: how a report gets Plotly.js (report/plotly_script.hpp).
#include "report/html.hpp"

#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "report/format.hpp"
#include "report/plotly_json.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>
#include <unistd.h>

namespace tribolab::report {
namespace {

namespace fs = std::filesystem;

Report one_plot() {
  Report r;
  r.title = "t";
  Figure f;
  f.title = "f";
  Series s;
  s.x = {0, 1};
  s.y = {1, 2};
  f.series = {s};
  r.add_section("s").add_figure(f);
  return r;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribolab_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

/// SHA-384 of `path` by coreutils' sha384sum (independent of the build's CMake digest), as
/// the base64 an integrity attribute holds.
std::string sha384_base64(const std::string& path) {
  FILE* p = ::popen(("sha384sum '" + path + "'").c_str(), "r");
  if (p == nullptr) return "popen failed";
  char buf[200] = {};
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, p);
  ::pclose(p);
  const std::string hex(buf, std::min<std::size_t>(n, 96));
  std::string bytes;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2) bytes += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
  return base64(bytes);
}

TEST(EmbeddedPlotly, HoldsEveryTraceTypeTheReportsDraw) {
  // The embedded library is Plotly's cartesian partial bundle (1.5 MB, not the full 4.8 MB).
  // Every trace type a figure can produce (series of every mode, error bars, a heat map) must
  // be registered in it, else the page draws nothing for that trace.
  Figure f;
  f.title = "every kind";
  f.x_axis.title = "x";
  f.y_axis.title = "y";
  HeatMap h;
  h.x = {0, 1};
  h.y = {0, 1};
  h.z = {{0, 1}, {1, 0}};
  f.heatmap = h;
  for (Mode m : {Mode::Lines, Mode::Markers, Mode::LinesMarkers}) {
    Series s;
    s.name = "s";
    s.mode = m;
    s.x = {0, 1};
    s.y = {0, 1};
    s.y_error = {0.1, 0.1};
    f.series.push_back(s);
  }
  const nlohmann::json fig = plotly_figure(f, "every-kind");
  std::set<std::string> types;
  for (const auto& trace : fig.at("data")) types.insert(trace.at("type").get<std::string>());
  EXPECT_EQ(types, (std::set<std::string>{"heatmap", "scatter"}));
  const std::string_view js = plotly_js();
  for (const std::string& t : types)
    EXPECT_NE(js.find("moduleType:\"trace\",name:\"" + t + "\""), std::string_view::npos) << t;
  EXPECT_LT(js.size(), 2'000'000u);  // the partial bundle (the full one is 4.8 MB)
}

TEST(PlotlyMode, EmbedIsTheDefaultAndHasNoScriptSource) {
  const std::string html = to_html(one_plot());
  EXPECT_EQ(html, to_html(one_plot(), PlotlyMode::embed));
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_NE(html.find("embedded in this file: the report works offline"), std::string::npos);
  EXPECT_GT(html.size(), plotly_js().size());
}

TEST(PlotlyMode, CdnPinsTheEmbeddedVersionWithItsSha384) {
  const std::string dir = temp_dir("plotly_cdn");
  const std::string copy = dir + "/embedded.js";
  std::ofstream(copy, std::ios::binary).write(plotly_js().data(), static_cast<std::streamsize>(plotly_js().size()));
  const std::string html = to_html(one_plot(), PlotlyMode::cdn);
  const std::regex tag("<script src=\"([^\"]+)\" integrity=\"sha384-([^\"]+)\" crossorigin=\"anonymous\"></script>");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, tag));
  EXPECT_EQ(m[1].str(), "https://cdn.jsdelivr.net/npm/plotly.js-cartesian-dist-min@" + std::string(plotly_version()) +
                            "/plotly-cartesian.min.js");
  EXPECT_EQ(m[2].str(), sha384_base64(copy));
  EXPECT_EQ("sha384-" + m[2].str(), plotly_integrity());
  EXPECT_LT(html.size(), 100000u);  // the library is not in the page
  EXPECT_NE(html.find("the plots need a network connection"), std::string::npos);  // the page says so
  EXPECT_EQ(html.find("works offline"), std::string::npos);
}

TEST(PlotlyMode, FileWritesOneSharedScriptOnceAndLinksItRelatively) {
  const std::string dir = temp_dir("plotly_file");
  const std::string script = dir + "/" + plotly_file_name();
  write_html(one_plot(), dir + "/a.html", PlotlyMode::file);
  ASSERT_TRUE(fs::exists(script));
  EXPECT_EQ(slurp(script), std::string(plotly_js()));  // the vendored bytes, not script-escaped
  EXPECT_NE(slurp(dir + "/a.html").find("<script src=\"" + plotly_file_name() + "\"></script>"), std::string::npos);
  // A second report (and one in a sub-folder pointing at the same script) does not rewrite it.
  const auto written = fs::last_write_time(script);
  fs::create_directories(dir + "/runs");
  write_html(one_plot(), dir + "/b.html", PlotlyMode::file);
  write_html(one_plot(), dir + "/runs/01.html", PlotlyMode::file, dir);
  EXPECT_EQ(fs::last_write_time(script), written);
  EXPECT_NE(slurp(dir + "/runs/01.html").find("<script src=\"../" + plotly_file_name() + "\"></script>"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/runs/" + plotly_file_name()));
  // A damaged copy is replaced.
  std::ofstream(script, std::ios::trunc) << "broken";
  write_html(one_plot(), dir + "/c.html", PlotlyMode::file);
  EXPECT_EQ(slurp(script).size(), plotly_js().size());
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 4);  // a, b, c and the one script: no temporary left behind
}

TEST(PlotlyMode, ParsesTheThreeNamesAndRejectsOthersNamingTheOption) {
  EXPECT_EQ(parse_plotly_mode("embed"), PlotlyMode::embed);
  EXPECT_EQ(parse_plotly_mode("cdn"), PlotlyMode::cdn);
  EXPECT_EQ(parse_plotly_mode("file"), PlotlyMode::file);
  try {
    parse_plotly_mode("web");
    FAIL() << "no error";
  } catch (const InputError& e) {
    // The field, which each front end spells: the command line --plotly, Python plotly.
    EXPECT_EQ(e.where(), "plotly");
    EXPECT_EQ(e.message([](std::string_view f) { return "<" + std::string(f) + ">"; }),
              "<plotly>: 'web' is not one of embed, cdn, file");
  }
}

}  // namespace
}  // namespace tribolab::report
