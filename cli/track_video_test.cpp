// `tribolab track video` as a user runs it: the real binary on videos rendered here.
#include "cli_test_util.hpp"

#include "io/track_import.hpp"
#include "io/tracker_trk.hpp"
#include "video/render.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace tribolab::cli {
namespace {

namespace fs = std::filesystem;
using testing::expect_error;
using testing::run_json;
using testing::q;
using testing::run_tribolab;
using testing::slurp;
using testing::temp_dir;

constexpr double kFps = 50;
constexpr int kFrames = 24;

/// A disc with a checker sticker crossing at 6 px per frame, and a spinning red ellipse.
cv::Point2d mark_at(int frame) { return {30 + 6.0 * frame, 60}; }
cv::Point2d ball_at(int frame) { return {60 + 4.0 * frame, 170 - 2.0 * frame}; }

video::Scene scene() {
  return [](double t) {
    const double f = t * kFps;
    video::ShapePose disc;
    disc.cx_px = 30 + 6 * f;
    disc.cy_px = 60;
    disc.a_px = disc.b_px = 12;
    disc.colour = cv::Scalar(90, 160, 90);
    disc.mark = true;
    disc.mark_size_px = 15;
    video::ShapePose e;
    e.cx_px = 60 + 4 * f;
    e.cy_px = 170 - 2 * f;
    e.a_px = 20;
    e.b_px = 13;
    e.angle_rad = 0.2 + 0.1 * f;
    e.colour = cv::Scalar(40, 40, 210);
    return std::vector<video::ShapePose>{disc, e};
  };
}

/// `the_scene` (the disc and ellipse of scene()) filmed to DIR/NAME.
std::string film(const std::string& dir, const video::Scene& the_scene = scene(), const std::string& name = "film.avi") {
  video::RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.fps = kFps;
  o.shutter_fraction = 0.3;
  o.background = video::RenderOptions::Background::plain;
  o.noise_sigma = 1;
  const std::string path = dir + "/" + name;
  video::write_video(path, the_scene, kFrames, o);
  return path;
}

TEST(TrackVideoCli, PointAndEllipseToCsvAndJsonSummary) {
  const std::string dir = temp_dir("tv_both");
  const std::string video = film(dir), out = dir + "/tracks.csv";
  const auto j = run_json("track video " + q(video) + " --start 'mark=30,60' --ellipse 'ball=76,162@4'" +
                          " --scale 0.001 --out " + q(out));
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["frames"], kFrames);
  EXPECT_DOUBLE_EQ(j["fps"].get<double>(), kFps);
  EXPECT_EQ(j["video"]["width"], 320);
  EXPECT_EQ(j["video"]["codec"], "MJPG");
  EXPECT_EQ(j["time_base"]["time_scale"], 1.0);
  EXPECT_EQ(j["calibration"]["calibrated"], true);
  EXPECT_DOUBLE_EQ(j["calibration"]["m_per_px"].get<double>(), 0.001);
  EXPECT_EQ(j["track_names"], nlohmann::json({"mark", "ball", "ball.A", "ball.B"}));
  EXPECT_EQ(j["tracks"]["mark"]["tracked"], kFrames);
  EXPECT_EQ(j["tracks"]["mark"]["lost"], 0);
  EXPECT_EQ(j["tracks"]["ball"]["start_frame"], 4);
  EXPECT_EQ(j["tracks"]["ball.B"]["rows"], kFrames - 4);
  EXPECT_GT(j["tracks"]["mark"]["median_score"].get<double>(), 0.8);
  EXPECT_TRUE(j["tracks"]["mark"]["vs_human"].is_null());
  EXPECT_TRUE(j["warnings"].empty());
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "track,frame,t,x,y,x_px,y_px,score");
  EXPECT_EQ(testing::count_lines(csv), 1 + kFrames + 3 * (kFrames - 4));
  // the file is what `track import` and the analyses read directly
  const track::TrackSet set = io::read_tracks(out);
  const track::Track& mark = set.find("mark");
  ASSERT_EQ(mark.points.size(), static_cast<std::size_t>(kFrames));
  for (const auto& p : mark.points) {
    // 1 mm per px from the bottom-left pixel: the sticker's centre to the trackers' accuracy
    // (~0.1 px measured in their tests; 0.5 px allows MJPG and noise)
    EXPECT_NEAR(p.x, mark_at(p.frame).x * 0.001, 0.5e-3) << p.frame;
    EXPECT_NEAR(p.y, (239 - mark_at(p.frame).y) * 0.001, 0.5e-3) << p.frame;
    EXPECT_DOUBLE_EQ(p.t, p.frame / kFps);
  }
  const track::Track& ball = set.find("ball");
  EXPECT_NEAR(ball.points.back().x, ball_at(kFrames - 1).x * 0.001, 0.5e-3);
}

TEST(TrackVideoCli, WrittenTrackerProjectImportsToTheCsvNumbers) {
  const std::string dir = temp_dir("tv_trk");
  const std::string video = film(dir), out = dir + "/tracks.csv", trk = dir + "/tracks.trk";
  const auto j = run_json("track video " + q(video) + " --start mark=30,60 --calibrate 0,0,200,0,0.5" +
                          " --origin 10,230 --axes-deg 5 --time-scale 0.125 --out " + q(out) +
                          " --write-trk " + q(trk));
  EXPECT_EQ(j["write_trk"], trk);
  EXPECT_DOUBLE_EQ(j["calibration"]["m_per_px"].get<double>(), 0.5 / 200);
  const track::TrackSet a = io::read_tracks(out), b = io::read_tracks(trk);
  ASSERT_EQ(b.tracks.size(), 1u);
  ASSERT_EQ(a.tracks[0].points.size(), b.tracks[0].points.size());
  for (std::size_t k = 0; k < a.tracks[0].points.size(); ++k) {
    const auto& p = a.tracks[0].points[k];
    const auto& r = b.tracks[0].points[k];
    EXPECT_EQ(p.frame, r.frame);
    // m -> px written in shortest round-trip form -> m; s vs Tracker's ms: rounding only
    EXPECT_NEAR(p.x, r.x, 1e-12);
    EXPECT_NEAR(p.y, r.y, 1e-12);
    EXPECT_NEAR(p.t, r.t, 1e-14);
  }
  // and the project opens with its video: tracking it again from its own track works
  const auto again = run_json("track video " + q(trk) + " --from-track mark --out " + q(dir + "/again.csv"));
  EXPECT_EQ(again["tracks"]["mark"]["vs_human"]["frames"], kFrames - 1);
  // the same tracker on the same frames, started from the first run's refined start point
  // (a sub-pixel shift of the template): the two runs agree to a small fraction of a pixel
  EXPECT_LT(again["tracks"]["mark"]["vs_human"]["median_px"].get<double>(), 0.2);
}

TEST(TrackVideoCli, ReportShowsThumbnailsAndTracks) {
  const std::string dir = temp_dir("tv_report");
  const std::string video = film(dir), out = dir + "/tracks.csv", html = dir + "/tracks.html";
  const auto j = run_json("track video " + q(video) + " --start mark=30,60 --ellipse ball=60,170 --out " +
                          q(out) + " --report " + q(html));
  EXPECT_EQ(j["report"], html);
  const std::string page = slurp(html);
  EXPECT_NE(page.find("<html"), std::string::npos);
  EXPECT_NE(page.find("data:image/jpeg;base64,"), std::string::npos);  // thumbnails embedded
  EXPECT_NE(page.find("ball.A"), std::string::npos);
  testing::expect_bad_report_paths("track video " + q(video) + " --start mark=30,60 --out " + q(dir + "/x.csv"),
                                   dir + "/x.csv");
}

TEST(TrackVideoCli, MarkCorrectsAFrameInCsvProjectAndSummary) {
  // A mark 2.5 px off the sticker's centre in frame 10 (a click is never exact): that row is
  // the user's position with score 1, in the CSV, the project and the summary; the frames
  // before it stay where they were, those after it are tracked on from it.
  const std::string dir = temp_dir("tv_mark");
  const std::string video = film(dir), out = dir + "/tracks.csv", plain = dir + "/plain.csv", trk = dir + "/tracks.trk";
  run_json("track video " + q(video) + " --start mark=30,60 --ellipse ball=60,170 --scale 0.001 --out " + q(plain));
  const cv::Point2d m = mark_at(10) + cv::Point2d(2.5, 0);
  const auto j = run_json("track video " + q(video) + " --start mark=30,60 --ellipse ball=60,170 --mark mark@10=" +
                          std::to_string(m.x) + "," + std::to_string(m.y) + " --mark ball@12=108,146 --scale 0.001 --out " +
                          q(out) + " --write-trk " + q(trk));
  EXPECT_EQ(j["tracks"]["mark"]["manual_frames"], nlohmann::json::array({10}));
  EXPECT_EQ(j["tracks"]["ball"]["manual_frames"], nlohmann::json::array({12}));
  EXPECT_EQ(j["tracks"]["ball.A"]["manual_frames"], nlohmann::json::array());
  const track::TrackSet a = io::read_tracks(out), before = io::read_tracks(plain), project = io::read_tracks(trk);
  const track::Track& marked = a.tracks[0];
  ASSERT_EQ(marked.name, "mark");
  ASSERT_EQ(marked.points.size(), static_cast<std::size_t>(kFrames));
  ASSERT_EQ(before.tracks[0].points.size(), marked.points.size());
  for (std::size_t k = 0; k < marked.points.size(); ++k) {
    const int f = marked.points[k].frame;
    if (f == 10) {
      // (std::to_string's six decimals are the mark as given)
      EXPECT_NEAR(marked.points[k].x, 0.001 * m.x, 1e-9);  // m, y up from the bottom-left pixel
      EXPECT_NEAR(marked.points[k].y, 0.001 * (239 - m.y), 1e-9);
      EXPECT_NEAR(project.tracks[0].points[k].x, marked.points[k].x, 1e-12);
      EXPECT_NEAR(project.tracks[0].points[k].y, marked.points[k].y, 1e-12);
    } else if (f <= 5) {
      EXPECT_EQ(marked.points[k].x, before.tracks[0].points[k].x) << f;
    } else {
      EXPECT_NEAR(marked.points[k].x, 0.001 * mark_at(f).x, 1e-3) << f;  // tracked on the sticker again (1 px)
    }
  }
  const std::string csv = slurp(out);
  EXPECT_NE(csv.find("mark,10,"), std::string::npos);
  const std::string tail = " --start mark=30,60 --out " + q(dir + "/bad.csv");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark nobody@3=40,60"), "no track named 'nobody' is followed ('mark')");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark=40,60"), "NAME@FRAME=X,Y");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark@3=nan,60"), "--mark mark@3");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark@3=400,60"), "outside the 320x240 image");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark@99=40,60"), "frame 99 is beyond the end of the clip (24 frames decoded)");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark@0=40,60"), "a mark must come after its start");
  expect_error(run_tribolab("track video " + q(video) + tail + " --mark mark@3=40,60 --mark mark@3=41,60"), "two marks on one frame");
  EXPECT_FALSE(fs::exists(dir + "/bad.csv"));
}

TEST(TrackVideoCli, HelpListsEveryOption) {
  const auto r = run_tribolab("track video --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* opt : {"--out", "--start", "--ellipse", "--from-track", "--mark", "--scale", "--calibrate",
                          "--origin", "--axes-deg", "--fps", "--time-scale", "--write-trk", "--report", "--json"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
}

/// The flags `--name` a text names, in order.
std::vector<std::string> flags_in(const std::string& text) {
  std::vector<std::string> flags;
  for (std::size_t p = text.find("--"); p != std::string::npos; p = text.find("--", p + 2)) {
    std::size_t e = p + 2;
    while (e < text.size() && (std::islower(static_cast<unsigned char>(text[e])) || text[e] == '-')) ++e;
    flags.push_back(text.substr(p, e - p));
  }
  return flags;
}

TEST(TrackVideoCli, ALostTrackIsWarnedNamingTheFlagsThatHelp) {
  // The core names the options that help as fields (field("max_gap"), numerics/error.hpp); the
  // command line spells them as its flags, in the JSON, the listing and on stderr, each one a
  // flag of `track video`, and no field mark (a control character) reaches the user.
  const std::string dir = temp_dir("tv_lost");
  const std::string help = run_tribolab("track video --help").out;
  const auto check = [&](const std::string& warning, const std::vector<std::string>& must) {
    for (const std::string& flag : must) EXPECT_NE(warning.find(flag), std::string::npos) << flag << " in " << warning;
    for (const std::string& flag : flags_in(warning))
      EXPECT_NE(help.find(" " + flag + " "), std::string::npos) << flag << " is no flag of track video: " << warning;
    EXPECT_EQ(warning.find_first_of("\x1e\x1f"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("max_gap"), std::string::npos) << warning;
  };
  {
    // The point tracker: the disc of film() gone after frame 11 (hidden or out of view).
    const video::Scene base = scene();
    const std::string gone = film(dir, [&](double t) {
      auto shapes = base(t);
      if (t * kFps > 11.5) shapes.erase(shapes.begin());
      return shapes;
    }, "gone.avi");
    const auto j = run_json("track video " + q(gone) + " --start 'mark=30,60' --scale 0.001 --out " + q(dir + "/p.csv"));
    ASSERT_EQ(j["warnings"].size(), 1u) << j.dump();
    EXPECT_EQ(j["tracks"]["mark"]["lost_ranges"], nlohmann::json::parse("[[12, 23]]"));
    check(j["warnings"][0].get<std::string>(), {"track 'mark': lost", "a larger --search or --max-gap", "--point-tracker frame"});
  }
  // The ellipse tracker: a ball filmed by `bounce render` leaving a 160 px view, given up
  // after --max-gap 1 lost frames (python/tests/test_track.py: the same film, max_gap).
  const std::string film_path = dir + "/ball.avi", truth = dir + "/truth.csv";
  const auto film = run_json("bounce render --out " + q(film_path) + " --truth " + q(truth) +
                             " --size 160x120 --fps 60 --height 0.5 --vx 3 --after 0.3 --scale 0.006 --background plain");
  ASSERT_TRUE(film.is_object());
  const track::Track ball = io::read_tracks(truth).find("ball");
  const double ox = film["origin_px"][0].get<double>(), oy = film["origin_px"][1].get<double>();
  const auto& p6 = ball.points.at(6);  // frame 6: the whole ball in view
  const std::string args = "track video " + q(film_path) + " --scale 0.006 --origin " + std::to_string(ox) + "," +
                           std::to_string(oy) + " --ellipse 'ball=" + std::to_string(ox + p6.x / 0.006) + "," +
                           std::to_string(oy - p6.y / 0.006) + "@6' --max-gap 1 --out " + q(dir + "/e.csv");
  const auto j = run_json(args);
  ASSERT_EQ(j["warnings"].size(), 1u) << j.dump();
  check(j["warnings"][0].get<std::string>(), {"track 'ball': lost", "--max-gap (1)", "--ellipse-min-score"});
  const auto listing = run_tribolab(args);  // the text listing and stderr spell them too
  EXPECT_EQ(listing.exit_code, 0) << listing.err;
  check(listing.err, {"tribolab: warning: track 'ball': lost", "--max-gap (1)"});
  check(listing.out, {"--max-gap (1)"});
}

TEST(TrackVideoCli, BadInputIsOneErrorLineAndNoOutputFile) {
  const std::string dir = temp_dir("tv_bad");
  const std::string video = film(dir), out = dir + "/out.csv", trk = dir + "/out.trk";
  const std::string tail = " --out " + q(out) + " --write-trk " + q(trk);
  std::ofstream(dir + "/notes.mp4") << "not a video\n";
  const std::string bytes = slurp(video);
  std::ofstream(dir + "/cut.avi", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  {
    io::TrkWriteSpec spec;
    spec.video_path = "videos/gone.avi";  // neither inside the archive nor beside it
    track::Track t{"hand", {{3, 0, 0.1, 0.2}}};
    std::ofstream(dir + "/novideo.trz", std::ios::binary) << io::write_trz(io::write_trk({t}, spec), "p.trk");
    spec.video_path = "film.avi";
    std::ofstream(dir + "/p.trk") << io::write_trk({t}, spec);
  }
  const std::pair<std::string, std::string> cases[] = {
      {q(dir + "/missing.avi") + " --start a=1,1", "missing.avi: no such file"},
      {q(dir + "/notes.mp4") + " --start a=1,1", "cannot be decoded as a video"},
      {q(dir + "/cut.avi") + " --start mark=30,60", "truncated"},
      {q(video) + " --start mark=400,60", "outside the 320x240 image"},
      {q(video) + " --start mark=300,20", "mark"},  // a featureless patch of plain background
      {q(video) + " --start 'mark=30;60'", "--start mark=30;60"},
      {q(video) + " --start =30,60", "NAME=X,Y"},
      {q(video) + " --start mark=30,60@-2", "frame"},
      {q(video), "nothing to track"},
      {q(dir + "/novideo.trz") + " --from-track hand", "no video"},
      {q(dir + "/p.trk") + " --from-track nobody", "its tracks: 'hand'"},
      {q(video) + " --from-track hand", "only a Tracker project"},
      {q(video) + " --start mark=30,60 --scale 0.001 --calibrate 0,0,10,0,1", "not both"},
      {q(video) + " --start mark=30,60 --fps 0.1", "--fps"},
  };
  for (const auto& [args, mention] : cases) {
    expect_error(run_tribolab("track video " + args + tail), mention, args);
    EXPECT_FALSE(fs::exists(out)) << args;
    EXPECT_FALSE(fs::exists(trk)) << args;
  }
  expect_error(run_tribolab("track video " + q(video) + " --start mark=30,60 --out " + q(out) +
                            " --write-trk " + q(dir + "/x.txt")),
               ".trk");
  EXPECT_FALSE(fs::exists(out));
  // no leftover temporary files beside the outputs
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

}  // namespace
}  // namespace tribolab::cli
