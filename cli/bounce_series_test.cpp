// Golden tests of `bounce analyze` over several files: the JSON shape {"runs", "summary"}, a bad
// file in the middle that keeps the others, the exit status, the summary against the runs'
// own values, --bounces-out read back by `bounce fit`, and the series report (every number
// the JSON's).
#include "cli_test_util.hpp"

#include "io/bounce_table.hpp"
#include "report/format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kDir = std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/bounce/";
const std::string kOpts = " --track-a A --track-b B --time-scale 0.125 --floor-y 0 --contact-duration 0.0167";

/// Three shipped filmed bounces.
std::vector<std::string> videos() { return {kDir + "higher.txt", kDir + "ordinary.txt", kDir + "backspin.txt"}; }

/// A tracked file that reads but has no bounce: both tips in straight flight.
std::string no_impact_file(const std::string& dir) {
  const std::string path = dir + "/flight.csv";
  std::ofstream out(path);
  out << "track,frame,t,x,y\n";
  for (int k = 0; k < 30; ++k)
    for (const char* tip : {"A", "B"}) {
      const double t = k / 240.0, dx = tip[0] == 'A' ? -0.145 : 0.145;
      out << tip << ',' << k << ',' << t << ',' << 1.5 * t + dx << ',' << 0.8 - 4.9 * t * t << '\n';
    }
  return path;
}

TEST(BounceAnalyzeSeries, RunsAreTheSingleFileObjectsPlusFile) {
  std::string args = "bounce analyze";
  for (const auto& v : videos()) args += " " + q(v);
  const json j = run_json(args + kOpts);
  ASSERT_TRUE(j.contains("runs") && j.contains("summary")) << j.dump().substr(0, 200);
  ASSERT_EQ(j["runs"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    json single = run_json("bounce analyze " + q(videos()[i]) + kOpts);
    single["file"] = videos()[i];
    EXPECT_EQ(j["runs"][i], single) << i;
  }
  const json& s = j["summary"];
  EXPECT_EQ(s["n_runs"], 3);
  EXPECT_EQ(s["n_ok"], 3);
  EXPECT_EQ(s["n_failed"], 0);
  for (const char* key : {"e_velocity", "e_height", "above_one", "bins", "energy_ratio_mean", "n_energy_gain",
                          "mean_normal_force", "contact_point", "outliers", "points"})
    EXPECT_TRUE(s.contains(key)) << key;
  // The summary from the runs' own values, recomputed here: the inverse-variance weighted mean
  // of e_velocity, and the count above 1 (higher.txt rises above its drop height).
  double sw = 0, swe = 0;
  int above = 0;
  for (const auto& r : j["runs"]) {
    const double e = r["e_velocity"], se = r["sigma_e_velocity"];
    sw += 1 / (se * se);
    swe += e / (se * se);
    above += e > 1;
  }
  EXPECT_NEAR(s["e_velocity"]["mean"].get<double>(), swe / sw, 1e-12);  // same sums, other order
  EXPECT_NEAR(s["e_velocity"]["sigma"].get<double>(), 1 / std::sqrt(sw), 1e-15);
  EXPECT_EQ(s["above_one"]["velocity"]["above"], above);
  EXPECT_GE(above, 1);
  // Every point is its run's: angle, e, force.
  ASSERT_EQ(s["points"].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& p = s["points"][i];
    const auto& r = j["runs"][i];
    EXPECT_EQ(p["file"], r["file"]);
    EXPECT_EQ(p["collision_angle_deg"], r["collision_angle_deg"]);
    EXPECT_EQ(p["sigma_collision_angle_deg"], r["sigma_collision_angle_deg"]);
    EXPECT_EQ(p["theta_deg"], r["theta_touch_deg"]);  // at first touch, as the angle
    EXPECT_EQ(p["contact_point_speed"], r["contact_point_speed"]);
    EXPECT_EQ(p["sigma_contact_point_speed"], r["sigma_contact_point_speed"]);
    EXPECT_EQ(p["e_velocity"], r["e_velocity"]);
    EXPECT_EQ(p["mean_normal_force"], r["mean_normal_force"]);
    EXPECT_EQ(p["energy_pre"]["total"], r["energy_pre"]);
  }
}

TEST(BounceAnalyzeSeries, ABadFileInTheMiddleKeepsTheOthers) {
  const auto dir = temp_dir("bounce_series_bad");
  const std::vector<std::string> files = {videos()[0], dir + "/missing.txt", no_impact_file(dir), videos()[1]};
  std::string args = "bounce analyze";
  for (const auto& f : files) args += " " + q(f);
  const auto r = run_tribolab(args + kOpts + " --json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("2 of 4 runs failed"), std::string::npos) << r.err;
  ASSERT_EQ(count_lines(r.out), 1) << r.out;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(j["runs"][i]["file"], files[i]);
  EXPECT_FALSE(j["runs"][0].contains("error"));
  EXPECT_TRUE(j["runs"][1].contains("error"));
  EXPECT_NE(j["runs"][1]["error"].get<std::string>().find("missing.txt"), std::string::npos);
  EXPECT_NE(j["runs"][2]["error"].get<std::string>().find("no impact"), std::string::npos) << j["runs"][2];
  EXPECT_FALSE(j["runs"][3].contains("error"));
  // The good runs are exactly what they are alone.
  json alone = run_json("bounce analyze " + q(files[3]) + kOpts);
  alone["file"] = files[3];
  EXPECT_EQ(j["runs"][3], alone);
  EXPECT_EQ(j["summary"]["n_ok"], 2);
  EXPECT_EQ(j["summary"]["n_failed"], 2);
  EXPECT_EQ(j["summary"]["points"].size(), 2u);
  // Text output too: every file named, the failures with their error.
  const auto t = run_tribolab(args + kOpts);
  EXPECT_NE(t.exit_code, 0);
  for (const auto& f : files) EXPECT_NE(t.out.find(f), std::string::npos) << f;
  EXPECT_NE(t.out.find("error:"), std::string::npos);
  // The summary's blocks: the mean of e_velocity only when the runs are one value, else the
  // headline with the relation to the angle (issue 27).
  if (j["summary"]["e_velocity_one_value"].get<bool>()) {
    EXPECT_NE(t.out.find("\ne_velocity:\n"), std::string::npos) << t.out;
  } else {
    EXPECT_EQ(t.out.find("\ne_velocity:\n"), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("e_velocity_headline"), std::string::npos) << t.out;
  }
  EXPECT_NE(t.out.find("\n  mean "), std::string::npos) << t.out;
  EXPECT_EQ(t.out.find("\"file\""), std::string::npos) << "points are not dumped as JSON in the text output";
}

TEST(BounceAnalyzeSeries, BouncesOutIsTheFitTableOfTheRuns) {
  const auto dir = temp_dir("bounce_series_out");
  const std::string table = dir + "/bounces.csv";
  std::string args = "bounce analyze";
  for (const auto& v : videos()) args += " " + q(v);
  const json j = run_json(args + kOpts + " --bounces-out " + q(table));
  EXPECT_EQ(j["summary"]["bounces_out"], table);
  const auto rows = io::read_bounce_table(table);
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    // The table's values are the analysis's, digit for digit (shortest round-trip text on
    // both sides): the state bounce fit's contact starts from (orientation and velocities at
    // first touch) and ends at (velocities at separation); vx and omega are constant in flight.
    const auto& r = j["runs"][i];
    EXPECT_EQ(rows[i].theta_deg, r["theta_touch_deg"].get<double>()) << i;
    EXPECT_EQ(rows[i].vx_in, r["pre"]["vx"].get<double>()) << i;
    EXPECT_EQ(rows[i].vy_in, r["vy_touch"].get<double>()) << i;
    EXPECT_EQ(rows[i].omega_in, r["pre"]["omega"].get<double>()) << i;
    EXPECT_EQ(rows[i].vx_out, r["post"]["vx"].get<double>()) << i;
    EXPECT_EQ(rows[i].vy_out, r["vy_separation"].get<double>()) << i;
    EXPECT_EQ(rows[i].omega_out, r["post"]["omega"].get<double>()) << i;
    // The impact_time values differ (the test would not pass on them).
    EXPECT_NE(rows[i].vy_in, r["pre"]["vy"].get<double>()) << i;
    EXPECT_NE(rows[i].theta_deg, r["theta_impact_deg"].get<double>()) << i;
  }
  // A plain table a spreadsheet opens (issue 27): the column line first, no '#' line, each
  // row's file in its last column.
  const std::string text = slurp(table);
  EXPECT_EQ(text.rfind("theta_deg,", 0), 0u) << text;
  EXPECT_EQ(text.find('#'), std::string::npos) << text;
  EXPECT_NE(text.find("," + videos()[1] + "\n"), std::string::npos) << text;
  // One more command fits the contact law to all the throws (K, n held: 3 rows, 9 residuals).
  const json fit = run_json("bounce fit " + q(table) + " --fix K=101054 --fix n=1.51");
  EXPECT_EQ(fit["n_rows"], 3);
  // A folder that does not exist fails before any work, and nothing is written.
  expect_error(args + kOpts + " --bounces-out " + q(dir + "/missing/b.csv"), "--bounces-out");
}

TEST(BounceAnalyzeSeries, ContactDurationAndFloorPerFile) {
  std::string args = "bounce analyze";
  for (const auto& v : videos()) args += " " + q(v);
  args += " --track-a A --track-b B --time-scale 0.125";
  const std::vector<std::string> T = {"0.0167", "0.02", "0.0125"};
  const json j = run_json(args + " --floor-y 0 --contact-duration " + T[0] + "," + T[1] + "," + T[2]);
  for (std::size_t i = 0; i < 3; ++i) {
    json alone = run_json("bounce analyze " + q(videos()[i]) + " --track-a A --track-b B --time-scale 0.125 --floor-y 0 "
                          "--contact-duration " + T[i]);
    alone["file"] = videos()[i];
    EXPECT_EQ(j["runs"][i], alone) << i;
  }
  // A count that matches neither one value nor one per file is an error before any work.
  expect_error(args + " --contact-duration 0.0167,0.02", "--contact-duration");
  expect_error(args + " --floor-y 0,0", "--floor-y");
  expect_error(args + " --contact-duration 0.0167,-1,0.02", "--contact-duration");
  // A negative floor is a value, not an option (the file's origin may lie above the floor).
  const json neg = run_json("bounce analyze " + q(videos()[0]) + " --track-a A --track-b B --time-scale 0.125 --floor-y -0.001");
  EXPECT_EQ(neg["floor_y"], -0.001);
}

TEST(BounceAnalyzeSeriesReport, ShowsTheNumbersOfTheJson) {
  const auto dir = temp_dir("bounce_series_report");
  const std::vector<std::string> files = {videos()[0], dir + "/missing.txt", videos()[1], videos()[2]};
  std::string args = "bounce analyze";
  for (const auto& f : files) args += " " + q(f);
  const std::string path = dir + "/series.html";
  const auto r = run_tribolab(args + kOpts + " --json --report " + q(path));
  EXPECT_NE(r.exit_code, 0);  // the missing file
  ASSERT_TRUE(fs::exists(path));
  const json j = json::parse(r.out);
  const std::string html = slurp(path);
  // Figures 32, 49, 50 (forces: --contact-duration) and 52.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 4u);
  using report::format_uncertain;
  using report::format_value;
  for (const auto& p : j["summary"]["points"]) {
    for (const std::string& cell :
         {format_value(p["collision_angle_deg"].get<double>(), 4),
          format_uncertain(p["e_velocity"].get<double>(), p["sigma_e_velocity"].get<double>()),
          format_uncertain(p["e_height"].get<double>(), p["sigma_e_height"].get<double>()),
          format_value(p["energy_pre"]["total"].get<double>(), 4), format_value(p["energy_post"]["total"].get<double>(), 4),
          format_uncertain(p["mean_normal_force"].get<double>(), p["sigma_mean_normal_force"].get<double>()),
          format_uncertain(p["contact_point_speed"].get<double>(), p["sigma_contact_point_speed"].get<double>())})
      EXPECT_NE(html.find("<td class=\"num\">" + cell + "</td>"), std::string::npos) << p["file"] << ": " << cell;
  }
  const auto& s = j["summary"];
  // The headline: the weighted mean when the runs are one value, else the relation with the
  // angle and no mean (issue 27: restitutions at different angles are no one quantity).
  if (s["e_velocity_one_value"].get<bool>()) {
    EXPECT_NE(html.find(format_uncertain(s["e_velocity"]["mean"].get<double>(), s["e_velocity"]["sigma_scaled"].get<double>())),
              std::string::npos);
  } else {
    EXPECT_NE(html.find(s["e_velocity_headline"].get<std::string>()), std::string::npos) << s["e_velocity_headline"];
    EXPECT_EQ(html.find("e from velocities, weighted mean"), std::string::npos);
  }
  EXPECT_NE(html.find(format_value(s["energy_ratio_mean"].get<double>(), 4)), std::string::npos);
  for (const auto& b : s["bins"])
    EXPECT_NE(html.find(format_uncertain(b["e_velocity"]["mean"].get<double>(), b["e_velocity"]["sigma_scaled"].get<double>())),
              std::string::npos);
  EXPECT_NE(html.find("failed: "), std::string::npos);  // the missing file's row
  EXPECT_NE(html.find("e = 1"), std::string::npos);
  // Every analysed run links to its own report, written beside the series report.
  int links = 0;
  for (auto p = html.find("<a href=\"series_runs/"); p != std::string::npos; p = html.find("<a href=\"series_runs/", p + 1)) {
    const auto end = html.find('"', p + 9);
    const std::string href = html.substr(p + 9, end - p - 9);
    EXPECT_TRUE(fs::exists(dir + "/" + href)) << href;
    ++links;
  }
  EXPECT_EQ(links, 3);
}

TEST(BounceAnalyzeSeriesReport, BadPathIsOneErrorLine) {
  std::string args = "bounce analyze";
  for (const auto& v : videos()) args += " " + q(v);
  expect_bad_report_paths(args + kOpts);
}

}  // namespace
}  // namespace tribolab::cli::testing
