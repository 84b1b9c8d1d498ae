// Tracking on real film (issue 24, docs/benchmarks.md#tracking-on-real-film): each real Tracker
// project with human marks (../shared/data/tracker, not in git) is tracked from the first
// human mark of its track, and the result is held against the other marks, as
// tools/track_eval.py reports them.
#include "numerics/error.hpp"
#include "video/track_video.hpp"

#include "video/test_videos.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tribolab::video {
namespace {

struct RealTrack {
  const char* file;
  const char* track;
  /// Frames allowed farther than 10 px from the human's mark with a position (a confident
  /// wrong answer): 0, but for one measured frame of jmoljana (below).
  int max_confidently_wrong = 0;
};

/// Largest share of marked frames a user may have to correct (no position, or farther than
/// 4 px per 640 px of width from the mark): the goal, 5 %. Measured 0 % on every
/// project tracked (docs/benchmarks.md#tracking-on-real-film); on BallToss (10 marks) and
/// uniform-motion-ball-slow (18) a single frame to correct already exceeds it.
constexpr double kMaxCorrectShare = 0.05;

void check(const RealTrack& r) {
  const std::string path = testing::tracker_project_path(r.file);
  if (path.empty()) GTEST_SKIP() << "../shared/data/tracker/" << r.file << " not found";
  TrackVideoOptions o;
  Target t;
  t.name = r.track;
  t.from_track = r.track;
  o.targets.push_back(t);
  o.thumbnails = 0;
  // FILM_BEFORE=1: the frame tracker, for the "before" table of docs/benchmarks.md.
  if (std::getenv("FILM_BEFORE")) o.offline_points = false;
  const TrackVideoResult res = track_video(path, o);
  ASSERT_EQ(res.series.size(), 1u);
  ASSERT_TRUE(res.series[0].vs_human.has_value());
  const HumanComparison& h = *res.series[0].vs_human;
  const double share = h.marks > 0 ? double(h.to_correct) / h.marks : 1.0;
  std::printf("%s %s: %d marks, %d tracked, median %.2f px, p90 %.2f px, max %.2f px, to correct %d (%.1f %%), confidently wrong %d\n",
              r.file, r.track, h.marks, h.frames, h.median_px, h.p90_px, h.max_px, h.to_correct, 100 * share,
              h.confidently_wrong);
  std::printf("  %dx%d, %d frames\n", res.input.info.width, res.input.info.height, res.frames);
  for (const std::string& w : res.warnings) std::printf("  warning: %s\n", plain_fields(w).c_str());
  ASSERT_GT(h.marks, 0);
  EXPECT_LE(h.confidently_wrong, r.max_confidently_wrong);  // frames > 10 px from the human's mark with a score
  EXPECT_LE(share, kMaxCorrectShare);
  // A track that a user need not correct is not told that it "has followed something else"
  // (jmoljana, 3.7 px median from marks that lie on a 2.8 px grid, was, by a fixed 3 px bar).
  if (share <= kMaxCorrectShare) {
    for (const std::string& w : res.warnings) EXPECT_EQ(w.find("project's own marks"), std::string::npos) << w;
  }
}

TEST(RealFilm, BallTossIsFollowedLikeTheHuman) { check({"BallToss.trz", "ball"}); }

TEST(RealFilm, SmallBallRollingOnARailIsFollowed) {
  // mass A: a ball of ~11 px on a textured rail, lost from frame 1 by the frame tracker.
  check({"uniform-motion-ball-slow.trz", "mass A"});
}

TEST(RealFilm, JmoljanaIsFollowed) {
  // A phone's 1920x1080 H.264, 150 frames: 1.5 s here, 2.8 s under ASan (its 51 px ball is
  // searched at quarter resolution; docs/benchmarks.md#tracking-at-1080p).
  // One frame (77) lies 11.7 px from the human's mark (the frame tracker: 11.6 px), inside the
  // 12 px a user corrects at this width but over the 10 px bar: allowed here so that a second
  // such frame fails. There the human's mark is off, not the track: it jumps 7 px from the
  // mean of the human's neighbouring marks while the track (correlation 0.999) stays within
  // 0.5 px of its own (docs/benchmarks.md#tracking-on-real-film).
  check({"jmoljana.trz", "mass A", 1});
}

// masa A: a toy car with little texture (refused by the frame tracker) in a loop, filmed as
// numbered JPEG images inside the .trz (53 frames, 1280x720). The car moves ~70 px per frame,
// blurred into a streak longer than its 51 px template, and turns into the loop.
TEST(RealFilm, PlainBlurredCarInAnImageSequenceIsNeverConfidentlyWrong) {
  // Frames 1-3 were reported 20-56 px from the human's marks with scores 0.86-0.94 (the
  // template slid along the streak); now every frame the tracker cannot place is lost. The
  // share to correct (100 %: no frame placed) is not checked here; the next test is the goal.
  const std::string path = testing::tracker_project_path("CarInLoop.trz");
  if (path.empty()) GTEST_SKIP() << "../shared/data/tracker/CarInLoop.trz not found";
  TrackVideoOptions o;
  Target t;
  t.name = t.from_track = "masa A";
  o.targets.push_back(t);
  o.thumbnails = 0;
  const TrackVideoResult res = track_video(path, o);
  ASSERT_EQ(res.series.size(), 1u);
  ASSERT_TRUE(res.series[0].vs_human.has_value());
  const HumanComparison& h = *res.series[0].vs_human;
  std::printf("CarInLoop.trz masa A: %d marks, %d tracked, max %.2f px, confidently wrong %d\n", h.marks, h.frames,
              h.max_px, h.confidently_wrong);
  EXPECT_EQ(h.marks, 52);
  EXPECT_EQ(h.confidently_wrong, 0);
  // An image sequence states no frame rate of its own (FFmpeg's image reader said 25): the
  // project's 240 fps is the clip's.
  EXPECT_EQ(res.input.info.fps, 0);
  EXPECT_NEAR(1 / res.input.time.frame_duration_s, 240, 1e-9);
  // The warning names the streak and the remedy.
  bool streak = false;
  for (const std::string& w : res.warnings) streak = streak || w.find("streak") != std::string::npos;
  EXPECT_TRUE(streak);
}

TEST(RealFilm, PlainBlurredCarIsNeverConfidentlyWrongWithTheOptionsAUserTriesNext) {
  // With --patch 25 frame 2 alone, between lost frames, sat on the car's green rear smear 47 px
  // from the human's mark (a sharp peak the ridge check passes); the confirmation rule (a run
  // of fewer than 3 reported points between lost frames is lost) removes it. With --patch 75
  // the path hopped from the car, across its lost points, to a still edge 785 px from the marks
  // and held it for 17 frames; the identity rule (a run whose last reported point before it is
  // more than max_gap + 1 frames back is lost) removes them (docs/benchmarks.md#tracking-on-real-film).
  const std::string path = testing::tracker_project_path("CarInLoop.trz");
  if (path.empty()) GTEST_SKIP() << "../shared/data/tracker/CarInLoop.trz not found";
  struct Variant {
    const char* what;
    int patch_px;
    double min_score;
    int search_px;
  };
  for (const Variant& v : {Variant{"--patch 25", 25, 0.6, 0}, Variant{"--patch 35", 35, 0.6, 0},
                           Variant{"--min-score 0.4", 0, 0.4, 0}, Variant{"--search 300", 0, 0.6, 300}, Variant{"--patch 75", 75, 0.6, 0}}) {
    TrackVideoOptions o;
    Target t;
    t.name = t.from_track = "masa A";
    o.targets.push_back(t);
    o.thumbnails = 0;
    o.path.patch_px = v.patch_px;
    o.path.min_score = v.min_score;
    o.path.search_px = v.search_px;
    const TrackVideoResult res = track_video(path, o);
    ASSERT_TRUE(res.series.at(0).vs_human.has_value());
    const HumanComparison& h = *res.series[0].vs_human;
    std::printf("CarInLoop.trz masa A %s: %d tracked, max %.2f px, confidently wrong %d\n", v.what, h.frames, h.max_px,
                h.confidently_wrong);
    EXPECT_EQ(h.confidently_wrong, 0) << v.what;
  }
}

TEST(RealFilm, TheHumansMarksOnEveryFifthFrameShowTheCarsLookToTheFramesBetween) {
  // A user correcting the car: the human's own marks given on every 5th frame (10 of 52). A
  // mark used to fix its own frame alone (the candidates came from the start's look, which the
  // car never shows again: 42 of the 42 frames between to correct). Now each mark's look is
  // searched in the frames from the mark before it to the mark after it, and turned with the car
  // (docs/theory.md#tracking-on-real-film, "A template that turns"). Measured 6 Dec 2026
  // (docs/benchmarks.md#tracking-on-real-film): 14 of the 42 to correct (15 before the turning
  // template), 2 of them placed 10-11 px from the human's mark (3 before; inside the car's blur,
  // where the human's marks shift with it). The bounds hold those figures: the test fails when
  // they regress. With a spinning look's turn rate (Look::expected, same night) 15 of 42: one
  // frame more, traded knowingly for the grid of throws (TrackingGrid: the spinning sticker's
  // lost frames 349 -> 180 of 918, the centre's 571 -> 252, none wrong).
  // docs/benchmarks.md#a-spinning-looks-turn-rate.
  const std::string path = testing::tracker_project_path("CarInLoop.trz");
  if (path.empty()) GTEST_SKIP() << "../shared/data/tracker/CarInLoop.trz not found";
  const VideoInput in = open_input(path, {});
  const auto human = std::find_if(in.marks_px.begin(), in.marks_px.end(), [](const track::Track& m) { return m.name == "masa A"; });
  ASSERT_NE(human, in.marks_px.end());
  TrackVideoOptions o;
  Target t;
  t.name = t.from_track = "masa A";
  int marked = 0;
  for (const track::TrackPoint& p : human->points) {
    if (p.frame > 0 && p.frame % 5 == 0) {
      t.marks.push_back({p.frame, p.x, p.y});
      ++marked;
    }
  }
  ASSERT_EQ(marked, 10);
  o.targets.push_back(t);
  o.thumbnails = 0;
  const TrackVideoResult res = track_video(path, o);
  const HumanComparison& h = res.series.at(0).vs_human.value();
  const int between = h.marks - marked;
  const int to_correct = h.to_correct;  // the marked frames lie on their marks: none to correct
  std::printf("CarInLoop.trz masa A with %d of the human's marks: of the %d frames between, %d to correct, %d confidently wrong\n",
              marked, between, to_correct, h.confidently_wrong);
  EXPECT_EQ(between, 42);
  EXPECT_LE(to_correct, 15);
  EXPECT_LE(h.confidently_wrong, 2);
}

// Not yet met (issue 24 open), so disabled rather than loosened: the car is not followed (no
// frame placed, with the turning template as before it). tools/film_probe.py measured why: from
// the blurred click no template of the start (turned, or matched to each frame's blur), no
// frame-to-frame chain (it slides 45-66 px along the streak in frames 1-6) and no foreground blob
// places a marked frame within 8 px, even searched next to the human's marks; nor does a template
// grown about the click (51-181 px: frame 1 peaks 23-26 px behind the mark at every side) or one
// without its background pixels (docs/benchmarks.md#tracking-on-real-film).
// Run with --gtest_also_run_disabled_tests.
TEST(RealFilm, DISABLED_PlainCarInAnImageSequenceIsFollowed) { check({"CarInLoop.trz", "masa A"}); }

}  // namespace
}  // namespace tribolab::video
