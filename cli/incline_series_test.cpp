// Golden tests of `incline analyze` and `incline mu-from-slide` over several files
// (docs/cli.md#several-runs): the {"runs", "summary"} JSON, each run equal to the single-file
// command's object plus `file`, a bad file in the middle kept as an error row with the others
// analysed and a non-zero exit, --phi-deg one value or one per file, and the series report
// (every number the JSON's, every run linking to its own report).
#include "cli_test_util.hpp"
#include "report/format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using report::format_uncertain;
using report::format_value;

#define EXPECT_SHOWS(html, text) EXPECT_NE((html).find(text), std::string::npos) << "missing: " << (text)

/// Synthetic runs of seed 000's disc (mu 0.634) at `phi_deg`, launch speeds v0s; returns the quoted paths.
std::vector<std::string> synth_runs(const std::string& dir, const std::vector<std::string>& v0s, const std::string& phi_deg,
                                    int seed0 = 20) {
  std::vector<std::string> files;
  int seed = seed0;
  for (const auto& v0 : v0s) {
    const std::string f = dir + "/run_" + phi_deg + "_" + v0 + ".txt";
    run_json("incline synth --mu 0.634 --phi-deg " + phi_deg + " --v0 " + v0 + " --fps 120 --seed " +
             std::to_string(seed++) + " --out '" + f + "'");
    files.push_back(f);
  }
  return files;
}

std::string join(const std::vector<std::string>& files) {
  std::string s;
  for (const auto& f : files) s += " '" + f + "'";
  return s;
}

/// stderr without the runs' "tribolab: warning: " lines (e.g. theta_c from fewer than 50
/// points, which the v0 2.0 m/s run at 120 fps has: 45).
std::string without_warnings(const std::string& err) {
  std::string out, line;
  std::istringstream in(err);
  while (std::getline(in, line))
    if (line.rfind("tribolab: warning: ", 0) != 0) out += line + "\n";
  return out;
}

TEST(InclineSeriesCli, SeveralFilesGiveRunsAndSummary) {
  const std::string dir = temp_dir("series_analyze");
  const auto files = synth_runs(dir, {"1.8", "2.2", "2.62", "3.0"}, "20.96");
  const json j = run_json("incline analyze" + join(files) + " --phi-deg 20.96");
  ASSERT_TRUE(j.contains("runs") && j.contains("summary")) << j.dump();
  ASSERT_EQ(j["runs"].size(), 4u);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const json& row = j["runs"][i];
    EXPECT_EQ(row["file"], files[i]);  // input order
    EXPECT_FALSE(row.contains("error"));
    // The row is the single-file command's object plus file and phi_deg, value for value.
    json single = run_json("incline analyze '" + files[i] + "' --phi-deg 20.96");
    EXPECT_FALSE(single.contains("runs"));  // one file: the output as it always was
    json stripped = row;
    stripped.erase("file");
    stripped.erase("phi_deg");
    EXPECT_EQ(stripped, single) << files[i];
  }
  const json& s = j["summary"];
  for (const char* key : {"mu", "sigma_mu", "chi2", "dof", "p_value", "n_runs", "n_ok", "n_failed", "stop_scaling",
                          "normal_friction", "theta_c_test", "outliers", "mu_pulls"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["n_runs"], 4);
  EXPECT_EQ(s["n_failed"], 0);
  EXPECT_EQ(s["dof"], 3);
  // Weighted mean by hand from the rows.
  double sw = 0, swx = 0;
  for (const auto& row : j["runs"]) {
    const double w = 1 / std::pow(row["sigma_mu"].get<double>(), 2);
    sw += w;
    swx += w * row["mu"].get<double>();
  }
  EXPECT_NEAR(s["mu"].get<double>(), swx / sw, 1e-12);
  EXPECT_NEAR(s["sigma_mu"].get<double>(), 1 / std::sqrt(sw), 1e-15);
  // Truth (0.634) within 3.3 sigma of the weighted mean (fixed seeds).
  EXPECT_NEAR(s["mu"].get<double>(), 0.634, 3.3 * s["sigma_mu"].get<double>());
  for (const char* rel : {"t_stop_v0", "x_stop_v0sq", "y_stop_v0sq", "y_stop_x_stop"}) {
    const json& r = s["stop_scaling"][rel];
    ASSERT_TRUE(r.is_object()) << rel;
    EXPECT_NEAR(r["mu"].get<double>(), 0.634, 0.01) << rel;  // ~1 % (slopes of 4 runs)
  }
  EXPECT_TRUE(s["theta_c_test"].is_null());  // one angle
  // Pooled normal friction: the weighted mean of the runs' model A f_N/m, by hand.
  double wn = 0, wnx = 0;
  for (const auto& row : j["runs"]) {
    const double w = 1 / std::pow(row["model_a"]["sigma_normal_accel"].get<double>(), 2);
    wn += w;
    wnx += w * row["model_a"]["normal_accel"].get<double>();
  }
  const json& nf = s["normal_friction"];
  EXPECT_NEAR(nf["normal_accel"].get<double>(), wnx / wn, 1e-12);
  EXPECT_NEAR(nf["sigma_normal_accel"].get<double>(), 1 / std::sqrt(wn), 1e-15);
  // No normal friction in the data: the pooled value within 3 sigma of 0. (Not the 95 %
  // verdict on these fixed seeds: with the camera frame's rotation fitted they give
  // 0.0103 +- 0.0052 m/s^2, 1.97 sigma, a 5 % draw; over 30 other seed sets of the same 4 runs
  // the verdict was "present" 1/30 and the pulls had sd 0.85, so the verdict is calibrated.)
  EXPECT_LT(std::abs(nf["normal_accel"].get<double>()), 3 * nf["sigma_normal_accel_scaled"].get<double>());
}

TEST(InclineSeriesCli, ABadFileInTheMiddleKeepsTheOthers) {
  const std::string dir = temp_dir("series_bad");
  auto files = synth_runs(dir, {"2.0", "2.6"}, "20.96");
  const std::string bad = dir + "/bad.txt";
  std::ofstream(bad) << "t\tx\ty\n0\t0.1\tabc\n";
  files.insert(files.begin() + 1, bad);
  const auto r = run_tribolab("incline analyze" + join(files) + " --phi-deg 20.96 --json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines(without_warnings(r.err)), 1) << r.err;  // the one error line names the failure
  EXPECT_NE(r.err.find("1 of 3 runs failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
  ASSERT_EQ(count_lines(r.out), 1) << r.out;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 3u);
  EXPECT_EQ(j["runs"][1]["file"], bad);
  ASSERT_TRUE(j["runs"][1].contains("error"));
  EXPECT_NE(j["runs"][1]["error"].get<std::string>().find(bad + ":2"), std::string::npos) << j["runs"][1]["error"];
  EXPECT_EQ(j["runs"][1].size(), 2u);  // file and error only
  EXPECT_TRUE(j["runs"][0].contains("mu"));
  EXPECT_TRUE(j["runs"][2].contains("mu"));
  EXPECT_EQ(j["summary"]["n_failed"], 1);
  EXPECT_EQ(j["summary"]["failed"], json::array({bad}));
  EXPECT_EQ(j["summary"]["n_mu"], 2);
  EXPECT_TRUE(j["summary"]["mu_pulls"][1].is_null());
  // A missing file is a failed run too, not the end of the series.
  const auto m = run_tribolab("incline analyze '" + files[0] + "' '" + dir + "/missing.txt' --phi-deg 20.96 --json");
  EXPECT_EQ(m.exit_code, 1);
  EXPECT_EQ(json::parse(m.out)["summary"]["n_ok"], 1);
}

TEST(InclineSeriesCli, PhiDegOnePerFileOrOneForAll) {
  const std::string dir = temp_dir("series_phi");
  auto files = synth_runs(dir, {"2.62"}, "12", 30);
  for (const char* phi : {"16", "20.96", "25"}) files.push_back(synth_runs(dir, {"2.62"}, phi, 31)[0]);
  const json j = run_json("incline analyze" + join(files) + " --phi-deg 12,16,20.96,25");
  EXPECT_EQ(j["runs"][0]["phi_deg"], 12);
  EXPECT_EQ(j["runs"][3]["phi_deg"], 25);
  const json& s = j["summary"];
  EXPECT_TRUE(s["phi_deg"].is_null());
  EXPECT_TRUE(s["stop_scaling"].is_null());
  EXPECT_NE(s["stop_scaling_note"].get<std::string>().find("different angles"), std::string::npos);
  ASSERT_TRUE(s["theta_c_test"].is_object()) << s["theta_c_note"];
  // Eq c': slope 1/mu; 4 runs give mu to a few per cent.
  EXPECT_NEAR(s["theta_c_test"]["mu"].get<double>(), 0.634, 0.05);
  // The count must match: 3 angles for 4 files is an error before any work.
  expect_error("incline analyze" + join(files) + " --phi-deg 12,16,20.96", "--phi-deg");
  expect_error("incline analyze" + join(files) + " --phi-deg 12,16,20.96", "gives 3 values for 4 files");
  expect_error("incline analyze" + join(files) + " --phi-deg 12,16,95,25", "--phi-deg");
}

TEST(InclineSeriesCli, TextOutputListsRunsThenSummary) {
  const std::string dir = temp_dir("series_text");
  const auto files = synth_runs(dir, {"2.0", "2.6"}, "20.96");
  const auto r = run_tribolab("incline analyze" + join(files) + " --phi-deg 20.96");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(without_warnings(r.err).empty()) << r.err;  // no progress line when stderr is not a terminal
  EXPECT_EQ(r.out.rfind("file", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(files[1]), std::string::npos);
  EXPECT_NE(r.out.find("\nsummary\n"), std::string::npos);
  EXPECT_NE(r.out.find("p_value"), std::string::npos);
}

TEST(InclineSeriesCli, MuFromSlideSeries) {
  const std::string dir = temp_dir("series_slide");
  std::vector<std::string> files;
  for (int i = 0; i < 3; ++i) {
    files.push_back(dir + "/slide" + std::to_string(i) + ".txt");
    run_json("incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed " +
             std::to_string(40 + i) + " --out '" + files.back() + "'");
  }
  const json j = run_json("incline mu-from-slide" + join(files) + " --phi-deg 41.09 --sigma-phi-deg 0.1");
  ASSERT_EQ(j["runs"].size(), 3u);
  const json single = run_json("incline mu-from-slide '" + files[2] + "' --phi-deg 41.09 --sigma-phi-deg 0.1");
  json row = j["runs"][2];
  row.erase("file");
  row.erase("phi_deg");
  EXPECT_EQ(row, single);
  const json& s = j["summary"];
  for (const char* key : {"mu", "sigma_mu", "chi2", "dof", "p_value"}) EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["dof"], 2);
  EXPECT_NEAR(s["mu"].get<double>(), 0.634, 3.3 * s["sigma_mu"].get<double>());
  // Without an angle there is no mu to combine: a note, not an error.
  const json a = run_json("incline mu-from-slide" + join(files));
  EXPECT_TRUE(a["summary"]["mu"].is_null());
  EXPECT_FALSE(a["summary"]["note"].get<std::string>().empty());
  expect_error("incline mu-from-slide" + join(files) + " --phi-deg 41,42", "--phi-deg");
}

TEST(InclineSeriesReport, ShowsTheJsonNumbersAndLinksEveryRun) {
  const std::string dir = temp_dir("series_report");
  auto files = synth_runs(dir, {"1.8", "2.2", "2.62", "3.0"}, "20.96");
  const std::string bad = dir + "/empty.txt";
  std::ofstream(bad) << "";
  files.push_back(bad);
  const std::string path = dir + "/series.html";
  const auto r = run_tribolab("incline analyze" + join(files) + " --phi-deg 20.96 --json --report '" + path + "'");
  EXPECT_EQ(r.exit_code, 1);  // the empty file failed; the report is still written
  const json j = json::parse(r.out);
  ASSERT_TRUE(fs::exists(path));
  const std::string html = slurp(path);
  // mu per run + 4 stop-point figures + pooled normal friction.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 6u);
  const json& s = j["summary"];
  EXPECT_SHOWS(html, format_uncertain(s["mu"], s["sigma_mu"]));
  EXPECT_SHOWS(html, format_value(s["chi2"], 4) + " / 3");
  EXPECT_SHOWS(html, format_value(s["p_value"], 3));
  for (const auto& [key, rel] : s["stop_scaling"].items()) {
    EXPECT_SHOWS(html, format_uncertain(rel["slope"], rel["sigma_slope"]));
    EXPECT_SHOWS(html, format_value(rel["mu"], 5));
  }
  const json& nf = s["normal_friction"];
  EXPECT_SHOWS(html, format_uncertain(nf["normal_accel"], nf["sigma_normal_accel"]));
  EXPECT_SHOWS(html, "[" + format_value(nf["normal_accel_ci95"][0], 5) + ", " + format_value(nf["normal_accel_ci95"][1], 5) + "]");
  for (std::size_t i = 0; i < 4; ++i) {
    const json& row = j["runs"][i];
    EXPECT_SHOWS(html, format_uncertain(row["mu"], row["sigma_mu"]));
    EXPECT_SHOWS(html, format_uncertain(row["v0"], row["sigma_v0"]));
    // Its own report beside the series report, linked from its row.
    const std::string own = "series_runs/" + std::to_string(i + 1) + "_" + fs::path(files[i]).stem().string() + ".html";
    EXPECT_TRUE(fs::exists(dir + "/" + own)) << own;
    EXPECT_SHOWS(html, "<a href=\"" + own + "\">");
    // The run's report shows the run's own numbers.
    EXPECT_SHOWS(slurp(dir + "/" + own), format_uncertain(row["mu"], row["sigma_mu"]));
  }
  EXPECT_SHOWS(html, "error: " + j["runs"][4]["error"].get<std::string>());
  EXPECT_FALSE(fs::exists(dir + "/series_runs/5_empty.html"));
  EXPECT_SHOWS(html, "incline study, eqs 7, 8 (七, 八)");
  EXPECT_EQ(html.find("SPEC §"), std::string::npos);  // cites docs/theory.md or the seed, never our spec
}

TEST(InclineSeriesReport, SeveralAnglesDrawTheThetaCTest) {
  const std::string dir = temp_dir("series_report_angles");
  std::vector<std::string> files;
  int seed = 50;
  for (const char* phi : {"12", "16", "20.96", "25"}) files.push_back(synth_runs(dir, {"2.62"}, phi, seed++)[0]);
  const std::string path = dir + "/angles.html";
  const json j = run_json("incline analyze" + join(files) + " --phi-deg 12,16,20.96,25 --report '" + path + "'");
  const std::string html = slurp(path);
  // mu per run + cos(theta_c)-tan(phi) + pooled normal friction; no stop slopes.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 3u);
  const json& t = j["summary"]["theta_c_test"];
  EXPECT_SHOWS(html, format_uncertain(t["mu"], t["sigma_mu"]));
  EXPECT_SHOWS(html, "different angles");
}

TEST(InclineSeriesReport, MuFromSlideSeriesReport) {
  const std::string dir = temp_dir("series_report_slide");
  std::vector<std::string> files;
  for (int i = 0; i < 3; ++i) {
    files.push_back(dir + "/slide" + std::to_string(i) + ".txt");
    run_json("incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed " +
             std::to_string(60 + i) + " --out '" + files.back() + "'");
  }
  const std::string path = dir + "/slides.html";
  const json j = run_json("incline mu-from-slide" + join(files) + " --phi-deg 41.09 --report '" + path + "'");
  const std::string html = slurp(path);
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 1u);
  EXPECT_SHOWS(html, format_uncertain(j["summary"]["mu"], j["summary"]["sigma_mu"]));
  for (const auto& row : j["runs"]) EXPECT_SHOWS(html, format_uncertain(row["mu"], row["sigma_mu"]));
  EXPECT_TRUE(fs::exists(dir + "/slides_runs/1_slide0.html"));
  expect_bad_report_paths("incline mu-from-slide" + join(files) + " --phi-deg 41.09");
}

}  // namespace
}  // namespace tribolab::cli::testing
