#include "track/track.hpp"

#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tribolab::track {
namespace {

using ::testing::HasSubstr;

TrackSet two_tracks() {
  TrackSet s;
  s.source = "run.trk";
  s.tracks = {{"tip A", {{0, 0, 0, 0}}}, {"tip B", {{0, 0, 1, 0}}}};
  return s;
}

TEST(TrackSet, FindsByName) { EXPECT_EQ(two_tracks().find("tip B").points[0].x, 1); }

TEST(TrackSet, UnknownNameListsTheAvailableTracks) {
  try {
    two_tracks().find("ball");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("run.trk"));
    EXPECT_THAT(e.what(), HasSubstr("'ball'"));
    EXPECT_THAT(e.what(), HasSubstr("'tip A', 'tip B'"));
  }
}

TEST(FrameStep, IsTheMostFrequentFrameDifference) {
  Track t{"a", {{3, 0, 0, 0}, {5, 1, 0, 0}, {7, 2, 0, 0}, {13, 3, 0, 0}, {15, 4, 0, 0}}};
  EXPECT_EQ(frame_step(t), 2);
  EXPECT_EQ(frame_step(Track{"b", {}}), 1);
}

TEST(ValidateTrack, RejectsDisorderAndNonFiniteValues) {
  EXPECT_NO_THROW(validate_track({"a", {{0, 0, 0, 0}, {1, 0.1, 0, 0}}}, "f"));
  EXPECT_THROW(validate_track({"a", {{1, 0, 0, 0}, {1, 0.1, 0, 0}}}, "f"), InputError);
  EXPECT_THROW(validate_track({"a", {{0, 0.1, 0, 0}, {1, 0.1, 0, 0}}}, "f"), InputError);
  EXPECT_THROW(validate_track({"a", {{0, 0, NAN, 0}}}, "f"), InputError);
}

}  // namespace
}  // namespace tribolab::track
