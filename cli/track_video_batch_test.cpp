// `tribolab track video A B C ...`: several videos in one call (docs/cli.md#several-videos).
// Good videos, a missing one, a corrupt one and one whose ball vanishes after its start frame,
// the bad ones in the middle: every good video's CSV (and project, report) is written and
// named NN_<stem>, every bad one is a row with its error and a line on stderr, the exit
// status is non-zero, and nothing of a bad video is left behind.
#include "cli_test_util.hpp"

#include "video/render.hpp"

#include <filesystem>
#include <fstream>

namespace tribolab::cli {
namespace {

namespace fs = std::filesystem;
using testing::q;
using testing::run_tribolab;
using testing::slurp;
using testing::temp_dir;

constexpr double kBatchFps = 50;
constexpr int kBatchFrames = 16;

/// A red ellipse crossing a plain background at 4 px per frame; with `vanishes` it is there
/// in frame 0 only (the object lost from the first frame on).
std::string batch_film(const std::string& path, double x0, bool vanishes) {
  video::RenderOptions o;
  o.width = 240;
  o.height = 160;
  o.fps = kBatchFps;
  o.shutter_fraction = 0.3;
  o.background = video::RenderOptions::Background::plain;
  o.noise_sigma = 1;
  const video::Scene scene = [x0, vanishes](double t) {
    const double f = t * kBatchFps;
    std::vector<video::ShapePose> shapes;
    if (vanishes && f > 0.5) return shapes;
    video::ShapePose e;
    e.cx_px = x0 + 4 * f;
    e.cy_px = 80 - 1.5 * f;
    e.a_px = 18;
    e.b_px = 12;
    e.angle_rad = 0.3 + 0.05 * f;
    e.colour = cv::Scalar(40, 40, 210);
    shapes.push_back(e);
    return shapes;
  };
  video::write_video(path, scene, kBatchFrames, o);
  return path;
}

TEST(TrackVideoBatchCli, BadVideosInTheMiddleNeverLoseTheOthersTracks) {
  const std::string dir = temp_dir("tv_batch");
  const std::string a = batch_film(dir + "/first.avi", 60, false);
  const std::string lost = batch_film(dir + "/vanishing.avi", 60, true);
  const std::string b = batch_film(dir + "/last.avi", 60, false);
  const std::string missing = dir + "/missing.avi";
  const std::string corrupt = dir + "/corrupt.avi";
  {
    std::ofstream f(corrupt, std::ios::binary);
    f << slurp(a).substr(0, 300);  // a truncated file: the container's header and nothing else
  }
  const std::string out = dir + "/tracks", trk = dir + "/projects", report = dir + "/batch.html";
  const auto r = run_tribolab("track video " + q(a) + " " + q(missing) + " " + q(corrupt) + " " + q(lost) + " " +
                              q(b) + " --ellipse 'ball=60,80' --out " + q(out) + " --write-trk " + q(trk) +
                              " --report " + q(report) + " --json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 5u);
  EXPECT_EQ(j["summary"]["n_runs"], 5);
  EXPECT_EQ(j["summary"]["n_ok"], 2);
  EXPECT_EQ(j["summary"]["n_failed"], 3);
  EXPECT_EQ(j["summary"]["failed"], nlohmann::json({missing, corrupt, lost}));
  // The good videos: the single-video object plus `file`, outputs named by position and stem.
  const std::vector<std::pair<std::size_t, std::string>> good = {{0, "1_first"}, {4, "5_last"}};
  for (const auto& [i, name] : good) {
    const auto& run = j["runs"][i];
    EXPECT_FALSE(run.contains("error")) << run.dump();
    EXPECT_EQ(run["file"], i == 0 ? a : b);
    EXPECT_EQ(run["out"], out + "/" + name + ".csv");
    EXPECT_EQ(run["write_trk"], trk + "/" + name + ".trk");
    EXPECT_EQ(run["report"], dir + "/batch_runs/" + name + ".html");
    EXPECT_EQ(run["tracks"]["ball"]["tracked"], kBatchFrames);
    EXPECT_TRUE(fs::exists(out + "/" + name + ".csv"));
    EXPECT_TRUE(fs::exists(trk + "/" + name + ".trk"));
    EXPECT_TRUE(fs::exists(dir + "/batch_runs/" + name + ".html"));
    // Every frame of the CSV has a position, and it follows the ball (4 px per frame).
    const std::string csv = slurp(out + "/" + name + ".csv");
    EXPECT_NE(csv.find("\nball,15,"), std::string::npos);
    EXPECT_EQ(csv.find(",,"), std::string::npos);
  }
  // The bad ones: an error naming the file and the cause, and no file of theirs.
  EXPECT_NE(j["runs"][1]["error"].get<std::string>().find("missing.avi"), std::string::npos);
  EXPECT_NE(j["runs"][2]["error"].get<std::string>().find("corrupt.avi"), std::string::npos);
  const std::string lost_error = j["runs"][3]["error"].get<std::string>();
  EXPECT_NE(lost_error.find("vanishing.avi"), std::string::npos) << lost_error;
  EXPECT_NE(lost_error.find("lost in every frame after its start"), std::string::npos) << lost_error;
  EXPECT_NE(lost_error.find("--max-gap"), std::string::npos) << "the option that helps: " << lost_error;
  for (const std::string name : {"2_missing", "3_corrupt", "4_vanishing"}) {
    EXPECT_FALSE(fs::exists(out + "/" + name + ".csv")) << name;
    EXPECT_FALSE(fs::exists(trk + "/" + name + ".trk")) << name;
    EXPECT_FALSE(fs::exists(dir + "/batch_runs/" + name + ".html")) << name;
  }
  // One error line per bad video, then the summary line.
  for (const std::string& f : {missing, corrupt, lost})
    EXPECT_NE(r.err.find("tribolab: error: " + f + ":"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("3 of 5 runs failed"), std::string::npos) << r.err;
  // The series page links each good video's report.
  const std::string page = slurp(report);
  EXPECT_NE(page.find("batch_runs/1_first.html"), std::string::npos);
  EXPECT_NE(page.find("batch_runs/5_last.html"), std::string::npos);
  fs::remove_all(dir);
}

TEST(TrackVideoBatchCli, AllGoodExitsZeroAndTheTextTableNamesTheOutputs) {
  const std::string dir = temp_dir("tv_batch_ok");
  const std::string a = batch_film(dir + "/one.avi", 60, false), b = batch_film(dir + "/two.avi", 70, false);
  const auto r = run_tribolab("track video " + q(a) + " " + q(b) + " --ellipse 'ball=60,80' --scale 0.001 --out " +
                              q(dir + "/out"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find(dir + "/out/1_one.csv"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(dir + "/out/2_two.csv"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("n_ok"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(TrackVideoBatchCli, OutputFolderThatIsAFileIsRefusedBeforeAnyWork) {
  const std::string dir = temp_dir("tv_batch_bad");
  const std::string a = batch_film(dir + "/one.avi", 60, false);
  { std::ofstream(dir + "/taken") << "x"; }
  testing::expect_error("track video " + q(a) + " " + q(a) + " --ellipse 'ball=60,80' --out " + q(dir + "/taken"),
                        "--out");
  testing::expect_error("track video " + q(a) + " " + q(a) + " --ellipse 'ball=60,80' --out " +
                            q(dir + "/no/such/folder"),
                        "cannot create the folder");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::cli
