// Golden tests of `tribolab incline ...`: JSON keys and values against independent
// formulas, CSV files, and bad input (one stderr line, non-zero exit, no output file).
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

TEST(InclineCli, PredictStops) {
  const json j = run_json("incline predict --mu 0.634 --phi-deg 20.96 --v0 2.62");
  const double phi = 20.96 * M_PI / 180, a = 9.8 * 0.634 * std::cos(phi);
  const double k = std::tan(phi) / 0.634, v0 = 2.62;
  EXPECT_EQ(j["regime"], "stops");
  // JSON carries 17 significant digits: agreement to rounding of the formulas.
  EXPECT_NEAR(j["k"].get<double>(), k, 1e-14);
  EXPECT_NEAR(j["t_stop"].get<double>(), v0 / (a * (1 - k * k)), 1e-13);      // seed eq 七
  EXPECT_NEAR(j["x_stop"].get<double>(), 2 * v0 * v0 / (a * (4 - k * k)), 1e-13);  // eq 八
  EXPECT_NEAR(j["y_stop"].get<double>(), -k * v0 * v0 / (4 * a * (1 - k * k)), 1e-13);
  EXPECT_TRUE(j["v_terminal"].is_null());
  EXPECT_NEAR(j["a_x0"].get<double>(), -5.802, 1e-3);
  EXPECT_NEAR(j["a_y0"].get<double>(), -3.506, 1e-3);
  EXPECT_NEAR(j["a_y_final"].get<double>(), 2.296, 1e-3);
  EXPECT_EQ(j["stays_at_rest"], true);
  for (const char* key : {"k", "regime", "t_stop", "x_stop", "y_stop", "v_terminal", "x_limit",
                          "a_x0", "a_y0", "a_y_final", "stays_at_rest"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
}

TEST(InclineCli, PredictOtherRegimes) {
  json j = run_json("incline predict --mu 0.5 --phi-deg 40 --v0 2");
  EXPECT_EQ(j["regime"], "accelerates");
  EXPECT_TRUE(j["t_stop"].is_null());
  EXPECT_FALSE(j["x_limit"].is_null());  // k = 1.68 < 2: finite lateral limit
  EXPECT_EQ(j["stays_at_rest"], false);
  j = run_json("incline predict --mu 0.2 --phi-deg 40 --v0 2");
  EXPECT_TRUE(j["x_limit"].is_null());  // k = 4.2 > 2
  j = run_json("incline predict --mu 0 --phi-deg 0 --v0 2");
  EXPECT_EQ(j["regime"], "terminal_speed");
  EXPECT_EQ(j["v_terminal"].get<double>(), 2.0);
  j = run_json("incline predict --mu 0.5 --phi-deg 40 --v0 2 --mu-static 0.9");
  EXPECT_EQ(j["stays_at_rest"], true);
}

TEST(InclineCli, SimulateWritesTheTrajectory) {
  const std::string dir = temp_dir("incline_sim");
  const std::string out = dir + "/traj.csv";
  const json j = run_json("incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --dt 0.01 --t-end 1 --out " + out);
  EXPECT_EQ(j["rows"], 101);
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,x,y,vx,vy,ax,ay");
  EXPECT_EQ(count_lines(csv), 102);
  EXPECT_EQ(csv.substr(csv.find('\n') + 1, 12), "0,0,0,2.62,0");
  // Analytic and numeric agree: the stop time printed by both.
  const json n = run_json("incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --method numeric --out " + out);
  // Numeric stop location agrees with the closed form to ~1e-11 (src/incline/numeric_test.cpp).
  EXPECT_NEAR(n["t_stop"].get<double>(), j["t_stop"].get<double>(), 1e-9);
  const json a = run_json("incline simulate --mu 0.634 --phi-deg 20.96 --v0 2.62 --model A --normal-accel 0.5 --out " + out);
  EXPECT_EQ(a["method"], "numeric");
  EXPECT_GT(a["y_stop"].get<double>(), j["y_stop"].get<double>());
  std::filesystem::remove_all(dir);
}

TEST(InclineCli, MuFromStopReproducesTable1) {
  // Seed 000, table 1 column phi = 10.37 deg: mu_A = 0.588.
  json j = run_json("incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036");
  EXPECT_NEAR(j["mu"].get<double>(), 0.58769, 1e-5);
  EXPECT_TRUE(j["sigma_mu"].is_null());
  EXPECT_TRUE(j["best_phi_deg"].is_null());
  j = run_json("incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036 "
               "--sigma-phi-deg 0.2 --sigma-pos 0.002 --plate-size 1");
  EXPECT_GT(j["sigma_mu"].get<double>(), 0);
  EXPECT_GT(j["best_phi_deg"].get<double>(), 10.37);
  EXPECT_LT(j["best_phi_deg"].get<double>(), std::atan(j["mu"].get<double>()) * 180 / M_PI);
}

TEST(InclineCli, FamiliesWriteAllMembers) {
  const std::string dir = temp_dir("incline_fam");
  const std::string out = dir + "/fam.csv";
  const json j = run_json("incline families --vary v0 --values 1,2,3 --mu 0.634 --phi-deg 20.96 "
                          "--samples 11 --out " + out);
  ASSERT_EQ(j["members"].size(), 3u);
  const double r0 = j["members"][0]["y_stop_over_x_stop"].get<double>();
  for (const auto& m : j["members"]) {
    // y_stop/x_stop independent of v0, t_stop/v0 constant (seed eqs 七-十).
    EXPECT_NEAR(m["y_stop_over_x_stop"].get<double>(), r0, 1e-14);
    EXPECT_NEAR(m["t_stop_over_v0"].get<double>(), j["members"][0]["t_stop_over_v0"].get<double>(), 1e-14);
  }
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "v0,t,x,y,vx,vy,ax,ay");
  EXPECT_EQ(count_lines(csv), 1 + 3 * 11);
  run_json("incline families --vary phi --values 10,20,40 --mu 0.634 --v0 2.62 --out " + out);
  EXPECT_EQ(slurp(out).substr(0, 8), "phi_deg,");
  // A member near k = 1 is warned on stderr and in the JSON; each member has its own t_end.
  const auto near = run_tribolab("incline families --vary phi --values 10,32.37 --mu 0.634 --v0 2.62 --json --out " + out);
  EXPECT_EQ(near.exit_code, 0) << near.err;
  const json nj = json::parse(near.out);
  EXPECT_EQ(nj["warnings"].size(), 1u);
  EXPECT_LT(nj["members"][0]["t_end"].get<double>(), 1.0);
  EXPECT_GT(nj["members"][1]["t_end"].get<double>(), 100.0);
  EXPECT_NE(near.err.find("tribolab: warning: phi = 32.37 gives k"), std::string::npos) << near.err;
  std::filesystem::remove_all(dir);
}

TEST(InclineCli, BadInput) {
  const std::string dir = temp_dir("incline_bad");
  const std::string out = dir + "/x.csv";
  expect_error("incline predict --mu 0.5x --phi-deg 10 --v0 1", "--mu");
  expect_error("incline predict --mu -0.1 --phi-deg 10 --v0 1", "--mu");
  expect_error("incline predict --mu 0.5 --phi-deg 90 --v0 1", "--phi-deg");
  expect_error("incline predict --mu 0.5 --phi-deg 10 --v0 -1", "--v0");
  expect_error("incline predict --mu 0.5 --phi-deg 10 --v0 nan", "--v0");
  expect_error("incline predict --mu 0.5 --phi-deg 10 --v0 1 --frobnicate 2", "frobnicate");
  expect_error("incline predict --mu 0.5 --phi-deg 10", "--v0");
  expect_error("incline mu-from-stop --phi-deg 10 --x-stop 0.2 --y-stop 0.05", "--y-stop");
  expect_error("incline mu-from-stop --phi-deg 10 --x-stop -0.2 --y-stop -0.05", "--x-stop");
  expect_error("incline mu-from-stop --phi-deg 0 --x-stop 0.2 --y-stop -0.05", "--phi-deg");
  expect_error("incline simulate --mu 0.5 --phi-deg 10 --v0 1 --model A --method analytic --out " + out, "--method");
  expect_error("incline simulate --mu 0.5 --phi-deg 10 --v0 1 --model C --out " + out, "--model");
  expect_error("incline simulate --mu 0.5 --phi-deg 10 --v0 1 --dt 0 --out " + out, "--dt");
  expect_error("incline simulate --mu 0.5 --phi-deg 10 --v0 1 --normal-accel 1 --out " + out, "--normal-accel");
  expect_error("incline simulate --mu 0.5 --phi-deg 10 --v0 1 --out " + dir + "/missing/x.csv", "directory");
  expect_error("incline families --vary g --values 1 --mu 0.5 --phi-deg 10 --v0 1 --out " + out, "--vary");
  expect_error("incline families --vary v0 --values 1,x --mu 0.5 --phi-deg 10 --out " + out, "--values");
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_TRUE(std::filesystem::is_empty(dir));  // no temporary files left behind either
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli::testing
