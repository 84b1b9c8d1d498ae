#include "io/track_csv.hpp"

#include "io/track_import.hpp"
#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;

track::TrackSet sample() {
  track::TrackSet s;
  s.source = "s";
  s.tracks = {{"tip A", {{0, 0, 0.1, 1.0 / 3}, {2, 0.1, 0.2, 2.0 / 3}}},
              {"tip, B", {{1, 0.05, -1e-7, 5}}}};
  return s;
}

TEST(TidyCsv, RoundTripIsExact) {
  std::ostringstream out;
  write_tidy_csv(out, sample());
  const auto got = parse_tracks(out.str(), "tidy.csv");
  ASSERT_EQ(got.tracks.size(), 2u);
  EXPECT_EQ(got.tracks[1].name, "tip, B");
  EXPECT_EQ(got.tracks[0].points[1].y, 2.0 / 3);
  EXPECT_EQ(got.tracks[1].points[0].x, -1e-7);
  EXPECT_EQ(got.format, "tidy_csv");
}

TEST(TidyCsv, SemicolonDecimalCommaUnitsAndAnyRowOrder) {
  const auto got = parse_tracks("track;frame;t;x (cm);y (cm)\nb;2;0,2;1,5;2\na;1;0,1;1;1\nb;1;0,1;1;1\n", "s.csv");
  ASSERT_EQ(got.tracks.size(), 2u);
  EXPECT_EQ(got.tracks[0].name, "b");
  EXPECT_EQ(got.tracks[0].points[0].frame, 1);
  EXPECT_DOUBLE_EQ(got.tracks[0].points[1].x, 0.015);
}

TEST(TidyCsv, ErrorsNameTheLine) {
  const auto err = [](const std::string& text) {
    try {
      parse_tracks(text, "t.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(err("track,frame,t,x,y\na,1,0,0,0\na,1,0.1,0,0\n"), HasSubstr("t.csv:3: track 'a': frame 1 appears twice"));
  EXPECT_THAT(err("track,frame,t,x,y\na,1.5,0,0,0\n"), HasSubstr("t.csv:2"));
  EXPECT_THAT(err("track,frame,t,x\na,1,0,0\n"), HasSubstr("missing column 'y'"));
  EXPECT_THAT(err("track,frame,t,x,y\na,1,0\n"), HasSubstr("t.csv:2: missing value"));
}

TEST(TidyCsv, LostRowsOfTrackVideoAreLeftOutWithOneWarning) {
  // `track video` writes the frames where it lost its object with empty positions, score 0
  const auto got = parse_tracks(
      "track,frame,t,x,y,x_px,y_px,score\n"
      "ball,0,0,0.1,0.2,10,20,0.99\n"
      "ball,1,0.01,,,,,0\n"
      "ball,2,0.02,,,,,0\n"
      "ball,3,0.03,0.13,0.21,13,19,0.97\n",
      "video.csv");
  ASSERT_EQ(got.tracks.size(), 1u);
  ASSERT_EQ(got.tracks[0].points.size(), 2u);
  EXPECT_EQ(got.tracks[0].points[1].frame, 3);
  EXPECT_EQ(got.tracks[0].points[1].x, 0.13);
  ASSERT_EQ(got.warnings.size(), 1u);
  EXPECT_THAT(got.warnings[0], HasSubstr("2 row(s) with empty x and y"));
  // one position without the other is still an error
  EXPECT_THROW(parse_tracks("track,frame,t,x,y\na,1,0,,3\n", "t.csv"), InputError);
}

TEST(KinematicsCsv, EmptyCellsWhereUndefined) {
  track::Kinematics k;
  track::KinematicsRow r;
  r.t = 0.5;
  r.x = 1;
  r.y = 2;
  r.vx = 3;
  r.vy = NAN;
  r.ax = r.ay = NAN;
  r.sigma_vx = 0.1;
  r.sigma_vy = r.sigma_ax = r.sigma_ay = NAN;
  k.rows = {r};
  std::ostringstream a, b;
  write_kinematics_csv(a, k, false);
  EXPECT_EQ(a.str(), "t,x,y,vx,vy,ax,ay\n0.5,1,2,3,,,\n");
  write_kinematics_csv(b, k, true);
  EXPECT_EQ(b.str(), "t,x,y,vx,vy,ax,ay,sigma_vx,sigma_vy,sigma_ax,sigma_ay\n0.5,1,2,3,,,,0.1,,,\n");
}


/// The InputError's message for `text` read as s.csv ("" when it is accepted).
std::string csv_error(const std::string& text) {
  try {
    parse_tracks(text, "s.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Regression (issue 26): "...,0,5,..." from a decimal comma was read as x = 0, y = 5.
TEST(TidyCsv, RowWithACellTooManyIsRefusedWithItsLine) {
  EXPECT_THAT(csv_error("track,frame,t,x,y\na,0,0,1,2\na,1,0.1,0,5,3\n"), HasSubstr("s.csv:3: 6 cells but the header has 5 columns"));
  EXPECT_EQ(csv_error("track,frame,t,x,y,\na,0,0,1,2,\na,1,0.1,1,3\n"), "");  // trailing delimiters are no cells
}

// Regression (issue 26): a NUL in a track name lost the point; invalid UTF-8 stopped the JSON writer.
TEST(TidyCsv, TrackNameWithNulOrInvalidUtf8IsRefusedWithItsLine) {
  EXPECT_THAT(csv_error(std::string("track,frame,t,x,y\na,0,0,1,2\na") + '\0' + "b,1,0.1,1,3\n"),
              HasSubstr("s.csv:3: the track name contains a control character (byte 0x00 at character 2)"));
  EXPECT_THAT(csv_error("track,frame,t,x,y\nb\xff,0,0,1,2\n"), HasSubstr("s.csv:2: the track name is not valid UTF-8 (byte 0xff"));
  EXPECT_EQ(csv_error("track,frame,t,x,y\n\xce\xbc-tip,0,0,1,2\n"), "");  // UTF-8 is welcome
}

// Regression (issue 26): one 1e308 in a good run gave mu 0.3996 (0.3001 without it), sigma null.
TEST(TidyCsv, ValueNoRunHasIsRefusedWithItsLine) {
  EXPECT_THAT(csv_error("track,frame,t,x,y\na,0,0,1,2\na,1,0.1,1e308,3\n"), HasSubstr("s.csv:3: x = 1e+308 is beyond"));
  EXPECT_THAT(csv_error("track,frame,t,x,y\na,0,0,1,2\na,1,1e9,1,3\n"), HasSubstr("s.csv:3: t = 1000000000 is beyond +-100000000"));
  EXPECT_EQ(csv_error("track,frame,t,x (mm),y (mm)\na,0,0,-999999,2\n"), "");  // a kilometre in mm: accepted
}

}  // namespace
}  // namespace tribolab::io
