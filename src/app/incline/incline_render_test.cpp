// `incline render` (the app function): the film's truth is the model-B path; the film, tracked by
// `track video` with the calibration the render prints and analysed by `incline analyze`, gives
// back the launch's mu and v0; bad options write nothing.
#include "app/incline/incline_analyze.hpp"
#include "app/incline/incline_render.hpp"
#include "app/track/track_video.hpp"

#include "incline/numeric.hpp"
#include "io/track_csv.hpp"
#include "numerics/error.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class InclineRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("incline_render_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  /// mu 0.45, phi 20 deg, v0 1.2 m/s (stops after 0.84 s) on a plain 320x240 background.
  InclineRenderOptions small() const {
    InclineRenderOptions o;
    o.launch.mu = 0.45;
    o.launch.phi_deg = 20;
    o.launch.v0 = 1.2;
    o.size = "320x240";
    o.background = "plain";
    o.out = (dir / "run.avi").string();
    o.truth = (dir / "truth.csv").string();
    return o;
  }
  fs::path dir;
};

TEST_F(InclineRender, TruthIsTheModelBPathAtEachFrameTime) {
  const InclineRenderResult r = incline_render(small());
  const json& j = r.json;
  const double fps = j["fps"], t_launch = j["truth"]["t0"];
  EXPECT_EQ(fps, 60);
  EXPECT_GT(t_launch, -1 / fps);
  EXPECT_LE(t_launch, 0);
  // Default length: 0.3 s past the stop.
  const double t_stop = j["truth"]["t_stop"];
  EXPECT_EQ(j["frames"].get<int>(), static_cast<int>(std::ceil((t_stop + 0.3) * fps - 1e-9)));
  EXPECT_EQ(j["truth"]["regime"], "stops");
  EXPECT_TRUE(j["disc_in_view"].get<bool>());
  // The truth is incline::simulate's path at each frame's time since the launch.
  incline::Parameters p;
  p.mu = 0.45;
  p.phi = 20 * M_PI / 180;
  p.v0 = 1.2;
  const auto& pts = r.truth.tracks.at(0).points;
  ASSERT_EQ(static_cast<int>(pts.size()), j["frames"].get<int>());
  std::vector<double> times;
  for (const auto& q : pts) times.push_back(q.t - t_launch);
  const auto run = incline::simulate(p, times);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    EXPECT_DOUBLE_EQ(pts[k].t, k / fps);
    EXPECT_NEAR(pts[k].x, run.samples[k].x, 1e-12) << k;  // the same integration, another sample grid
    EXPECT_NEAR(pts[k].y, run.samples[k].y, 1e-12) << k;
  }
  EXPECT_NEAR(j["truth"]["x_stop"].get<double>(), *run.x_stop, 1e-12);
  // The CSV holds the same, and the pixels the listing's calibration maps it to.
  std::ifstream in(dir / "truth.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "track,frame,t,x,y,x_px,y_px");
  const double s = j["scale_m_per_px"], ox = j["origin_px"][0], oy = j["origin_px"][1];
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell[7];
    for (auto& c : cell) std::getline(row, c, ',');
    ASSERT_EQ(cell[0], "disc");
    const auto& q = pts.at(n++);
    EXPECT_EQ(std::stod(cell[3]), q.x);
    EXPECT_NEAR(std::stod(cell[5]), ox + q.x / s, 1e-9);
    EXPECT_NEAR(std::stod(cell[6]), oy - q.y / s, 1e-9);
  }
  EXPECT_EQ(n, pts.size());
  EXPECT_NEAR(j["disc_start_px"][0].get<double>(), ox + pts[0].x / s, 1e-9);
}

// Render -> track video (the printed calibration and start) -> incline analyze: the tracked
// centre's largest distance from the truth (px), the frames lost, and z = (fitted - truth) / sigma
// of mu, v0 and t0.
struct TrackedLaunch {
  double worst_px = 0;
  int lost = 0;
  std::map<std::string, double> z;
};

TrackedLaunch track_and_analyse(const InclineRenderOptions& o, const fs::path& dir) {
  const json film = incline_render(o).json;
  TrackVideoOptions t;
  t.input = o.out;
  t.out = (dir / "tracked.csv").string();
  t.scale = film["scale_m_per_px"].get<double>();
  t.origin = fmt::format("{},{}", film["origin_px"][0].get<double>(), film["origin_px"][1].get<double>());
  t.ellipse = {fmt::format("disc={},{}@0", film["disc_start_px"][0].get<double>(), film["disc_start_px"][1].get<double>())};
  const TrackVideoResult tracked = track_video(t);
  const auto centre = std::find_if(tracked.series.begin(), tracked.series.end(), [](const auto& x) { return x.name == "disc"; });
  TrackedLaunch out;
  if (centre == tracked.series.end()) {
    ADD_FAILURE() << "no disc track";
    return out;
  }
  std::ifstream truth_in(o.truth);
  const auto truth = io::parse_tidy_csv(std::string(std::istreambuf_iterator<char>(truth_in), {}), o.truth);
  const auto& rows = centre->rows;
  const auto& want = truth.find("disc").points;
  EXPECT_EQ(rows.size(), want.size());
  const double s = film["scale_m_per_px"];
  for (std::size_t k = 0; k < rows.size() && k < want.size(); ++k) {
    if (rows[k].lost) {
      ++out.lost;
      continue;
    }
    out.worst_px = std::max({out.worst_px, std::abs(rows[k].x - want[k].x) / s, std::abs(rows[k].y - want[k].y) / s});
  }
  std::printf("centre: %d frames lost, the others within %.3f px of the truth\n", out.lost, out.worst_px);
  InclineAnalyzeOptions a;
  a.files = {t.out};
  a.phi_deg = {*o.launch.phi_deg};
  a.no_model_a = true;
  a.input.track = "disc";
  const json r = incline_analyze(a).json;
  const json& truth_json = film["truth"];
  for (const char* k : {"mu", "v0", "t0"}) {
    out.z[k] = (r[k].get<double>() - truth_json[k].get<double>()) / r[std::string("sigma_") + k].get<double>();
    std::printf("%s: fitted %.6g +- %.2g, truth %.6g, z = %+.2f\n", k, r[k].get<double>(),
                r[std::string("sigma_") + k].get<double>(), truth_json[k].get<double>(), out.z[k]);
  }
  return out;
}

// Every frame tracked, within `worst_px` of the truth, and mu, v0, t0 within 3 sigma of the launch.
void expect_given_back(const TrackedLaunch& r, double worst_px) {
  EXPECT_EQ(r.lost, 0);
  EXPECT_LT(r.worst_px, worst_px) << "px";
  for (const auto& [k, z] : r.z) EXPECT_LT(std::abs(z), 3) << k;
}

// The tracked centre within 0.25 px of the truth in every frame (the ellipse fit's error on
// rendered film with motion blur and noise 2 is ~0.05-0.1 px, src/video/ellipse_tracker_test.cpp),
// and mu, v0, t0 within 3 of their sigmas of the launch. Observed for this seed (the default
// exposure 0.5, whose centroid offset a (s/fps)^2/24 is ~0.02 px here, docs/theory.md#rendering):
// z(mu) = -1.96, z(v0) = -1.34, z(t0) = +0.88; 3 leaves room for other platforms' codecs without
// hiding a bias of several sigma.
TEST_F(InclineRender, TrackedFilmGivesBackTheLaunch) {
  InclineRenderOptions o = small();
  o.size = "640x480";
  o.seed = 4;
  expect_given_back(track_and_analyse(o, dir), 0.25);
}

// A disc filmed in motion from its first frame: at 30 fps on texture the launch blurs the edge of
// the 25 px radius disc by ~30 px (the 0.5 exposure of its 63 px travel per frame), wider than a
// sharp edge's profiles reach. The start was refused ("not an ellipse with a clear edge", score
// 0.42) before the start fit allowed blur (docs/theory.md#ellipse-tracking, item 1); now every
// frame is tracked and the launch given back.
// Measured: the centre 2.1 px from the truth in the blurred first frame, within 0.8 px after;
// z(mu) = -0.13, z(v0) = -0.60, z(t0) = +0.80.
TEST_F(InclineRender, ADiscBlurredInItsFirstFrameIsStarted) {
  InclineRenderOptions o = small();
  o.launch.mu = 0.328;
  o.launch.phi_deg = 12.1;
  o.launch.v0 = 1.51;
  o.fps = 30;
  o.size = "640x480";
  o.background = "texture";
  o.seed = 1;
  expect_given_back(track_and_analyse(o, dir), 3);
}

TEST_F(InclineRender, BadOptionsNameTheFieldAndWriteNothing) {
  auto fails = [&](InclineRenderOptions o, const std::string& field_name) {
    try {
      incline_render(o);
      ADD_FAILURE() << "no error for " << field_name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field_name), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(o.out)) << field_name;
    EXPECT_FALSE(fs::exists(o.truth)) << field_name;
  };
  InclineRenderOptions o = small();
  o.size = "320by240";
  fails(o, "size");
  o = small();
  o.shutter = 1.5;
  fails(o, "shutter");
  o = small();
  o.launch.mu.reset();
  fails(o, "mu");
  o = small();
  o.launch.phi_deg = 95;
  fails(o, "phi_deg");
  o = small();
  o.scale = 0.01;  // a 2 cm disc of 2 px... 1 px: too small to film
  o.radius = 0.01;
  fails(o, "scale");
  o = small();
  o.out = (dir / "run.mkv").string();
  fails(o, "run.mkv");
  o = small();
  o.background = "stripes";
  fails(o, "background");
}

}  // namespace
}  // namespace tribolab::app
