// EllipseTracker on rendered scenes with known truth (docs/theory.md#ellipse-tracking).
#include "video/ellipse_tracker.hpp"
#include "video/codec.hpp"

#include "numerics/units.hpp"

#include "numerics/error.hpp"
#include "video/ellipse_fit.hpp"
#include "video/render.hpp"
#include "video/test_videos.hpp"
#include "numerics/statistics.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <numbers>
#include <vector>

namespace tribolab::video {
namespace {

/// Frame `index` of the scene (test_videos.hpp).
constexpr auto& frame_at = testing::rendered_frame;

RenderOptions small_video() {
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.fps = 240;
  o.shutter_fraction = 0.5;
  o.noise_sigma = 2;
  o.background = RenderOptions::Background::plain;
  return o;
}

ShapePose ball(double x, double y, double a, double b, double angle) {
  ShapePose p;
  p.cx_px = x, p.cy_px = y, p.a_px = a, p.b_px = b, p.angle_rad = angle;
  p.colour = cv::Scalar(40, 40, 200);
  return p;
}

struct TrackRun {
  std::vector<EllipseObservation> obs;
  std::vector<double> centre_err_px, angle_err_rad;  ///< per frame not lost
  int lost = 0;
};

/// Tracks the first shape of `scene` from its true centre in frame 0 over `frames` frames and
/// compares with the truth (angle error modulo 2 pi: the labels must follow the body x-axis).
TrackRun track(const Scene& scene, int frames, const RenderOptions& o, const EllipseTrackerOptions& eo = {}) {
  TrackRun run;
  EllipseTracker tracker(eo);
  for (int i = 0; i < frames; ++i) {
    const Frame f = frame_at(scene, i, o);
    const ShapePose truth = scene(f.t).front();
    const EllipseObservation e =
        i == 0 ? tracker.start(f, truth.cx_px, truth.cy_px, "ball") : tracker.update(f);
    run.obs.push_back(e);
    if (e.centre.lost) {
      ++run.lost;
      continue;
    }
    run.centre_err_px.push_back(std::hypot(e.centre.x_px - truth.cx_px, e.centre.y_px - truth.cy_px));
    run.angle_err_rad.push_back(std::remainder(e.centre.angle_rad - truth.angle_rad, 2 * kPi));
  }
  return run;
}

TEST(EllipseFit, BoxConventionGivesMajorAxisDirection) {
  // OpenCV's RotatedRect: `width` runs along angle (degrees, image coordinates, y down).
  const Ellipse e = ellipse_from_box(cv::RotatedRect({10, 20}, {20, 60}, 30));
  EXPECT_DOUBLE_EQ(e.a, 30);
  EXPECT_DOUBLE_EQ(e.b, 10);
  EXPECT_NEAR(e.psi, to_rad(30 + 90 - 180), 1e-6);  // mod pi, in [-pi/2, pi/2]
}

TEST(EllipseFit, SharpEllipseIsFittedToAHundredthOfAPixel) {
  RenderOptions o = small_video();
  o.noise_sigma = 0;
  o.shutter_fraction = 0;
  o.supersample = 8;  // at 4x the renderer's own aliasing tilts the outline by 0.001 rad
  for (const double angle : {0.4, 1.1, -0.7}) {
    const Scene scene = [&](double) { return std::vector<ShapePose>{ball(150.3, 110.7, 40, 25, angle)}; };
    const Frame f = frame_at(scene, 0, o);
    cv::Mat fimg, dist;
    f.bgr.convertTo(fimg, CV_32FC3);
    const cv::Mat diff = fimg - cv::Scalar(40, 40, 200);
    std::vector<cv::Mat> ch;
    cv::split(diff.mul(diff), ch);
    cv::sqrt(ch[0] + ch[1] + ch[2], dist);
    const Ellipse init{148, 112, 37, 27, -angle + 0.1};  // a rough start, as from the segmentation
    EdgeFitOptions eo;
    eo.min_contrast = 50;
    const EdgeFit fit = fit_ellipse_edges(dist, {0, 0}, init, eo);
    ASSERT_TRUE(fit.ok);
    // Measured at 8x supersampling: centre within 0.005 px, axes within 0.013 px (the pixel
    // and bilinear smoothing of the curved outline), orientation within 1e-4 rad; the
    // tolerances are about twice that.
    EXPECT_NEAR(fit.ellipse.cx, 150.3, 0.01);
    EXPECT_NEAR(fit.ellipse.cy, 110.7, 0.01);
    EXPECT_NEAR(fit.ellipse.a, 40, 0.025);
    EXPECT_NEAR(fit.ellipse.b, 25, 0.025);
    EXPECT_NEAR(std::remainder(fit.ellipse.psi + angle, kPi), 0, 2e-4);  // psi is in image axes (y down)
    EXPECT_EQ(fit.inliers, fit.profiles);
  }
}

/// Seed 001's rugby ball: 40 rad/s at 240 fps (0.167 rad per frame), shutter half the frame
/// period (blur of 4.8 degrees, 3.3 px at the tips), noise sd 2 grey levels, drifting on a
/// parabola; frames from `o`'s background.
struct SpinResult {
  double centre_px, angle_deg, worst_angle_rad;
  int lost;
};
SpinResult spinning_ball(const RenderOptions& o, int frames = 48) {
  const Scene scene = [](double t) {
    return std::vector<ShapePose>{ball(100 + 300 * t, 80 + 200 * t - 0.5 * 1000 * t * t, 40, 25, 0.3 + 40 * t)};
  };
  const TrackRun run = track(scene, frames, o);
  std::vector<double> abs_angle;
  for (double a : run.angle_err_rad) abs_angle.push_back(std::abs(a));
  return {median(run.centre_err_px), to_deg(median(abs_angle)),
          abs_angle.empty() ? 0 : *std::max_element(abs_angle.begin(), abs_angle.end()), run.lost};
}

TEST(EllipseTracker, SpinningBallAt40RadPerSecondWithBlurAndNoise) {
  RenderOptions o = small_video();
  o.background = RenderOptions::Background::gradient;  // the renderer's default
  const SpinResult r = spinning_ball(o);
  RecordProperty("median_centre_error_px", std::to_string(r.centre_px));
  RecordProperty("median_angle_error_deg", std::to_string(r.angle_deg));
  std::printf("spin 40 rad/s: median centre error %.4f px, orientation %.4f deg, worst %.4f deg\n", r.centre_px,
              r.angle_deg, to_deg(r.worst_angle_rad));
  EXPECT_EQ(r.lost, 0);
  // The requirement is 0.5 px and 0.5 degree; measured 0.012 px and 0.014 degree, so
  // 0.05 px and 0.07 degree catch a regression by a factor of 4-5.
  EXPECT_LE(r.centre_px, 0.05);
  EXPECT_LE(r.angle_deg, 0.07);
  // Labels: every frame's A is the body's +x tip (error modulo 2 pi, not pi); worst frame
  // measured 0.046 degree = 0.0008 rad.
  EXPECT_LT(r.worst_angle_rad, 0.005);
}

TEST(EllipseTracker, SpinningBallOnATexturedBackground) {
  // A smooth random texture (+-25 % at a 12 px scale) behind the ball: the background next to
  // the edge differs from the one a few px farther out.
  RenderOptions o = small_video();
  o.background = RenderOptions::Background::texture;
  const SpinResult r = spinning_ball(o);
  std::printf("spin 40 rad/s, texture: median centre error %.4f px, orientation %.4f deg, worst %.4f deg\n",
              r.centre_px, r.angle_deg, to_deg(r.worst_angle_rad));
  EXPECT_EQ(r.lost, 0);
  // Measured 0.054 px and 0.084 degree (worst frame 0.34 degree = 0.006 rad): the issue's
  // 0.5 px and 0.5 degree hold; a margin of about 3 for another texture seed.
  EXPECT_LE(r.centre_px, 0.15);
  EXPECT_LE(r.angle_deg, 0.25);
  EXPECT_LT(r.worst_angle_rad, 0.02);
}

TEST(EllipseTracker, SpinningBallDecodedFromCompressedVideo) {
  // The same throw written by write_video (MJPG q95 .avi, mp4v .mp4: 4:2:0 chroma, blocks) and
  // decoded by OpenCV, as `track video` sees it.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() /
                       ("ellipse_tracker_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                        "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  RenderOptions o = small_video();
  o.background = RenderOptions::Background::gradient;
  const Scene scene = [](double t) {
    return std::vector<ShapePose>{ball(100 + 300 * t, 80 + 200 * t - 0.5 * 1000 * t * t, 40, 25, 0.3 + 40 * t)};
  };
  for (const char* name : {"throw.avi", "throw.mp4"}) {
    const std::string path = (dir / name).string();
    write_video(path, scene, 24, o);
    const auto cap = open_video_file(path);
    ASSERT_TRUE(cap) << path;
    EllipseTracker tracker;
    std::vector<double> centre, angle;
    Frame f;
    for (int i = 0; cap->read(f.bgr); ++i) {
      f.index = i;
      f.t = i / o.fps;
      make_gray(f);
      const ShapePose truth = scene(f.t).front();
      const EllipseObservation e = i == 0 ? tracker.start(f, truth.cx_px, truth.cy_px, "ball") : tracker.update(f);
      EXPECT_FALSE(e.centre.lost) << name << " frame " << i;
      centre.push_back(std::hypot(e.centre.x_px - truth.cx_px, e.centre.y_px - truth.cy_px));
      angle.push_back(std::abs(std::remainder(e.centre.angle_rad - truth.angle_rad, 2 * kPi)));
    }
    EXPECT_EQ(centre.size(), 24u) << name;
    std::printf("%s: median centre error %.4f px, orientation %.4f deg\n", name, median(centre),
                to_deg(median(angle)));
    // Measured (avi, mp4) 0.022, 0.030 px and 0.021, 0.042 degree; 0.1 px and 0.15 degree
    // leave a margin of 3 (codec versions differ) within the 0.5 px and 0.5 degree.
    EXPECT_LE(median(centre), 0.1) << name;
    EXPECT_LE(to_deg(median(angle)), 0.15) << name;
  }
  fs::remove_all(dir);
}

TEST(EllipseTracker, LabelsStayOnTheSameTipsOverFiveTurns) {
  // 0.5 rad per frame (120 rad/s at 240 fps): 60 frames are 30 rad, almost five turns.
  RenderOptions o = small_video();
  const Scene scene = [](double t) { return std::vector<ShapePose>{ball(160, 120, 36, 20, -1.2 + 120 * t)}; };
  const TrackRun run = track(scene, 60, o);
  EXPECT_EQ(run.lost, 0);
  ASSERT_EQ(run.angle_err_rad.size(), 60u);
  std::vector<double> abs_angle;
  for (double a : run.angle_err_rad) abs_angle.push_back(std::abs(a));
  std::printf("spin 0.5 rad/frame: median centre error %.4f px, orientation %.4f deg, worst %.4f deg\n",
              median(run.centre_err_px), to_deg(median(abs_angle)),
              to_deg(*std::max_element(abs_angle.begin(), abs_angle.end())));
  for (std::size_t i = 0; i < run.angle_err_rad.size(); ++i) {
    // A wrong label is an error of pi; with 15 degrees of blur per frame the orientation is
    // still within 0.15 degree (measured worst; median 0.022), so 0.05 rad separates the two.
    EXPECT_LT(std::abs(run.angle_err_rad[i]), 0.05) << "frame " << i;
  }
  // A's screen angle unwraps with the spin: 29.5 rad after 59 frames.
  EXPECT_NEAR(run.obs.back().centre.angle_rad - run.obs.front().centre.angle_rad, 59 * 0.5, 0.05);
}

TEST(EllipseTracker, ABounceThatChangesTheSpinIsFollowedWithTheNewSpin) {
  // A ball turning 1.45 rad (83 degrees) per frame falls and bounces between frames 10 and 11;
  // the bounce turns its spin to -0.6 rad (-34 degrees) per frame. An ellipse looks the same
  // after half a turn, so each frame's turn is known only modulo 180 degrees: taken nearest the
  // old spin's prediction, the new one was read as +146 degrees per frame (a rugby ball's
  // -19 rad/s at 30 fps as +75 rad/s, docs/theory.md#ellipse-tracking, item 7). The bounce
  // restarts the spin model with the motion model.
  RenderOptions o = small_video();
  o.fps = 30;
  o.shutter_fraction = 0.25;
  constexpr double kBounce = 10.5, kSpinIn = 1.45, kSpinOut = -0.6;  // frame; rad per frame
  const Scene scene = [&](double t) {
    const double f = t * 30;
    const double g = 0.9, vy_in = 2 * g * kBounce;  // px per frame^2, px per frame down at the floor
    const double y_floor = 40 + g * kBounce * kBounce, turned = 0.3 + kSpinIn * kBounce;
    if (f < kBounce) return std::vector<ShapePose>{ball(60 + 10 * f, 40 + g * f * f, 30, 18, 0.3 + kSpinIn * f)};
    const double s = f - kBounce;
    return std::vector<ShapePose>{ball(60 + 10 * f, y_floor - 0.6 * vy_in * s + g * s * s, 30, 18, turned + kSpinOut * s)};
  };
  const TrackRun run = track(scene, 20, o);
  EXPECT_EQ(run.lost, 0);
  ASSERT_EQ(run.obs.size(), 20u);
  for (int i = 0; i < 20; ++i) {
    if (i == 10 || i == 11) continue;  // the frames about the bounce, their exposure across it
    const double err = std::remainder(run.obs[i].centre.angle_rad - scene(i / 30.0).front().angle_rad, 2 * kPi);
    EXPECT_LT(std::abs(err), 0.1) << "frame " << i;  // a wrong label is off by pi
  }
}

TEST(EllipseTracker, ABlurredBouncingBallIsReportedAtEachFramesTime) {
  // A tilted ball falling ever faster at 30 fps (1.5 px/frame^2, up to 30 px per frame) bounces
  // between frames 10 and 11 (no exposure spans the bounce) with a new spin, filmed with
  // exposures of a quarter to three quarters of the frame period. A profile's edge is the
  // moving outline's mean crossing of a fixed normal line: where the outline slides along
  // itself (the tips) it lies inside the ellipse at mid-exposure, so a fit to the edges turns
  // the ball towards the motion, most in the fastest frames, just before and after the bounce;
  // and frame 0, fitted before any motion is known with edge windows for a sharp edge, is
  // 0.36 degrees off at 0.75 until it is refitted with the motion the next frame gives.
  // The pass over the whole track (at_frame_time) reads the exposure from the edge ramps, the
  // motion from each frame's neighbours in its flight, and refits each frame from its edge
  // points moved to the outline at its time: the first frames after the bounce included, which
  // a correction made while tracking cannot do (docs/theory.md#ellipse-tracking, item 4).
  constexpr double kBounce = 10.5, kG = 0.75;  // frame; px per frame^2
  const Scene scene = [](double t) {
    const double f = t * 30;
    if (f < kBounce) return std::vector<ShapePose>{ball(100 + 6 * f, 40 + 5 * f + kG * f * f, 36, 24, 0.5 + 0.05 * f)};
    const double s = f - kBounce, vy_in = 5 + 2 * kG * kBounce;
    const double y_floor = 40 + 5 * kBounce + kG * kBounce * kBounce;
    return std::vector<ShapePose>{ball(100 + 6 * f, y_floor - 0.6 * vy_in * s + kG * s * s, 36, 24, 0.5 + 0.05 * kBounce - 0.1 * s)};
  };
  for (const double shutter : {0.25, 0.5, 0.75}) {
    RenderOptions o;
    o.width = 480;
    o.height = 480;
    o.fps = 30;
    o.shutter_fraction = shutter;
    o.blur_samples = 32;
    o.noise_sigma = 1;
    o.background = RenderOptions::Background::plain;
    EllipseTracker tracker;
    std::vector<EllipseObservation> seen;
    std::vector<ShapePose> truth;
    for (int i = 0; i < 20; ++i) {
      const Frame f = frame_at(scene, i, o);
      truth.push_back(scene(f.t).front());
      seen.push_back(i == 0 ? tracker.start(f, truth[0].cx_px, truth[0].cy_px, "ball") : tracker.update(f));
      ASSERT_FALSE(seen.back().centre.lost) << "shutter " << shutter << " frame " << i;
    }
    const EllipseTracker::AtFrameTime at = tracker.at_frame_time();
    const auto worst = [&](const std::vector<EllipseObservation>& obs, double& deg, double& px) {
      deg = px = 0;
      for (const EllipseObservation& e : obs) {
        const ShapePose& t = truth[static_cast<std::size_t>(e.centre.frame)];
        deg = std::max(deg, to_deg(std::abs(std::remainder(e.centre.angle_rad - t.angle_rad, 2 * kPi))));

        px = std::max(px, std::hypot(e.centre.x_px - t.cx_px, e.centre.y_px - t.cy_px));
      }
    };
    std::vector<EllipseObservation> corrected = seen;
    for (const EllipseObservation& e : at.poses) corrected[static_cast<std::size_t>(e.centre.frame)] = e;
    double raw_deg = 0, raw_px = 0, deg = 0, px = 0;
    worst(seen, raw_deg, raw_px);
    worst(corrected, deg, px);
    std::printf("shutter %.2f: exposure read %.3f, %zu frames corrected; worst orientation %.2f -> %.2f deg, "
                "worst centre %.3f -> %.3f px\n",
                shutter, at.exposure, at.poses.size(), raw_deg, deg, raw_px, px);
    EXPECT_NEAR(at.exposure, shutter, 0.03);
    EXPECT_LE(deg, 0.3);
    EXPECT_LE(px, 0.3);
    if (shutter >= 0.5) {
      EXPECT_GT(raw_deg, 2 * deg);  // the blur's bias is there to correct
    }
  }
}

TEST(EllipseTracker, FastParabolicFlight) {
  // A small ball crossing the frame at 22 px per frame (5280 px/s at 240 fps) under "gravity":
  // blur of 11 px along the path, more than the ball's radius.
  const RenderOptions o = small_video();
  const Scene scene = [](double t) {
    const double f = t * 240;  // frames
    return std::vector<ShapePose>{ball(20 + 22 * f, 150 - 14 * f + 0.9 * f * f, 12, 9, 0.2 * f)};
  };
  const TrackRun run = track(scene, 13, o);  // frame 13 would be partly out of view
  EXPECT_EQ(run.lost, 0);
  const double centre = median(run.centre_err_px);
  const double worst = *std::max_element(run.centre_err_px.begin(), run.centre_err_px.end());
  std::printf("flight 22 px/frame: median centre error %.4f px, max %.4f px\n", centre, worst);
  // Measured 0.038 px median, 0.087 px worst: the blurred outline is not quite an ellipse and
  // changes with the direction of flight; a fit holding the previous shape was 0.67 px off.
  EXPECT_LE(centre, 0.15);
  EXPECT_LE(worst, 0.3);
}

TEST(EllipseTracker, SharpTossAt15FramesPerSecond) {
  // Tracker's BallToss seen small: a white ball of 5 px radius on black, 15 fps with a short
  // exposure (sharp), 40-55 px per frame and 9 px/frame^2 of gravity; a bright bar stands
  // 12 px from its path, as the ruler in the real video.
  RenderOptions o = small_video();
  o.fps = 15;
  o.shutter_fraction = 0.02;
  o.background_colour = cv::Scalar(20, 20, 20);
  const Scene scene = [](double t) {
    const double f = t * 15;
    ShapePose b = ball(30 + 40 * f, 200 - 40 * f + 4.5 * f * f, 5, 5, 0);
    b.colour = cv::Scalar(230, 235, 235);
    ShapePose bar;
    bar.kind = ShapePose::Kind::rectangle;
    bar.cx_px = 170, bar.cy_px = 120, bar.a_px = 3, bar.b_px = 100;
    bar.colour = cv::Scalar(180, 220, 230);
    return std::vector<ShapePose>{b, bar};
  };
  const TrackRun run = track(scene, 8, o);
  EXPECT_EQ(run.lost, 0);
  const double worst = *std::max_element(run.centre_err_px.begin(), run.centre_err_px.end());
  std::printf("toss at 15 fps: median centre error %.4f px, max %.4f px\n", median(run.centre_err_px), worst);
  EXPECT_LE(worst, 0.1);  // measured 0.016 px: a sharp, small ball
  for (const auto& e : run.obs) EXPECT_TRUE(e.round);
}

TEST(EllipseTracker, BounceNearADarkFloor) {
  // A spinning ball falls onto a dark floor band (grey level close to the ball's: only the
  // colour tells them apart) and bounces (e = 0.7) with its centre 31 px above the floor edge,
  // its tips passing within 1 px of it.
  RenderOptions o = small_video();
  const double floor_top = 200, y_hit = floor_top - 31, g = 0.5, v0 = 6;  // px, px/frame^2, px/frame
  const double f_hit = (-v0 + std::sqrt(v0 * v0 + 2 * g * (y_hit - 90))) / g;
  const double v_up = 0.7 * (v0 + g * f_hit);
  const Scene scene = [=](double t) {
    const double f = t * 240;
    const double y = f < f_hit ? 90 + v0 * f + 0.5 * g * f * f
                               : y_hit - v_up * (f - f_hit) + 0.5 * g * (f - f_hit) * (f - f_hit);
    ShapePose floor;
    floor.kind = ShapePose::Kind::rectangle;
    floor.cx_px = 160, floor.cy_px = 240, floor.a_px = 200, floor.b_px = 40;
    floor.colour = cv::Scalar(70, 70, 70);
    return std::vector<ShapePose>{ball(60 + 4 * f, y, 30, 18, 1 + f / 6), floor};
  };
  const TrackRun run = track(scene, 30, o);
  EXPECT_EQ(run.lost, 0);
  const double centre = median(run.centre_err_px);
  const double worst = *std::max_element(run.centre_err_px.begin(), run.centre_err_px.end());
  std::printf("bounce by the floor: median centre error %.4f px, max %.4f px\n", centre, worst);
  EXPECT_LE(centre, 0.1);  // measured 0.01 px, as in open air
  EXPECT_LE(worst, 0.3);   // the floor's edge must not pull the fit (measured below 0.05 px)
  double worst_angle = 0;
  for (double a : run.angle_err_rad) worst_angle = std::max(worst_angle, std::abs(a));
  std::printf("bounce by the floor: worst orientation error %.4f deg\n", to_deg(worst_angle));
  EXPECT_LT(worst_angle, 0.01);  // measured 0.24 degree = 0.004 rad
}

TEST(EllipseTracker, BriefOcclusionIsReportedThenBridged) {
  // A hand (a skin-coloured rectangle in front) hides the ball for a few frames.
  const RenderOptions o = small_video();
  const Scene scene = [](double t) {
    const double f = t * 240;
    ShapePose hand;
    hand.kind = ShapePose::Kind::rectangle;
    hand.cx_px = 160, hand.cy_px = 120, hand.a_px = 30, hand.b_px = 70;
    hand.colour = cv::Scalar(120, 160, 220);
    return std::vector<ShapePose>{ball(20 + 12 * f, 120 + 0.5 * f, 20, 14, 0.3 + 0.1 * f), hand};
  };
  const TrackRun run = track(scene, 23, o);
  // Fully hidden while |x - 160| < 10 px (frames 11, 12); lost at least then, and at most
  // while partly hidden (|x - 160| < 50, frames 8..15).
  EXPECT_GE(run.lost, 2);
  EXPECT_LE(run.lost, 8);
  for (int i = 11; i <= 12; ++i) EXPECT_TRUE(run.obs[static_cast<std::size_t>(i)].centre.lost) << "frame " << i;
  // Every frame not marked lost is right (no half-hidden fit passed off as good) ...
  for (std::size_t i = 0; i < run.obs.size(); ++i) {
    if (run.obs[i].centre.lost) continue;
    const double f = static_cast<double>(i);
    EXPECT_LT(std::hypot(run.obs[i].centre.x_px - (20 + 12 * f), run.obs[i].centre.y_px - (120 + 0.5 * f)), 0.5)
        << "frame " << i;
  }
  // ... and the ball is found again after the hand.
  for (std::size_t i = 16; i < run.obs.size(); ++i) EXPECT_FALSE(run.obs[i].centre.lost) << "frame " << i;
}

TEST(EllipseTracker, ABallLeavingTheViewIsFollowedWhileMostOfItShows) {
  // A ball (semi-axes 20 and 14 px) leaving the 320 px wide view to the right at 6 px per frame.
  // The normals of its outline that run off the image are no evidence against a fit; a fit on
  // at least three quarters of the outline stays confident, a smaller part of it does not.
  const RenderOptions o = small_video();
  const auto x_at = [](double f) { return 200 + 6 * f; };
  const Scene scene = [&](double t) { return std::vector<ShapePose>{ball(x_at(t * 240), 120, 20, 14, 0)}; };
  const TrackRun run = track(scene, 30, o);
  for (std::size_t i = 0; i < run.obs.size(); ++i) {
    const EllipseObservation& e = run.obs[i];
    const double x = x_at(static_cast<double>(i));
    // Followed, and right, until its centre reaches the image's edge (x = 320 at frame 20; half
    // of the outline in view scores at most 0.5 / 0.75); lost once less than half of it shows.
    EXPECT_EQ(e.centre.lost, x > 320) << "frame " << i << ", score " << e.centre.score;
    if (!e.centre.lost) {
      EXPECT_LT(std::hypot(e.centre.x_px - x, e.centre.y_px - 120), 0.1) << "frame " << i;
    }
  }
  // With a quarter of the outline's normals off the image (9 of 35: its right tip just past the
  // edge), the fit is as confident as in full view (0.99; 0.74 when they counted against it).
  EXPECT_GT(run.obs[17].centre.score, 0.95);
}

TEST(EllipseTracker, NeverJumpsToASecondBall) {
  // A second ball of the same colour and size passes 40 px below the tracked one; then the
  // tracked ball vanishes (frame 22) while the other is still close: lost, not swapped.
  const RenderOptions o = small_video();
  const Scene scene = [](double t) {
    const double f = t * 240;
    std::vector<ShapePose> shapes;
    if (f < 21.5) shapes.push_back(ball(60 + 5 * f, 100, 16, 12, 0.5));
    shapes.push_back(ball(260 - 5 * f, 140, 16, 12, 0.5));
    return shapes;
  };
  EllipseTracker tracker;
  for (int i = 0; i < 34; ++i) {
    const Frame f = frame_at(scene, i, o);
    const EllipseObservation e = i == 0 ? tracker.start(f, 60, 100, "ball") : tracker.update(f);
    if (i < 22) {
      EXPECT_FALSE(e.centre.lost) << "frame " << i;
      EXPECT_LT(std::hypot(e.centre.x_px - (60 + 5 * i), e.centre.y_px - 100), 0.3) << "frame " << i;
    } else {
      EXPECT_TRUE(e.centre.lost) << "frame " << i << " at " << e.centre.x_px << ", " << e.centre.y_px;
    }
  }
}

TEST(EllipseTracker, RoundBallHasNoOrientation) {
  const RenderOptions o = small_video();
  const Scene scene = [](double t) { return std::vector<ShapePose>{ball(80 + 2400 * t, 120, 15, 15, 0)}; };
  const TrackRun run = track(scene, 10, o);
  EXPECT_EQ(run.lost, 0);
  for (const auto& e : run.obs) {
    EXPECT_TRUE(e.round);
    EXPECT_EQ(e.centre.angle_rad, 0);  // A to the right, kept (no spin measured)
    EXPECT_NEAR(e.ax_px - e.centre.x_px, e.centre.major_px, 1e-9);
  }
  EXPECT_LE(median(run.centre_err_px), 0.1);
}

TEST(EllipseTracker, EmptyRepeatedAndBlankFramesAreLostNotFatal) {
  const RenderOptions o = small_video();
  const Scene scene = [](double t) { return std::vector<ShapePose>{ball(100 + 2400 * t, 120, 20, 14, 0)}; };
  const Scene nothing = [](double) { return std::vector<ShapePose>{}; };
  EllipseTracker tracker;
  tracker.start(frame_at(scene, 0, o), 100, 120, "ball");
  EXPECT_FALSE(tracker.update(frame_at(scene, 1, o)).centre.lost);
  EXPECT_FALSE(tracker.update(frame_at(scene, 1, o)).centre.lost);  // the same frame again
  Frame empty;
  empty.index = 2;
  EXPECT_TRUE(tracker.update(empty).centre.lost);
  for (int i = 3; i < 20; ++i) {  // the ball gone: lost, then given up, the prediction far away
    const EllipseObservation e = tracker.update(frame_at(nothing, i, o));
    EXPECT_TRUE(e.centre.lost);
    EXPECT_TRUE(std::isfinite(e.centre.x_px) && std::isfinite(e.ax_px));
  }
}

TEST(EllipseTracker, BadStartsNameTheTarget) {
  const RenderOptions o = small_video();
  const Scene scene = [](double) {
    ShapePose floor;
    floor.kind = ShapePose::Kind::rectangle;
    floor.cx_px = 160, floor.cy_px = 240, floor.a_px = 200, floor.b_px = 40;
    floor.colour = cv::Scalar(70, 70, 70);
    return std::vector<ShapePose>{ball(100, 100, 20, 14, 0), floor};
  };
  const Frame f = frame_at(scene, 0, o);
  const auto message = [&](double x, double y) {
    EllipseTracker tracker;
    try {
      tracker.start(f, x, y, "rugby");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(-3, 50).find("ellipse rugby: start point (-3, 50) is outside the 320x240 image"), std::string::npos);
  EXPECT_NE(message(100, 240).find("outside"), std::string::npos);
  EXPECT_NE(message(250, 60).find("ellipse rugby: no contrasting object"), std::string::npos);  // background
  EXPECT_NE(message(160, 225).find("no contrasting object"), std::string::npos);  // floor: not fully in view
  EXPECT_EQ(message(100, 100), "no error");
  EXPECT_NE(EllipseTrackerOptions{.min_score = 1.5}.validate(), "");
  EXPECT_THROW(EllipseTracker(EllipseTrackerOptions{.min_score = -1}), InputError);
}

}  // namespace
}  // namespace tribolab::video
