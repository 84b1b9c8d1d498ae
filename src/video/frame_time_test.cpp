// FrameTimePass (docs/theory.md#ellipse-tracking, item 4) on edge points made by hand.
#include "video/frame_time.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tribolab::video {
namespace {

/// Where the line p + r n crosses the outline of `e` on its outer side (the larger root).
double crossing(const Ellipse& e, cv::Point2d p, cv::Point2d n) {
  const double c = std::cos(e.psi), s = std::sin(e.psi);
  const cv::Point2d d = p - cv::Point2d(e.cx, e.cy);
  const double u0 = c * d.x + s * d.y, v0 = -s * d.x + c * d.y;  // in the ellipse's axes
  const double du = c * n.x + s * n.y, dv = -s * n.x + c * n.y;
  const double A = du * du / (e.a * e.a) + dv * dv / (e.b * e.b);
  const double B = 2 * (u0 * du / (e.a * e.a) + v0 * dv / (e.b * e.b));
  const double C = u0 * u0 / (e.a * e.a) + v0 * v0 / (e.b * e.b) - 1;
  return (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A);
}

/// A long track of an ellipse: a bounce every 20 frames (a new piece), each piece falling from
/// rest 1.5 px per frame faster each frame, crossing 12 px per frame and turning 0.05 rad per
/// frame (to 30 px per frame, a 30 fps throw's).
struct Track {
  static constexpr int kBounceEvery = 20;
  static Ellipse at(double k) {  // k in frames, within the piece of floor(k)
    const double s = k - kBounceEvery * std::floor(k / kBounceEvery);
    Ellipse e;
    e.cx = 100 + 12 * s;
    e.cy = 50 + 0.75 * s * s;
    e.a = 30;
    e.b = 18;
    e.psi = -(0.3 + 0.05 * s);  // image axes: screen counter-clockwise is clockwise
    return e;
  }
  static FrameMotion motion(int k) {
    const int s = k % kBounceEvery;
    return {{12, 1.5 * s}, {0, 1.5}, -0.05};
  }
  /// Frame k as an exposure of `exposure` frame periods shows it: along each normal of the
  /// ellipse at the frame's time, the edge is the mean crossing of the moving outline (64
  /// sub-poses), and its ramp is the point's travel along the normal.
  static FittedFrame frame(int k, double exposure) {
    const Ellipse e = at(k);
    const FrameMotion m = motion(k);
    FittedFrame f;
    f.index = k;
    f.piece = k / kBounceEvery;
    f.a0 = e.a;
    f.b0 = e.b;
    f.phi = -e.psi;
    f.score = 1;
    const double c = std::cos(e.psi), s = std::sin(e.psi);
    for (int i = 0; i < 60; ++i) {
      const double t = 2 * std::numbers::pi * i / 60;
      const double u = e.a * std::cos(t), v = e.b * std::sin(t);
      double nu = std::cos(t) / e.a, nv = std::sin(t) / e.b;
      const double nn = std::hypot(nu, nv);
      nu /= nn, nv /= nn;
      EdgePoint p;
      p.at = {e.cx + c * u - s * v, e.cy + s * u + c * v};
      p.normal = {c * nu - s * nv, s * nu + c * nv};
      double mean = 0;
      for (int j = 0; j < 64; ++j) {
        const double tau = exposure * ((j + 0.5) / 64 - 0.5);  // frames from the frame's time
        Ellipse q = e;
        q.cx += tau * m.velocity.x + 0.5 * tau * tau * m.acceleration.x;
        q.cy += tau * m.velocity.y + 0.5 * tau * tau * m.acceleration.y;
        q.psi += tau * m.turn_rad;
        mean += crossing(q, p.at, p.normal) / 64;
      }
      p.at += mean * p.normal;
      const double rx = p.at.x - e.cx, ry = p.at.y - e.cy;
      const double vx = m.velocity.x - m.turn_rad * ry, vy = m.velocity.y + m.turn_rad * rx;
      p.ramp_px = exposure * std::abs(vx * p.normal.x + vy * p.normal.y);
      f.edges.push_back(p);
    }
    f.found = e;  // the ellipse at the frame's time; the test fits the blurred outline
    return f;
  }
};

TEST(FrameTimePass, PutsALongTracksFramesAtTheirTimeHoldingOnlyAFew) {
  // 600 frames in 30 pieces, each frame's edge points where a half-frame exposure puts the
  // blurred outline. The pass reads the exposure from the ramps (their length over each
  // head-on normal's travel, the motion from the frame's neighbours in its piece: exact on a
  // parabola), refits every frame to the ellipse at its time, and never holds more than the
  // 2 x 3 neighbours behind the next frame and the 6 it waits for ahead.
  FrameTimePass pass;
  std::size_t most = 0;
  double raw_deg = 0;
  for (int k = 0; k < 600; ++k) {
    FittedFrame f = Track::frame(k, 0.5);
    // The blurred outline's own fit, as the tracker finds it: the ellipse nearest the points.
    const Ellipse truth = f.found;
    ASSERT_TRUE(fit_at_frame_time(f.edges, truth, f.a0, f.b0, FrameMotion{}, 0, f.found));
    raw_deg = std::max(raw_deg, std::abs(std::remainder(f.found.psi - truth.psi, std::numbers::pi)) * 180 / std::numbers::pi);
    pass.add(std::move(f));
    most = std::max(most, pass.held_frames());
  }
  EXPECT_LE(most, 13u);
  const FrameTimePass::Result r = pass.result();
  EXPECT_NEAR(r.exposure, 0.5, 1e-3);
  ASSERT_EQ(r.frames.size(), 600u);
  double worst_px = 0, worst_deg = 0;
  for (const RetimedFrame& f : r.frames) {
    const Ellipse truth = Track::at(f.frame.index);
    worst_px = std::max(worst_px, std::hypot(f.at.cx - truth.cx, f.at.cy - truth.cy));
    worst_deg = std::max(worst_deg, std::abs(std::remainder(f.at.psi - truth.psi, std::numbers::pi)) * 180 / std::numbers::pi);
  }
  std::printf("blurred outline fitted: worst orientation %.3f deg; at the frame's time: %.4f px, %.4f deg\n", raw_deg,
              worst_px, worst_deg);
  EXPECT_GT(raw_deg, 0.5);  // the blur's bias is there to correct
  EXPECT_LT(worst_px, 0.02);
  EXPECT_LT(worst_deg, 0.02);
}

TEST(FrameTimePass, ASlowTrackIsLeftAsFitted) {
  // Half a pixel per frame: no normal is crossed head-on by 8 px per frame, the least travel a
  // ramp is read over, so no exposure is read, nothing is refitted, and no more than 240
  // frames are held waiting for one.
  FrameTimePass pass;
  std::size_t most = 0;
  for (int k = 0; k < 1000; ++k) {
    FittedFrame f = Track::frame(0, 0);  // sharp
    f.index = k;
    f.piece = 0;
    f.found.cx += 0.5 * k;
    for (EdgePoint& p : f.edges) p.at.x += 0.5 * k;
    pass.add(f);
    most = std::max(most, pass.held_frames());
  }
  EXPECT_LE(most, 240u + 13u);
  const FrameTimePass::Result r = pass.result();
  EXPECT_EQ(r.exposure, 0);
  EXPECT_TRUE(r.frames.empty());
}

}  // namespace
}  // namespace tribolab::video
