// Golden tests of `--report FILE.html` on the tracked-run analyses (`incline analyze`,
// `mu-from-slide`, `normal-friction-test`, `mu-from-stop`): the numbers in the report are the
// ones the same command prints as JSON (formatted by report::format_uncertain), the figures
// are all there, and a bad --report path is one error line with no file and no output.
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
using report::format_value;

/// Runs `command --json --report DIR/r.html`; returns the JSON and the report's text.
std::pair<json, std::string> json_and_report(const std::string& command, std::size_t figures) {
  const std::string path = temp_dir("incline_report") + "/r.html";
  const json j = run_json(command + " --json --report '" + path + "'");
  EXPECT_TRUE(fs::exists(path)) << command;
  const std::string html = fs::exists(path) ? slurp(path) : std::string();
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), figures) << command;
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  return {j, html};
}

/// The table row whose first cell is `label` has `value` as its next cell.
std::string row_value(const std::string& html, const std::string& label) {
  const auto p = html.find(">" + label + "</td>");
  if (p == std::string::npos) return "<no row " + label + ">";
  std::size_t after = p + label.size() + 6;  // just after the label's </td>
  // A quantity table has a unit column after the label (report/units.hpp): skip it.
  const auto table = html.rfind("<table>", p);
  const auto unit_header = html.find("<th>unit</th>", table);
  if (table != std::string::npos && unit_header != std::string::npos && unit_header < p)
    after = html.find("</td>", after) + 5;
  const auto open = html.find('>', after);  // end of the next <td ...>
  const auto close = html.find("</td>", open);
  return html.substr(open + 1, close - open - 1);
}

/// The report shows `text` (a number formatted as its table does).
#define EXPECT_SHOWS(html, text) EXPECT_NE((html).find(text), std::string::npos) << "missing: " << (text)

std::string interval(const json& ci) {
  return "[" + format_value(ci[0].get<double>(), 5) + ", " + format_value(ci[1].get<double>(), 5) + "]";
}

std::string synth(const std::string& dir, const std::string& name, const std::string& args) {
  const std::string f = dir + "/" + name;
  run_json("incline synth " + args + " --out '" + f + "'");
  return f;
}

TEST(InclineAnalysisReport, AnalyzeShowsTheJsonNumbersAndElevenFigures) {
  const std::string dir = temp_dir("incline_report_analyze");
  const std::string f = synth(dir, "run.txt", "--mu 0.634 --phi-deg 20.96 --v0 2.62 --fps 120 --seed 3");
  // 7 kinematics + residuals of B and of A + a_N–sin(theta) + theta_c.
  const auto [j, html] = json_and_report("incline analyze '" + f + "' --phi-deg 20.96", 11);
  EXPECT_SHOWS(html, format_uncertain(j["mu"], j["sigma_mu"]));
  EXPECT_SHOWS(html, format_uncertain(j["v0"], j["sigma_v0"]));
  EXPECT_SHOWS(html, format_uncertain(j["t0"], j["sigma_t0"]));
  EXPECT_SHOWS(html, format_uncertain(j["x0"], j["sigma_x0"]));
  EXPECT_SHOWS(html, format_uncertain(j["y0"], j["sigma_y0"]));
  for (const char* k : {"mu", "v0", "t0", "x0", "y0"}) EXPECT_SHOWS(html, interval(j["ci95"][k]));
  const json& a = j["model_a"];
  EXPECT_SHOWS(html, format_uncertain(a["normal_accel"], a["sigma_normal_accel"]));
  EXPECT_SHOWS(html, interval(a["normal_accel_ci95"]));
  EXPECT_SHOWS(html, format_value(a["p_value"], 3));
  EXPECT_SHOWS(html, format_value(a["f_statistic"], 4));
  const json& nf = j["normal_friction"];
  EXPECT_SHOWS(html, format_uncertain(nf["slope"], nf["sigma_slope"]));
  EXPECT_SHOWS(html, interval(nf["intercept_ci95"]));
  EXPECT_SHOWS(html, format_uncertain(j["theta_c"]["cos_theta_c"], j["theta_c"]["sigma_cos_theta_c"]));
  EXPECT_EQ(row_value(html, "verdict: normal friction"), nf["verdict"].get<std::string>());
  EXPECT_SHOWS(html, "F-test of A against B is significant (p &lt; 0.05)");  // the decision rule
  for (const char* eq : {"incline study, eq b", "incline study, eq c", "incline study, eq 2 (二)", "incline study, eqs 7, 8, 9 (七, 八, 九)"})
    EXPECT_SHOWS(html, eq);
  EXPECT_SHOWS(html, "a_N against sin θ");
}

TEST(InclineAnalysisReport, AnalyzeWithoutModelAHasNoModelAResiduals) {
  const std::string dir = temp_dir("incline_report_analyze_b");
  const std::string f = synth(dir, "run.txt", "--mu 0.634 --phi-deg 20.96 --v0 2.62 --fps 120 --seed 4");
  const auto [j, html] = json_and_report("incline analyze '" + f + "' --phi-deg 20.96 --no-model-a", 10);
  EXPECT_TRUE(j["model_a"].is_null());
  EXPECT_EQ(row_value(html, "decided by"), "a_N intercept");
  EXPECT_EQ(html.find("residuals of model A"), std::string::npos);
}

TEST(InclineAnalysisReport, MuFromSlideShowsAAndMu) {
  const std::string dir = temp_dir("incline_report_slide");
  const std::string f =
      synth(dir, "slide.txt", "--mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 2");
  const auto [j, html] = json_and_report("incline mu-from-slide '" + f + "' --phi-deg 41.09 --sigma-phi-deg 0.1", 3);
  EXPECT_SHOWS(html, format_uncertain(j["a"], j["sigma_a"]));
  EXPECT_SHOWS(html, format_uncertain(j["mu"], j["sigma_mu"]));
  EXPECT_SHOWS(html, format_uncertain(j["a_velocity_line"], j["sigma_a_velocity_line"]));
  EXPECT_SHOWS(html, "incline study, eq a");
  // The straight slide made by `incline synth --v0 0` is what eq (a) needs: mu within 3.3 sigma.
  EXPECT_NEAR(j["mu"].get<double>(), 0.634, 3.3 * j["sigma_mu"].get<double>());
  EXPECT_NEAR(j["direction_deg"].get<double>(), -90, 0.5);
}

TEST(InclineAnalysisReport, NormalFrictionTestShowsSlopeAndIntercept) {
  const std::string dir = temp_dir("incline_report_nft");
  std::string files;
  for (const char* phi : {"12", "16", "20.96", "25"})
    files += " '" + synth(dir, std::string("run_") + phi + ".txt",
                          std::string("--mu 0.634 --v0 2.62 --fps 120 --seed 5 --phi-deg ") + phi) + "'";
  const auto [j, html] = json_and_report("incline normal-friction-test" + files + " --phi-deg 12,16,20.96,25", 1);
  EXPECT_SHOWS(html, format_uncertain(j["slope"], j["sigma_slope"]));
  EXPECT_SHOWS(html, format_uncertain(j["mu"], j["sigma_mu"]));
  EXPECT_SHOWS(html, format_uncertain(j["intercept"], j["sigma_intercept"]));
  EXPECT_SHOWS(html, interval(j["intercept_ci95"]));
  for (const auto& run : j["runs"])
    EXPECT_SHOWS(html, format_uncertain(run["cos_theta_c"], run["sigma_cos_theta_c"]));
  EXPECT_SHOWS(html, "incline study, eq c");
}

TEST(InclineAnalysisReport, NormalFrictionTestFromATableHasNoErrorBars) {
  const std::string path = temp_dir("incline_report_nft_table") + "/t.csv";
  std::ofstream(path) << "phi_deg,cos_theta_c\n12,0.335\n16,0.452\n20.96,0.604\n25,0.736\n";
  const auto [j, html] = json_and_report("incline normal-friction-test --table '" + path + "'", 1);
  EXPECT_SHOWS(html, format_uncertain(j["mu"], j["sigma_mu"]));
}

TEST(InclineAnalysisReport, MuFromStopShowsInputsResultAndTrajectory) {
  // Seed 000, table 1 at 20.96 deg.
  const auto [j, html] = json_and_report(
      "incline mu-from-stop --phi-deg 20.96 --x-stop 0.6197 --y-stop -0.2808 --sigma-phi-deg 0.1 --sigma-pos 0.002 "
      "--plate-size 1",
      1);
  EXPECT_SHOWS(html, format_uncertain(j["mu"], j["sigma_mu"]));
  EXPECT_SHOWS(html, format_value(j["k"], 6));
  EXPECT_SHOWS(html, format_value(j["v0"], 5));
  EXPECT_SHOWS(html, format_uncertain(0.6197, 0.002));
  EXPECT_SHOWS(html, format_value(j["best_phi_deg"], 4));
  EXPECT_SHOWS(html, format_value(j["best_sigma_mu"], 3));
  EXPECT_SHOWS(html, "incline study, eq 10A (十A)");
  EXPECT_SHOWS(html, "Trajectory to the stop");
}

TEST(InclineAnalysisReport, BadReportPathIsOneErrorLineAndNoFile) {
  const std::string dir = temp_dir("incline_report_bad");
  const std::string run = synth(dir, "run.txt", "--mu 0.634 --phi-deg 20.96 --v0 2.62");
  const std::string slide = synth(dir, "slide.txt", "--mu 0.634 --phi-deg 41.09 --v0 0 --duration 0.6");
  for (const std::string& cmd :
       {"incline analyze '" + run + "' --phi-deg 20.96", "incline mu-from-slide '" + slide + "' --phi-deg 41.09",
        "incline normal-friction-test '" + run + "' '" + run + "' '" + run + "' --phi-deg 20,21,22",
        std::string("incline mu-from-stop --phi-deg 20.96 --x-stop 0.62 --y-stop -0.28")}) {
    expect_bad_report_paths(cmd);
  }
}

TEST(InclineAnalysisReport, FailedAnalysisWritesNoReport) {
  // A disc that never moves cannot support the fit: one error line and no report file.
  const std::string dir = temp_dir("incline_report_fail");
  const std::string still = dir + "/still.txt";
  std::ofstream(still) << "t\tx\ty\n0\t0.1\t0.2\n0.01\t0.1\t0.2\n0.02\t0.1\t0.2\n0.03\t0.1\t0.2\n";
  const auto r = run_tribolab("incline analyze '" + still + "' --phi-deg 20 --report '" + dir + "/r.html'");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/r.html"));
}

}  // namespace
}  // namespace tribolab::cli::testing
