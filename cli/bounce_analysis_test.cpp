// Golden tests of `tribolab bounce analyze|fit|synth-video|synth-table`.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(BounceAnalysisCli, SynthVideoThenAnalyzeRecoversTheTruth) {
  const auto dir = temp_dir("bounce_analyze");
  const std::string video = dir + "/video.txt";
  const json truth = run_json("bounce synth-video --seed 7 --out '" + video + "'");
  const json r = run_json("bounce analyze '" + video + "' --track-a A --track-b B --time-scale 0.125 --floor-y 0");
  for (const char* key : {"impact_time", "pre", "post", "e_velocity", "e_height", "theta_impact_deg",
                          "energy_pre", "energy_post", "collision_angle_deg", "sigma_e_velocity"})
    EXPECT_TRUE(r.contains(key)) << key;
  // 5 standard errors: a deterministic seed, far from a chance failure (p < 1e-6).
  EXPECT_NEAR(r["pre"]["vx"].get<double>(), truth["vx_in"].get<double>(), 5 * r["pre"]["sigma_vx"].get<double>());
  EXPECT_NEAR(r["pre"]["omega"].get<double>(), truth["omega_in"].get<double>(), 5 * r["pre"]["sigma_omega"].get<double>());
  EXPECT_NEAR(r["post"]["omega"].get<double>(), truth["omega_out"].get<double>(), 5 * r["post"]["sigma_omega"].get<double>());
  EXPECT_NEAR(r["e_height"].get<double>(), truth["e_height"].get<double>(), 5 * r["sigma_e_height"].get<double>());
  // The impact time (real seconds after --time-scale) lies within the contact.
  EXPECT_GT(r["impact_time"].get<double>(), truth["t_touch"].get<double>() - 1e-3);
  EXPECT_LT(r["impact_time"].get<double>(), truth["t_separation"].get<double>() + 1e-3);
  // With the floor the contact duration is located (touch to separation), so the mean force
  // is there; without floor and duration (bracketed floor) it is not.
  EXPECT_TRUE(r.contains("mean_normal_force"));
  EXPECT_EQ(r["force_duration_method"], "located");
  const json f = run_json("bounce analyze '" + video + "' --track-a A --track-b B --time-scale 0.125 --contact-duration 0.02");
  EXPECT_TRUE(f.contains("mean_normal_force"));
  EXPECT_EQ(f["force_duration_method"], "given");
  const json nf = run_json("bounce analyze '" + video + "' --track-a A --track-b B --time-scale 0.125");
  EXPECT_FALSE(nf.contains("mean_normal_force"));
}

// Regression (issue 26): one tip's y 100 times off (a lost decimal point) before the impact
// moved the impact and the orientation at it (-44 instead of -100 deg) with a warning about
// the floor only. Now the frame is left out of both tips, named, and the result is the clean
// file's.
TEST(BounceAnalysisCli, AValueAHundredTimesOffIsLeftOutWithAWarning) {
  const auto dir = temp_dir("bounce_outlier");
  const std::string clean = dir + "/clean.txt", bad = dir + "/bad.txt";
  run_json("bounce synth-video --seed 7 --out '" + clean + "'");
  std::ifstream in(clean);
  std::string text, line;
  int changed = 0;
  for (int n = 1; std::getline(in, line); ++n) {
    // The first data row whose tip A y (third tab-separated column) is mid-flight: row 20.
    if (n == 20) {
      std::vector<std::string> f;
      std::size_t p = 0;
      for (std::size_t q; (q = line.find('\t', p)) != std::string::npos; p = q + 1) f.push_back(line.substr(p, q - p));
      f.push_back(line.substr(p));
      f[2] = std::to_string(100 * std::stod(f[2]));
      line.clear();
      for (std::size_t k = 0; k < f.size(); ++k) line += (k ? "\t" : "") + f[k];
      ++changed;
    }
    text += line + "\n";
  }
  ASSERT_EQ(changed, 1);
  write(bad, text);
  const std::string opts = " --track-a A --track-b B --time-scale 0.125 --floor-y 0";
  const json c = run_json("bounce analyze '" + clean + "'" + opts);
  const auto r = run_tribolab("bounce analyze '" + bad + "'" + opts + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  // One frame fewer of ~160: e within a third of its sigma of the clean file's.
  EXPECT_NEAR(j["e_velocity"].get<double>(), c["e_velocity"].get<double>(), c["sigma_e_velocity"].get<double>() / 3);
  EXPECT_NEAR(j["theta_impact_deg"].get<double>(), c["theta_impact_deg"].get<double>(), 1.0);
  EXPECT_NE(r.err.find("tribolab: warning: track 'A' frame "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("left out as a typo"), std::string::npos) << r.err;
}

TEST(BounceAnalysisCli, ContactDurationLocatesTheFloorForEHeight) {
  const auto dir = temp_dir("bounce_analyze_floor");
  const std::string video = dir + "/video.txt";
  const json truth = run_json("bounce synth-video --seed 11 --out '" + video + "'");
  const std::string base = "bounce analyze '" + video + "' --track-a A --track-b B --time-scale 0.125";
  // Neither --floor-y nor --contact-duration: the floor is only bracketed and e_height null.
  const json none = run_json(base);
  EXPECT_EQ(none["floor_method"], "bracket");
  EXPECT_TRUE(none["e_height"].is_null());
  // The contact duration to the nearest frame, as a team counts it (240 fps).
  const double T = std::round((truth["t_separation"].get<double>() - truth["t_touch"].get<double>()) * 240) / 240;
  const json r = run_json(base + " --contact-duration " + std::to_string(T));
  EXPECT_EQ(r["floor_method"], "contact_duration");
  // The floor (truth y = 0) to a few mm: half a frame of T (2 ms) at ~2 m/s (dfloor/dT).
  EXPECT_NEAR(r["floor_y"].get<double>(), 0.0, 0.005);
  // 4 standard uncertainties (deterministic seed; the error is at most 1.73 sd when the
  // uniform error of T dominates).
  EXPECT_NEAR(r["e_height"].get<double>(), truth["e_height"].get<double>(), 4 * r["sigma_e_height"].get<double>());
}

// Two commands computing the same quantities must agree: `bounce analyze` on a filmed bounce
// and `bounce simulate` started at that bounce's touch state (from synth-video's truth).
TEST(BounceAnalysisCli, AnalyzeAgreesWithSimulateAtTheTouch) {
  const auto dir = temp_dir("bounce_analyze_simulate");
  const std::string video = dir + "/video.txt";
  const std::string law = " --restitution 0.5";
  const json truth = run_json("bounce synth-video --seed 3 --theta-deg -30 --omega -40 --vx 1" + law + " --out '" + video + "'");
  const json a = run_json("bounce analyze '" + video + "' --track-a A --track-b B --time-scale 0.125 --floor-y 0");
  auto arg = [&](const char* key) { return std::to_string(truth[key].get<double>()); };
  const json s = run_json("bounce simulate --vx " + arg("vx_in") + " --vy " + arg("vy_in") + " --omega " + arg("omega_in") +
                          " --theta-deg " + arg("theta_touch_deg") + law);
  // 4 of analyze's stated sigmas (deterministic seed; p ~ 6e-5 each for a correct sigma).
  // Before touch and separation were located the angle differed by 33 deg and e by 21 sigma.
  EXPECT_NEAR(a["collision_angle_deg"].get<double>(), s["collision_angle_deg"].get<double>(),
              4 * a["sigma_collision_angle_deg"].get<double>());
  EXPECT_NEAR(a["e_velocity"].get<double>(), s["e"].get<double>(), 4 * a["sigma_e_velocity"].get<double>());
  EXPECT_NEAR(a["contact_duration"].get<double>(), s["contact_duration"].get<double>(),
              4 * a["sigma_contact_duration"].get<double>());
  EXPECT_NEAR(a["pre"]["omega"].get<double>(), truth["omega_in"].get<double>(), 4 * a["pre"]["sigma_omega"].get<double>());
  EXPECT_NEAR(a["post"]["omega"].get<double>(), s["omega"].get<double>(), 4 * a["post"]["sigma_omega"].get<double>());
  EXPECT_NEAR(a["post"]["vx"].get<double>(), s["vx"].get<double>(), 4 * a["post"]["sigma_vx"].get<double>());
  EXPECT_NEAR(a["vy_separation"].get<double>(), s["vy"].get<double>(), 4 * a["sigma_vy_separation"].get<double>());
  EXPECT_TRUE(a["warnings"].empty()) << a["warnings"].dump();
  for (const char* key : {"t_touch", "sigma_t_touch", "t_separation", "theta_touch_deg", "contact_point_speed",
                          "contact_point_vx", "contact_point_vy", "e_velocity_common", "gravity", "gravity_tilt_deg"})
    EXPECT_TRUE(a.contains(key)) << key;
}

TEST(BounceAnalysisCli, SynthIsDeterministicBySeed) {
  const auto dir = temp_dir("bounce_synth_seed");
  run_json("bounce synth-table --rows 5 --seed 3 --out '" + dir + "/a.csv'");
  run_json("bounce synth-table --rows 5 --seed 3 --out '" + dir + "/b.csv'");
  run_json("bounce synth-table --rows 5 --seed 4 --out '" + dir + "/c.csv'");
  EXPECT_EQ(slurp(dir + "/a.csv"), slurp(dir + "/b.csv"));
  EXPECT_NE(slurp(dir + "/a.csv"), slurp(dir + "/c.csv"));
}

TEST(BounceAnalysisCli, FitReportsParametersAndResiduals) {
  const auto dir = temp_dir("bounce_fit");
  const std::string table = dir + "/t.csv";
  const json truth = run_json("bounce synth-table --rows 15 --seed 9 --mu 0.45 --out '" + table + "'")["truth"];
  // "with known truth": the table's command prints it, under the keys `bounce fit` prints.
  EXPECT_EQ(truth["model"], "hunt-crossley");
  EXPECT_EQ(truth["K"].get<double>(), 101054);
  EXPECT_EQ(truth["D"].get<double>(), 60423);
  EXPECT_EQ(truth["mu"].get<double>(), 0.45);
  EXPECT_EQ(truth["friction"], "coulomb");
  const json r = run_json("bounce fit '" + table + "' --fix K=101054 --fix n=1.51");
  for (const char* key : {"K", "n", "D", "mu", "sigma_K", "sigma_n", "sigma_D", "sigma_mu", "rms", "residuals"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r["residuals"].size(), 15u);
  EXPECT_EQ(r["sigma_K"].get<double>(), 0.0);  // fixed
  // 4 standard errors of the fit (deterministic seed).
  EXPECT_NEAR(r["mu"].get<double>(), truth["mu"].get<double>(), 4 * r["sigma_mu"].get<double>());
  EXPECT_NEAR(r["D"].get<double>(), truth["D"].get<double>(), 4 * r["sigma_D"].get<double>());
}

TEST(BounceAnalysisCli, BadInputGivesOneLine) {
  const auto dir = temp_dir("bounce_analysis_bad");
  // A ball that never hits anything: one straight flight, no impact.
  {
    std::ofstream out(dir + "/flight.txt");
    out << "#multi:\n\tA\t\tB\t\t\nt\tx\ty\tx\ty\t\n";
    for (int k = 0; k < 40; ++k) {
      const double t = k / 240.0;
      const double y = 1 - 4.9 * t * t;
      out << t << '\t' << t - 0.145 << '\t' << y << '\t' << t + 0.145 << '\t' << y << '\n';
    }
  }
  expect_error("bounce analyze '" + dir + "/flight.txt' --track-a A --track-b B", "no impact found");
  expect_error("bounce analyze '" + dir + "/flight.txt' --track-a A --track-b C", "C");
  expect_error("bounce analyze '" + dir + "/missing.txt' --track-a A --track-b B", "missing.txt");
  expect_error("bounce analyze '" + dir + "/flight.txt' --track-a A --track-b B --time-scale -1", "--time-scale");
  run_tribolab("bounce synth-video --after 0.1 --out '" + dir + "/short.txt'");  // ~24 frames after
  expect_error("bounce analyze '" + dir + "/short.txt' --track-a A --track-b B --time-scale 0.125 --exclude 30",
                        "at least 5 are needed");
  write(dir + "/apart.txt", "#multi:\n\tA\t\tB\t\t\nt\tx\ty\tx\ty\t\n0\t0\t1\t\t\n0.1\t0\t0.9\t\t\n"
                             "0.2\t\t\t0.3\t0.8\n0.3\t\t\t0.3\t0.7\n");
  expect_error("bounce analyze '" + dir + "/apart.txt' --track-a A --track-b B", "share 0 frame");
  // Tables.
  write(dir + "/bad.csv", "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out\n1,2,-3,4,5,6,7\n1,2,x,4,5,6,7\n");
  expect_error("bounce fit '" + dir + "/bad.csv'", "bad.csv:3");
  write(dir + "/nohead.csv", "theta_deg,vx_in,vy_in\n1,2,3\n");
  expect_error("bounce fit '" + dir + "/nohead.csv'", "missing column 'omega_in'");
  write(dir + "/short.csv", "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out\n1,2,-3,4,5,6\n");
  expect_error("bounce fit '" + dir + "/short.csv'", "short.csv:2");
  write(dir + "/one.csv", "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out\n10,1,-4,30,0.5,2,10\n");
  expect_error("bounce fit '" + dir + "/one.csv'", "free parameters need more rows");
  expect_error("bounce fit '" + dir + "/one.csv' --fix q=1", "unknown parameter 'q'");
  expect_error("bounce fit '" + dir + "/one.csv' --fix n", "NAME=VALUE");
  expect_error("bounce fit '" + dir + "/one.csv' --loss l2", "--loss");
  // No partial output when the synthetic generator fails.
  expect_error("bounce synth-table --rows 0 --out '" + dir + "/x.csv'", "rows");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv"));
}

}  // namespace
}  // namespace tribolab::cli::testing
