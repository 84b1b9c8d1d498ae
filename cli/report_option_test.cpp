// In-process tests of the --report helper that analysis commands share.
#include "report_option.hpp"

#include "cli_test_util.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace tribolab::cli::testing {
namespace {

/// Parses `args` for a command that has only --report (and --plotly); returns CLI11's error or "".
std::string parse(const std::vector<std::string>& args, std::string& path,
                  report::PlotlyMode* plotly_out = nullptr) {
  CLI::App app{"test"};
  report::PlotlyMode plotly = report::PlotlyMode::embed;
  add_report_option(app, path, plotly);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return e.what();  // malformed command line (exit 2)
  } catch (const InputError& e) {
    return e.what();  // a file-system problem (exit 1), as for every output
  }
  if (plotly_out) *plotly_out = plotly;
  return {};
}

report::Report small_report() {
  report::Report r;
  r.title = "t";
  r.add_section("s").add_paragraph("p");
  return r;
}

TEST(ReportOption, AcceptsAnHtmlFileInAnExistingFolder) {
  const std::string dir = temp_dir("report_option");
  std::string path;
  EXPECT_EQ(parse({"--report", dir + "/r.html"}, path), "");
  EXPECT_EQ(path, dir + "/r.html");
  int built = 0;
  EXPECT_TRUE(write_report_if_requested(path, report::PlotlyMode::embed, [&] {
    ++built;
    return small_report();
  }));
  EXPECT_EQ(built, 1);
  EXPECT_NE(slurp(path).find("tribolab-status"), std::string::npos);
}

TEST(ReportOption, NotRequestedMeansNotBuiltAndNoFile) {
  std::string path;
  EXPECT_EQ(parse({}, path), "");
  int built = 0;
  EXPECT_FALSE(write_report_if_requested(path, report::PlotlyMode::file, [&] {
    ++built;
    return small_report();
  }));
  EXPECT_EQ(built, 0);
}

TEST(ReportOption, BadPathsFailWhileParsingWithTheReason) {
  const std::string dir = temp_dir("report_option_bad");
  std::filesystem::create_directories(dir + "/folder.html");
  std::string path;
  EXPECT_NE(parse({"--report", dir + "/data.csv"}, path).find("must end in .html"),
            std::string::npos);
  EXPECT_NE(parse({"--report", dir + "/missing/r.html"}, path).find("does not exist"),
            std::string::npos);
  EXPECT_NE(parse({"--report", dir + "/folder.html"}, path).find("is a directory"),
            std::string::npos);
  EXPECT_EQ(check_report_path(dir + "/R.HTM"), "");
}

TEST(ReportOption, PlotlyModeIsParsedBesideTheReportAndDefaultsToEmbed) {
  const std::string dir = temp_dir("report_option_plotly");
  std::string path;
  report::PlotlyMode mode = report::PlotlyMode::file;
  EXPECT_EQ(parse({"--report", dir + "/r.html"}, path, &mode), "");
  EXPECT_EQ(mode, report::PlotlyMode::embed);
  EXPECT_EQ(parse({"--report", dir + "/r.html", "--plotly", "cdn"}, path, &mode), "");
  EXPECT_EQ(mode, report::PlotlyMode::cdn);
  EXPECT_EQ(parse({"--report", dir + "/r.html", "--plotly", "file"}, path, &mode), "");
  EXPECT_EQ(mode, report::PlotlyMode::file);
  EXPECT_NE(parse({"--plotly", "web"}, path), "");  // a malformed command line (exit 2)
}

}  // namespace
}  // namespace tribolab::cli::testing
