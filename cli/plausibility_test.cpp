// The plausibility warnings as a user meets them on the command line: in the JSON, on stderr
// (with the file of a series' run), in the report (docs/theory.md#plausibility-checks).
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

bool any_contains(const json& list, const std::string& text) {
  for (const auto& w : list)
    if (w.get<std::string>().find(text) != std::string::npos) return true;
  return false;
}

// A series analysed with --json used to print its runs' warnings nowhere but inside the JSON:
// a user piping the JSON into a script never saw "floor not known". Each run's warnings now
// reach stderr with the run's file.
TEST(PlausibilityCli, SeriesRunWarningsReachStderrWithTheirFile) {
  const auto dir = temp_dir("plaus_series_stderr");
  std::string files;
  for (int seed = 1; seed <= 2; ++seed) {
    const std::string f = dir + "/throw" + std::to_string(seed) + ".txt";
    run_json("bounce synth-video --seed " + std::to_string(seed) + " --out '" + f + "'");
    files += " '" + f + "'";
  }
  const auto r = run_tribolab("bounce analyze" + files + " --track-a A --track-b B --time-scale 0.125 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("tribolab: warning: " + dir + "/throw1.txt: floor not known"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tribolab: warning: " + dir + "/throw2.txt: floor not known"), std::string::npos) << r.err;
}

// Four throws of one ball; one file's slow motion is 8.4x instead of 8x (its frame rate
// noted 5 % wrong) and is analysed with the others' --time-scale 0.125: its g is 10 % low.
// The summary names that file; before, only its own row said "not 9.8", like any bad run.
TEST(PlausibilityCli, AFileWithAnotherFrameRateStandsOutOfItsSeries) {
  const auto dir = temp_dir("plaus_series_g");
  std::string files;
  for (int seed = 1; seed <= 4; ++seed) {
    const std::string f = dir + "/throw" + std::to_string(seed) + ".txt";
    run_json("bounce synth-video --seed " + std::to_string(seed) + (seed == 3 ? " --time-factor 8.4" : "") +
             " --out '" + f + "'");
    files += " '" + f + "'";
  }
  const json j = run_json("bounce analyze" + files + " --track-a A --track-b B --time-scale 0.125 --floor-y 0");
  const json& w = j["summary"]["warnings"];
  ASSERT_EQ(w.size(), 1u) << w.dump();
  EXPECT_EQ(w[0].get<std::string>().rfind(dir + "/throw3.txt: its flights fall at g", 0), 0u) << w[0];
}

// A table of bounces whose rebounds were written 1.5 times too fast (e.g. vy_out in another
// unit): the law cannot follow, the solver stops on a wall of its search (measured with the
// table's own law, whole impacts: n at its lower bound 1, D = 3080 printed as if fitted, 27 of
// 36 residuals beyond the loss scale) and says so, in the JSON, on stderr and in the report.
// The honest table, fitted with the law family that made it, raises nothing. (The restitution
// law, one e for every speed, does not describe a table of constant D over 2-5 m/s: rms 0.18
// m/s, and it says so too.)
TEST(PlausibilityCli, BounceFitNamesAParameterStoppedAtItsBound) {
  const auto dir = temp_dir("plaus_fit_bound");
  const std::string table = dir + "/bounces.csv", fast = dir + "/fast.csv", report = dir + "/fit.html";
  run_json("bounce synth-table --rows 12 --seed 4 --out '" + table + "'");
  std::ifstream in(table);
  std::ofstream out(fast);
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || header) {
      header = header && (line.empty() || line[0] == '#');
      out << line << '\n';
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 7u) << line;
    cells[5] = std::to_string(1.5 * std::stod(cells[5]));  // vy_out
    for (std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << cells[k];
    out << '\n';
  }
  out.close();
  const json honest = run_json("bounce fit '" + table + "'");
  // (Its rows that gain or lose a touch within the fit's interval may be named as left out:
  // that is not a plausibility warning.)
  EXPECT_FALSE(any_contains(honest["warnings"], "sits at its")) << honest["warnings"].dump();
  EXPECT_FALSE(any_contains(honest["warnings"], "does not follow")) << honest["warnings"].dump();
  const json mismatched = run_json("bounce fit '" + table + "' --restitution");
  EXPECT_TRUE(any_contains(mismatched["warnings"], "residuals exceed the loss scale")) << mismatched["warnings"].dump();
  const json j = run_json("bounce fit '" + fast + "' --report '" + report + "'");
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_TRUE(any_contains(j["warnings"], "sits at its")) << j["warnings"].dump();
  EXPECT_TRUE(any_contains(j["warnings"], "the law does not follow these bounces")) << j["warnings"].dump();
  EXPECT_NE(slurp(report).find(j["warnings"][0].get<std::string>().substr(0, 40)), std::string::npos);
}

// Two slides on surfaces with mu 0.634 and 0.55 analysed as one series: they contradict each
// other and the summary says so; two runs of one surface do not.
TEST(PlausibilityCli, InclineRunsOfTwoSurfacesContradictEachOther) {
  const auto dir = temp_dir("plaus_incline_series");
  const std::string a = dir + "/a.txt", b = dir + "/b.txt", c = dir + "/c.txt";
  run_json("incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 1 --out '" + a + "'");
  run_json("incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --seed 2 --out '" + b + "'");
  run_json("incline synth --mu 0.55 --phi-deg 20.96 --v0 2.62 --seed 3 --out '" + c + "'");
  const json same = run_json("incline analyze '" + a + "' '" + b + "' --phi-deg 20.96");
  EXPECT_TRUE(same["summary"]["warnings"].empty()) << same["summary"]["warnings"].dump();
  const json two = run_json("incline analyze '" + a + "' '" + b + "' '" + c + "' --phi-deg 20.96");
  EXPECT_TRUE(any_contains(two["summary"]["warnings"], "contradict each other on mu")) << two["summary"].dump();
}

// The sweep's spin axis says its sign: the seed's figure 53 spins clockwise (negative here),
// the demo's maps say "clockwise"; before, the sweep report said only "incoming spin".
TEST(PlausibilityCli, SweepReportSaysTheSpinSign) {
  const auto dir = temp_dir("plaus_sweep_sign");
  run_json("bounce sweep --theta-deg 100:170:3 --omega -50:-30:3 --tol 1e-6 --out '" + dir + "/map.csv' --report '" +
           dir + "/map.html'");
  EXPECT_NE(slurp(dir + "/map.html").find("counter-clockwise positive"), std::string::npos);
}

// Cross-command consistency on one state: `incline simulate` writes the exact model-B slide
// of the seed's disc; `incline analyze` of that file must give back the simulated mu and v0
// and the stop that `incline simulate` and `incline predict` computed. The fit of exact data
// is exact to the solver's tolerances (1e-9 relative here: its parameter tolerance).
TEST(PlausibilityCli, InclineAnalyzeOfASimulatedSlideGivesBackItsParameters) {
  const auto dir = temp_dir("plaus_incline_cross");
  const std::string f = dir + "/sim.csv";
  const std::string state = " --mu 0.634 --phi-deg 20.96 --v0 2.62";
  const json sim = run_json("incline simulate" + state + " --out '" + f + "'");
  const json pre = run_json("incline predict" + state);
  const json a = run_json("incline analyze '" + f + "' --phi-deg 20.96");
  EXPECT_NEAR(a["mu"].get<double>(), 0.634, 1e-9);
  EXPECT_NEAR(a["v0"].get<double>(), 2.62, 1e-9);
  EXPECT_NEAR(a["k"].get<double>(), pre["k"].get<double>(), 1e-9);
  for (const char* key : {"t_stop", "x_stop", "y_stop"}) {
    EXPECT_NEAR(a[key].get<double>(), sim[key].get<double>(), 1e-9) << key;
    EXPECT_NEAR(sim[key].get<double>(), pre[key].get<double>(), 1e-12) << key;
  }
  EXPECT_TRUE(a["warnings"].empty()) << a["warnings"].dump();
  EXPECT_EQ(a["normal_friction"]["verdict"], "absent");
}

}  // namespace
}  // namespace tribolab::cli::testing
