#include "io/tracker_trk.hpp"

#include "io/track_import.hpp"
#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;
using track::Track;

/// Two point masses in world metres; frames on a clip starting at 3 with step 2.
std::vector<Track> world_tracks() {
  Track a{"mass A", {}}, b{"tip <B> & co", {}};
  for (int k = 0; k < 12; ++k) {
    const int f = 3 + 2 * k;
    a.points.push_back({f, 0, 0.1 + 0.05 * k, 1.0 + 0.2 * k - 0.03 * k * k});
    if (k % 3 != 1) b.points.push_back({f, 0, -0.4 + 0.01 * k, 0.25 * std::sin(k)});
  }
  return {a, b};
}

TrkWriteSpec spec() {
  TrkWriteSpec s;
  s.coords = {{0, 320.5, 241.25, 30.0, 400.0, 390.0}};
  s.start_frame = 3;
  s.step_size = 2;
  s.frame_duration_ms = 1000.0 / 240;
  s.start_time_ms = 12.5;
  return s;
}

void expect_same(const std::vector<Track>& want, const track::TrackSet& got, double scale = 1) {
  ASSERT_EQ(got.tracks.size(), want.size());
  const TrkWriteSpec s = spec();
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got.tracks[i].name, want[i].name);
    ASSERT_EQ(got.tracks[i].points.size(), want[i].points.size());
    for (std::size_t j = 0; j < want[i].points.size(); ++j) {
      const auto& w = want[i].points[j];
      const auto& g = got.tracks[i].points[j];
      EXPECT_EQ(g.frame, w.frame);
      // world -> pixels -> world through a rotation and two scales: a few ulps of ~400 px
      EXPECT_NEAR(g.x, w.x * scale, 1e-13);
      EXPECT_NEAR(g.y, w.y * scale, 1e-13);
      const double t = (s.start_time_ms + (w.frame - s.start_frame) * s.frame_duration_ms) / 1000;
      EXPECT_DOUBLE_EQ(g.t, t);
    }
  }
}

TEST(TrackerTrk, RoundTripThroughRotatedScaledCoordinates) {
  const auto tracks = world_tracks();
  const std::string xml = write_trk(tracks, spec());
  expect_same(tracks, parse_trk(xml, "run.trk"));
}

TEST(TrackerTrk, ImageToWorldFollowsTrackersConvention) {
  // angle 90 deg: world x points up the image (-py), world y points left (-px)
  const TrkCoordFrame c{0, 100, 200, 90, 10, 10};
  const auto [x, y] = image_to_world(c, 100, 190);  // 10 px above the origin
  EXPECT_NEAR(x, 1, 1e-15);
  EXPECT_NEAR(y, 0, 1e-15);
  const auto [x2, y2] = image_to_world(c, 90, 200);  // 10 px left of the origin
  EXPECT_NEAR(x2, 0, 1e-15);
  EXPECT_NEAR(y2, 1, 1e-15);
}

TEST(TrackerTrk, KeyFramesHoldUntilTheNext) {
  TrkWriteSpec s = spec();
  s.coords = {{0, 320, 240, 0, 400, 400}, {11, 300, 260, 10, 500, 480}, {20, 310, 250, -5, 450, 450}};
  const auto tracks = world_tracks();
  const std::string xml = write_trk(tracks, s);
  const auto set = parse_trk(xml, "k.trk");
  expect_same(tracks, set);
  // the same world points written with the first key frame everywhere read back differently
  TrkWriteSpec one = s;
  one.coords.resize(1);
  const auto moved = parse_trk(write_trk(tracks, one), "k.trk");
  EXPECT_NEAR(moved.tracks[0].points[3].x, tracks[0].points[3].x, 1e-13);  // frame 9 < 11
}

TEST(TrackerTrk, ZipRoundTripAndEntryChoice) {
  const auto tracks = world_tracks();
  const std::string trz = write_trz(write_trk(tracks, spec()), "run_tab.trk");
  expect_same(tracks, read_trz(trz, "run.trz"));
  try {
    read_trz(trz, "run.trz", "other.trk");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'run_tab.trk'"));
  }
  const std::string no_trk = write_trz("hello", "notes.txt");
  EXPECT_THROW(read_trz(no_trk, "x.trz"), InputError);
  EXPECT_THROW(read_trz("PK\x03\x04garbage", "x.trz"), InputError);
}

TEST(TrackerTrk, ProjectKeepsItsVideoClipAndMarksInPixels) {
  TrkWriteSpec s = spec();
  s.video_path = "videos/throw & catch.mp4";
  s.video_frame_count = 240;
  s.step_count = 12;
  const auto tracks = world_tracks();
  const TrkProject p = parse_trk_project(write_trk(tracks, s), "p.trk");
  EXPECT_EQ(p.video_path, "videos/throw & catch.mp4");
  EXPECT_EQ(p.video_frame_count, 240);
  EXPECT_EQ(p.clip.start_frame, 3);
  EXPECT_EQ(p.clip.step_size, 2);
  EXPECT_EQ(p.clip.step_count, 12);
  EXPECT_DOUBLE_EQ(p.clip.frame_duration_ms, 1000.0 / 240);
  EXPECT_EQ(p.length_unit, "m");
  ASSERT_EQ(p.coords.size(), 1u);
  ASSERT_EQ(p.marks_px.size(), 2u);
  const auto& m = p.marks_px[0].points[4];
  const auto [px, py] = world_to_image(s.coords[0], tracks[0].points[4].x, tracks[0].points[4].y);
  EXPECT_EQ(m.frame, tracks[0].points[4].frame);
  EXPECT_NEAR(m.x, px, 1e-10);  // printed shortest round-trip: the same double
  EXPECT_NEAR(m.y, py, 1e-10);
  EXPECT_DOUBLE_EQ(m.t, p.clip.t(m.frame));
  // without a video the project says so with an empty path
  EXPECT_TRUE(parse_trk_project(write_trk(tracks, spec()), "n.trk").video_path.empty());
  // the frame count is kept without a video path too (found by fuzz_trk_roundtrip)
  TrkWriteSpec counted = spec();
  counted.video_frame_count = 50;
  const TrkProject c = parse_trk_project(write_trk(tracks, counted), "c.trk");
  EXPECT_TRUE(c.video_path.empty());
  EXPECT_EQ(c.video_frame_count, 50);
}

TEST(TrackerTrk, TrzOnDiskIsReadAndItsEntriesExtracted) {
  const auto dir = std::filesystem::temp_directory_path() / ("tribolab_trz_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string zip = (dir / "p.trz").string();
  const std::string video(100000, 'v');
  {
    std::ofstream out(zip, std::ios::binary);
    out << write_trz(write_trk(world_tracks(), spec()), "sub/p.trk", {{"sub/videos/a.mp4", video}});
  }
  const TrzContents z = read_trz_file(zip);
  EXPECT_EQ(z.trk_entry, "sub/p.trk");
  EXPECT_EQ(z.entries.size(), 2u);
  EXPECT_EQ(z.project.source, zip + ":sub/p.trk");
  const std::string out = (dir / "a.mp4").string();
  extract_zip_entry(zip, "sub/videos/a.mp4", out);
  std::ifstream in(out, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), video);
  EXPECT_THROW(extract_zip_entry(zip, "missing.mp4", out), InputError);
  EXPECT_THROW(extract_zip_entry(zip, "sub/videos/a.mp4", out, 1000), InputError);  // over the cap
  EXPECT_THROW(read_trz_file((dir / "none.trz").string()), InputError);
  std::filesystem::remove_all(dir);
}

TEST(TrackerTrk, AVideoEntryInflatingLikeAZipBombIsRefusedEarly) {
  // Issue 26: a 6 MB .trz wrote 6 GB of "video" to $TMPDIR (the only cap was 16 GB). A video
  // deflates by ~1 %; 24 MiB of zeros deflate ~1000x, past the bound of 16 MiB + 100x the
  // compressed bytes (~24 KB: 16 + 2.3 MiB), so extraction stops after ~18.3 MiB written.
  const auto dir = std::filesystem::temp_directory_path() / ("tribolab_bomb_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string zip = (dir / "bomb.trz").string();
  {
    std::ofstream out(zip, std::ios::binary);
    out << write_trz(write_trk(world_tracks(), spec()), "p.trk", {{"v.mp4", std::string(24u << 20, '\0')}});
  }
  ASSERT_LT(std::filesystem::file_size(zip), 1u << 20);
  const std::string out = (dir / "v.mp4").string();
  try {
    extract_zip_entry(zip, "v.mp4", out);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(zip + ":v.mp4: entry too large (over 18 MB, 100 times its "),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("compressed bytes: a video inflates ~1x; a zip bomb?)"),
              std::string::npos) << e.what();
  }
  EXPECT_LT(std::filesystem::file_size(out), 19u << 20);
  std::filesystem::remove_all(dir);
}

TEST(TrackerTrk, LengthUnitCentimetresIsConvertedToMetres) {
  TrkWriteSpec s = spec();
  s.length_unit = "cm";
  const auto tracks = world_tracks();
  const auto set = parse_tracks(write_trk(tracks, s), "run.trk");
  EXPECT_EQ(set.file_length_unit, "cm");
  expect_same(tracks, set, 0.01);
}

TEST(TrackerTrk, PointsOutsideTheClipStepsAreLeftOutWithAWarning) {
  auto tracks = world_tracks();
  tracks[0].points.push_back({4, 0, 0, 0});    // between steps (start 3, step 2)
  tracks[0].points.push_back({1, 0, 0, 0});    // before the start frame
  std::sort(tracks[0].points.begin(), tracks[0].points.end(),
            [](auto& p, auto& q) { return p.frame < q.frame; });
  const auto set = parse_trk(write_trk(tracks, spec()), "c.trk");
  EXPECT_EQ(set.tracks[0].points.size(), 12u);
  ASSERT_EQ(set.warnings.size(), 1u);
  EXPECT_THAT(set.warnings[0], HasSubstr("2 point(s)"));
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

TEST(TrackerTrk, DecimalCommaInNumbersIsAccepted) {
  const auto tracks = world_tracks();
  std::string xml = write_trk(tracks, spec());
  xml = replace(xml, "<property name=\"xscale\" type=\"double\">400.0<",
                "<property name=\"xscale\" type=\"double\">400,0<");
  expect_same(tracks, parse_trk(xml, "comma.trk"));
}

void expect_trk_error(const std::string& xml, const std::string& fragment) {
  try {
    parse_trk(xml, "bad.trk");
    FAIL() << "no error for " << fragment;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bad.trk"));
    EXPECT_THAT(e.what(), HasSubstr(fragment));
  }
}

TEST(TrackerTrk, ClearErrorsNamingTheElement) {
  const std::string xml = write_trk(world_tracks(), spec());
  expect_trk_error(xml.substr(0, xml.size() / 2), "bad.trk:");  // truncated: file:line
  expect_trk_error(replace(xml, "name=\"delta_t\"", "name=\"dt\""), "clipcontrol/delta_t");
  expect_trk_error(replace(xml, "name=\"xscale\"", "name=\"xs\""), "coords/framedata/[0]/xscale");
  expect_trk_error(replace(xml, ">400.0<", ">four hundred<"), "xscale");
  expect_trk_error(replace(xml, ">400.0<", ">-400.0<"), "positive");
  expect_trk_error(replace(xml, "name=\"[3]\"", "name=\"[-3]\""), "[n]");
  expect_trk_error(replace(xml, "name=\"x\" type", "name=\"q\" type"), "(mass A)/framedata/[3]/x");
  expect_trk_error("<object class=\"Something\"/>", "TrackerPanel");
  expect_trk_error("<?xml version=\"1.0\"?><object class=\"x.TrackerPanel\"></object>", "coords");
}

TEST(TrackerTrk, NoPointMassIsAnError) {
  std::string xml = write_trk(world_tracks(), spec());
  while (xml.find(".PointMass\"") != std::string::npos) xml = replace(xml, ".PointMass\"", ".Protractor\"");
  expect_trk_error(xml, "no PointMass");
}

TEST(TrackerTrk, FixedCoordinateSystemTakesTheLastKeyEverywhere) {
  TrkWriteSpec s = spec();
  s.coords = {{0, 320, 240, 0, 400, 400}, {11, 300, 260, 10, 500, 480}};
  std::string xml = write_trk(world_tracks(), s);
  xml = replace(xml, "\"fixedscale\" type=\"boolean\">false", "\"fixedscale\" type=\"boolean\">true");
  const TrkProject p = parse_trk_project(xml, "f.trk");
  ASSERT_EQ(p.coords.size(), 2u);
  EXPECT_EQ(p.coords[0].xscale, 500);  // the scale is fixed: the last saved value holds
  EXPECT_EQ(p.coords[0].origin_x, 320);  // the origin is not
  EXPECT_EQ(coord_at(p.coords, 5).frame, 0);
  EXPECT_EQ(coord_at(p.coords, 11).frame, 11);
}


// Regression (issue 26): a frame marked twice in one track kept the last mark silently.
TEST(TrackerTrk, FrameMarkedTwiceInATrackIsRefused) {
  const std::string xml = write_trk(world_tracks(), spec());
  expect_trk_error(replace(xml, "name=\"[5]\"", "name=\"[3]\""), "(mass A)/framedata/[3]: frame 3 is marked twice");
}

// Regression (issue 26): "NaN" where a number is required was called a "missing element".
TEST(TrackerTrk, NaNWhereANumberIsRequiredIsCalledNaN) {
  const std::string xml = write_trk(world_tracks(), spec());
  expect_trk_error(replace(xml, ">400.0<", ">NaN<"), "xscale: NaN where a number is required");
}

// Regression (issue 26): a non-UTF-8 name ended in "[json.exception.type_error.316]" without a file.
TEST(TrackerTrk, TrackNameOfInvalidUtf8IsRefusedWithItsElement) {
  const std::string xml = write_trk(world_tracks(), spec());
  expect_trk_error(replace(xml, ">mass A<", ">mass \xe9<"), "/name: the track name is not valid UTF-8 (byte 0xe9");
}

TEST(TrackerTrk, MarkBeyondAMillionPixelsIsRefused) {
  const std::string xml = write_trk(world_tracks(), spec());
  const std::string mark = "name=\"x\" type=\"double\">";
  const auto x = xml.find(mark);
  ASSERT_NE(x, std::string::npos);
  const auto begin = x + mark.size(), end = xml.find('<', begin);
  std::string bad = xml;
  bad.replace(begin, end - begin, "1e308");
  expect_trk_error(bad, "x (px) = 1e+308 is beyond");
}

// Found by fuzz_trk_roundtrip in CI: 3e27 px per unit on one axis and 31 on the other made
// the writer put a mark at 1e11 px, which its own reader then refused.
TEST(TrackerTrk, TheWriterRefusesAMarkItsReaderWouldRefuse) {
  TrkWriteSpec s = spec();
  const std::vector<Track> far{{"far", {{3, 0, 3000.0, 0.5}}}};  // at 400 px/m, 30 deg: x = 1.04e6 px
  try {
    write_trk(far, s);
    FAIL() << "a mark at 1.04e6 px was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("track 'far' frame 3: the position maps to pixel"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("beyond +-1000000 px"), std::string::npos) << e.what();
  }
  const std::vector<Track> near{{"near", {{3, 0, 2000.0, 0.5}}}};  // x = 6.9e5 px: written, read
  EXPECT_EQ(parse_trk_project(write_trk(near, s), "n.trk").marks_px.at(0).points.size(), 1u);
}

// Regression (issue 26): two tracks of one name: --track picked the first, silently.
TEST(TrackImport, TwoTracksOfOneNameAreRefused) {
  std::vector<Track> tracks = world_tracks();
  tracks[1].name = tracks[0].name;
  try {
    parse_tracks(write_trk(tracks, spec()), "twins.trk");
    FAIL() << "two tracks named 'mass A' accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("twins.trk: two tracks are named 'mass A' (tracks 1 and 2)"));
  }
}

}  // namespace
}  // namespace tribolab::io
