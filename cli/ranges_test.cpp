// Physical ranges of the inputs (docs/cli.md#physical-ranges): an input outside its range is
// refused with the uniform one-line message naming the option; an input at the edge of its
// range is computed to finite numbers (no inf, NaN, or null where a number is promised).
// Found with tools/probe_ranges.py, which runs every command at extreme values.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;

/// Fails when any number in the output is printed as inf/nan, or a key listed in `numbers`
/// is not a finite number.
void expect_finite(const std::string& args, const std::vector<std::string>& numbers) {
  const auto r = run_tribolab(args + " --json");
  ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  EXPECT_FALSE(std::regex_search(r.out, std::regex("inf|nan", std::regex::icase))) << args << "\n" << r.out;
  const json j = json::parse(r.out);
  for (const auto& k : numbers) {
    const json& v = j[json::json_pointer(k)];
    EXPECT_TRUE(v.is_number()) << args << ": " << k << " = " << v.dump();
  }
}

/// Out of range: one line "--opt: V UNIT is outside the physical range [LO, HI] UNIT".
void expect_outside(const std::string& args, const std::string& option) {
  const auto r = run_tribolab(args);
  expect_error(r, option + ": ", args);
  EXPECT_NE(r.err.find("is outside the physical range"), std::string::npos) << args << "\n" << r.err;
}

TEST(PhysicalRanges, AbsurdLaunchSpeedIsRefusedNotPrintedAsNull) {
  // Issue 11: `incline predict --v0 1e308` exited 0 printing null stop coordinates (v0^2
  // overflows). Now refused; the edge of the range (1000 m/s) computes finite numbers.
  const auto r = run_tribolab("incline predict --mu 0.5 --phi-deg 10 --v0 1e308");
  expect_error(r, "--v0: 1e+308 m/s is outside the physical range [0, 1000] m/s");
  expect_finite("incline predict --mu 0.5 --phi-deg 10 --v0 1000", {"/t_stop", "/x_stop", "/y_stop", "/x_limit"});
  // Every corner of the launch ranges that stops: the stop is finite.
  expect_finite("incline predict --mu 10 --phi-deg 0 --v0 1000 --g 0.01", {"/t_stop", "/x_stop"});
  expect_finite("incline predict --mu 1e-300 --phi-deg 0 --v0 1000 --g 0.01", {"/t_stop", "/x_stop"});
  expect_finite("incline predict --mu 10 --phi-deg 84 --v0 1000 --g 1000", {"/t_stop", "/x_stop", "/y_stop"});
}

TEST(PhysicalRanges, EveryCommandRefusesOutOfRangeNumbersUniformly) {
  const std::string run = " " + std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/incline/run_20.96deg.txt ";
  const std::string dir = temp_dir("ranges");
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"incline predict --mu 11 --phi-deg 10 --v0 1", "--mu"},
           {"incline predict --mu 0.5 --phi-deg 10 --v0 1 --g 1e6", "--g"},
           {"incline predict --mu 0.5 --phi-deg 10 --v0 1 --mu-static 1e308", "--mu-static"},
           {"incline simulate --mu 0.5 --phi-deg 10 --v0 1 --model A --normal-accel 1e308 --out " + dir + "/x.csv", "--normal-accel"},
           {"incline simulate --mu 0.5 --phi-deg 10 --v0 1 --t-end 1e308 --out " + dir + "/x.csv", "--t-end"},
           {"incline families --mu 0.5 --phi-deg 10 --vary v0 --values 1,1e308 --out " + dir + "/x.csv", "--values (v0)"},
           {"incline mu-from-stop --phi-deg 20 --x-stop 1e308 --y-stop -0.2", "--x-stop"},
           {"incline mu-from-stop --phi-deg 20 --x-stop 0.5 --y-stop -0.2 --sigma-pos 1e308", "--sigma-pos"},
           {"incline synth --mu 0.6 --phi-deg 20 --v0 2 --noise 1e308 --out " + dir + "/x.txt", "--noise"},
           {"incline synth --mu 0.6 --phi-deg 20 --v0 2 --x0 1e308 --out " + dir + "/x.txt", "--x0"},
           {"incline analyze" + run + "--phi-deg 20.96 --time-scale 1e-9", "--time-scale"},
           {"incline analyze" + run + "--phi-deg 20.96 --g 1e-9", "--g"},
           {"bounce simulate --vy -4 --mass 1e308", "--mass"},
           {"bounce simulate --vy -4 --inertia 1e308", "--inertia"},
           {"bounce simulate --vy -1e308", "--vy"},
           {"bounce simulate --vy -4 --omega 1e308", "--omega"},
           {"bounce simulate --vy -4 --K 1e308", "--K"},
           {"bounce simulate --vy -4 --tol 1e-300", "--tol"},
           {"bounce contact-time --height 1e308", "--height"},
           {"bounce contact-time --height 0.5 --b 1e-300", "--b"},
           {"bounce drop --height 0.5 --g 1e308", "--g"},
           {"bounce sweep --theta-deg 100:170:2 --omega 30:50:2 --vx 1e308 --out " + dir + "/x.csv", "--vx"},
           {"bounce sweep --theta-deg 100:170:2 --omega 30:50:2 --speed 1e308 --out " + dir + "/x.csv", "--speed"},
           {"bounce sweep --theta-deg 100:170:2 --omega 1e300:1e301:2 --out " + dir + "/x.csv", "--omega"},
           {"bounce sweep --theta-deg 100:170:2 --omega 30:50:2 --mu 0:1e308:2 --out " + dir + "/x.csv", "--mu"},
           {"bounce synth-video --height 1e308 --out " + dir + "/x.txt", "--height"},
           {"track kinematics" + run + "--time-scale 1e308 --out " + dir + "/x.csv", "--time-scale"},
       })
    expect_outside(args, option);
}

TEST(PhysicalRanges, EdgesOfTheRangesComputeFiniteNumbers) {
  // The largest accepted values where tools/probe_ranges.py found overflow before (energies
  // of a 1e308 kg ball, a sweep cell at 1e308 N/m^n).
  expect_finite("bounce simulate --vy -1000 --mass 1000 --inertia 1000", {"/energy_in", "/energy_out", "/e"});
  expect_finite("bounce simulate --vy -4 --mass 1e-6 --inertia 1e-12", {"/energy_in", "/energy_out", "/e"});
  expect_finite("bounce contact-time --height 1000 --g 0.01", {"/t_contact", "/collision_angle_deg"});
  expect_finite("bounce contact-time --height 0.5 --b 0.001", {"/t_contact", "/collision_angle_deg"});
}

// Regression (issue 26): `bounce sweep --K 1e-320` marked every cell NaN and said "completed";
// `bounce render --scale 1e-320` printed `--origin -inf ... ball=-nan,-inf`. A subnormal input
// is refused as such wherever a range or a finiteness check looks at it.
TEST(PhysicalRanges, SubnormalInputsAreRefusedAsSubnormal) {
  const std::string dir = temp_dir("subnormal");
  for (const std::string& args : std::vector<std::string>{
           "bounce sweep --K 1e-320 --theta-deg 0:90:3 --omega 0:10:3 --out " + dir + "/m.csv",
           "bounce render --scale 1e-320 --out " + dir + "/f.avi",
           "bounce simulate --vx 0.5 --vy -4 --K 1e-320"}) {
    const auto r = run_tribolab(args);
    expect_error(r, "is subnormal", args);
    EXPECT_EQ(r.err.find("non-finite"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// Regression (issue 26): `track video --fps 0` and `--scale 0` were taken as "not given".
TEST(PhysicalRanges, ZeroForAnOptionWhoseDefaultIsUnsetIsRefused) {
  const std::string dir = temp_dir("zero_unset");
  for (const char* opt : {"--fps", "--scale", "--search"}) {
    const auto r = run_tribolab(std::string("track video missing.avi --start A=1,1 ") + opt + " 0 --out " + dir + "/t.csv");
    expect_error(r, std::string(opt) + ": must be > 0, got 0", opt);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace tribolab::cli::testing
