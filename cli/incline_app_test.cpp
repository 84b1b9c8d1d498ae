// The incline workflows of the application layer (src/app/incline_*.hpp) called directly give
// exactly the JSON the binary prints for the same options (dumped, so to the last digit):
// the command line only binds options and prints.
#include "cli_test_util.hpp"

#include "app/incline/incline_forward.hpp"
#include "app/incline/incline_stop.hpp"
#include "app/incline/incline_analysis.hpp"
#include "app/incline/incline_analyze.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

app::InclineLaunchOptions launch(double mu, double phi_deg, double v0) {
  app::InclineLaunchOptions l;
  l.mu = mu;
  l.phi_deg = phi_deg;
  l.v0 = v0;
  return l;
}

TEST(InclineApp, PredictPrintsTheWorkflowsJson) {
  app::InclinePredictOptions o;
  o.launch = launch(0.634, 20.96, 2.62);
  EXPECT_EQ(app::incline_predict(o).json.dump(),
            run_json("incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62").dump());
}

TEST(InclineApp, SimulatePrintsTheWorkflowsJson) {
  const std::string dir = temp_dir("incline_app_sim");
  app::InclineSimulateOptions o;
  o.launch = launch(0.634, 20.96, 2.62);
  o.model = "A";
  o.normal_accel = 0.5;
  o.out = dir + "/a.csv";
  const app::InclineSimulateResult r = app::incline_simulate(o);
  const std::string app_csv = slurp(o.out);
  const json cli = run_json("incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --model A "
                            "--normal-accel 0.5 --out " + o.out);
  EXPECT_EQ(r.json.dump(), cli.dump());
  EXPECT_EQ(slurp(o.out), app_csv);
  EXPECT_EQ(r.trajectory.size(), cli["rows"].get<std::size_t>());
  std::filesystem::remove_all(dir);
}

TEST(InclineApp, MuFromStopPrintsTheWorkflowsJson) {
  app::InclineMuFromStopOptions o;
  o.phi_deg = 10.37;
  o.x_stop = 0.214;
  o.y_stop = -0.036;
  o.sigma_phi_deg = 0.2;
  o.sigma_pos = 0.002;
  o.plate_size = 1;
  EXPECT_EQ(app::incline_mu_from_stop(o).json.dump(),
            run_json("incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036 "
                     "--sigma-phi-deg 0.2 --sigma-pos 0.002 --plate-size 1").dump());
}

TEST(InclineApp, FamiliesPrintsTheWorkflowsJson) {
  const std::string dir = temp_dir("incline_app_fam");
  app::InclineFamiliesOptions o;
  o.launch = launch(0.634, 0, 2.62);
  o.launch.phi_deg.reset();
  o.vary = "phi";
  o.values = {10, 32.37};
  o.samples = 11;
  o.out = dir + "/f.csv";
  const app::InclineFamiliesResult r = app::incline_families(o);
  const auto cli = run_tribolab("incline families --vary phi --values 10,32.37 --mu 0.634 --v0 2.62 "
                                "--samples 11 --json --out " + o.out);
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(r.json.dump(), json::parse(cli.out).dump());
  ASSERT_EQ(r.family.members.size(), 2u);
  EXPECT_EQ(r.family.members[1].trajectory.size(), 11u);
  std::filesystem::remove_all(dir);
}

TEST(InclineApp, TrackedRunCommandsPrintTheWorkflowsJson) {
  const std::string dir = temp_dir("incline_app_runs");
  // synth: the same file and JSON.
  app::InclineSynthOptions s;
  s.mu = 0.634;
  s.v0 = 2.62;
  s.fps = 120;
  std::vector<std::string> files;
  for (const double phi : {12.0, 16.0, 20.96}) {
    s.phi_deg = phi;
    s.out = dir + "/run_" + std::to_string(files.size()) + ".txt";
    const json j = app::incline_synth(s).json;
    const std::string text = slurp(s.out);
    const json cli = run_json("incline synth --mu 0.634 --v0 2.62 --fps 120 --phi-deg " +
                              nlohmann::json(phi).dump() + " --out " + s.out);
    EXPECT_EQ(j.dump(), cli.dump());
    EXPECT_EQ(slurp(s.out), text);
    files.push_back(s.out);
  }
  // analyze, one file and a series.
  app::InclineAnalyzeOptions a;
  a.files = {files[2]};
  a.phi_deg = {20.96};
  EXPECT_EQ(app::incline_analyze(a).json.dump(),
            run_json("incline analyze " + files[2] + " --phi-deg 20.96").dump());
  a.files = files;
  a.phi_deg = {12, 16, 20.96};
  EXPECT_EQ(app::incline_analyze(a).json.dump(),
            run_json("incline analyze " + files[0] + " " + files[1] + " " + files[2] + " --phi-deg 12,16,20.96").dump());
  // normal-friction-test over the three.
  app::InclineNormalFrictionTestOptions n;
  n.files = files;
  n.phi_deg = {12, 16, 20.96};
  EXPECT_EQ(app::incline_normal_friction_test(n).json.dump(),
            run_json("incline normal-friction-test " + files[0] + " " + files[1] + " " + files[2] +
                     " --phi-deg 12,16,20.96").dump());
  std::filesystem::remove_all(dir);
}

TEST(InclineApp, MuFromSlidePrintsTheWorkflowsJson) {
  const std::string dir = temp_dir("incline_app_slide");
  const std::string f = dir + "/slide.txt";
  run_json("incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --out " + f);
  app::InclineMuFromSlideOptions o;
  o.files = {f};
  o.phi_deg = {41.09};
  o.sigma_phi_deg = {0.2};
  EXPECT_EQ(app::incline_mu_from_slide(o).json.dump(),
            run_json("incline mu-from-slide " + f + " --phi-deg 41.09 --sigma-phi-deg 0.2").dump());
  std::filesystem::remove_all(dir);
}

TEST(InclineApp, FamiliesWithABadOutWritesNoReport) {
  // All or nothing: the output file is opened before the report is written (it was written
  // after it, so a missing --out folder left a report behind).
  const std::string dir = temp_dir("incline_app_fam_bad");
  expect_error("incline families --vary v0 --values 1,2 --mu 0.5 --phi-deg 10 --out " + dir +
                   "/missing/f.csv --report " + dir + "/r.html",
               "missing");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli::testing
