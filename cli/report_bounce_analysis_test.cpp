// Golden tests of `bounce analyze --report` and `bounce fit --report`: the numbers the report
// shows are the command's own JSON (formatted as the report formats them), the figures are all
// there, and a bad report path is one error line with no output.
#include "cli_test_util.hpp"

#include "report/format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using report::format_uncertain;

const std::string kVideo = std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/bounce/higher.txt";
const std::string kTable = std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/bounce/table.csv";

/// The cell text of value ± sigma of `j[key]`, `j["sigma_" + key]`.
std::string json_cell(const json& j, const std::string& key) {
  return format_uncertain(j[key].get<double>(), j["sigma_" + key].get<double>());
}

/// Runs `command --json --report FILE` and returns the JSON and the report's text.
std::pair<json, std::string> run_with_report(const std::string& name, const std::string& command) {
  const std::string path = temp_dir(name) + "/r.html";
  const auto r = run_tribolab(command + " --json --report '" + path + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // stderr holds only the result's own warnings, one line each.
  std::string warnings;
  if (!r.out.empty())
    for (const auto& w : json::parse(r.out).value("warnings", json::array())) warnings += "tribolab: warning: " + w.get<std::string>() + "\n";
  EXPECT_EQ(r.err, warnings);
  EXPECT_TRUE(fs::exists(path)) << command;
  const std::string html = fs::exists(path) ? slurp(path) : std::string();
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  // The report does not change what the command prints.
  EXPECT_EQ(json::parse(r.out), run_json(command));
  return {json::parse(r.out), html};
}

TEST(BounceAnalyzeReport, ShowsTheNumbersOfTheJson) {
  const auto [j, html] = run_with_report(
      "report_bounce_analyze",
      "bounce analyze '" + kVideo + "' --track-a A --track-b B --time-scale 0.125 --floor-y 0 --contact-duration 0.0167");
  // x-t, y-t, trajectory, residuals, theta-t, omega-t.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 6u);
  for (const char* seg : {"pre", "post"})
    for (const char* key : {"vx", "vy", "omega", "ay", "apex_height"})
      EXPECT_NE(html.find(json_cell(j[seg], key)), std::string::npos) << seg << "." << key << " = " << json_cell(j[seg], key);
  for (const char* key : {"e_velocity", "e_height", "mean_normal_force", "collision_angle_deg", "t_touch", "t_separation",
                          "contact_duration", "contact_point_speed", "e_velocity_common", "theta_touch_deg"})
    EXPECT_NE(html.find(json_cell(j, key)), std::string::npos) << key << " = " << json_cell(j, key);
  for (const auto& [key, v] : {std::pair{"theta_impact_deg", j["theta_impact_deg"]}, {"collision_angle_impact_deg", j["collision_angle_impact_deg"]},
                               {"energy_pre", j["energy_pre"]}, {"energy_post", j["energy_post"]}, {"impact_time", j["impact_time"]}})
    EXPECT_NE(html.find(report::format_value(v.get<double>(), 4)), std::string::npos) << key;
  // The equations cite the seed.
  for (const char* source : {"rugby-ball study, experiment 1 (實驗一) (x = vt + x_0)", "rugby-ball study, experiment 2 (3) (實驗二 (三))", "rugby-ball study, eq 20", "rugby-ball study, discussion (討論)"})
    EXPECT_NE(html.find(source), std::string::npos) << source;
  EXPECT_NE(html.find("mean normal force"), std::string::npos);
}

TEST(BounceAnalyzeReport, WithoutContactDurationHasNoForce) {
  const auto [j, html] =
      run_with_report("report_bounce_analyze_nf", "bounce analyze '" + kVideo + "' --track-a A --track-b B --time-scale 0.125");
  EXPECT_FALSE(j.contains("mean_normal_force"));
  EXPECT_EQ(html.find("mean normal force"), std::string::npos);
  // Without --floor-y or --contact-duration the floor is only bracketed: no e_height, and why.
  EXPECT_EQ(j["floor_method"], "bracket");
  EXPECT_TRUE(j["e_height"].is_null());
  EXPECT_NE(html.find("not reported: the floor estimated without --floor-y"), std::string::npos);
}

TEST(BounceAnalyzeReport, BadPathIsOneErrorLine) {
  expect_bad_report_paths("bounce analyze '" + kVideo + "' --track-a A --track-b B --time-scale 0.125");
}

TEST(BounceFitReport, ShowsTheNumbersOfTheJson) {
  const auto [j, html] = run_with_report("report_bounce_fit", "bounce fit '" + kTable + "' --fix n=1.51");
  // Three parity plots, residuals by row and against theta.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 5u);
  for (const char* key : {"K", "D", "mu"}) EXPECT_NE(html.find(json_cell(j, key)), std::string::npos) << key << " = " << json_cell(j, key);
  EXPECT_NE(html.find(">1.51</td><td>fixed</td>"), std::string::npos);  // n, fixed
  EXPECT_EQ(count(html, "<td>fitted</td>"), 3u);                            // K, D, mu
  EXPECT_NE(html.find(report::format_value(j["rms"].get<double>(), 4)), std::string::npos);
  // Each row's prediction is the JSON's (the bounce table of the report).
  ASSERT_EQ(j["residuals"].size(), 40u);
  for (const auto& row : j["residuals"])
    EXPECT_NE(html.find(">" + report::format_value(row["vy_pred"].get<double>(), 4) + "</td>"), std::string::npos)
        << row;
  EXPECT_NE(html.find("Hunt &amp; Crossley"), std::string::npos);  // the contact law's equation
}

TEST(BounceFitReport, BadPathIsOneErrorLine) { expect_bad_report_paths("bounce fit '" + kTable + "'"); }

}  // namespace
}  // namespace tribolab::cli::testing
