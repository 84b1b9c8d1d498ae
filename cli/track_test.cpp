// Golden tests of `tribolab track`: real files written here (a tiny hand-written Tracker
// .trk and Export Data text), the real binary, exit codes, stdout, stderr and output files.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace tribolab::cli::testing {
namespace {

namespace fs = std::filesystem;

/// A minimal Tracker project: 30 px per cm, origin at (100, 200), 40 ms per frame,
/// one point mass "puck" moving 1 cm right per frame from frame 1 (frames 1..6).
std::string tiny_trk() {
  std::string s =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">\n"
      " <property name=\"videoclip\" type=\"object\"><object class=\"org.opensourcephysics.media.core.VideoClip\">\n"
      "  <property name=\"startframe\" type=\"int\">0</property>\n"
      "  <property name=\"stepsize\" type=\"int\">1</property>\n"
      "  <property name=\"stepcount\" type=\"int\">10</property>\n"
      "  <property name=\"starttime\" type=\"double\">0.0</property>\n"
      " </object></property>\n"
      " <property name=\"clipcontrol\" type=\"object\"><object class=\"org.opensourcephysics.media.core.StepperClipControl\">\n"
      "  <property name=\"delta_t\" type=\"double\">40.0</property>\n"
      " </object></property>\n"
      " <property name=\"coords\" type=\"object\"><object class=\"org.opensourcephysics.media.core.ImageCoordSystem\">\n"
      "  <property name=\"fixedorigin\" type=\"boolean\">true</property>\n"
      "  <property name=\"framedata\" type=\"array\">\n"
      "   <property name=\"[0]\" type=\"object\"><object class=\"org.opensourcephysics.media.core.ImageCoordSystem$FrameData\">\n"
      "    <property name=\"xorigin\" type=\"double\">100.0</property>\n"
      "    <property name=\"yorigin\" type=\"double\">200.0</property>\n"
      "    <property name=\"angle\" type=\"double\">0.0</property>\n"
      "    <property name=\"xscale\" type=\"double\">30.0</property>\n"
      "    <property name=\"yscale\" type=\"double\">30.0</property>\n"
      "   </object></property>\n"
      "  </property>\n"
      " </object></property>\n"
      " <property name=\"length_unit\" type=\"string\">cm</property>\n"
      " <property name=\"tracks\" type=\"collection\">\n"
      "  <property name=\"item\" type=\"object\"><object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">\n"
      "   <property name=\"name\" type=\"string\">puck</property>\n"
      "   <property name=\"framedata\" type=\"array\">\n";
  for (int f = 1; f <= 6; ++f) {
    s += "    <property name=\"[" + std::to_string(f) +
         "]\" type=\"object\"><object class=\"x.PointMass$FrameData\"><property name=\"x\" type=\"double\">" +
         std::to_string(100 + 30 * f) + ".0</property><property name=\"y\" type=\"double\">170.0</property></object></property>\n";
  }
  s += "   </property>\n  </object></property>\n </property>\n</object>\n";
  return s;
}

/// Tracker 6 Export Data, two tracks, tab delimited, decimal comma.
const char* kExport =
    "#multi:\n"
    "\tA\t\tB\t\t\n"
    "t\tx\ty\tx\ty\t\n"
    "0,0\t0,0\t1,0\t2,0\t0,0\n"
    "0,1\t0,1\t1,1\t2,0\t0,1\n"
    "0,2\t0,2\t1,2\t2,0\t0,2\n"
    "0,3\t0,3\t1,3\t2,0\t0,3\n"
    "0,4\t0,4\t1,4\t2,0\t0,4\n";

struct Files {
  std::string dir, trk, txt;
};

Files files(const std::string& name) {
  Files f;
  f.dir = temp_dir("track_" + name);
  f.trk = f.dir + "/puck.trk";
  f.txt = f.dir + "/two.txt";
  std::ofstream(f.trk) << tiny_trk();
  std::ofstream(f.txt) << kExport;
  return f;
}

/// One error line on stderr containing `fragment`, non-zero exit, nothing on stdout.
TEST(TrackCli, ImportWritesTheTidyTableInSecondsAndMetres) {
  const Files f = files("import");
  const std::string out = f.dir + "/tidy.csv";
  const auto r = run_tribolab("track import '" + f.trk + "' --out '" + out + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // frame 1: pixel (130, 170) -> (1 cm, 1 cm) = (0.01 m, 0.01 m), t = 40 ms
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n', csv.find('\n') + 1) + 1),
            "track,frame,t,x,y\npuck,1,0.04,0.01,0.01\n");
  EXPECT_EQ(count_lines(csv), 7);
}

TEST(TrackCli, ImportJsonSummary) {
  const Files f = files("json");
  const auto r = run_tribolab("track import '" + f.txt + "' --time-scale 0.5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "export");
  EXPECT_EQ(j["track_names"], nlohmann::json::array({"A", "B"}));
  EXPECT_EQ(j["tracks"]["B"]["points"], 5);
  EXPECT_DOUBLE_EQ(j["tracks"]["A"]["t_max"].get<double>(), 0.2);  // 0.4 s * 0.5
  EXPECT_DOUBLE_EQ(j["tracks"]["B"]["y_max"].get<double>(), 0.4);
  EXPECT_TRUE(j["out"].is_null());
}

TEST(TrackCli, KinematicsTrackerMethodMatchesTheStencils) {
  const Files f = files("kin");
  const std::string out = f.dir + "/k.csv";
  const auto r = run_tribolab("track kinematics '" + f.txt + "' --track B --impacts none --out '" + out + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "tracker");
  EXPECT_EQ(j["velocities_defined"], 3);
  EXPECT_EQ(j["accelerations_defined"], 1);
  EXPECT_EQ(slurp(out),
            "t,x,y,vx,vy,ax,ay\n"
            "0,2,0,,,,\n"
            "0.1,2,0.1,0,1,,\n"
            "0.2,2,0.2,0,1,0,0\n"
            "0.3,2,0.3,0,1,,\n"
            "0.4,2,0.4,,,,\n");
}

TEST(TrackCli, KinematicsSavgolAddsSigmaColumns) {
  const Files f = files("sg");
  const std::string out = f.dir + "/k.csv";
  const auto r = run_tribolab("track kinematics '" + f.trk + "' --method savgol --window 5 --order 2 --out '" + out + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,x,y,vx,vy,ax,ay,sigma_vx,sigma_vy,sigma_ax,sigma_ay");
  EXPECT_EQ(count_lines(csv), 7);
}

TEST(TrackCli, BadInputIsOneErrorLineAndNoOutputFile) {
  const Files f = files("errors");
  const std::string out = f.dir + "/never.csv";
  const std::string o = " --out '" + out + "'";
  expect_error(run_tribolab("track import '" + f.dir + "/missing.trk'" + o), "missing.trk: cannot open");
  expect_error(run_tribolab("track kinematics '" + f.txt + "' --track C" + o),
                   "available tracks: 'A', 'B'");
  expect_error(run_tribolab("track kinematics '" + f.txt + "'" + o), "choose one with --track");
  expect_error(run_tribolab("track import '" + f.trk + "' --time-scale -2" + o), "--time-scale");
  expect_error(run_tribolab("track import '" + f.trk + "' --time-scale abc" + o), "--time-scale");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --method spline" + o), "--method");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --method savgol --window 3" + o), "--window");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --window 9" + o), "savgol only");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --impacts maybe" + o), "--impacts");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --g 0" + o), "--g");
  expect_error(run_tribolab("track kinematics '" + f.trk + "' --g -9.8" + o), "--g");
  expect_error(run_tribolab("track import '" + f.trk + "' --length-unit parsec" + o), "--length-unit");
  // malformed and truncated files
  const std::string trunc = f.dir + "/trunc.trk";
  const std::string full = tiny_trk();
  std::ofstream(trunc) << full.substr(0, full.size() / 2);
  expect_error(run_tribolab("track import '" + trunc + "'" + o), "trunc.trk:");
  const std::string bad = f.dir + "/bad.txt";
  std::ofstream(bad) << "t,x,y\n0,1,2\n0.1,1.5,oops\n";
  expect_error(run_tribolab("track import '" + bad + "'" + o), "bad.txt:3");
  const std::string junk = f.dir + "/junk.trz";
  std::ofstream(junk) << "PK\x03\x04 not really a zip";
  expect_error(run_tribolab("track import '" + junk + "'" + o), "junk.trz");
  const std::string nodt = f.dir + "/nodt.trk";
  std::string s = full;
  s.replace(s.find("delta_t"), 7, "rate_t");
  std::ofstream(nodt) << s;
  expect_error(run_tribolab("track import '" + nodt + "'" + o), "clipcontrol/delta_t");
  EXPECT_FALSE(fs::exists(out));
  // kinematics needs --out
  const auto r = run_tribolab("track kinematics '" + f.trk + "'");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

TEST(TrackCli, KinematicsWarnsWhenAFreeFlightDoesNotFallAtG) {
  // A ball thrown up at 3 m/s filmed at 240 fps, its times written as if at 30 fps (slow
  // motion analysed as real time): it falls at 9.8/64 = 0.153 m/s^2 in the file's time.
  const std::string dir = temp_dir("track_kin_g");
  const std::string csv = dir + "/throw.csv", out = dir + "/k.csv";
  {
    std::ofstream f(csv);
    f << "t,x,y\n";
    for (int i = 0; i < 144; ++i) {
      const double s = i / 240.0;
      f << i / 30.0 << ',' << 0.2 + 1.5 * s << ',' << 1.0 + 3.0 * s - 4.9 * s * s << '\n';
    }
  }
  const auto r = run_tribolab("track kinematics '" + csv + "' --out '" + out + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;  // a warning, not an error: the numbers are still written
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("tribolab: warning: segment 1 of 1 (frames 0-143"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--time-scale 0.125 "), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["g"], 9.8);
  EXPECT_EQ(j["segment_fits"][0]["gravity_plausible"], false);
  EXPECT_TRUE(fs::exists(out));
  // The same file held against the g it shows is quiet: --g is the g the check uses.
  const auto quiet = run_tribolab("track kinematics '" + csv + "' --g 0.153125 --out '" + out + "'");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST(TrackCli, KinematicsFromToKeepsOnlyThoseTimes) {
  const Files f = files("from_to");
  const std::string out = f.dir + "/k.csv";
  const auto r = run_tribolab("track kinematics '" + f.txt + "' --track B --from 0.1 --to 0.3 --impacts none --out '" +
                              out + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], 3);
  EXPECT_DOUBLE_EQ(j["t_from"].get<double>(), 0.1);
  EXPECT_EQ(slurp(out), "t,x,y,vx,vy,ax,ay\n0.1,2,0.1,,,,\n0.2,2,0.2,0,1,,\n0.3,2,0.3,,,,\n");
  // the fields' own spelling works too, and a reversed range is one error line naming them
  const auto bad = run_tribolab("track kinematics '" + f.txt + "' --track B --t-from 0.3 --t-to 0.1 --out '" +
                                f.dir + "/bad.csv'");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--t-from/--t-to: must be times in s"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(f.dir + "/bad.csv"));
}

TEST(TrackCli, RotationGivesTheSpinOfOnePointAboutItsPivot) {
  // An exact circle of radius 0.2 m about (1, 2) at 5 rad/s, 30 fps, 20 frames.
  const std::string dir = temp_dir("track_rotation");
  const std::string csv = dir + "/mark.csv";
  {
    std::ofstream o(csv);
    o.precision(17);
    o << "track,frame,t,x,y\n";
    for (int i = 0; i < 20; ++i) {
      const double t = i / 30.0;
      o << "mark," << i << ',' << t << ',' << 1 + 0.2 * std::cos(5 * t) << ',' << 2 + 0.2 * std::sin(5 * t) << '\n';
    }
  }
  const auto r = run_tribolab("track rotation '" + csv + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["omega"].get<double>(), 5, 1e-9);  // exact data: round-off only
  EXPECT_NEAR(j["pivot_x"].get<double>(), 1, 1e-9);
  EXPECT_NEAR(j["radius"].get<double>(), 0.2, 1e-9);
  const auto half = run_tribolab("track rotation '" + csv + "' --pivot-x 1");
  EXPECT_EQ(half.exit_code, 1);
  EXPECT_NE(half.err.find("--pivot-x and --pivot-y go together"), std::string::npos) << half.err;
}

}  // namespace
}  // namespace tribolab::cli::testing
