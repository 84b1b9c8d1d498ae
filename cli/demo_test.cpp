// Golden tests of `tribolab demo`: the report appears where asked, is self-contained, and a
// folder that cannot be created is one error line.
#include "cli_test_util.hpp"
#include "report/embedded.hpp"
#include "report/plotly_script.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace tribolab::cli::testing {
namespace {

TEST(Demo, WritesAnOfflineReportAndSaysWhere) {
  const std::string dir = temp_dir("demo") + "/new/out";  // parents are created too
  const auto r = run_tribolab("demo --out '" + dir + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const std::string path = dir + "/report.html";
  EXPECT_NE(r.out.find(path), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::exists(path));
  const std::string html = slurp(path);
  EXPECT_NE(html.find("<div id=\"tribolab-status\" hidden>pending</div>"), std::string::npos);
  EXPECT_NE(html.find("window.onerror"), std::string::npos);
  // The demo's reports share one Plotly.js beside them (--plotly file): offline, written once.
  const std::string script = report::plotly_file_name();
  EXPECT_EQ(html.find("* plotly.js v"), std::string::npos);  // not embedded
  EXPECT_NE(html.find("<script src=\"" + script + "\"></script>"), std::string::npos);
  EXPECT_EQ(slurp(dir + "/" + script), std::string(report::plotly_js()));
  EXPECT_NE(slurp(dir + "/film_tracking.html").find("<script src=\"" + script + "\"></script>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_NE(html.find(script + " beside them"), std::string::npos);  // the index says so
  // And README.md says so (it said the library was inside every report file).
  const std::string readme = slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/README.md");
  EXPECT_NE(readme.find("share one `plotly-VERSION.min.js` beside them"), std::string::npos);
  EXPECT_EQ(script, "plotly-" + std::string(report::plotly_version()) + ".min.js");
  EXPECT_NE(html.find("About this report"), std::string::npos);
  for (const char* heading : {"The incline study: table 1", "Incline runs: tracked launches analysed",
                              "Bounce: table 4", "Errata found in the two studies"})
    EXPECT_NE(html.find(heading), std::string::npos) << heading;
  EXPECT_NE(r.out.find("table 1:"), std::string::npos) << r.out;  // the summary on stdout
  // The shipped bounce data is written next to the report, for the commands the report shows.
  for (const char* f : {"higher.txt", "ordinary.txt", "backspin.txt", "table.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/data/bounce/" + f)) << f;
  EXPECT_NE(html.find("tribolab bounce analyze data/bounce/higher.txt --track-a A --track-b B --time-scale 0.125"),
            std::string::npos);
  // The film case study renders its video at demo time and links its tracking report.
  for (const char* f : {"/data/film/throw.avi", "/data/film/tracks.csv", "/film_tracking.html"})
    EXPECT_TRUE(std::filesystem::exists(dir + f)) << f;
  EXPECT_NE(html.find("<a href=\"film_tracking.html\">film_tracking.html</a>"), std::string::npos);
}

TEST(Demo, JsonNamesTheReportAndCountsItsFigures) {
  const std::string dir = temp_dir("demo_json");
  const auto r = run_tribolab("demo --json --out '" + dir + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(count_lines(r.out), 1) << r.out;  // one JSON object, no progress lines
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["report"], dir + "/report.html");
  EXPECT_EQ(j["case_studies"],
            nlohmann::json::parse(R"(["about", "incline", "incline-runs", "incline-series", "bounce", "bounce-runs", "bounce-series", "film", "errata"])"));
  // about 0, incline 7 x 5 (二, 四, 五, 六, 七) + 4 (八), bounce 1 + 4 + 1 + 1 + 5 (maps 53-55).
  // incline-runs: 2 full analyses x (7 kinematics + 2 residuals + a_N + theta_c), the
  // normal-friction test 1, the slide 3. bounce-runs: 3 x 6 (videos) + 5 (table fit).
  // incline-series: seven discs at one angle (mu per run, 4 stop slopes, pooled f_N) and ten
  // at four angles (mu per run, cos theta_c - tan phi, pooled f_N).
  // bounce-series: analysed vs truth 1 + figures 32, 49, 50, 52. film: the 6 of bounce analyze.
  EXPECT_EQ(j["figures"], 51 + 2 * 11 + 1 + 3 + 3 * 6 + 5 + (1 + 4 + 1) + (1 + 1 + 1) + 5 + 6);
  // incline-series: an introduction, then per series a truth table and 4 summary sections.
  // bounce-series: an introduction and 5 series sections. film: one section.
  EXPECT_EQ(j["sections"], 1 + 5 + 5 + 5 + 4 + 1 + (1 + 2 * (1 + 4)) + 6 + 1);
  const std::string html = slurp(dir + "/report.html");
  EXPECT_EQ(j["figures"].get<std::size_t>(), count(html, "class=\"tribolab-plot\""));
  EXPECT_EQ(j["sections"].get<std::size_t>(), count(html, "<section id="));
}

TEST(Demo, OutUnderARegularFileIsOneErrorLine) {
  const std::string dir = temp_dir("demo_bad");
  std::ofstream(dir + "/file") << "not a folder\n";
  for (const std::string& out : {dir + "/file/sub", dir + "/file"}) {
    const auto r = run_tribolab("demo --out '" + out + "'");
    EXPECT_NE(r.exit_code, 0) << out;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/file/sub/report.html"));
}

}  // namespace
}  // namespace tribolab::cli::testing
