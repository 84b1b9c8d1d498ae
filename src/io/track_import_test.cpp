#include "io/track_import.hpp"

#include "io/tracker_export.hpp"
#include "io/tracker_trk.hpp"
#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;

std::string temp(const std::string& name, const std::string& content) {
  const auto p = std::filesystem::temp_directory_path() / ("tribolab_import_" + name);
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

std::vector<track::Track> two() {
  return {{"A", {{0, 0, 1, 2}, {1, 0.5, 2, 3}}}, {"B", {{0, 0, 5, 6}, {1, 0.5, 7, 8}}}};
}

TEST(ReadTracks, DetectsEveryFormatByExtensionAndContent) {
  TrkWriteSpec s;
  s.frame_duration_ms = 500;
  const std::string trk = write_trk(two(), s);
  EXPECT_EQ(read_tracks(temp("a.trk", trk)).format, "trk");
  EXPECT_EQ(read_tracks(temp("a.xml", trk)).format, "trk");
  EXPECT_EQ(read_tracks(temp("a.trz", write_trz(trk, "a.trk"))).format, "trz");
  EXPECT_EQ(read_tracks(temp("a.dat", write_trz(trk, "a.trk"))).format, "trz");
  EXPECT_EQ(read_tracks(temp("a.txt", write_export_text(two()))).format, "export");
  EXPECT_EQ(read_tracks(temp("a.csv", "track,frame,t,x,y\nA,0,0,1,2\n")).format, "tidy_csv");
}

TEST(ReadTracks, TimeScaleSelectionAndUnitOverride) {
  ImportOptions o;
  o.time_scale = 0.125;  // 240 fps recorded, 30 fps played
  o.tracks = {"B"};
  o.length_unit = "mm";
  const auto set = read_tracks(temp("b.txt", write_export_text(two())), o);
  ASSERT_EQ(set.tracks.size(), 1u);
  EXPECT_EQ(set.tracks[0].name, "B");
  EXPECT_DOUBLE_EQ(set.tracks[0].points[1].t, 0.0625);
  EXPECT_DOUBLE_EQ(set.tracks[0].points[1].x, 0.007);
  EXPECT_EQ(set.time_scale, 0.125);
}

TEST(ReadTracks, ErrorsAreClear) {
  const auto err = [](const std::string& path, ImportOptions o = {}) {
    try {
      read_tracks(path, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(err("/nonexistent/run.trk"), HasSubstr("/nonexistent/run.trk: cannot open"));
  EXPECT_THAT(err(std::filesystem::temp_directory_path().string()), HasSubstr("directory"));
  ImportOptions bad;
  bad.time_scale = -1;
  EXPECT_THAT(err(temp("c.txt", write_export_text(two())), bad), HasSubstr("time_scale"));
  ImportOptions unknown;
  unknown.tracks = {"C"};
  EXPECT_THAT(err(temp("d.txt", write_export_text(two())), unknown),
              HasSubstr("available tracks: 'A', 'B'"));
  ImportOptions unit;
  unit.length_unit = "parsec";
  EXPECT_THAT(err(temp("e.txt", write_export_text(two())), unit), HasSubstr("length_unit"));
  EXPECT_THAT(err(temp("f.txt", "\xef\xbb\xbf   \n")), HasSubstr("empty"));
  EXPECT_THAT(err(temp("g.txt", "t,x,y\n")), HasSubstr("no tracked points"));
}

TEST(MetresPerUnit, KnownUnits) {
  EXPECT_EQ(metres_per_unit("cm", ""), 0.01);
  EXPECT_EQ(metres_per_unit("MM", ""), 0.001);
  EXPECT_EQ(metres_per_unit("in", ""), 0.0254);
  EXPECT_THROW(metres_per_unit("cubit", "x"), InputError);
}

}  // namespace
}  // namespace tribolab::io
