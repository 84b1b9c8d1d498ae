#include "io/tracker_export.hpp"

#include "io/track_import.hpp"
#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;
using track::Track;

/// Two tracks with awkward numbers (thirds, tiny and large magnitudes) and a gap.
std::vector<Track> tracks() {
  Track a{"A", {}}, b{"B", {}};
  for (int f = 0; f < 15; ++f) {
    const double t = f / 3.0 / 80;
    if (f != 6) a.points.push_back({f, t, 0.1 * f / 3.0, -1.234567890123e-5 * f});
    if (f >= 2) b.points.push_back({f, t, 123.456 + f / 7.0, std::sqrt(2.0) * f});
  }
  return {a, b};
}

void expect_exact(const std::vector<Track>& want, const track::TrackSet& got) {
  ASSERT_EQ(got.tracks.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got.tracks[i].name, want[i].name);
    ASSERT_EQ(got.tracks[i].points.size(), want[i].points.size()) << want[i].name;
    for (std::size_t j = 0; j < want[i].points.size(); ++j) {
      const auto& w = want[i].points[j];
      const auto& g = got.tracks[i].points[j];
      EXPECT_EQ(g.frame, w.frame);
      EXPECT_EQ(g.t, w.t);  // shortest round-trip text: bit-exact
      EXPECT_EQ(g.x, w.x);
      EXPECT_EQ(g.y, w.y);
    }
  }
}

TEST(TrackerExport, RoundTripEveryDelimiterAndDecimalSeparator) {
  for (char d : {'\t', ',', ';', ' '}) {
    for (bool comma : {false, true}) {
      if (comma && d == ',') continue;
      for (bool frame_column : {false, true}) {
        ExportWriteOptions o;
        o.delimiter = d;
        o.decimal_comma = comma;
        o.frame_column = frame_column;
        o.extra_columns = true;
        const std::string text = write_export_text(tracks(), o);
        SCOPED_TRACE(text.substr(0, 200));
        expect_exact(tracks(), parse_export_text(text, "e.txt", "unused"));
      }
    }
  }
}

TEST(TrackerExport, SingleTrackLayouts) {
  const std::vector<Track> one{tracks()[0]};
  for (bool tracker6 : {true, false}) {
    for (bool name_row : {true, false}) {
      ExportWriteOptions o;
      o.tracker6 = tracker6;
      o.name_row = name_row;
      const auto set = parse_export_text(write_export_text(one, o), "A.txt", "A");
      expect_exact(one, set);
    }
  }
  // Tracker 5 replaced spaces in the name by underscores
  std::vector<Track> spaced = one;
  spaced[0].name = "mass A";
  ExportWriteOptions legacy;
  legacy.tracker6 = false;
  EXPECT_EQ(parse_export_text(write_export_text(spaced, legacy), "f", "d").tracks[0].name, "mass_A");
}

TEST(TrackerExport, StepSizeTwoRowsWithOnlyTimeAreSkipped) {
  // Tracker writes every frame; with step size 2 the odd frames hold only t
  const std::string text =
      "\tball\t\t\n"
      "t\tx\ty\t\n"
      "0,0\t1,0\t2,0\n"
      "0,01\t\t\n"
      "0,02\t1,5\t2,5\n"
      "0,03\t\t\n"
      "0,04\t2,0E0\t3,0E0\n";
  const auto set = parse_export_text(text, "s.txt", "x");
  ASSERT_EQ(set.tracks.size(), 1u);
  EXPECT_EQ(set.tracks[0].name, "ball");
  ASSERT_EQ(set.tracks[0].points.size(), 3u);
  EXPECT_EQ(set.tracks[0].points[2].frame, 4);
  EXPECT_EQ(set.tracks[0].points[2].x, 2.0);
  EXPECT_EQ(set.tracks[0].points[1].t, 0.02);
}

TEST(TrackerExport, UnitsInTheHeader) {
  ExportWriteOptions o;
  o.length_unit = "cm";
  const auto set = parse_tracks(write_export_text(tracks(), o), "cm.txt");
  EXPECT_EQ(set.file_length_unit, "cm");
  EXPECT_DOUBLE_EQ(set.tracks[1].points[0].x, tracks()[1].points[0].x * 0.01);
  const auto ms = parse_export_text("t (ms),x,y\n10,1,2\n20,2,3\n", "ms.csv", "p");
  EXPECT_DOUBLE_EQ(ms.tracks[0].points[1].t, 0.02);
}

TEST(TrackerExport, PlainCsvTable) {
  const auto set = parse_tracks("t,x,y\n0,0,1\n0.1,0.5,1.2\n", "/data/roll.csv");
  ASSERT_EQ(set.tracks.size(), 1u);
  EXPECT_EQ(set.tracks[0].name, "roll");
  EXPECT_EQ(set.tracks[0].points[1].frame, 1);
}

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_tracks(text, "bad.txt");
    FAIL() << "no error for " << fragment;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(fragment));
  }
}

TEST(TrackerExport, ClearErrorsWithFileAndLine) {
  expect_error("t,x,y\n0,1,2\n0.1,abc,3\n", "bad.txt:3");
  expect_error("t,x,y\n0,1,2\n0.1,,3\n", "bad.txt:3: track 'bad' has y but no x");
  expect_error("t,x,y\n0,1,2\n0,2,3\n", "bad.txt:3");  // time does not increase
  expect_error("name\nfoo,bar\n1,2\n", "bad.txt:1");    // no header
  expect_error("#multi:\n\tA\t\tB\t\nt\tx\ty\tx\tv\t\n", "track 'B' has no 'y' column");
  expect_error("t,x,y\n0,1,2,3\n", "bad.txt:2: 4 cells");
  expect_error("t,x (cm),y (mm)\n0,1,2\n", "conflicting length units");
  expect_error("t,x (furlong),y (furlong)\n0,1,2\n", "unknown length unit");
  expect_error("", "empty");
  expect_error("#multi:\n", "no data");
}


// Regression (issue 26): a non-UTF-8 track name and a 1e308 value: refused with file:line.
TEST(TrackerExport, InvalidNameOrValueIsRefusedWithItsLine) {
  auto error = [](const std::string& text) {
    try {
      parse_tracks(text, "e.txt");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(error("A\xff\t\t\nt\tx\ty\n0\t1\t2\n0.1\t1\t3\n"), HasSubstr("e.txt:1: the track name in column 1 is not valid UTF-8"));
  EXPECT_THAT(error("A\t\t\nt\tx\ty\n0\t1\t2\n0.1\t1e308\t3\n"), HasSubstr("e.txt:4: x of track 'A' = 1e+308 is beyond"));
  EXPECT_THAT(error("A\t\t\tA\t\t\nt\tx\ty\tt\tx\ty\n0\t1\t2\t0\t1\t2\n"), HasSubstr("two tracks are named 'A'"));
}

}  // namespace
}  // namespace tribolab::io
