// `track import` and `track kinematics` in the application layer (src/app/track_import.hpp,
// track_kinematics.hpp), called directly: the tracks and derivatives come back as plain vectors
// beside the JSON, the numbers match the known motion, and bad options throw the CLI's messages.
#include "app/track_kinematics.hpp"

#include "app/track_test_util.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;

TEST(TrackImport, ReturnsTheTracksBesideTheSummary) {
  const std::string dir = testing::temp_dir("import");
  testing::SpinningBody b;
  TrackImportOptions o;
  o.input.file = b.write(dir + "/body.csv");
  o.input.time_scale = 0.5;
  o.track = {"B"};
  o.out = dir + "/tidy.csv";
  const auto r = track_import(o);
  ASSERT_EQ(r.tracks.size(), 1u);
  EXPECT_EQ(r.tracks[0].name, "B");
  ASSERT_EQ(r.tracks[0].points.size(), static_cast<std::size_t>(b.frames));
  const auto truth = b.tracks().tracks[1].points;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_EQ(r.tracks[0].points[i].frame, truth[i].frame);
    EXPECT_DOUBLE_EQ(r.tracks[0].points[i].t, 0.5 * truth[i].t);  // the time scale is applied
    EXPECT_EQ(r.tracks[0].points[i].x, truth[i].x);  // shortest round-trip CSV: exact
  }
  EXPECT_EQ(r.json["track_names"], nlohmann::json::array({"B"}));
  EXPECT_EQ(r.json["tracks"]["B"]["points"], b.frames);
  EXPECT_EQ(r.json["format"], "tidy_csv");
  EXPECT_EQ(r.json["out"], o.out);
  EXPECT_TRUE(fs::exists(o.out));
}

TEST(TrackKinematics, SavgolRecoversTheParabolaOfTheCentre) {
  // Point A's x is the centre's straight line plus a rotation; take the body without spin so
  // both points fly on the parabola: a quadratic local fit is then exact.
  const std::string dir = testing::temp_dir("kin");
  testing::SpinningBody b;
  b.omega = 0;
  TrackKinematicsOptions o;
  o.input.file = b.write(dir + "/body.csv");
  o.track = "A";
  o.method = "savgol";
  o.impacts = "none";  // exact data have no noise to measure a velocity jump against
  o.out = dir + "/k.csv";
  const auto r = track_kinematics(o);
  ASSERT_EQ(r.kinematics.rows.size(), static_cast<std::size_t>(b.frames));
  for (const auto& row : r.kinematics.rows) {
    // exact quadratic data: the fit is exact to rounding (~1e-10 m/s^2 after dividing by dt^2)
    EXPECT_NEAR(row.ay, -b.g, 1e-6);
    EXPECT_NEAR(row.vx, b.vx, 1e-9);
    EXPECT_NEAR(row.vy, b.vy - b.g * row.t, 1e-9);
  }
  EXPECT_EQ(r.json["method"], "savgol");
  EXPECT_EQ(r.json["window"], 7);
  EXPECT_EQ(r.json["points"], b.frames);
  EXPECT_TRUE(r.json["impacts"].empty());
}

TEST(TrackKinematics, BadOptionsThrowTheCliMessages) {
  const std::string dir = testing::temp_dir("kin_bad");
  TrackKinematicsOptions o;
  o.input.file = testing::SpinningBody{}.write(dir + "/body.csv");
  o.track = "A";
  o.out = dir + "/never.csv";
  const auto message = [&](auto change) {
    auto c = o;
    change(c);
    try {
      track_kinematics(c);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([](auto& c) { c.method = "spline"; }), "method: must be tracker or savgol, got 'spline'");
  EXPECT_EQ(message([](auto& c) { c.window = 9; }), "window/order: apply to method savgol only");
  EXPECT_EQ(message([](auto& c) { c.impacts = "maybe"; }), "impacts: must be auto or none, got 'maybe'");
  EXPECT_NE(message([](auto& c) { c.track.clear(); }).find("choose one with track"), std::string::npos);
  EXPECT_NE(message([](auto& c) { c.track = "C"; }).find("available tracks: 'A', 'B'"), std::string::npos);
  EXPECT_NE(message([](auto& c) { c.out.clear(); }).find("out"), std::string::npos);
  EXPECT_FALSE(fs::exists(o.out));
}

}  // namespace
}  // namespace tribolab::app
