#include "video/point_tracker.hpp"
#include "video/codec.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "video/motion_model.hpp"
#include "video/render.hpp"
#include "video/source.hpp"
#include "video/test_videos.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace tribolab::video {
namespace {

/// Frame `index` of the scene (test_videos.hpp).
constexpr auto& film = testing::rendered_frame;

RenderOptions small_point_video() {
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.fps = 240;
  o.shutter_fraction = 0;
  o.background = RenderOptions::Background::plain;
  o.noise_sigma = 2;
  return o;
}

// A wheel of radius 70 px turning at `deg_per_frame`, a 15 px checker sticker 40 px from
// its hub; the sticker's centre is the truth.
struct Wheel {
  double cx = 160, cy = 120, radius = 70, mark_r = 40, mark_size = 15, deg_per_frame = 22.5;
  double fps = 240;
  double angle(double t) const { return to_rad(deg_per_frame) * fps * t + 0.3; }
  ShapePose pose(double t) const {
    ShapePose s;
    s.cx_px = cx;
    s.cy_px = cy;
    s.a_px = s.b_px = radius;
    s.angle_rad = angle(t);
    s.colour = cv::Scalar(60, 140, 60);
    s.mark = true;
    s.mark_u_px = mark_r;
    s.mark_size_px = mark_size;
    return s;
  }
  cv::Point2d mark(double t) const {
    const double a = angle(t);
    return {cx + mark_r * std::cos(a), cy - mark_r * std::sin(a)};
  }
};

struct Errors {
  std::vector<double> position_px, angle_deg;
  int lost = 0;
  std::vector<int> lost_frames;
  double median(std::vector<double> v) const {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
  double max(const std::vector<double>& v) const {
    return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
  }
  void print(const char* what) const {
    std::printf("[ measured ] %s: %zu frames tracked, %d lost, position error median %.3f max %.3f px,"
                " angle error median %.3f max %.3f deg\n",
                what, position_px.size(), lost, median(position_px), max(position_px),
                median(angle_deg), max(angle_deg));
  }
};

// Tracks `frames` frames of `scene`, comparing with `truth(t)` and `turn(t)` (rad since t=0).
template <class Truth, class Turn>
Errors track_points(const Scene& scene, const RenderOptions& o, int frames, Truth truth, Turn turn,
             const PointTrackerOptions& options = {}) {
  PointTracker tracker(options);
  Errors e;
  const Frame f0 = film(scene, 0, o);
  const cv::Point2d p0 = truth(0.0);
  tracker.start(f0, p0.x, p0.y, "mark");
  for (int i = 1; i < frames; ++i) {
    const Frame f = film(scene, i, o);
    const Observation ob = tracker.update(f);
    EXPECT_EQ(ob.frame, i);
    if (ob.lost) {
      ++e.lost;
      e.lost_frames.push_back(i);
      continue;
    }
    const cv::Point2d p = truth(f.t);
    e.position_px.push_back(std::hypot(ob.x_px - p.x, ob.y_px - p.y));
    e.angle_deg.push_back(to_deg(std::abs(ob.angle_rad - turn(f.t))));
  }
  return e;
}

TEST(PointTracker, FollowsAMarkOnAWheelTurning20To25DegreesPerFrame) {
  for (double rate : {20.0, 25.0}) {
    Wheel w;
    w.deg_per_frame = rate;
    const RenderOptions o = small_point_video();
    const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
    const Errors e = track_points(scene, o, 32, [&](double t) { return w.mark(t); },
                           [&](double t) { return w.angle(t) - w.angle(0); });
    e.print(rate == 20 ? "wheel 20 deg/frame" : "wheel 25 deg/frame");
    EXPECT_EQ(e.lost, 0);
    // Measured 0.04 / 0.06 px and 0.08 / 0.16 deg at 22.5 deg/frame; about 3x margin for
    // the rate and noise seed.
    EXPECT_LT(e.median(e.position_px), 0.15);
    EXPECT_LT(e.max(e.position_px), 0.3);
    EXPECT_LT(e.median(e.angle_deg), 0.3);
    EXPECT_LT(e.max(e.angle_deg), 0.6);
  }
}

TEST(PointTracker, FollowsAMarkOnAWheelTurning22DegreesPerFrame) {
  const Wheel w;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  const Errors e = track_points(scene, o, 40, [&](double t) { return w.mark(t); },
                         [&](double t) { return w.angle(t) - w.angle(0); });
  e.print("wheel 22.5 deg/frame");
  EXPECT_EQ(e.lost, 0);
  // Tolerances: about 2.5x the measured values (median 0.043, max 0.059 px; angle 0.080,
  // max 0.162 deg), room for another OpenCV build, never for a wrong match (>= 1 px).
  EXPECT_LT(e.median(e.position_px), 0.1);
  EXPECT_LT(e.max(e.position_px), 0.15);
  EXPECT_LT(e.median(e.angle_deg), 0.2);
  EXPECT_LT(e.max(e.angle_deg), 0.4);
}

TEST(PointTracker, TemplateMatchingWithoutRotationLosesTheWheelMark) {
  // Tracker's autotracker matches the unturned template: with max_turn_deg = 0 the same
  // tracker must fail on the turning mark, showing the rotation search is what follows it.
  const Wheel w;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  PointTrackerOptions plain;
  plain.max_turn_deg = 0;
  const Errors e = track_points(scene, o, 16, [&](double t) { return w.mark(t); },
                         [&](double) { return 0.0; }, plain);
  e.print("wheel without rotation search");
  EXPECT_GT(e.lost, 12);  // measured 14 of 15: lost as soon as the mark has turned
}

// A ball of radius 6 px thrown across the frame: 42 px per frame, parabola.
struct Throw {
  double x0 = 20, y0 = 200, vx = 36, vy = -22, ay = 3, fps = 240;  // px, px/frame, px/frame^2
  cv::Point2d at(double t) const {
    const double n = t * fps;
    return {x0 + vx * n, y0 + vy * n + 0.5 * ay * n * n};
  }
  ShapePose pose(double t) const {
    ShapePose s;
    const cv::Point2d p = at(t);
    s.cx_px = p.x;
    s.cy_px = p.y;
    s.a_px = s.b_px = 6;
    s.colour = cv::Scalar(30, 30, 200);
    return s;
  }
};

TEST(PointTracker, FollowsAFastBallOnAParabola) {
  const Throw b;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{b.pose(t)}; };
  const Errors e = track_points(scene, o, 8, [&](double t) { return b.at(t); }, [](double) { return 0.0; });
  e.print("ball 42 px/frame");
  EXPECT_EQ(e.lost, 0);
  // Measured median 0.006, max 0.007 px: a sharp disc on a plain background.
  EXPECT_LT(e.median(e.position_px), 0.03);
  EXPECT_LT(e.max(e.position_px), 0.05);
}

TEST(PointTracker, FollowsABlurredNoisyBall) {
  const Throw b;
  RenderOptions o = small_point_video();
  o.shutter_fraction = 0.5;
  o.noise_sigma = 4;
  const Scene scene = [&](double t) { return std::vector<ShapePose>{b.pose(t)}; };
  const Errors e = track_points(scene, o, 8, [&](double t) { return b.at(t); }, [](double) { return 0.0; });
  e.print("blurred ball 42 px/frame");
  EXPECT_EQ(e.lost, 0);
  // Measured median 0.072, max 0.109 px (a 21 px streak in noise 4).
  EXPECT_LT(e.median(e.position_px), 0.15);
  EXPECT_LT(e.max(e.position_px), 0.25);
}

TEST(PointTracker, KeepsABallSetInMotionFromRestSharpAndBlurredApart) {
  // A ball starting at rest and accelerating to 54 px/frame, shutter 0.5: its image goes
  // from sharp (the template) to a 27 px streak. Matching the sharp template alone (measured
  // with the smear disabled) drops the score to 0.64 and puts the ball 5.5 px off along its
  // streak; smearing it along the predicted change of velocity keeps 0.965 and 0.04 px.
  RenderOptions o = small_point_video();
  o.shutter_fraction = 0.5;
  auto at = [&](double t) {
    const double n = t * o.fps;
    return cv::Point2d(20 + 0.5 * 4.4 * n * n, 40 + 0.5 * 2.2 * n * n);
  };
  const Scene scene = [&](double t) {
    ShapePose s;
    s.cx_px = at(t).x;
    s.cy_px = at(t).y;
    s.a_px = s.b_px = 6;
    s.colour = cv::Scalar(30, 30, 200);
    return std::vector<ShapePose>{s};
  };
  PointTracker tracker;
  tracker.start(film(scene, 0, o), at(0).x, at(0).y, "ball");
  Errors e;
  double lowest = 1;
  for (int i = 1; i <= 11; ++i) {
    const Frame f = film(scene, i, o);
    const Observation ob = tracker.update(f);
    ASSERT_FALSE(ob.lost) << "frame " << i;
    lowest = std::min(lowest, ob.score);
    e.position_px.push_back(std::hypot(ob.x_px - at(f.t).x, ob.y_px - at(f.t).y));
  }
  e.print("ball from rest to 54 px/frame, shutter 0.5");
  std::printf("[ measured ] lowest score %.3f\n", lowest);
  EXPECT_GT(lowest, 0.9);                   // measured 0.965 (0.64 unsmeared)
  EXPECT_LT(e.median(e.position_px), 0.1);  // measured 0.018 px
  EXPECT_LT(e.max(e.position_px), 0.3);     // measured 0.041 px (5.5 px unsmeared)
}

TEST(PointTracker, FollowsABlurredNoisyWheelMark) {
  const Wheel w;
  RenderOptions o = small_point_video();
  o.shutter_fraction = 0.5;
  o.noise_sigma = 4;
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  const Errors e = track_points(scene, o, 40, [&](double t) { return w.mark(t); },
                         [&](double t) { return w.angle(t) - w.angle(0); });
  e.print("blurred wheel 22.5 deg/frame");
  EXPECT_EQ(e.lost, 0);
  // Measured median 0.021, max 0.052 px; angle median 0.048, max 0.182 deg (before the
  // refinement on a resampled window the angle was biased by -0.86 deg here).
  EXPECT_LT(e.median(e.position_px), 0.06);
  EXPECT_LT(e.max(e.position_px), 0.12);
  EXPECT_LT(e.median(e.angle_deg), 0.12);
  EXPECT_LT(e.max(e.angle_deg), 0.4);
}

TEST(PointTracker, ReportsAnOcclusionAndNeverGivesAWrongPosition) {
  // A hand (grey rectangle) rests over the left of the wheel: the mark passes under it for
  // about five frames in every turn of 16 frames.
  const Wheel w;
  const RenderOptions o = small_point_video();
  const cv::Rect2d hand_box(-20, 90, 160, 60);
  const Scene scene = [&](double t) {
    ShapePose hand;
    hand.kind = ShapePose::Kind::rectangle;
    hand.cx_px = hand_box.x + hand_box.width / 2;
    hand.cy_px = hand_box.y + hand_box.height / 2;
    hand.a_px = hand_box.width / 2;
    hand.b_px = hand_box.height / 2;
    hand.colour = cv::Scalar(150, 170, 190);
    return std::vector<ShapePose>{w.pose(t), hand};
  };
  const int frames = 50;
  const Errors e = track_points(scene, o, frames, [&](double t) { return w.mark(t); },
                         [&](double t) { return w.angle(t) - w.angle(0); });
  e.print("wheel with occluder");
  // Frames whose 21 px patch the hand touches (the hand within 15 px, the patch's
  // half-diagonal, of the mark's centre) may be lost; all others must be tracked.
  std::vector<int> touched;
  for (int i = 1; i < frames; ++i) {
    const cv::Point2d m = w.mark(i / o.fps);
    const double dx = std::max({hand_box.x - m.x, 0.0, m.x - hand_box.br().x});
    const double dy = std::max({hand_box.y - m.y, 0.0, m.y - hand_box.br().y});
    if (std::hypot(dx, dy) < 15) touched.push_back(i);
  }
  for (int i : e.lost_frames) {
    EXPECT_TRUE(std::find(touched.begin(), touched.end(), i) != touched.end()) << "frame " << i << " lost in the clear";
  }
  std::printf("[ measured ] %zu frames touched by the hand, %d lost\n", touched.size(), e.lost);
  EXPECT_GT(e.lost, 6);  // the mark is fully hidden for about 4 frames in each of 3 passes
  // Tracked frames, hand near or not, stay accurate: measured max 0.122 px (0.059 px in the
  // clear; the hand's edge inside the patch costs a little); 0.3 px, never a wrong match.
  EXPECT_LT(e.max(e.position_px), 0.3);
}

TEST(PointTracker, DoesNotHoldOnToTheTexturedBackgroundABallLeaves) {
  // A 6 px ball in a 21 px patch on a textured background: two thirds of the template are
  // background, which stays where the ball was. Before the first match had to score 0.9, the
  // background left behind (score 0.84) was accepted and held the track, 36-254 px from the
  // ball. Lost frames are acceptable here; a wrong position is not.
  const Throw b;
  RenderOptions o = small_point_video();
  o.background = RenderOptions::Background::texture;
  const Scene scene = [&](double t) { return std::vector<ShapePose>{b.pose(t)}; };
  const Errors e = track_points(scene, o, 8, [&](double t) { return b.at(t); }, [](double) { return 0.0; });
  e.print("ball on a textured background");
  EXPECT_LT(e.max(e.position_px), 0.3);  // any frame reported found must be on the ball
}

TEST(PointTracker, IsNotCapturedByADistractor) {
  // Two identical balls: ours flies on a parabola and hides behind a hand; the other rests
  // near where ours disappears. The track must report the hidden frames, not jump.
  const Throw b;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) {
    ShapePose other = b.pose(0);
    const cv::Point2d mid = b.at(4 / 240.0);
    other.cx_px = mid.x + 6;
    other.cy_px = mid.y + 28;
    ShapePose hand;
    hand.kind = ShapePose::Kind::rectangle;
    hand.cx_px = mid.x;
    hand.cy_px = mid.y - 40;
    hand.a_px = 30;
    hand.b_px = 48;
    hand.colour = cv::Scalar(150, 170, 190);
    return std::vector<ShapePose>{other, b.pose(t), hand};
  };
  const Errors e = track_points(scene, o, 8, [&](double t) { return b.at(t); }, [](double) { return 0.0; });
  e.print("ball with distractor");
  EXPECT_GT(e.lost, 0);
  EXPECT_LT(e.max(e.position_px), 0.1);  // measured 0.030 px; the distractor is 28 px away
}

// A disc with a sticker drifting right at 1 px/frame and turning 2 deg/frame, a hand that
// covers it from frame 10 to 24 (15 frames, more than max_gap_frames = 8), and an identical
// disc resting 130 px to the right: inside the re-acquisition search, outside its gate.
struct HiddenDisc {
  double fps = 240;
  int hand_from = 10, hand_to = 24;
  bool hand_stays = false;  // true: the hand never leaves
  double alike_x = 230;     // the look-alike's centre, px (at y = 120, resting)
  ShapePose disc(double cx, double cy, double angle) const {
    ShapePose s;
    s.cx_px = cx;
    s.cy_px = cy;
    s.a_px = s.b_px = 22;
    s.angle_rad = angle;
    s.colour = cv::Scalar(60, 140, 60);
    s.mark = true;
    s.mark_size_px = 15;
    return s;
  }
  cv::Point2d at(double t) const { return {80 + t * fps, 120}; }
  double turn(double t) const { return to_rad(2) * t * fps; }
  Scene scene() const {
    return [*this](double t) {
      const int frame = static_cast<int>(std::lround(t * fps));
      std::vector<ShapePose> s{disc(at(t).x, at(t).y, 0.3 + turn(t)), disc(alike_x, 120, 0.3)};
      if (frame >= hand_from && (hand_stays || frame <= hand_to)) {
        ShapePose hand;
        hand.kind = ShapePose::Kind::rectangle;
        hand.cx_px = 95;
        hand.cy_px = 120;
        hand.a_px = 40;
        hand.b_px = 60;
        hand.colour = cv::Scalar(150, 170, 190);
        s.push_back(hand);
      }
      return s;
    };
  }
};

TEST(PointTracker, FindsThePointAgainAfterALongOcclusionAndNotTheLookAlike) {
  // Before re-acquisition, the point was given up after 8 lost frames and every later frame
  // was lost. Now it is searched for again and found as soon as the hand has gone; the
  // identical disc 130 px away is never taken, neither while ours is hidden (it is the only
  // match in the image then) nor after.
  const HiddenDisc d;
  const RenderOptions o = small_point_video();
  PointTracker tracker;
  tracker.start(film(d.scene(), 0, o), d.at(0).x, d.at(0).y, "disc");
  Errors e;
  int refound = -1;
  for (int i = 1; i < 40; ++i) {
    const Frame f = film(d.scene(), i, o);
    const Observation ob = tracker.update(f);
    if (ob.refound) {
      EXPECT_EQ(refound, -1) << "found again twice";
      refound = i;
    }
    if (ob.lost) {
      ++e.lost;
      e.lost_frames.push_back(i);
      continue;
    }
    e.position_px.push_back(std::hypot(ob.x_px - d.at(f.t).x, ob.y_px - d.at(f.t).y));
    e.angle_deg.push_back(to_deg(std::abs(ob.angle_rad - d.turn(f.t))));
  }
  e.print("disc hidden 15 frames beside a look-alike");
  std::printf("[ measured ] found again at frame %d\n", refound);
  ASSERT_FALSE(e.lost_frames.empty());
  EXPECT_GE(e.lost_frames.front(), 5);   // the hand's edge reaches the patch at frame ~7
  EXPECT_LE(e.lost_frames.back(), 24);   // nothing lost once the hand has gone
  EXPECT_GT(e.lost, 8);                  // more than max_gap_frames: given up, then found
  EXPECT_EQ(refound, 25);                // the first frame without the hand
  // Every accepted frame is on our disc (the look-alike is 130 px away): 0.2 px is twice the
  // wheel tests' worst error, far below any wrong match.
  EXPECT_LT(e.max(e.position_px), 0.2);
}

// Follows the disc of `d` (whose hand stays) over 40 frames: once lost, it must stay lost (the
// look-alike never taken). Returns the tracker.
PointTracker follow_hidden_for_good(const HiddenDisc& d) {
  const RenderOptions o = small_point_video();
  PointTracker tracker;
  tracker.start(film(d.scene(), 0, o), d.at(0).x, d.at(0).y, "disc");
  int lost_from = -1;
  for (int i = 1; i < 40; ++i) {
    const Observation ob = tracker.update(film(d.scene(), i, o));
    if (ob.lost && lost_from < 0) lost_from = i;
    if (lost_from > 0) {
      EXPECT_TRUE(ob.lost) << "frame " << i << " found at (" << ob.x_px << ", " << ob.y_px << ")";
    }
  }
  EXPECT_GT(lost_from, 0);
  return tracker;
}

TEST(PointTracker, NeverTakesTheLookAlikeWhileThePointStaysHidden) {
  // The same scene with a hand that never leaves: the look-alike is the only match in the
  // image, 130 px from where ours is hidden, and must not be taken.
  HiddenDisc d;
  d.hand_stays = true;
  follow_hidden_for_good(d);
}

TEST(PointTracker, TellsAStillLookAlikeInsideTheGateFromThePoint) {
  // The look-alike rests 50 px from where ours is hidden for good: inside the gate that
  // widens while the point is lost, and the only match there. It looks as its place looked
  // while our disc was elsewhere: still background, so every frame from the loss on is lost
  // (before the scene memory, the look-alike was taken from frame 19 on, 31-51 px from ours).
  HiddenDisc d;
  d.hand_stays = true;
  d.alike_x = 150;
  const PointTracker tracker = follow_hidden_for_good(d);
  EXPECT_NE(tracker.loss_hint().find("still background"), std::string::npos) << tracker.loss_hint();
}

TEST(PointTracker, FollowsTheWheelMarkThroughTheCodec) {
  // Written as MJPG (quality 95) and decoded by OpenCV like a user's video: compression
  // artefacts on top of blur and noise.
  const Wheel w;
  RenderOptions o = small_point_video();
  o.shutter_fraction = 0.5;
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("point_tracker_codec_" + std::to_string(::getpid()) + ".avi");
  const int frames = 24;
  write_video(path.string(), scene, frames, o);
  auto video = open_video_file(path.string());
  ASSERT_TRUE(video);
  PointTracker tracker;
  Errors e;
  for (int i = 0; i < frames; ++i) {
    Frame f;
    f.index = i;
    f.t = i / o.fps;
    ASSERT_TRUE(video->read(f.bgr)) << "frame " << i;
    make_gray(f);
    if (i == 0) {
      tracker.start(f, w.mark(0).x, w.mark(0).y, "mark");
      continue;
    }
    const Observation ob = tracker.update(f);
    if (ob.lost) {
      ++e.lost;
      continue;
    }
    e.position_px.push_back(std::hypot(ob.x_px - w.mark(f.t).x, ob.y_px - w.mark(f.t).y));
    e.angle_deg.push_back(to_deg(std::abs(ob.angle_rad - (w.angle(f.t) - w.angle(0)))));
  }
  video.reset();  // closed before the file is removed
  std::filesystem::remove(path);
  e.print("blurred wheel through MJPG");
  EXPECT_EQ(e.lost, 0);
  // Measured median 0.017, max 0.046 px (MJPG at quality 95 adds little to blur and noise).
  EXPECT_LT(e.median(e.position_px), 0.05);
  EXPECT_LT(e.max(e.position_px), 0.12);
  EXPECT_LT(e.median(e.angle_deg), 0.12);  // measured 0.049 deg
}

TEST(PointTracker, FollowsBallTossFromTheHumansFirstMark) {
  // Tracker's own example (640x480, 15 fps, a small bright ball tossed in front of a hand;
  // not in the repository: docs/theory.md#tracker-files). Started from the human's first
  // mark, the tracker must stay within the scatter of human marks (~1 px) of every other
  // mark. Before the first window grew to a quarter of the image, the 70 px first step
  // left the ball outside it and a match on the hand (score 0.69) was accepted: 47 px off.
  const std::string path = testing::ball_toss_path();
  if (path.empty()) GTEST_SKIP() << "BallToss.trz not found beside the repository";
  // The human's marks in image pixels and the project's video, as `track video` reads them.
  const VideoInput in = open_input(path, {});
  const track::Track* marks = nullptr;
  for (const auto& t : in.marks_px)
    if (t.name == "ball") marks = &t;
  ASSERT_NE(marks, nullptr);
  ASSERT_EQ(marks->points.size(), 11u);  // frames 2..12
  FrameReader reader(in);
  PointTracker tracker;
  std::vector<double> deviation;
  std::size_t next = 0;
  Frame f;
  while (next < marks->points.size() && reader.next(f)) {
    if (f.index < marks->points[0].frame) continue;
    ASSERT_EQ(marks->points[next].frame, f.index);
    const track::TrackPoint& human = marks->points[next++];
    if (next == 1) {
      tracker.start(f, human.x, human.y, "ball");
      continue;
    }
    const Observation ob = tracker.update(f);
    EXPECT_FALSE(ob.lost) << "frame " << f.index;
    deviation.push_back(std::hypot(ob.x_px - human.x, ob.y_px - human.y));
  }
  ASSERT_EQ(next, marks->points.size());
  Errors e;
  e.position_px = deviation;
  e.print("BallToss against the human's marks");
  // Measured median 0.43 px, max 0.68 px (0.26-0.75 px median for starts moved by up to
  // half a pixel: the human's start mark is itself uncertain by that); the issue asks <= 1.5 px median (human marks
  // scatter ~1 px), and no frame may be off by more than that scatter allows.
  EXPECT_LT(e.median(deviation), 1.0);
  EXPECT_LT(e.max(deviation), 1.5);
}

TEST(PointTracker, RejectsAFeaturelessStart) {
  const Wheel w;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  PointTracker tracker;
  const Frame f0 = film(scene, 0, o);
  try {
    tracker.start(f0, 30, 30, "corner");  // plain background with sensor noise
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("corner"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("texture"), std::string::npos) << err.what();
  }
  EXPECT_NO_THROW(tracker.start(f0, w.mark(0).x, w.mark(0).y, "mark"));
}

TEST(PointTracker, RejectsAStartOnAStraightEdge) {
  // The wheel's rim, far from the mark: strong gradient across it, none along it, so the
  // correlation is flat along the edge (aperture problem) and the start is refused.
  const Wheel w;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  PointTracker tracker;
  const Frame f0 = film(scene, 0, o);
  EXPECT_THROW(tracker.start(f0, w.cx, w.cy + w.radius, "rim"), InputError);
}

TEST(PointTracker, ReportsABallLeavingTheViewAsLost) {
  // The thrown ball leaves the 320 px frame after frame 8: the following frames are lost
  // (the prediction runs on outside the image), never placed on something else, and the
  // tracker gives up after max_gap_frames.
  const Throw b;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{b.pose(t)}; };
  PointTrackerOptions options;
  options.max_gap_frames = 2;
  const Errors e = track_points(scene, o, 14, [&](double t) { return b.at(t); }, [](double) { return 0.0; }, options);
  e.print("ball leaving the view");
  ASSERT_EQ(e.lost_frames.size(), 5u);
  EXPECT_EQ(e.lost_frames.front(), 9);  // x = 20 + 36 * 9 = 344 px: outside
  EXPECT_LT(e.max(e.position_px), 0.1);  // measured 0.007 px while in view
}

TEST(PointTracker, ValidatesItsOptions) {
  PointTrackerOptions o;
  EXPECT_EQ(o.validate(), "");
  o.patch_px = 20;
  EXPECT_NE(o.validate().find("patch_px"), std::string::npos);
  o = {};
  o.min_score = 1.5;
  EXPECT_NE(o.validate().find("min_score"), std::string::npos);
  o = {};
  o.max_turn_deg = -1;
  EXPECT_THROW(PointTracker{o}, InputError);
  // Regression (issue 26): 1e308 was echoed with 309 digits (std::to_string).
  o.max_turn_deg = 1e308;
  EXPECT_EQ(o.validate(), "max_turn_deg must lie in [0, 90], got 1e+308");
  o = {};
  o.step_s = -0.01;
  EXPECT_EQ(o.validate(), "step_s must be >= 0 (0: unknown), got -0.01");
  o.step_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(o.validate().find("step_s"), std::string::npos);
}

TEST(PointTracker, RejectsAStartOutsideTheImage) {
  const Wheel w;
  const RenderOptions o = small_point_video();
  const Scene scene = [&](double t) { return std::vector<ShapePose>{w.pose(t)}; };
  PointTracker tracker;
  const Frame f0 = film(scene, 0, o);
  EXPECT_THROW(tracker.start(f0, 400, 100, "mark"), InputError);
  EXPECT_THROW(tracker.start(f0, -1, 100, "mark"), InputError);
  EXPECT_THROW(tracker.start(f0, 5, 100, "mark"), InputError);  // pattern cut by the border
  EXPECT_THROW(tracker.update(f0), InputError);                 // never started
}

TEST(MotionModel, PredictsAParabolaExactly) {
  MotionModel m;
  for (int i = 0; i < 4; ++i) m.add(i, 3 + 2 * i + 0.5 * i * i, 1 - i, 0.1 * i);
  const MotionState s = m.predict(6);
  EXPECT_NEAR(s.x_px, 3 + 12 + 18, 1e-9);  // exact polynomial: rounding only
  EXPECT_NEAR(s.y_px, -5, 1e-9);
  EXPECT_NEAR(s.angle_rad, 0.6, 1e-9);
  EXPECT_NEAR(s.vx_px, 2 + 6, 1e-9);
}

TEST(MotionModel, PredictsAMarkOnATurningWheelExactly) {
  // A mark 40 px from the hub of a wheel rolling right at 3 px/frame and turning 25 deg/frame:
  // the turning-body model reproduces it to rounding; a parabola through the same five
  // positions misses by several px (third derivative of the circle).
  const double w = to_rad(25);
  auto at = [&](int i) {
    const double a = 0.2 + w * i;
    return cv::Point2d(100 + 3 * i + 40 * std::cos(a), 80 - 40 * std::sin(a));
  };
  MotionModel m;
  for (int i = 0; i < 5; ++i) m.add(i, at(i).x, at(i).y, w * i);
  const MotionState s = m.predict(7);
  EXPECT_NEAR(s.x_px, at(7).x, 1e-9);
  EXPECT_NEAR(s.y_px, at(7).y, 1e-9);
  EXPECT_NEAR(s.angle_rad, 7 * w, 1e-12);
  MotionModel no_turn;  // the same positions with the angles unknown (all 0): parabola
  for (int i = 0; i < 5; ++i) no_turn.add(i, at(i).x, at(i).y, 0);
  const MotionState p = no_turn.predict(7);
  EXPECT_GT(std::hypot(p.x_px - at(7).x, p.y_px - at(7).y), 5.0);
}

}  // namespace
}  // namespace tribolab::video
