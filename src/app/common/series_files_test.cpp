// The files of a series: the runs' own reports beside the series' one, and the links to them
// (series_files.hpp). One function writes them for every series report (incline analyze,
// incline mu-from-slide, bounce analyze).
#include "app/common/series_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;

fs::path fresh_series_dir() {
  const fs::path d = fs::temp_directory_path() / ("tribolab_series_files_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(SeriesFiles, RunFilesSortInRunOrderAndHoldOnlySafeCharacters) {
  EXPECT_EQ(series_run_file(0, "data/a b.csv", 12), "01_a_b.html");
  EXPECT_EQ(series_run_file(11, "x/run#2.trk", 12), "12_run_2.html");
  EXPECT_EQ(series_runs_folder("out/my series.html"), "out/my series_runs");
}

TEST(SeriesFiles, EachRunWithAReportIsWrittenAndLinkedEncoded) {
  // A report named with a space gives a folder with a space: the series' links to it are
  // encoded (the bounce series linked it as it was, the incline ones encoded it).
  const fs::path dir = fresh_series_dir();
  const std::string report = (dir / "my series.html").string();
  const std::vector<std::string> sources = {"in/a.csv", "in/b.csv", "in/c.csv"};
  std::vector<std::size_t> asked;
  const std::vector<std::string> links =
      write_run_reports(sources, report, report::PlotlyMode::cdn, [&](std::size_t i) -> std::optional<report::Report> {
        asked.push_back(i);
        if (i == 1) return std::nullopt;  // a run that failed has no report of its own
        report::Report r;
        r.title = "run " + std::to_string(i);
        return r;
      });
  EXPECT_EQ(asked, (std::vector<std::size_t>{0, 1, 2}));
  ASSERT_EQ(links.size(), 3u);
  EXPECT_EQ(links[0], "my%20series_runs/1_a.html");
  EXPECT_EQ(links[1], "");
  EXPECT_EQ(links[2], "my%20series_runs/3_c.html");
  EXPECT_TRUE(fs::exists(dir / "my series_runs" / "1_a.html"));
  EXPECT_FALSE(fs::exists(dir / "my series_runs" / "2_b.html"));
  EXPECT_TRUE(fs::exists(dir / "my series_runs" / "3_c.html"));
  fs::remove_all(dir);
}

TEST(SeriesFiles, NoSeriesReportWritesNothing) {
  const fs::path dir = fresh_series_dir();
  bool asked = false;
  const std::vector<std::string> links = write_run_reports({"a.csv", "b.csv"}, "", report::PlotlyMode::cdn,
                                                           [&](std::size_t) -> std::optional<report::Report> {
                                                             asked = true;
                                                             return report::Report{};
                                                           });
  EXPECT_EQ(links, (std::vector<std::string>{"", ""}));
  EXPECT_FALSE(asked);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(SeriesFiles, LinksEncodeEveryByteALinkDoesNotTake) {
  EXPECT_EQ(encode_link("a b/c#d%e.html"), "a%20b/c%23d%25e.html");
  EXPECT_EQ(encode_link("Ω_runs/1_x.html"), "%CE%A9_runs/1_x.html");
  EXPECT_EQ(encode_link("plain-name_1.2/x.html"), "plain-name_1.2/x.html");
}

}  // namespace
}  // namespace tribolab::app
