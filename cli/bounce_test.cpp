// Golden tests of `tribolab bounce ...`: the real binary, as a user runs it.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

TEST(BounceCli, ContactTimeWithoutSpinIsFreeFall) {
  const json j = run_json("bounce contact-time --height 0.7 --theta-deg 0");
  // Centre falls H - b = 0.605 m: t = sqrt(2 * 0.605 / 9.8) = 0.35136...
  EXPECT_NEAR(j["t_contact"].get<double>(), std::sqrt(2 * 0.605 / 9.8), 1e-12) << j.dump();
  EXPECT_NEAR(j["contact_point"][1].get<double>(), -0.095, 1e-15);
  EXPECT_NEAR(j["vy"].get<double>(), -std::sqrt(2 * 9.8 * 0.605), 1e-12);
  for (const char* k : {"theta_contact_deg", "vx", "omega", "collision_angle_deg", "contact_point_velocity", "t_min", "t_max"})
    EXPECT_TRUE(j.contains(k)) << k;
}

TEST(BounceCli, ContactTimeSeedTable4Row1) {
  // seed 001 table 4, experiment 1: H = 0.715 m, 47.60 rad/s (clockwise), 0.197 rad, ball
  // length 0.286 m: predicted 0.350 s. Our value 0.3491 s (docs/theory.md, errata).
  const json j = run_json("bounce contact-time --height 0.715 --omega -47.60 --theta-deg 11.2873 --a 0.143");
  EXPECT_NEAR(j["t_contact"].get<double>(), 0.3491, 5e-4) << j.dump();
}

TEST(BounceCli, SimulateDefaultsPrintTheSpecKeys) {
  const json j = run_json("bounce simulate --vx 0.5 --vy -4 --omega 40 --theta-deg 30");
  for (const char* k : {"vx", "vy", "omega", "e", "contact_duration", "peak_force", "energy_in", "energy_out",
                        "impulse_normal", "dissipated_normal", "dissipated_friction", "phases", "law"})
    EXPECT_TRUE(j.contains(k)) << k << " missing: " << j.dump();
  EXPECT_EQ(j["law"]["K"].get<double>(), 101054);
  EXPECT_EQ(j["law"]["D"].get<double>(), 60423);
  EXPECT_LT(j["energy_out"].get<double>(), j["energy_in"].get<double>());
  EXPECT_GT(j["vy"].get<double>(), 0);
}

TEST(BounceCli, SimulateCentralRestitutionTarget) {
  // Hunt–Crossley from a target restitution, central impact, no gravity: e = 0.6 exactly.
  const json j = run_json("bounce simulate --vy -3 --restitution 0.6 --g 1e-300 --tol 1e-12");
  EXPECT_NEAR(j["e"].get<double>(), 0.6, 1e-9) << j.dump();
}

TEST(BounceCli, EveryModelAndFrictionRuns) {
  for (const char* m : {"hooke", "hertz", "hunt-crossley", "flores", "lankarani-nikravesh", "gonthier"}) {
    const std::string law = std::string(m) == "hertz" ? "" : " --restitution 0.7";
    for (const char* f : {"coulomb", "regularized", "spring"}) {
      const json j = run_json(std::string("bounce simulate --vy -4 --omega 30 --theta-deg 20 --model ") + m + law +
                              " --friction " + f);
      EXPECT_EQ(j["status"], "separated") << m << " " << f;
    }
  }
}

TEST(BounceCli, HistoryFileIsWritten) {
  const std::string dir = temp_dir("bounce_hist");
  const std::string file = dir + "/h.csv";
  const auto r = run_tribolab("bounce simulate --vy -4 --history '" + file + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurp(file);
  EXPECT_EQ(csv.rfind("t,x,y,theta,vx,vy,omega,d,d_dot,N,f,v_t,phase\n", 0), 0u);
  EXPECT_GT(count_lines(csv), 50);
}

TEST(BounceCli, FailedSimulateLeavesNoHistoryFile) {
  const std::string dir = temp_dir("bounce_nohist");
  const std::string file = dir + "/h.csv";
  expect_error("bounce simulate --vy 2 --history '" + file + "'", "--vy");
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(BounceCli, DropReportsApexesAndReleaseCrossing) {
  const json j = run_json("bounce drop --height 0.8 --bounces 3");
  EXPECT_EQ(j["apex_heights"].size(), j["bounces"].size());
  EXPECT_FALSE(j["rebounds_above_release"].get<bool>());
  EXPECT_TRUE(j["first_above_release"].is_null());
  // Elastic spinning ball released at 0.6 m, axis horizontal, -40 rad/s: first apex 1.07 m.
  const json k = run_json("bounce drop --height 0.6 --omega -40 --theta-deg 0 --model hertz --bounces 1");
  EXPECT_TRUE(k["rebounds_above_release"].get<bool>()) << k.dump();
}

TEST(BounceCli, DropTrajectoryFile) {
  const std::string dir = temp_dir("bounce_traj");
  const std::string file = dir + "/t.csv";
  const auto r = run_tribolab("bounce drop --height 0.8 --bounces 2 --trajectory '" + file + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(file).rfind("t,x,y,theta,vx,vy,omega,in_contact\n", 0), 0u);
}

/// Central Hunt-Crossley restitution from its exact relation 1 - e z = (1 + z) exp(-z (1 + e)),
/// z = (D/K) v_in (docs/theory.md#hunt-crossley-restitution), by bisection on (0, 1): an
/// independent solution of the relation (the library's solver is not used).
double exact_hunt_crossley_e(double z) {
  const auto f = [z](double e) { return 1 - e * z - (1 + z) * std::exp(-z * (1 + e)); };
  double lo = 1e-12, hi = 1 - 1e-12;  // f(lo) > 0 > f(hi) for z > 0
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(BounceCli, SimulateWithoutGravityGivesTheExactHuntCrossleyRestitution) {
  // The seed's fitted law (K 101054, D 60423) at 4 m/s: z = 4 D/K = 2.392. The exact relation
  // holds only without gravity; at tol 1e-12 the simulation reproduces it to ~1e-12 (measured
  // 3e-13), so 1e-9 is the integrator's error with margin. With g = 9.8 gravity acts during the
  // ~15 ms contact and e drops by ~0.02 (measured 0.3444 against 0.3638).
  const double e_exact = exact_hunt_crossley_e(4 * 60423.0 / 101054.0);
  const json j = run_json("bounce simulate --vy -4 --g 0 --tol 1e-12");
  EXPECT_NEAR(j["e"].get<double>(), e_exact, 1e-9) << j.dump();
  const json k = run_json("bounce simulate --vy -4 --tol 1e-12");
  EXPECT_GT(std::abs(k["e"].get<double>() - e_exact), 0.01) << k.dump();
  // The sweep's cells start at touch too: one central cell (collision angle 90 deg, no spin)
  // at g = 0 and the sweep's tol 1e-6 (measured error 6e-7).
  const std::string out = temp_dir("bounce_g0") + "/map.csv";
  run_json("bounce sweep --theta-deg 90:90:1 --omega 0:0:1 --g 0 --threads 1 --out " + out);
  std::istringstream csv(slurp(out));
  std::string line, header, row;
  while (std::getline(csv, line))
    if (!line.empty() && line[0] != '#') (header.empty() ? header : row) = line;
  const auto cells = [](const std::string& l) {
    std::vector<std::string> c;
    std::stringstream ss(l);
    for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
    return c;
  };
  const auto h = cells(header), r = cells(row);
  const auto col = std::find(h.begin(), h.end(), "e") - h.begin();
  ASSERT_LT(static_cast<std::size_t>(col), r.size()) << header;
  EXPECT_NEAR(std::stod(r[col]), e_exact, 1e-5);
  // Where a flight needs gravity it stays required.
  expect_error("bounce drop --height 1 --g 0", "--g");
  expect_error("bounce simulate --vy -4 --g -1", "--g");
}

TEST(BounceCli, BadInputIsOneLineNamingTheProblem) {
  expect_error("bounce simulate --vy -4 --mass -1", "--mass");
  expect_error("bounce simulate --vy -4 --a 0.05", "--b");
  expect_error("bounce simulate --vy -4 --model kelvin", "--model");
  expect_error("bounce simulate --vy 0", "--vy");
  expect_error("bounce simulate --vy -4 --D 10 --restitution 0.5", "--D");
  expect_error("bounce simulate --vy -4 --restitution 1.5", "--restitution");
  expect_error("bounce simulate --vy -4 --friction sticky", "--friction");
  expect_error("bounce simulate --vy -4 --mu -0.1", "--mu");
  expect_error("bounce simulate --vy abc", "--vy");
  expect_error("bounce simulate --vy nan", "--vy");
  expect_error("bounce simulate --vy -4 --model hertz --D 5", "--D");
  expect_error("bounce simulate --vy -0.1 --omega -100 --theta-deg 30", "--omega");
  expect_error("bounce contact-time --height 0.05", "--height");
  expect_error("bounce contact-time --height 1 --g 0", "--g");
  expect_error("bounce contact-time --omega 3", "--height");
  expect_error("bounce drop --height 1 --bounces 0", "--bounces");
  expect_error("bounce drop --height 0.01", "height");
  expect_error("bounce simulate --vy -4 --inertia 0", "--inertia");
}

}  // namespace
}  // namespace tribolab::cli::testing
