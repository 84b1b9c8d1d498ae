// `tribolab track rigid-body` as a user runs it, and the track commands' JSON equal to what the
// application layer returns (src/app/track_*.hpp) on the same input: the CLI only binds options.
#include "cli_test_util.hpp"

#include "app/track/track_import.hpp"
#include "app/track/track_kinematics.hpp"
#include "app/track/track_rigid_body.hpp"
#include "app/track/track_test_util.hpp"

#include <filesystem>

namespace tribolab::cli {
namespace {

namespace fs = std::filesystem;
using testing::expect_error;
using testing::run_json;
using testing::q;
using testing::run_tribolab;

TEST(TrackRigidBodyCli, JsonIsTheApplicationLayersJson) {
  const std::string dir = testing::temp_dir("rb_cli");
  app::testing::SpinningBody b;
  b.noise = 0.5e-3;
  const std::string file = b.write(dir + "/body.csv"), out = dir + "/rb.csv";
  const auto j = run_json("track rigid-body " + q(file) + " --track-a A --track-b B --time-scale 0.5 --out " + q(out));
  app::TrackRigidBodyOptions o;
  o.input.file = file;
  o.input.time_scale = 0.5;
  o.track_a = "A";
  o.track_b = "B";
  o.out = out;
  EXPECT_EQ(j, app::track_rigid_body(o).json);
  // half the time per frame: twice the spin
  EXPECT_NEAR(j["omega"].get<double>(), 2 * b.omega, 0.2);
  EXPECT_TRUE(fs::exists(out));
}

TEST(TrackRigidBodyCli, ImportAndKinematicsJsonAreTheApplicationLayersJson) {
  const std::string dir = testing::temp_dir("track_app_cli");
  const std::string file = app::testing::SpinningBody{}.write(dir + "/body.csv"), out = dir + "/k.csv";
  app::TrackImportOptions io;
  io.input.file = file;
  io.track = {"B", "A"};
  EXPECT_EQ(run_json("track import " + q(file) + " --track B --track A"), app::track_import(io).json);
  app::TrackKinematicsOptions ko;
  ko.input.file = file;
  ko.track = "A";
  ko.method = "savgol";
  ko.window = 9;
  ko.out = out;
  EXPECT_EQ(run_json("track kinematics " + q(file) + " --track A --method savgol --window 9 --out " + q(out)),
            app::track_kinematics(ko).json);
}

TEST(TrackRigidBodyCli, BadInputIsOneErrorLineAndNoOutput) {
  const std::string dir = testing::temp_dir("rb_cli_bad");
  app::testing::SpinningBody b;
  const std::string file = b.write(dir + "/body.csv"), out = dir + "/never.csv";
  b.frames = 2;
  const std::string two = b.write(dir + "/two.csv");
  const std::string tail = " --out " + q(out);
  expect_error("track rigid-body " + q(file) + " --track-a A" + tail, "--track-b");
  expect_error("track rigid-body " + q(file) + " --track-a A --track-b C" + tail, "available tracks: 'A', 'B'");
  expect_error("track rigid-body " + q(file) + " --track-a A --track-b A" + tail, "--track-b");
  expect_error("track rigid-body " + q(two) + " --track-a A --track-b B" + tail, "share 2 frame(s)");
  expect_error("track rigid-body " + q(file) + " --track-a A --track-b B --window 1" + tail, "--window");
  expect_error("track rigid-body " + q(file) + " --track-a A --track-b B --max-drift 2" + tail, "--max-drift");
  EXPECT_FALSE(fs::exists(out));
  testing::expect_bad_report_paths("track rigid-body " + q(file) + " --track-a A --track-b B" + tail, out);
}

TEST(TrackRigidBodyCli, HelpShowsDefaultsFromTheOptionsNotByHand) {
  for (const char* cmd : {"import", "kinematics", "rigid-body", "video"}) {
    const auto r = run_tribolab(std::string("track ") + cmd + " --help");
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_EQ(r.out.find("(default"), std::string::npos) << cmd << "\n" << r.out;
  }
  const auto rb = run_tribolab("track rigid-body --help");
  for (const char* opt : {"--track-a", "--track-b", "--window", "--max-drift", "--time-scale", "--length-unit",
                          "--entry", "--out", "--report", "--json"}) {
    EXPECT_NE(rb.out.find(opt), std::string::npos) << opt;
  }
  EXPECT_NE(rb.out.find("--max-drift NUM=0.03"), std::string::npos) << rb.out;
  // sentinels are optional: no "=0" shown for them
  const auto video = run_tribolab("track video --help");
  for (const char* opt : {"--scale NUM ", "--fps NUM ", "--search INT "}) {
    EXPECT_NE(video.out.find(opt), std::string::npos) << opt << "\n" << video.out;
  }
}

}  // namespace
}  // namespace tribolab::cli
