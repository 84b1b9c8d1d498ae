// The bounce commands print exactly their application-layer function's JSON (src/app/bounce_*):
// one case per command, the binary against the function called in this process. Numbers are
// compared as JSON values, i.e. to the last digit.
#include "cli_test_util.hpp"

#include "app/bounce/bounce_analyze.hpp"
#include "app/bounce/bounce_simulate.hpp"
#include "app/bounce/bounce_synth.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tribolab::cli {
namespace {

using namespace tribolab::cli::testing;
using nlohmann::json;

TEST(BounceApp, ContactTimePrintsTheFunctionsJson) {
  app::BounceContactTimeOptions o;
  o.height = 0.715;
  o.omega = -47.6;
  o.theta_deg = 11.2873;
  o.ball.ball.a = 0.143;
  EXPECT_EQ(run_json("bounce contact-time --height 0.715 --omega -47.6 --theta-deg 11.2873 --a 0.143"),
            app::bounce_contact_time(o).json);
}

TEST(BounceApp, SimulatePrintsTheFunctionsJson) {
  app::BounceSimulateOptions o;
  o.vx = 0.5;
  o.vy = -4;
  o.omega = 40;
  o.theta_deg = 30;
  o.law.restitution = 0.7;
  o.law.friction = "regularized";
  o.g = 9.81;
  EXPECT_EQ(run_json("bounce simulate --vx 0.5 --vy -4 --omega 40 --theta-deg 30 --restitution 0.7 --friction regularized --g 9.81"),
            app::bounce_simulate(o).json);
}

TEST(BounceApp, DropPrintsTheFunctionsJson) {
  app::BounceDropOptions o;
  o.height = 0.8;
  o.omega = 30;
  o.theta_deg = 15;
  o.bounces = 3;
  EXPECT_EQ(run_json("bounce drop --height 0.8 --omega 30 --theta-deg 15 --bounces 3"), app::bounce_drop(o).json);
}

TEST(BounceApp, SynthAnalyzeFitPrintTheFunctionsJson) {
  const auto dir = temp_dir("bounce_app");
  app::BounceSynthVideoOptions v;
  v.out = dir + "/video.txt";
  v.seed = 7;
  v.law.model = "hertz";
  const json video = app::bounce_synth_video(v).json;
  std::filesystem::rename(v.out, dir + "/video_app.txt");
  EXPECT_EQ(run_json("bounce synth-video --seed 7 --model hertz --out '" + v.out + "'"), video);
  // Both wrote the same file.
  EXPECT_EQ(slurp(v.out), slurp(dir + "/video_app.txt"));

  app::BounceAnalyzeOptions a;
  a.file = v.out;
  a.track_a = "A";
  a.track_b = "B";
  a.time_scale = 0.125;
  a.floor_y = 0;
  EXPECT_EQ(run_json("bounce analyze '" + v.out + "' --track-a A --track-b B --time-scale 0.125 --floor-y 0"),
            app::bounce_analyze(a).json);

  app::BounceSynthTableOptions t;
  t.out = dir + "/table.csv";
  t.rows = 8;
  t.seed = 3;
  const json table = app::bounce_synth_table(t).json;
  EXPECT_EQ(run_json("bounce synth-table --rows 8 --seed 3 --out '" + t.out + "'"), table);

  app::BounceFitOptions f;
  f.file = t.out;
  f.fix = {"n=1.51"};
  EXPECT_EQ(run_json("bounce fit '" + t.out + "' --fix n=1.51"), app::bounce_fit(f).json);
}

TEST(BounceApp, RenderPrintsTheFunctionsJson) {
  const auto dir = temp_dir("bounce_app_render");
  app::BounceRenderOptions o;
  o.out = dir + "/app.avi";
  o.size = "160x120";
  o.fps = 60;
  o.after = 0.05;
  o.supersample = 1;
  o.blur_samples = 1;
  json expected = app::bounce_render(o).json;
  expected["out"] = dir + "/cli.avi";
  EXPECT_EQ(run_json("bounce render --size 160x120 --fps 60 --after 0.05 --supersample 1 --blur-samples 1 --out '" +
                     dir + "/cli.avi'"),
            expected);
}

}  // namespace
}  // namespace tribolab::cli
