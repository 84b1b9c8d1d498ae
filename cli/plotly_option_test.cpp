// Golden tests of `--plotly embed|cdn|file` (docs/cli.md#plotly-in-reports): every command
// that writes --report offers it; `file` makes a series of reports share one script.
#include "cli_test_util.hpp"
#include "report/embedded.hpp"
#include "report/plotly_script.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;

TEST(PlotlyOption, EveryCommandWithReportOffersIt) {
  for (const char* cmd : {"incline predict", "incline simulate", "incline families", "incline mu-from-stop",
                          "incline analyze", "incline mu-from-slide", "incline normal-friction-test",
                          "bounce contact-time", "bounce simulate", "bounce drop", "bounce analyze", "bounce fit",
                          "bounce sweep", "bounce merge", "track kinematics", "track rigid-body", "track video"}) {
    const auto r = run_tribolab(std::string(cmd) + " --help");
    ASSERT_NE(r.out.find("--report"), std::string::npos) << cmd << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("--plotly"), std::string::npos) << cmd;
  }
}

TEST(PlotlyOption, SeriesRunReportsShareTheOneScriptBesideTheSeriesReport) {
  const std::string dir = temp_dir("plotly_series");
  const std::string data = std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/bounce/";
  const auto r = run_tribolab("bounce analyze '" + data + "higher.txt' '" + data +
                              "ordinary.txt' --track-a A --track-b B --time-scale 0.125 --floor-y 0 --report '" + dir +
                              "/series.html' --plotly file");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string script = report::plotly_file_name();
  EXPECT_EQ(slurp(dir + "/" + script), std::string(report::plotly_js()));
  EXPECT_NE(slurp(dir + "/series.html").find("<script src=\"" + script + "\">"), std::string::npos);
  int runs = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().extension() != ".html" || e.path().parent_path() == fs::path(dir)) continue;
    ++runs;
    EXPECT_NE(slurp(e.path().string()).find("<script src=\"../" + script + "\">"), std::string::npos) << e.path();
  }
  EXPECT_EQ(runs, 2);
  int scripts = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) scripts += e.path().filename() == script ? 1 : 0;
  EXPECT_EQ(scripts, 1);
}

TEST(PlotlyOption, CdnWritesASmallPageThatSaysItNeedsTheNetwork) {
  const std::string dir = temp_dir("plotly_cdn_cmd");
  const auto r = run_tribolab("incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62 --report '" + dir +
                              "/p.html' --plotly cdn");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = slurp(dir + "/p.html");
  EXPECT_LT(html.size(), 200000u);
  EXPECT_NE(html.find("integrity=\"" + report::plotly_integrity() + "\""), std::string::npos);
  EXPECT_NE(html.find("need a network connection"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/" + report::plotly_file_name()));
}

TEST(PlotlyOption, AnUnknownModeIsAMalformedCommandLine) {
  const std::string dir = temp_dir("plotly_bad");
  const auto r = run_tribolab("incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62 --report '" + dir +
                              "/p.html' --plotly web");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--plotly"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/p.html"));
}

}  // namespace
}  // namespace tribolab::cli::testing
