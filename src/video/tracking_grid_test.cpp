// Tracking over a grid of ordinary throws (docs/benchmarks.md#tracking-over-a-grid-of-throws):
// not chosen cases but every throw of a seeded grid of releases, frame rates and sizes, each
// rendered on texture with a checker sticker, the sticker and the ball's centre followed by
// the default point tracker (the path tracker) from their true places in the first frame, and
// the ball by the ellipse tracker (track video --ellipse) from its true centre.
#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "video/codec.hpp"
#include "video/ellipse_tracker.hpp"
#include "video/path_tracker.hpp"
#include "video/point_tracker.hpp"
#include "video/render.hpp"
#include "video/render_throw.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace tribolab::video {
namespace {

struct GridRun {
  int frames = 0, lost = 0, wrong = 0;  // wrong: reported farther than 10 px per 640 px of width
  double worst_px = 0;
  double worst_deg = 0;  // the ellipse tracker: the orientation's largest error (modulo 180 degrees)
  std::string hint;  // the tracker's loss hint
};

// Follows one point (`truth` per frame) over the film's frames, with the path tracker (the
// default) or the frame tracker (`frame_tracker`, track video's --point-tracker frame).
GridRun follow(const ThrowFilm& film, const std::vector<Frame>& frames, const std::vector<cv::Point2d>& truth,
               bool frame_tracker) {
  std::vector<Observation> obs;
  std::string hint;
  int patch = 0;
  if (frame_tracker) {
    PointTrackerOptions fo;
    fo.step_s = 1 / film.render.fps;  // as track video gives it
    PointTracker tracker(fo);
    try {
      tracker.start(frames[0], truth[0].x, truth[0].y, "point");
      for (std::size_t k = 1; k < frames.size(); ++k) obs.push_back(tracker.update(frames[k]));
      hint = tracker.loss_hint();
    } catch (const std::exception& e) {
      hint = e.what();
      for (std::size_t k = obs.size() + 1; k < frames.size(); ++k) {
        Observation o;
        o.frame = static_cast<int>(k);
        o.lost = true;
        obs.push_back(o);
      }
    }
  } else {
    PathTrackerOptions po;
    po.step_s = 1 / film.render.fps;  // as track video gives it, from the clip's time base
    PathTracker tracker(po);
    tracker.start(frames[0], truth[0].x, truth[0].y, "point");
    for (std::size_t k = 1; k < frames.size(); ++k) tracker.update(frames[k]);
    obs = tracker.finish();
    hint = tracker.loss_hint();
    patch = tracker.patch_px();
  }
  GridRun r;
  const double wrong_px = 10.0 * film.render.width / 640.0;
  for (const Observation& o : obs) {
    ++r.frames;
    if (o.lost) {
      ++r.lost;
      continue;
    }
    const cv::Point2d t = truth[static_cast<std::size_t>(o.frame)];
    const double d = std::hypot(o.x_px - t.x, o.y_px - t.y);
    if (std::getenv("GRID_VERBOSE")) {
      std::printf("    frame %2d: (%.1f, %.1f) truth (%.1f, %.1f) %.1f px, score %.3f\n", o.frame, o.x_px, o.y_px, t.x,
                  t.y, d, o.score);
    }
    r.worst_px = std::max(r.worst_px, d);
    if (d > wrong_px) ++r.wrong;
  }
  if (r.lost * 2 > r.frames) std::printf("  hint: %s (patch %d px)\n", plain_fields(hint).c_str(), patch);
  r.hint = hint;
  return r;
}

// The clip as a phone or a messenger leaves it (GRID_H264=1): encoded as H.264 and decoded
// again. Empty when this FFmpeg has no H.264 encoder.
std::vector<Frame> through_h264(const std::vector<Frame>& clip, double fps) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("tribolab_grid_h264_" + std::to_string(::getpid()) + ".mp4")).string();
  std::vector<Frame> out;
  {
    const auto w = create_video_file(path, fourcc('a', 'v', 'c', '1'), fps, frame_size(clip[0]));
    if (!w) return out;
    for (const Frame& f : clip) w->write(f.bgr);
  }
  if (const auto r = open_video_file(path)) {
    cv::Mat bgr;
    for (const Frame& f : clip) {
      if (!r->read(bgr)) break;
      Frame g;
      g.index = f.index;
      g.t = f.t;
      g.bgr = bgr.clone();
      out.push_back(std::move(g));
    }
  }
  std::filesystem::remove(path);
  if (out.size() != clip.size()) out.clear();
  return out;
}

// Follows the ball with the ellipse tracker from its true centre in the first frame: the centre
// against the truth, and where the ball is not round, the major axis against the truth's modulo
// 180 degrees (both counter-clockwise on screen).
GridRun follow_ball(const ThrowFilm& film, const std::vector<Frame>& frames, const std::vector<cv::Point2d>& centre) {
  std::vector<EllipseObservation> obs;
  GridRun r;
  EllipseTracker tracker;
  try {
    tracker.start(frames[0], centre[0].x, centre[0].y, "ball");
    for (std::size_t k = 1; k < frames.size(); ++k) obs.push_back(tracker.update(frames[k]));
    r.hint = tracker.loss_hint();
  } catch (const std::exception& e) {
    r.hint = e.what();
    const std::size_t done = obs.size();
    obs.resize(frames.size() - 1);
    for (std::size_t k = done; k < obs.size(); ++k) obs[k].centre.lost = true;
  }
  const double wrong_px = 10.0 * film.render.width / 640.0;
  for (std::size_t k = 0; k < obs.size(); ++k) {
    const EllipseObservation& e = obs[k];
    ++r.frames;
    if (e.centre.lost) {
      ++r.lost;
      continue;
    }
    const cv::Point2d t = centre[k + 1];
    const double d = std::hypot(e.centre.x_px - t.x, e.centre.y_px - t.y);
    r.worst_px = std::max(r.worst_px, d);
    if (d > wrong_px) ++r.wrong;
    if (e.round) continue;
    const double truth_rad = film.scene(frames[k + 1].t).front().angle_rad;
    const double off_deg = to_deg(std::abs(std::remainder(e.centre.angle_rad - truth_rad, kPi)));
    if (std::getenv("GRID_VERBOSE")) std::printf("    ball frame %2zu: %.2f px, orientation %.2f deg\n", k + 1, d, off_deg);
    r.worst_deg = std::max(r.worst_deg, off_deg);
  }
  if (r.lost * 2 > r.frames) std::printf("  hint: %s\n", plain_fields(r.hint).c_str());
  return r;
}

// 12 throws: heights 0.5-1.2 m, release angles +-60 deg, spins up to 50 rad/s either way,
// 0.5-2.5 m/s across, at 60, 120 and 240 fps, 480x360 px. Measured 6 Dec 2026 with the path
// tracker: no frame confidently wrong (farther than 10 px per 640 px of width); lost 38.0 % of
// the sticker's frames (349 of 918: it spins 20-45 degrees per frame at 60 fps, beyond the
// turns the path tracker searches) and 62.2 % of the centre's (571 of 918: a 91 px template of
// a plain turning ellipse, the ellipse tracker's case). The frame tracker loses 3.9 % of the
// sticker's frames but places 3 of them 70 px off. With a spinning look's turn rate
// (Look::expected, the same night): lost 19.6 % of the sticker's frames (180 of 918; the 60
// fps throws, 20-45 degrees per frame, still mostly lost, and throw 4's 11 px sticker in all
// 61 frames, as before) and 27.5 % of the
// centre's (252), none wrong. With the reach a speed (given the clip's time base, as track
// video gives it), the last confident sighting searched while the object is lost, and the
// background check measured against the object where it was clicked (a path of 34 still
// texture points after 26 on the sticker had made the path's median the texture's: throw 4):
// lost 12.5 % of the sticker's frames (115; throws 0 and 6 at 60 fps 28 -> 3 and 27 -> 17,
// throw 4 61 -> 36), the centre's as before, none wrong. With a step's best three by cost on
// a quick difference from the background also anchors where nothing was confident (7 Dec
// 2026): the sticker's 9.0 % (83; throw 4 36 -> 5, throw 10 5 -> 4), the centre's as before,
// none wrong. The frame tracker (the tracker a lost sticker's hint names) follows the sticker
// as well since that day: with still texture told from the object (SceneMemory: a match that
// shows what its place showed when the object was elsewhere is lost), 4.4 % of the sticker's
// frames lost (40), none wrong (3 wrong before, up to 71 px: throw 3). With a path tracker's
// template never under 15 px a side (the blurred sticker's 9-11 px ones lost to still
// texture), the sticker's 7.0 % (64; throw 3 at 60 fps 21 -> 2, throw 4 5 -> 7), none wrong.
// The ball by the ellipse tracker (the ball's centre and spin: the bounce study's case), with
// its fit bar at 0.55 (0.6 before): no frame lost (8 of 918 at 0.6), none wrong, orientation
// within 3.1 degrees of the truth. The lost shares and the orientation's bound below are
// regression bounds, not goals.
// GRID_ONLY=i runs throw i alone (the same throw: its parameters are drawn all the same; the
// bounds are not checked then); GRID_FPS=f films every throw at f frames per second and
// GRID_H264=1 passes every clip through H.264 (the bounds are not checked then either: at 30
// fps both trackers lose most sticker frames; docs/benchmarks.md, "A template's least size");
// GRID_VERBOSE=1 prints every reported point against the truth, with its score.
TEST(TrackingGrid, OrdinaryThrowsAreFollowedAndNeverConfidentlyWrong) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> height(0.5, 1.2), theta(-60, 60), omega(-50, 50), vx(0.5, 2.5);
  const int fps_choice[] = {60, 120, 240};
  int frames[4] = {}, lost[4] = {}, wrong[4] = {};
  int ball_frames = 0, ball_lost = 0, ball_wrong = 0;
  double ball_worst_deg = 0;
  const int n = std::getenv("GRID_N") ? std::atoi(std::getenv("GRID_N")) : 12;
  const double fps = std::getenv("GRID_FPS") ? std::atof(std::getenv("GRID_FPS")) : 0;
  for (int i = 0; i < n; ++i) {
    ThrowFilmOptions o;
    o.motion.height = height(rng);
    o.motion.theta_deg = theta(rng);
    o.motion.omega = omega(rng);
    o.motion.vx = vx(rng);
    if (std::getenv("GRID_ONLY") && i != std::atoi(std::getenv("GRID_ONLY"))) continue;
    o.motion.after = 0.15;
    o.motion.seed = static_cast<std::uint64_t>(i + 1);
    o.render.fps = fps ? fps : fps_choice[i % 3];
    o.render.width = 480;
    o.render.height = 360;
    o.render.background = RenderOptions::Background::texture;
    o.render.supersample = 2;
    o.render.seed = static_cast<std::uint64_t>(i + 1);
    o.sticker = true;
    const ThrowFilm film = plan_throw_film(o);
    std::vector<Frame> clip;
    std::vector<cv::Point2d> sticker, centre;
    for (int k = 0; k < film.frames; ++k) {
      Frame f;
      f.index = k;
      f.t = k / o.render.fps;
      f.bgr = render_frame(film.scene, f.t, film.render, k);
      clip.push_back(f);
      const ShapePose s = film.scene(f.t).front();
      centre.push_back({s.cx_px, s.cy_px});
      sticker.push_back({s.cx_px + s.mark_u_px * std::cos(s.angle_rad), s.cy_px - s.mark_u_px * std::sin(s.angle_rad)});
    }
    if (std::getenv("GRID_H264")) {
      clip = through_h264(clip, o.render.fps);
      ASSERT_FALSE(clip.empty()) << "no H.264 round trip here";
    }
    // Runs: the sticker and the centre by the path tracker, the sticker by the frame tracker
    // (the tracker a lost sticker's hint names), and, with GRID_FRAME=1 (for the comparison in
    // docs/benchmarks.md, not checked: a plain ball's centre is the ellipse tracker's case), the
    // centre by the frame tracker.
    const int runs = std::getenv("GRID_FRAME") ? 4 : 3;
    for (int which = 0; which < runs; ++which) {
      const bool on_sticker = which % 2 == 0, by_frame = which >= 2;
      const GridRun r = follow(film, clip, on_sticker ? sticker : centre, by_frame);
      std::printf("throw %2d (%3.0f fps, h %.2f m, theta %5.1f deg, omega %5.1f rad/s, vx %.2f m/s) %s%s: %d frames, lost %d, wrong %d, worst %.2f px\n",
                  i, o.render.fps, o.motion.height, o.motion.theta_deg, o.motion.omega, o.motion.vx,
                  on_sticker ? "sticker" : "centre", by_frame ? " (frame tracker)" : "", r.frames, r.lost, r.wrong,
                  r.worst_px);
      frames[which] += r.frames;
      lost[which] += r.lost;
      wrong[which] += r.wrong;
      if (which == 3) continue;
      // Every tracker says why it lost frames.
      if (r.lost > 0) {
        EXPECT_FALSE(r.hint.empty()) << "throw " << i << " run " << which;
      }
      EXPECT_EQ(r.wrong, 0) << "throw " << i << (on_sticker ? " sticker" : " centre")
                            << (by_frame ? " by the frame tracker" : "");
      // A spinning sticker lost in most frames: the hint names the trackers that follow it, or
      // the ball it is on.
      if (which == 0 && r.lost * 2 > r.frames) {
        EXPECT_NE(plain_fields(r.hint).find("point_tracker frame"), std::string::npos) << plain_fields(r.hint);
        EXPECT_NE(plain_fields(r.hint).find("a mark on a ball, ellipse"), std::string::npos) << plain_fields(r.hint);
      }
    }
    // The ball by the ellipse tracker: never confidently wrong, and says why it lost frames.
    const GridRun b = follow_ball(film, clip, centre);
    std::printf("throw %2d (%3.0f fps) ball (ellipse tracker): %d frames, lost %d, wrong %d, worst %.2f px, orientation worst %.1f deg\n",
                i, o.render.fps, b.frames, b.lost, b.wrong, b.worst_px, b.worst_deg);
    ball_frames += b.frames;
    ball_lost += b.lost;
    ball_wrong += b.wrong;
    ball_worst_deg = std::max(ball_worst_deg, b.worst_deg);
    EXPECT_EQ(b.wrong, 0) << "throw " << i << " ball";
    if (b.lost > 0) {
      EXPECT_FALSE(b.hint.empty()) << "throw " << i << " ball";
    }
  }
  const char* name[4] = {"sticker", "centre", "sticker (frame tracker)", "centre (frame tracker)"};
  std::printf("%d throws:", n);
  for (int which = 0; which < 4; ++which) {
    if (frames[which] == 0) continue;
    std::printf("%s %s lost %d of %d (%.1f %%), wrong %d", which ? ";" : "", name[which], lost[which], frames[which],
                100.0 * lost[which] / frames[which], wrong[which]);
  }
  std::printf("; ball (ellipse tracker) lost %d of %d (%.1f %%), wrong %d, orientation worst %.1f deg\n", ball_lost,
              ball_frames, 100.0 * ball_lost / std::max(1, ball_frames), ball_wrong, ball_worst_deg);
  if (n == 12 && !std::getenv("GRID_ONLY") && fps == 0 && !std::getenv("GRID_H264")) {
    EXPECT_LE(double(lost[0]) / frames[0], 0.08);
    EXPECT_LE(double(lost[1]) / frames[1], 0.30);
    EXPECT_LE(double(lost[2]) / frames[2], 0.06);
    EXPECT_LE(double(ball_lost) / ball_frames, 0.005);
    EXPECT_LE(ball_worst_deg, 5);
  }
}

}  // namespace
}  // namespace tribolab::video
