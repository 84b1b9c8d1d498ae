#include "report/html.hpp"
#include "report/embedded.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace tribolab::report {
namespace {

/// The JSON the page hands to Plotly, cut out of the HTML as a browser would read it.
nlohmann::json figures_block(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"" + std::string(kFiguresId) +
                           "\">";
  const auto begin = html.find(open);
  if (begin == std::string::npos) throw std::runtime_error("no figures block");
  const auto start = begin + open.size();
  const auto end = html.find("</script>", start);
  return nlohmann::json::parse(html.substr(start, end - start));
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

/// Everything after the embedded library: the report's own markup and data.
std::string body_of(const std::string& html) { return html.substr(html.find("<body>")); }

Figure series_figure() {
  Figure f;
  f.title = "x–t";
  f.x_axis = {"t (s)", false};
  f.y_axis = {"x (m)", true};
  Series s;
  s.name = "data";
  s.x = {0.1 + 0.2, 1.0 / 3.0, 1e-300, 2.0};
  s.y = {1.0, kNaN, 3.0, 4.0};
  s.y_error = {0.1, 0.1, kNaN, 0.1};
  s.mode = Mode::LinesMarkers;
  s.color = "black";
  f.series.push_back(s);
  return f;
}

Figure heatmap_figure() {
  Figure f;
  f.title = "rebound";
  f.x_axis = {"θ_{in} (°)", false};
  f.y_axis = {"ω (rad/s)", false};
  HeatMap h;
  h.x = {0.0, 45.0, 90.0};
  h.y = {-10.0, 10.0};
  h.z = {{0.5, 0.9, 1.1}, {kNaN, 1.0, 1.2}};
  h.colorbar_title = "e";
  h.colorscale = ColorScale::RdBu;
  h.z_mid = 1.0;
  f.heatmap = h;
  Series boundary;
  boundary.name = "e = 1";
  boundary.x = {45.0, 60.0, kNaN, 70.0, 80.0};
  boundary.y = {10.0, 0.0, kNaN, -5.0, -10.0};
  boundary.mode = Mode::Lines;
  boundary.dash = Dash::Dash;
  f.series.push_back(boundary);
  return f;
}

Report two_figure_report() {
  Report r;
  r.title = "T";
  auto& s = r.add_section("Plots");
  s.add_figure(series_figure());
  s.add_figure(heatmap_figure());
  return r;
}

TEST(Html, TitleWithMarkupIsShownNotRun) {
  Report r;
  r.title = "<script>alert('x')</script> & \"q\"";
  r.add_section("A <b> section").add_paragraph("1 < 2 & 'x'").add_list({"<i>item</i>"});
  const std::string html = to_html(r);
  EXPECT_NE(html.find("<title>&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; "
                      "&quot;q&quot;</title>"),
            std::string::npos);
  const std::string body = body_of(html);
  EXPECT_EQ(body.find("<script>alert"), std::string::npos);
  EXPECT_NE(body.find("<h2>A &lt;b&gt; section</h2>"), std::string::npos);
  EXPECT_NE(body.find("<p>1 &lt; 2 &amp; &#39;x&#39;</p>"), std::string::npos);
  EXPECT_NE(body.find("<li>&lt;i&gt;item&lt;/i&gt;</li>"), std::string::npos);
}

TEST(Html, PageIsSelfContainedWithStatusMarkerAndLibrary) {
  const std::string html = to_html(two_figure_report());
  EXPECT_NE(html.find("<div id=\"tribolab-status\" hidden>pending</div>"), std::string::npos);
  EXPECT_NE(html.find("window.onerror"), std::string::npos);
  EXPECT_NE(html.find("tribolabShowStatus('ok ' + done[0].length)"), std::string::npos);
  EXPECT_NE(html.find("Plotly.newPlot"), std::string::npos);
  // the library's own banner (the cartesian bundle's: "* plotly.js (cartesian - minified) vX.Y.Z")
  EXPECT_NE(html.find("* plotly.js (cartesian - minified) v" + std::string(plotly_version())), std::string::npos);
  // Nothing is loaded from outside: no script or stylesheet references anywhere.
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(body_of(html).find(" src="), std::string::npos);
  EXPECT_EQ(html.substr(0, html.find("* plotly.js v")).find("<link"), std::string::npos);
}

TEST(Html, OnePlotElementPerFigureMatchingTheData) {
  const Report r = two_figure_report();
  const std::string html = to_html(r);
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), static_cast<std::size_t>(r.figure_count()));
  const auto spec = figures_block(html);
  ASSERT_EQ(spec["figures"].size(), 2u);
  EXPECT_EQ(spec["figures"][0]["id"], "figure-1");
  EXPECT_EQ(spec["figures"][1]["id"], "figure-2");
  EXPECT_NE(html.find("id=\"figure-1\""), std::string::npos);
  EXPECT_NE(html.find("<figcaption>Figure 2. rebound</figcaption>"), std::string::npos);
}

TEST(Html, SeriesNumbersRoundTripExactlyAndNaNIsNull) {
  const auto fig = figures_block(to_html(two_figure_report()))["figures"][0];
  const auto& trace = fig["data"][0];
  EXPECT_EQ(trace["type"], "scatter");
  EXPECT_EQ(trace["mode"], "lines+markers");
  EXPECT_EQ(trace["name"], "data");
  // Full precision: the parsed doubles are bit-for-bit the ones written.
  EXPECT_EQ(trace["x"][0].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(trace["x"][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(trace["x"][2].get<double>(), 1e-300);
  EXPECT_TRUE(trace["y"][1].is_null());  // a gap
  EXPECT_FALSE(trace["connectgaps"].get<bool>());
  EXPECT_TRUE(trace["error_y"]["array"][2].is_null());
  EXPECT_EQ(trace["error_y"]["array"][0].get<double>(), 0.1);
  EXPECT_EQ(trace["line"]["color"], "black");
  EXPECT_EQ(fig["layout"]["xaxis"]["type"], "linear");
  EXPECT_EQ(fig["layout"]["yaxis"]["type"], "log");
  EXPECT_EQ(fig["layout"]["xaxis"]["title"]["text"], "t (s)");
}

TEST(Html, HeatMapWithOverlaySerialisesGridAndBoundary) {
  const auto fig = figures_block(to_html(two_figure_report()))["figures"][1];
  ASSERT_EQ(fig["data"].size(), 2u);
  const auto& heat = fig["data"][0];  // drawn first, under the overlay
  EXPECT_EQ(heat["type"], "heatmap");
  EXPECT_EQ(heat["x"], nlohmann::json({0.0, 45.0, 90.0}));
  EXPECT_EQ(heat["y"], nlohmann::json({-10.0, 10.0}));
  ASSERT_EQ(heat["z"].size(), 2u);  // rows follow y
  EXPECT_EQ(heat["z"][0], nlohmann::json({0.5, 0.9, 1.1}));
  EXPECT_TRUE(heat["z"][1][0].is_null());
  EXPECT_EQ(heat["z"][1][2].get<double>(), 1.2);
  // Diverging scale over the data's range 0.5..1.2 (not made symmetric about 1: Plotly's
  // zmid would run the colour bar to 1.5), with the neutral white exactly at e = 1.
  EXPECT_FALSE(heat.contains("zmid"));
  EXPECT_EQ(heat["zmin"].get<double>(), 0.5);
  EXPECT_EQ(heat["zmax"].get<double>(), 1.2);
  const double at_one = (1.0 - 0.5) / (1.2 - 0.5);
  bool neutral_at_one = false;
  for (const auto& stop : heat["colorscale"])
    neutral_at_one |= stop[1] == "rgb(247,247,247)" && std::abs(stop[0].get<double>() - at_one) < 1e-12;
  EXPECT_TRUE(neutral_at_one) << heat["colorscale"].dump();  // 1e-12: rounding of two divisions
  EXPECT_EQ(heat["colorscale"].front()[1], "rgb(103,0,31)");  // e = 0.5 is the far side: deepest red
  EXPECT_EQ(heat["colorscale"].back()[0].get<double>(), 1.0);
  EXPECT_EQ(heat["colorbar"]["title"]["text"], "e");
  const auto& line = fig["data"][1];
  EXPECT_EQ(line["mode"], "lines");
  EXPECT_EQ(line["line"]["dash"], "dash");
  EXPECT_TRUE(line["x"][2].is_null());  // two branches in one series
  EXPECT_EQ(fig["layout"]["xaxis"]["title"]["text"], "θ<sub>in</sub> (°)");
}

TEST(Html, PlotlyConfigWorksOfflineAndExportsPng) {
  const auto config = figures_block(to_html(two_figure_report()))["figures"][0]["config"];
  EXPECT_FALSE(config["showSendToCloud"].get<bool>());
  EXPECT_EQ(config["plotlyServerURL"], "");
  EXPECT_NE(config["modeBarButtonsToRemove"].dump().find("sendChartToCloud"), std::string::npos);
  EXPECT_EQ(config["toImageButtonOptions"]["format"], "png");
  EXPECT_EQ(config["toImageButtonOptions"]["filename"], "tribolab-figure-1-x-t");
}

TEST(Html, TextInFiguresIsEscapedForPlotly) {
  Report r;
  Figure f;
  f.title = "<img src=x onerror=alert(1)>";
  f.series.push_back({"<b>\"name\"</b>", {1.0}, {2.0}, {}, {}, Mode::Markers, Dash::Solid, ""});
  r.add_section("S").add_figure(f);
  const std::string html = to_html(r);
  const auto fig = figures_block(html)["figures"][0];
  EXPECT_EQ(fig["layout"]["title"]["text"], "&lt;img src=x onerror=alert(1)&gt;");
  EXPECT_EQ(fig["data"][0]["name"], "&lt;b&gt;\"name\"&lt;/b&gt;");
  EXPECT_EQ(body_of(html).find("<img"), std::string::npos);
}

TEST(Html, EquationsShowSubscriptsAndCiteTheirSource) {
  Report r;
  r.add_section("Theory").add_equation("x_f = -2 v_0^2 / (α (k^2 - 4))", "seed 000, eq 八",
                                       "stopping position");
  const std::string body = body_of(to_html(r));
  EXPECT_NE(body.find("<span class=\"math\">x<sub>f</sub> = -2 v<sub>0</sub><sup>2</sup> / (α "
                      "(k<sup>2</sup> - 4))</span>"),
            std::string::npos);
  EXPECT_NE(body.find("<span class=\"source\">seed 000, eq 八</span>"), std::string::npos);
  EXPECT_NE(body.find("<p class=\"note\">stopping position</p>"), std::string::npos);
}

TEST(Html, TablesRightAlignNumericColumns) {
  Report r;
  r.add_section("T").add_table({"caption & more",
                                {"q", "v_0 (m/s)", "unit"},
                                {{"μ", "0.634 ± 0.012", "—"}, {"-x", "—", "m"}}});
  const std::string body = body_of(to_html(r));
  EXPECT_NE(body.find("<caption>caption &amp; more</caption>"), std::string::npos);
  EXPECT_NE(body.find("<th>v<sub>0</sub> (m/s)</th>"), std::string::npos);
  // Column 2 holds a number and a missing value: right-aligned; "-x" and "m" are text.
  EXPECT_NE(body.find("<tr><td>μ</td><td class=\"num\">0.634 ± 0.012</td><td>—</td></tr>"),
            std::string::npos)
      << body;
  EXPECT_NE(body.find("<tr><td>-x</td><td class=\"num\">—</td><td>m</td></tr>"),
            std::string::npos);
}

TEST(Html, TableRowsLinkTheirFirstCellToRelativePathsOnly) {
  Report r;
  Table t{"runs", {"run", "μ"}, {{"a & b.csv", "0.6"}, {"c.csv", "0.7"}}};
  t.links = {"series_runs/1_a%20b.html", ""};
  r.add_section("T").add_table(t);
  const std::string body = body_of(to_html(r));
  EXPECT_NE(body.find("<td><a href=\"series_runs/1_a%20b.html\">a &amp; b.csv</a></td>"), std::string::npos) << body;
  EXPECT_NE(body.find("<tr><td>c.csv</td>"), std::string::npos) << body;
  // A link off the disc or into script is refused, as is a count that does not match the rows.
  for (const std::string bad : {"javascript:alert(1)", "/etc/passwd", "http://x.org/a.html", "a\"b.html"}) {
    Report q;
    Table u = t;
    u.links = {bad, ""};
    q.add_section("T").add_table(u);
    EXPECT_NE(q.validate().find("is not a relative path"), std::string::npos) << bad;
  }
  Report q;
  Table u = t;
  u.links = {"a.html"};
  q.add_section("T").add_table(u);
  EXPECT_NE(q.validate().find("1 links for 2 rows"), std::string::npos);
}

TEST(Html, GalleryEmbedsImagesAsDataUrisWithEscapedCaptions) {
  // The 8-byte PNG signature plus one byte, and a JPEG start: enough for the writer, which
  // only reads the signature (the browser test decodes real images).
  const std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0x00};
  const std::vector<unsigned char> jpeg = {0xFF, 0xD8, 0xFF, 0xE0};
  Report r;
  r.add_section("Frames").add_gallery({"all <frames>", {{png, "frame 1 & t = 0 s", ""}, {jpeg, "frame 2", "a \"quoted\" alt"}}});
  const std::string body = body_of(to_html(r));
  // base64 of 89 50 4E 47 0D 0A 1A 0A 00 is "iVBORw0KGgoA"; of FF D8 FF E0 is "/9j/4A==".
  EXPECT_NE(body.find("<figure><img class=\"tribolab-image\" alt=\"frame 1 &amp; t = 0 s\" "
                      "src=\"data:image/png;base64,iVBORw0KGgoA\"><figcaption>frame 1 &amp; t = 0 s</figcaption></figure>"),
            std::string::npos)
      << body;
  EXPECT_NE(body.find("alt=\"a &quot;quoted&quot; alt\" src=\"data:image/jpeg;base64,/9j/4A==\">"), std::string::npos)
      << body;
  EXPECT_NE(body.find("<p class=\"gallery-caption\">all &lt;frames&gt;</p>"), std::string::npos);
  // Images are not plots: the page still waits for no plot, but checks that every image decodes.
  EXPECT_EQ(count(body, "class=\"tribolab-plot\""), 0u);
  EXPECT_NE(body.find("img.decode()"), std::string::npos);
}

TEST(Html, GalleryRefusesBytesThatAreNotAnImage) {
  Report r;
  r.add_section("Frames").add_gallery({"g", {{{0xFF, 0xD8, 0xFF}, "fine", ""}, {{'G', 'I', 'F', '8'}, "frame 4", ""}}});
  EXPECT_EQ(r.validate(), "section 'Frames', gallery 'g', image 2 ('frame 4'): not a JPEG or PNG file (4 bytes)");
  Report e;
  e.add_section("Frames").add_gallery({"g", {{{}, "empty", ""}}});
  EXPECT_NE(e.validate().find("image 1 ('empty'): not a JPEG or PNG file (0 bytes)"), std::string::npos);
  EXPECT_THROW(to_html(e), std::invalid_argument);
  EXPECT_EQ(image_mime({0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A}), "");  // a signature cut short
}

TEST(Report, SectionReferencesStayValidWhileAddingSections) {
  Report r;
  Section& first = r.add_section("first");
  for (int i = 0; i < 100; ++i) r.add_section("more");
  first.add_paragraph("still here");  // would be a dangling reference with a vector
  EXPECT_EQ(std::get<Paragraph>(r.sections.front().blocks.at(0)).text, "still here");
}

TEST(Html, SectionIdsAreUniqueAndListedInContents) {
  Report r;
  r.add_section("Results");
  r.add_section("Results");
  r.add_section("斜面");
  const std::string body = body_of(to_html(r));
  EXPECT_NE(body.find("<section id=\"results\">"), std::string::npos);
  EXPECT_NE(body.find("<section id=\"results-2\">"), std::string::npos);
  EXPECT_NE(body.find("<section id=\"section\">"), std::string::npos);
  EXPECT_NE(body.find("<a href=\"#results-2\">Results</a>"), std::string::npos);
}

TEST(Html, MalformedReportIsRejectedNamingTheCulprit) {
  Report r;
  Figure f;
  f.title = "x-t";
  f.series.push_back({"data", {1, 2, 3}, {1, 2}, {}, {}, Mode::Markers, Dash::Solid, ""});
  r.add_section("Incline").add_figure(f);
  try {
    to_html(r);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "section 'Incline', figure 'x-t': series 'data': x has 3 values, y has 2"),
              std::string::npos)
        << e.what();
  }
  Report t;
  t.add_section("S").add_table({"tab", {"a", "b"}, {{"1", "2"}, {"3"}}});
  EXPECT_THROW(to_html(t), std::invalid_argument);
  Report h;
  Figure hf;
  hf.heatmap = HeatMap{{1, 2}, {1}, {{1, 2, 3}}, "", ColorScale::Viridis, std::nullopt};
  h.add_section("S").add_figure(hf);
  EXPECT_NE(h.validate().find("z row 0 has 3 values, x has 2"), std::string::npos);
}

TEST(Html, WriteIsAtomicAndNamesAnUnwritablePath) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tribolab_html_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string good = (dir / "r.html").string();
  write_html(two_figure_report(), good);
  std::ifstream in(good);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), to_html(two_figure_report()));

  const std::string missing = (dir / "no" / "r.html").string();
  EXPECT_THROW(write_html(two_figure_report(), missing), InputError);

  Report bad;
  bad.add_section("S").add_table({"tab", {"a"}, {{"1", "2"}}});
  const std::string bad_path = (dir / "bad.html").string();
  EXPECT_THROW(write_html(bad, bad_path), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(bad_path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);  // only r.html: no temporary files left behind
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::report
