// Manual marks (docs/theory.md#manual-marks): a user's correction of one frame makes the
// trackers report that frame as marked and track on from it; the path tracker re-tracks the
// frames before it as well, frames far from it are left as they were.
#include "numerics/error.hpp"
#include "video/path_tracker.hpp"
#include "video/point_tracker.hpp"
#include "video/render.hpp"
#include "video/test_videos.hpp"
#include "video/track_video.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>
#include <unistd.h>

namespace tribolab::video {
namespace {

// The scene: our ball rolls right at 4 px/frame, bounces off a wall at frame 15 (x = 100 px)
// and rolls back; a look-alike rolls through the bounce point along the way ours would have
// gone on (right and slightly down). A smooth-motion prior prefers the look-alike after the
// bounce: the path tracker reports the frames after it lost (the look-alike explains them as
// well) or on the look-alike, the frame tracker follows the look-alike.
constexpr int kMarkSceneFrames = 31;
constexpr int kBounceFrame = 15;

cv::Point2d marked_scene_ours(int i) {
  return i <= kBounceFrame ? cv::Point2d(40 + 4.0 * i, 80) : cv::Point2d(100 - 4.0 * (i - kBounceFrame), 80);
}
cv::Point2d marked_scene_other(int i) { return {104 + 4.0 * (i - 16), 80 + 3.0 * (i - 16)}; }

RenderOptions marked_scene_options() {
  RenderOptions o;
  o.width = 240;
  o.height = 160;
  o.fps = 30;
  o.shutter_fraction = 0;
  o.supersample = 2;
  o.background = RenderOptions::Background::texture;
  o.noise_sigma = 2;
  return o;
}

Scene marked_scene() {
  return [](double t) {
    const int i = static_cast<int>(std::lround(t * 30));
    std::vector<ShapePose> shapes;
    for (const cv::Point2d c : {marked_scene_other(i), marked_scene_ours(i)}) {
      ShapePose s;
      s.cx_px = c.x;
      s.cy_px = c.y;
      s.a_px = s.b_px = 6;
      s.colour = {40, 40, 200};
      shapes.push_back(s);
    }
    return shapes;
  };
}

std::vector<Observation> path_track_marked_scene(const std::vector<ManualMark>& marks) {
  const RenderOptions o = marked_scene_options();
  const Scene scene = marked_scene();
  PathTracker tracker;
  const cv::Point2d p0 = marked_scene_ours(0);
  tracker.start(testing::rendered_frame(scene, 0, o), p0.x, p0.y, "ball");
  tracker.set_marks(marks);
  for (int i = 1; i < kMarkSceneFrames; ++i) tracker.update(testing::rendered_frame(scene, i, o));
  return tracker.finish();
}

bool on_ours(const Observation& ob) {
  const cv::Point2d t = marked_scene_ours(ob.frame);
  return !ob.lost && std::hypot(ob.x_px - t.x, ob.y_px - t.y) < 1.5;
}

TEST(ManualMark, PathTrackerRetracksBothWaysFromAMarkAndLeavesFarFramesAlone) {
  const std::vector<Observation> before = path_track_marked_scene({});
  ASSERT_EQ(before.size(), static_cast<std::size_t>(kMarkSceneFrames - 1));
  int right_after = 0, wrong_after = 0;
  for (const Observation& ob : before) {
    right_after += ob.frame > kBounceFrame && on_ours(ob);
    wrong_after += ob.frame > kBounceFrame && !ob.lost && !on_ours(ob);
  }
  std::printf("without a mark: of the %d frames after the bounce %d on our ball, %d reported on something else\n",
              kMarkSceneFrames - 1 - kBounceFrame, right_after, wrong_after);
  ASSERT_LE(right_after, 3) << "the scene no longer fools the tracker: the test shows nothing";

  constexpr int kMarkFrame = 22;
  const cv::Point2d m = marked_scene_ours(kMarkFrame) + cv::Point2d(0.4, -0.3);  // a click is never exact
  const std::vector<Observation> after = path_track_marked_scene({{kMarkFrame, m.x, m.y}});
  ASSERT_EQ(after.size(), before.size());
  int fixed = 0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    const Observation& a = after[k];
    const Observation& b = before[k];
    if (a.frame == kMarkFrame) {
      EXPECT_TRUE(a.manual);
      EXPECT_FALSE(a.lost);
      EXPECT_EQ(a.score, 1);
      EXPECT_EQ(a.x_px, m.x);
      EXPECT_EQ(a.y_px, m.y);
      continue;
    }
    EXPECT_FALSE(a.manual) << a.frame;
    if (a.frame <= kBounceFrame - 4) {
      // Far from the mark (and before the bounce): exactly as without it.
      EXPECT_EQ(a.lost, b.lost) << a.frame;
      EXPECT_EQ(a.x_px, b.x_px) << a.frame;
      EXPECT_EQ(a.y_px, b.y_px) << a.frame;
    } else if (a.frame > kBounceFrame) {
      fixed += on_ours(a);
      if (!on_ours(a)) std::printf("with the mark, frame %d is %s\n", a.frame, a.lost ? "lost" : "elsewhere");
      EXPECT_FALSE(!a.lost && !on_ours(a)) << "frame " << a.frame << " reported on something else";
    }
  }
  // Backward (16..21) and forward (23..30) from the mark: on our ball, at most the frame right
  // after the bounce left lost.
  std::printf("with a mark at frame %d: %d frames after the bounce on our ball\n", kMarkFrame, fixed);
  EXPECT_GE(fixed, kMarkSceneFrames - 1 - kBounceFrame - 1 - 1);
}

TEST(ManualMark, PathTrackerChoosesThePathAgainAfterNewMarksWithoutTheFrames) {
  // finish() again after set_marks: the path chosen anew among the candidates already found
  // (the mark's frame is the mark, the frames around it follow it), and with the marks removed
  // the track is as at first, bit for bit. (A fresh tracking with the mark searches around it
  // as well: PathTrackerSearchesTheFramesAroundAMarkForItsLook.)
  const RenderOptions o = marked_scene_options();
  const Scene scene = marked_scene();
  PathTracker tracker;
  tracker.start(testing::rendered_frame(scene, 0, o), marked_scene_ours(0).x, marked_scene_ours(0).y, "ball");
  for (int i = 1; i < kMarkSceneFrames; ++i) tracker.update(testing::rendered_frame(scene, i, o));
  const std::vector<Observation> plain = tracker.finish();
  const ManualMark m{22, marked_scene_ours(22).x, marked_scene_ours(22).y};
  tracker.set_marks({m});
  const std::vector<Observation> again = tracker.finish();
  int changed = 0, right_after = 0;
  for (std::size_t k = 0; k < again.size(); ++k) {
    EXPECT_EQ(again[k].manual, again[k].frame == m.frame) << again[k].frame;
    changed += again[k].lost != plain[k].lost;
    right_after += again[k].frame > kBounceFrame && on_ours(again[k]);
  }
  EXPECT_GT(changed, 5);  // the mark did change the track
  EXPECT_GE(right_after, kMarkSceneFrames - 1 - kBounceFrame - 2);
  tracker.set_marks({});  // and removed, the track is as at first
  const std::vector<Observation> removed = tracker.finish();
  for (std::size_t k = 0; k < removed.size(); ++k) {
    EXPECT_EQ(removed[k].lost, plain[k].lost) << removed[k].frame;
    EXPECT_EQ(removed[k].x_px, plain[k].x_px) << removed[k].frame;
  }
}

// The look-change scene: our object slides right at 4 px/frame over texture; until frame
// kChangeFrame it is a round blue disc, from then on a dark bar standing across its path (what a
// turning car or a ball whose sticker comes into view does to a template). The start's look
// does not match the bar: the path tracker loses it after the change. A user's mark on the bar
// shows the tracker its new look.
constexpr int kChangeFrames = 31;
constexpr int kChangeFrame = 12;

cv::Point2d change_scene_at(int i) { return {30 + 4.0 * i, 70}; }

Scene change_scene() {
  return [](double t) {
    const int i = static_cast<int>(std::lround(t * 30));
    ShapePose s;
    s.cx_px = change_scene_at(i).x;
    s.cy_px = change_scene_at(i).y;
    if (i < kChangeFrame) {
      s.a_px = s.b_px = 7;
    } else {
      s.a_px = 3;
      s.b_px = 10;
      s.colour = {30, 30, 30};
    }
    return std::vector<ShapePose>{s};
  };
}

std::vector<Observation> path_track_change_scene(std::optional<ManualMark> mark) {
  const RenderOptions o = marked_scene_options();
  const Scene scene = change_scene();
  PathTracker tracker;
  tracker.start(testing::rendered_frame(scene, 0, o), change_scene_at(0).x, change_scene_at(0).y, "ball");
  if (mark) {
    tracker.set_marks({*mark});
    const Frame f = testing::rendered_frame(scene, mark->frame, o);
    const cv::Rect r = PathTracker::look_crop(f.gray.size(), mark->x_px, mark->y_px);
    tracker.add_look(mark->frame, f.gray(r), mark->x_px - r.x, mark->y_px - r.y);
  }
  for (int i = 1; i < kChangeFrames; ++i) tracker.update(testing::rendered_frame(scene, i, o));
  return tracker.finish();
}

TEST(ManualMark, PathTrackerSearchesTheFramesAroundAMarkForItsLook) {
  auto on_object = [](const Observation& ob) {
    const cv::Point2d t = change_scene_at(ob.frame);
    return !ob.lost && std::hypot(ob.x_px - t.x, ob.y_px - t.y) < 1.5;
  };
  const std::vector<Observation> plain = path_track_change_scene(std::nullopt);
  int before_change = 0, after_change = 0;
  for (const Observation& ob : plain) {
    before_change += ob.frame < kChangeFrame && on_object(ob);
    after_change += ob.frame >= kChangeFrame && on_object(ob);
    EXPECT_FALSE(!ob.lost && !on_object(ob)) << "frame " << ob.frame << " reported elsewhere";
  }
  std::printf("without a mark: %d of %d frames before the change, %d of %d after it on the object\n", before_change,
              kChangeFrame - 1, after_change, kChangeFrames - kChangeFrame);
  EXPECT_EQ(before_change, kChangeFrame - 1);
  ASSERT_LE(after_change, 2) << "the start's look still matches the bar: the scene shows nothing";

  constexpr int kMarkFrame = 22;
  const cv::Point2d m = change_scene_at(kMarkFrame) + cv::Point2d(0.3, -0.4);  // a click is never exact
  const std::vector<Observation> marked = path_track_change_scene(ManualMark{kMarkFrame, m.x, m.y});
  int fixed = 0;
  for (const Observation& ob : marked) {
    if (ob.frame == kMarkFrame) {
      EXPECT_TRUE(ob.manual);
      continue;
    }
    EXPECT_FALSE(!ob.lost && !on_object(ob)) << "frame " << ob.frame << " reported elsewhere";
    if (ob.frame < kChangeFrame) {
      EXPECT_TRUE(on_object(ob)) << ob.frame;
    }
    fixed += ob.frame >= kChangeFrame && on_object(ob);
  }
  // Backward (12..21) and forward (23..30) from the mark: the bar is found in every frame.
  std::printf("with a mark at frame %d: %d of %d frames after the change on the object\n", kMarkFrame, fixed,
              kChangeFrames - kChangeFrame - 1);
  EXPECT_EQ(fixed, kChangeFrames - kChangeFrame - 1);
}

TEST(ManualMark, PathTrackerKeepsTheFramesNextToAClickThatIsAFewPixelsOff) {
  // A user's clicks scatter: marks 3 px off the object's point (640 px wide: within the 4 px
  // correction distance, so none a user would correct) on every 5th frame of a ball rolling at
  // 3 px/frame. Dropping the frame next to such a mark made the path's acceleration through it
  // cheaper than keeping it (jmoljana with the human's marks: 44 of 120 frames lost); the
  // acceleration through a mark now allows for the click's scatter (kClickPx): every frame kept.
  RenderOptions o = marked_scene_options();
  o.width = 640;
  o.height = 240;
  auto at = [](int i) { return cv::Point2d(60 + 3.0 * i, 120); };
  const Scene scene = [&](double t) {
    ShapePose s;
    const cv::Point2d c = at(static_cast<int>(std::lround(t * 30)));
    s.cx_px = c.x;
    s.cy_px = c.y;
    s.a_px = s.b_px = 8;
    s.mark = true;
    s.mark_size_px = 9;
    return std::vector<ShapePose>{s};
  };
  constexpr int kFrames = 41;
  std::vector<ManualMark> marks;
  for (int k = 5; k < kFrames; k += 5) {
    const double sx = (k / 5) % 2 == 0 ? 1 : -1, sy = (k / 5) % 3 == 0 ? 1 : -1;
    marks.push_back({k, at(k).x + sx * 2.4, at(k).y + sy * 1.8});  // 3 px off
  }
  PathTracker tracker;
  tracker.start(testing::rendered_frame(scene, 0, o), at(0).x, at(0).y, "ball");
  tracker.set_marks(marks);
  for (int i = 1; i < kFrames; ++i) tracker.update(testing::rendered_frame(scene, i, o));
  int kept = 0, between = 0;
  for (const Observation& ob : tracker.finish()) {
    if (ob.manual) continue;
    ++between;
    const bool on = !ob.lost && std::hypot(ob.x_px - at(ob.frame).x, ob.y_px - at(ob.frame).y) < 1.5;
    if (!on) std::printf("frame %d %s\n", ob.frame, ob.lost ? "lost" : "off the ball");
    kept += on;
  }
  EXPECT_EQ(between, kFrames - 1 - static_cast<int>(marks.size()));
  EXPECT_EQ(kept, between);
}

TEST(ManualMark, PathTrackerTakesALookOnlyAtAMarkNotYetTracked) {
  const RenderOptions o = marked_scene_options();
  const Scene scene = change_scene();
  PathTracker tracker;
  tracker.start(testing::rendered_frame(scene, 0, o), change_scene_at(0).x, change_scene_at(0).y, "ball");
  const Frame f = testing::rendered_frame(scene, 5, o);
  EXPECT_THROW(tracker.add_look(5, f.gray, 50, 70), InputError);  // no mark on frame 5
  tracker.set_marks({{5, 50, 70}, {9, 66, 70}});
  EXPECT_THROW(tracker.add_look(5, f.gray, -1, 70), InputError);  // the image does not hold the mark
  tracker.add_look(5, f.gray, 50, 70);
  tracker.update(testing::rendered_frame(scene, 1, o));
  for (int i = 2; i <= 9; ++i) tracker.update(testing::rendered_frame(scene, i, o));
  EXPECT_THROW(tracker.add_look(9, testing::rendered_frame(scene, 9, o).gray, 66, 70), InputError);  // tracked already
  const cv::Mat flat(40, 40, CV_8UC1, cv::Scalar(128));
  tracker.set_marks({{12, 78, 70}});
  tracker.add_look(12, flat, 20, 20);  // nothing to match: not used, not an error
  EXPECT_EQ(tracker.finish().size(), 9u);
}

TEST(ManualMark, PathTrackerRefusesMarksItCannotHonour) {
  const RenderOptions o = marked_scene_options();
  PathTracker tracker;
  tracker.start(testing::rendered_frame(marked_scene(), 0, o), 40, 80, "ball");
  EXPECT_THROW(tracker.set_marks({{5, 300, 20}}), InputError);              // outside the image
  EXPECT_THROW(tracker.set_marks({{0, 41, 80}}), InputError);               // the start frame
  EXPECT_THROW(tracker.set_marks({{5, 60, 80}, {5, 61, 80}}), InputError);  // twice one frame
}

TEST(ManualMark, FrameTrackerRestartsFromAMarkBothWays) {
  // The frame-to-frame tracker follows the look-alike after the bounce (or loses the ball);
  // from a mark on our ball it follows ours again, forward, and backward (a fresh tracker run
  // over the held frames in reverse) until it meets the forward track before the bounce.
  const std::string dir = (std::filesystem::temp_directory_path() / ("manual_mark_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string video = dir + "/bounce.avi";
  write_video(video, marked_scene(), kMarkSceneFrames, marked_scene_options());
  TrackVideoOptions o;
  o.offline_points = false;
  o.thumbnails = 0;
  Target t;
  t.name = "ball";
  t.x_px = marked_scene_ours(0).x;
  t.y_px = marked_scene_ours(0).y;
  t.frame = 0;
  o.targets.push_back(t);
  const TrackVideoResult plain = track_video(video, o);
  constexpr int kMarkFrame = 20;
  o.targets[0].marks.push_back({kMarkFrame, marked_scene_ours(kMarkFrame).x, marked_scene_ours(kMarkFrame).y});
  const TrackVideoResult marked = track_video(video, o);
  std::filesystem::remove_all(dir);
  ASSERT_EQ(marked.series[0].rows.size(), plain.series[0].rows.size());
  EXPECT_EQ(marked.series[0].manual_frames, std::vector<int>{kMarkFrame});
  auto on = [](const TrackedRow& r) {
    const cv::Point2d c = marked_scene_ours(r.frame);
    return !r.lost && std::hypot(r.x_px - c.x, r.y_px - c.y) < 1.5;
  };
  int plain_on = 0, marked_on = 0, plain_back = 0, marked_back = 0;
  for (std::size_t k = 0; k < plain.series[0].rows.size(); ++k) {
    const TrackedRow& a = plain.series[0].rows[k];
    const TrackedRow& b = marked.series[0].rows[k];
    if (a.frame <= kBounceFrame) {  // where the forward track was right: as it was
      EXPECT_EQ(a.lost, b.lost) << a.frame;
      if (!a.lost) {
        EXPECT_EQ(a.x_px, b.x_px) << a.frame;
      }
      continue;
    }
    if (a.frame < kMarkFrame) {  // after the bounce, before the mark: re-tracked backward
      EXPECT_FALSE(b.manual);
      plain_back += on(a);
      marked_back += on(b);
      continue;
    }
    if (a.frame == kMarkFrame) {
      EXPECT_TRUE(b.manual);
      EXPECT_EQ(b.score, 1);
      continue;
    }
    plain_on += on(a);
    marked_on += on(b);
  }
  std::printf("frames after the mark on our ball: %d without it, %d with it; between the bounce and the mark: %d, %d\n",
              plain_on, marked_on, plain_back, marked_back);
  EXPECT_LE(plain_on, 2);
  EXPECT_GE(marked_on, kMarkSceneFrames - 1 - kMarkFrame - 1);
  EXPECT_LE(plain_back, 1);
  EXPECT_EQ(marked_back, kMarkFrame - kBounceFrame - 1);  // frames 16..19 all on our ball
}

TEST(ManualMark, EllipseTrackerFoundAgainBothWaysFromAMarkAfterAnOcclusion) {
  // A ball rolls behind a board for longer than the ellipse tracker bridges (max_gap 2): it
  // gives up and every later frame is lost. A mark at frame 27 resumes it forward, and the
  // backward pass finds the ball in the frames between the board and the mark.
  const std::string dir = (std::filesystem::temp_directory_path() / ("manual_ellipse_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string video = dir + "/board.avi";
  auto ball_at = [](int i) { return cv::Point2d(30 + 5.0 * i, 80); };
  RenderOptions r = marked_scene_options();
  r.background = RenderOptions::Background::plain;
  const Scene scene = [&](double t) {
    const int i = static_cast<int>(std::lround(t * 30));
    ShapePose ball;
    ball.cx_px = ball_at(i).x;
    ball.cy_px = ball_at(i).y;
    ball.a_px = ball.b_px = 9;
    ball.colour = {40, 40, 200};
    ShapePose board;
    board.kind = ShapePose::Kind::rectangle;
    board.cx_px = 125;
    board.cy_px = 80;
    board.a_px = 20;
    board.b_px = 40;
    board.colour = {150, 170, 190};
    return std::vector<ShapePose>{ball, board};
  };
  write_video(video, scene, kMarkSceneFrames, r);
  TrackVideoOptions o;
  o.thumbnails = 0;
  o.ellipse.max_gap_frames = 2;
  Target t;
  t.kind = Target::Kind::ellipse;
  t.name = "ball";
  t.x_px = ball_at(0).x;
  t.y_px = ball_at(0).y;
  t.frame = 0;
  o.targets = {t};
  const TrackVideoResult plain = track_video(video, o);
  constexpr int kMarkFrame = 27;
  o.targets[0].marks.push_back({kMarkFrame, ball_at(kMarkFrame).x, ball_at(kMarkFrame).y});
  const TrackVideoResult marked = track_video(video, o);
  std::filesystem::remove_all(dir);
  auto on = [&](const TrackedRow& row) {
    return !row.lost && std::hypot(row.x_px - ball_at(row.frame).x, row.y_px - ball_at(row.frame).y) < 1.0;
  };
  int plain_after = 0, marked_before = 0, marked_after = 0;
  ASSERT_EQ(plain.series[0].rows.size(), marked.series[0].rows.size());
  for (std::size_t k = 0; k < plain.series[0].rows.size(); ++k) {
    const TrackedRow& a = plain.series[0].rows[k];
    const TrackedRow& b = marked.series[0].rows[k];
    if (a.frame <= 12) {  // before the board: as it was
      EXPECT_EQ(a.lost, b.lost) << a.frame;
      EXPECT_EQ(a.x_px, b.x_px) << a.frame;
    } else if (a.frame >= 24 && a.frame < kMarkFrame) {  // out from behind the board, before the mark
      plain_after += on(a);
      marked_before += on(b);
    } else if (a.frame > kMarkFrame) {
      plain_after += on(a);
      marked_after += on(b);
    }
  }
  std::printf("after the board: %d frames on the ball without the mark; with it %d before the mark, %d after\n",
              plain_after, marked_before, marked_after);
  EXPECT_EQ(plain_after, 0);
  EXPECT_EQ(marked_before, 3);  // 24, 25, 26
  EXPECT_EQ(marked_after, kMarkSceneFrames - 1 - kMarkFrame);
  // The ends: A and B on the ellipse's major axis either side of the centre (a round ball: 9 px out).
  for (std::size_t k = 0; k < marked.series[0].rows.size(); ++k) {
    const TrackedRow& c = marked.series[0].rows[k];
    if (c.frame < 24 || c.lost) continue;
    EXPECT_NEAR(std::hypot(marked.series[1].rows[k].x_px - c.x_px, marked.series[1].rows[k].y_px - c.y_px), 9, 1.0) << c.frame;
  }
}

TEST(ManualMark, TrackVideoShowsThePathTrackerEachMarksLookBeforeTheFramesAroundIt) {
  // track_video reads the marked frames first (a decoding up to the last mark), so a mark's
  // look is searched in the frames before it as well as after: as PathTracker given the look
  // before its first frame.
  const std::string dir = (std::filesystem::temp_directory_path() / ("manual_look_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string video = dir + "/change.avi";
  write_video(video, change_scene(), kChangeFrames, marked_scene_options());
  TrackVideoOptions o;
  Target t;
  t.name = "ball";
  t.x_px = change_scene_at(0).x;
  t.y_px = change_scene_at(0).y;
  constexpr int kMarkFrame = 22;
  const cv::Point2d m = change_scene_at(kMarkFrame);
  t.marks.push_back({kMarkFrame, m.x, m.y});
  o.targets = {t};
  const TrackVideoResult r = track_video(video, o);
  int found = 0;
  for (const TrackedRow& row : r.series[0].rows) {
    const cv::Point2d at = change_scene_at(row.frame);
    const bool on = !row.lost && std::hypot(row.x_px - at.x, row.y_px - at.y) < 1.5;
    EXPECT_FALSE(!row.lost && !on) << "frame " << row.frame << " reported elsewhere";
    found += on;
  }
  EXPECT_EQ(found, kChangeFrames) << "every frame on the object, the bar before the mark included";
  std::filesystem::remove_all(dir);
}

TEST(ManualMark, RetrackingASessionChoosesThePathAmongTheCandidatesFound) {
  // The studio's answer to a drag: the path chosen anew with the new marks among the
  // candidates of the first tracking, without decoding; what PathTracker::finish gives after
  // set_marks (PathTrackerChoosesThePathAgainAfterNewMarksWithoutTheFrames). Tracking afresh
  // with the mark searches for its look as well: it reports on the ball every frame the
  // re-tracking does (and may report more, from the look's own candidates).
  const std::string dir = (std::filesystem::temp_directory_path() / ("manual_retrack_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  const std::string video = dir + "/bounce.avi";
  write_video(video, marked_scene(), kMarkSceneFrames, marked_scene_options());
  TrackVideoOptions o;
  o.thumbnails = 2;
  Target t;
  t.name = "ball";
  t.x_px = marked_scene_ours(0).x;
  t.y_px = marked_scene_ours(0).y;
  t.frame = 0;
  Target e = t;  // a frame-to-frame point on the same ball
  e.name = "framed";
  o.targets = {t};
  TrackSession session;
  const TrackVideoResult plain = track_video(video, o, &session);
  ASSERT_FALSE(session.empty());
  std::vector<Target> marked = o.targets;
  marked[0].marks.push_back({22, marked_scene_ours(22).x, marked_scene_ours(22).y});
  const std::optional<TrackVideoResult> again = retrack(session, marked);
  ASSERT_TRUE(again.has_value());
  o.targets = marked;
  const TrackVideoResult fresh = track_video(video, o);
  ASSERT_EQ(again->series[0].rows.size(), fresh.series[0].rows.size());
  int differ_from_plain = 0;
  for (std::size_t k = 0; k < fresh.series[0].rows.size(); ++k) {
    const TrackedRow& a = again->series[0].rows[k];
    const TrackedRow& b = fresh.series[0].rows[k];
    EXPECT_EQ(a.manual, b.manual) << a.frame;
    auto on_ball = [](const TrackedRow& r) {
      return !r.lost && std::hypot(r.x_px - marked_scene_ours(r.frame).x, r.y_px - marked_scene_ours(r.frame).y) < 1.5;
    };
    EXPECT_TRUE(a.lost || on_ball(a)) << "re-tracked frame " << a.frame << " off the ball";
    EXPECT_TRUE(b.lost || on_ball(b)) << "freshly tracked frame " << b.frame << " off the ball";
    if (!a.lost) {
      EXPECT_FALSE(b.lost) << a.frame;
    }
    differ_from_plain += a.lost != plain.series[0].rows[k].lost;
  }
  EXPECT_GT(differ_from_plain, 5);
  EXPECT_EQ(again->series[0].manual_frames, std::vector<int>{22});
  EXPECT_EQ(again->thumbnails.size(), fresh.thumbnails.size());
  // A bad mark: refused, the session as it was.
  std::vector<Target> bad = marked;
  bad[0].marks[0].x_px = 1e6;
  EXPECT_THROW(retrack(session, bad), InputError);
  EXPECT_EQ(retrack(session, marked)->series[0].manual_frames, std::vector<int>{22});
  // Other targets, or a frame-to-frame track's marks: no re-tracking, track afresh.
  std::vector<Target> moved = marked;
  moved[0].x_px += 1;
  EXPECT_FALSE(retrack(session, moved).has_value());
  TrackVideoOptions f = o;
  f.offline_points = false;
  f.targets = {e};
  TrackSession framed;
  track_video(video, f, &framed);
  std::vector<Target> framed_marked = f.targets;
  framed_marked[0].marks.push_back({20, marked_scene_ours(20).x, marked_scene_ours(20).y});
  EXPECT_FALSE(retrack(framed, framed_marked).has_value());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::video
