// Unit tests of the `track video` report builder (src/app/track/report_track_video.hpp) on a result made
// by hand: every number of the summary is shown with its unit, lost frames are gaps in the
// positions and red markers on the score, the orientation is unwrapped, the thumbnails are
// embedded byte for byte, and an ellipse's ends do not repeat its orientation and score.
#include "app/track/report_track_video.hpp"
#include "video/codec.hpp"

#include "report/format.hpp"
#include "report/html.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>  // cv::IMREAD_*
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tribolab::app {
namespace {

using video::Target;
using video::TrackedRow;
using video::TrackedSeries;

constexpr double kVideoFps = 240;
constexpr int kVideoFrames = 24;

/// A frame with a dark ball on grey, encoded as OpenCV writes thumbnails.
std::vector<unsigned char> thumbnail_jpeg(int frame) {
  cv::Mat img(120, 160, CV_8UC3, cv::Scalar(200, 200, 200));
  cv::circle(img, cv::Point(20 + 5 * frame, 60), 12, cv::Scalar(40, 40, 200), cv::FILLED, cv::LINE_AA);
  std::vector<unsigned char> jpeg = video::encode_image(".jpg", img);
  EXPECT_FALSE(jpeg.empty());
  return jpeg;
}

/// A point turning 0.4 rad per frame (crossing ±π several times) lost on frames 5-7, and an
/// ellipse "ball" with its ends ball.A, ball.B, in a calibrated video (500 px per m).
video::TrackVideoResult hand_made(bool calibrated) {
  video::TrackVideoResult r;
  r.input.input = "throw.mp4";
  r.input.info = {"throw.mp4", 320, 240, kVideoFrames, kVideoFps, "mp4v"};
  r.input.time.frame_duration_s = 1 / kVideoFps;
  r.input.calibration.calibrated = calibrated;
  if (calibrated) {
    r.input.calibration.coords.front().xscale = 500;
    r.input.calibration.coords.front().yscale = 500;
    r.input.calibration.coords.front().origin_y = 240;
  }
  r.frames = kVideoFrames;
  TrackedSeries mark;
  mark.name = "mark";
  mark.kind = Target::Kind::point;
  for (int i = 0; i < kVideoFrames; ++i) {
    TrackedRow row;
    row.frame = i;
    row.t = i / kVideoFps;
    row.lost = i >= 5 && i <= 7;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    row.x = row.lost ? nan : 0.1 + 0.002 * i;
    row.y = row.lost ? nan : 0.3;
    row.x_px = row.y_px = row.lost ? nan : 100;
    row.score = row.lost ? 0.2 : 0.9;
    mark.rows.push_back(row);
    // The tracker's angle wraps to (-π, π]; the truth is 0.4 i.
    mark.angle_rad.push_back(row.lost ? nan : std::remainder(0.4 * i, 2 * std::numbers::pi));
  }
  mark.tracked = kVideoFrames - 3;
  mark.lost_ranges = {{5, 7}};
  mark.median_score = 0.9;
  mark.vs_human = video::HumanComparison{12, 0.74, 1.9};
  r.series.push_back(mark);
  for (const char* name : {"ball", "ball.A", "ball.B"}) {
    TrackedSeries s;
    s.name = name;
    s.kind = Target::Kind::ellipse;
    for (int i = 0; i < kVideoFrames; ++i) {
      s.rows.push_back({i, i / kVideoFps, 0.2, 0.1 + 0.001 * i, 100, 140, 0.95, false});
      s.angle_rad.push_back(0.1);
    }
    s.tracked = kVideoFrames;
    s.median_score = 0.95;
    r.series.push_back(s);
  }
  r.thumbnails = {{0, 0.0, thumbnail_jpeg(0)}, {12, 12 / kVideoFps, thumbnail_jpeg(12)}};
  r.input.warnings = {"no scale: positions are in pixels"};
  r.warnings = {"mark: lost on frames 5-7 (occluded?)"};
  return r;
}

const report::Table* table_in(const report::Report& r, const std::string& caption) {
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* t = std::get_if<report::Table>(&b); t && t->caption == caption) return t;
  return nullptr;
}

std::string cell(const report::Table& t, const std::string& first, std::size_t column = 1) {
  for (const auto& row : t.rows)
    if (row[0] == first) return row.at(column);
  return "(no row '" + first + "')";
}

std::vector<const report::Figure*> video_figures(const report::Report& r) {
  std::vector<const report::Figure*> out;
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* f = std::get_if<report::Figure>(&b)) out.push_back(f);
  return out;
}

const report::Series* series_in(const report::Figure& f, const std::string& name) {
  for (const auto& s : f.series)
    if (s.name == name) return &s;
  return nullptr;
}

TEST(TrackVideoReport, SummaryShowsTheVideoTimeBaseAndCalibrationWithUnits) {
  const auto rep = track_video_report(hand_made(true));
  EXPECT_EQ(rep.validate(), "");
  const auto* t = table_in(rep, "The video, its time base and its calibration");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(cell(*t, "input"), "throw.mp4");
  EXPECT_EQ(cell(*t, "image size (px)"), "320 × 240");
  EXPECT_EQ(cell(*t, "frames decoded (the clip's steps)"), "24");
  EXPECT_EQ(cell(*t, "frame rate in the container (1/s)"), "240");
  EXPECT_EQ(cell(*t, "frame duration Δt (s)"), "0.00416667");
  EXPECT_EQ(cell(*t, "time scale (real s per video s)"), "1");
  EXPECT_EQ(cell(*t, "calibration"), "500 px per m along x, 500 along y (from frame 0; 1 key frame(s))");
  EXPECT_EQ(cell(*t, "origin x, y (px)"), "0, 240");
  EXPECT_EQ(cell(*t, "axes' angle (deg)"), "0");
  const auto figs = video_figures(rep);
  ASSERT_EQ(figs.size(), 4u);  // x, y, orientation, score
  EXPECT_EQ(figs[0]->y_axis.title, "x (m)");
  EXPECT_EQ(figs[1]->y_axis.title, "y (m)");
}

TEST(TrackVideoReport, UncalibratedVideoSaysPixels) {
  const auto rep = track_video_report(hand_made(false));
  const auto* t = table_in(rep, "The video, its time base and its calibration");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(cell(*t, "calibration"), "none: positions in pixels, y up (no scale given)");
  EXPECT_EQ(video_figures(rep).at(0)->y_axis.title, "x (px)");
}

TEST(TrackVideoReport, TracksTableHasLostRangesScoresAndHumanDistance) {
  const auto rep = track_video_report(hand_made(true));
  const auto* t = table_in(rep, "Tracks");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->rows.size(), 4u);
  EXPECT_EQ(cell(*t, "mark", 1), "point");
  EXPECT_EQ(cell(*t, "mark", 2), "24 (0–23)");
  EXPECT_EQ(cell(*t, "mark", 3), "21");
  EXPECT_EQ(cell(*t, "mark", 4), "5–7");
  EXPECT_EQ(cell(*t, "mark", 5), "0.9");
  EXPECT_EQ(cell(*t, "mark", 6), "median 0.74, largest 1.9 over 12 frames");
  EXPECT_EQ(cell(*t, "ball", 1), "ellipse: centre");
  EXPECT_EQ(cell(*t, "ball.B", 1), "ellipse: end B of the major axis");
  EXPECT_EQ(cell(*t, "ball.A", 4), "none");
  EXPECT_EQ(cell(*t, "ball.A", 6), "—");
  // A track none of whose marked frames has a position has no distance to state.
  auto lost = hand_made(true);
  lost.series[0].vs_human = video::HumanComparison{};
  lost.series[0].vs_human->marks = 23;
  const auto lost_rep = track_video_report(lost);
  const auto* none = table_in(lost_rep, "Tracks");
  ASSERT_NE(none, nullptr);
  EXPECT_EQ(cell(*none, "mark", 6), "no marked frame tracked (23 marks)");
}

TEST(TrackVideoReport, WarningsOfTheInputAndTheTrackingAreListed) {
  const auto rep = track_video_report(hand_made(true));
  std::vector<std::string> items;
  for (const auto& s : rep.sections)
    for (const auto& b : s.blocks)
      if (const auto* l = std::get_if<report::List>(&b)) items = l->items;
  EXPECT_EQ(items, (std::vector<std::string>{"no scale: positions are in pixels", "mark: lost on frames 5-7 (occluded?)"}));
  auto quiet = hand_made(true);
  quiet.input.warnings.clear();
  quiet.warnings.clear();
  const auto q = track_video_report(quiet);
  bool said = false;
  for (const auto& b : q.sections.front().blocks)
    if (const auto* p = std::get_if<report::Paragraph>(&b)) said = said || p->text == "No warnings.";
  EXPECT_TRUE(said);
}

TEST(TrackVideoReport, LostFramesAreGapsInPositionsAndRedMarkersOnTheScore) {
  const auto rep = track_video_report(hand_made(true));
  const auto figs = video_figures(rep);
  const auto* x = series_in(*figs[0], "mark");
  ASSERT_NE(x, nullptr);
  ASSERT_EQ(x->y.size(), 24u);
  for (int i = 0; i < kVideoFrames; ++i) EXPECT_EQ(std::isnan(x->y[i]), i >= 5 && i <= 7) << i;
  EXPECT_DOUBLE_EQ(x->y[4], 0.108);
  const auto* lost = series_in(*figs[3], "mark: lost");
  ASSERT_NE(lost, nullptr);
  EXPECT_EQ(lost->x, (std::vector<double>{5 / kVideoFps, 6 / kVideoFps, 7 / kVideoFps}));
  EXPECT_EQ(lost->y, (std::vector<double>{0.2, 0.2, 0.2}));
  EXPECT_EQ(lost->color, "#d62728");
  // Nothing lost on the ball: no lost series for it.
  EXPECT_EQ(series_in(*figs[3], "ball: lost"), nullptr);
}

TEST(TrackVideoReport, OrientationIsUnwrappedInDegreesAcrossLostFrames) {
  const auto rep = track_video_report(hand_made(true));  // the figures point into it
  const auto figs = video_figures(rep);
  ASSERT_EQ(figs[2]->title, "Orientation against time");
  const auto* a = series_in(*figs[2], "mark");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->y.size(), 24u);
  const double deg = 180 / std::numbers::pi;
  for (int i = 0; i < kVideoFrames; ++i) {
    if (i >= 5 && i <= 7) {
      EXPECT_TRUE(std::isnan(a->y[i])) << i;
    } else {
      // 0.4 rad (22.9 deg) per frame: unwrapped it is 0.4 i exactly (to rounding), up to 527 deg;
      // across the 4-frame gap the step is 91.7 deg, still below 180, so it stays continuous.
      EXPECT_NEAR(a->y[i], 0.4 * i * deg, 1e-9) << i;
    }
  }
}

TEST(TrackVideoReport, EllipseEndsShareTheCentresOrientationAndScore) {
  const auto rep = track_video_report(hand_made(true));  // the figures point into it
  const auto figs = video_figures(rep);
  // Positions: all four tracks; orientation and score: the point and the ellipse once.
  EXPECT_EQ(figs[0]->series.size(), 4u);
  EXPECT_NE(series_in(*figs[2], "ball"), nullptr);
  EXPECT_EQ(series_in(*figs[2], "ball.A"), nullptr);
  EXPECT_EQ(series_in(*figs[3], "ball.B"), nullptr);
  EXPECT_NE(series_in(*figs[3], "ball"), nullptr);
}

TEST(TrackVideoReport, ThumbnailsAreEmbeddedByteForByte) {
  const auto r = hand_made(true);
  const std::string html = report::to_html(track_video_report(r));
  for (const auto& th : r.thumbnails) {
    const std::string uri =
        "data:image/jpeg;base64," + report::base64(std::string(th.jpeg.begin(), th.jpeg.end())) + "\"";
    EXPECT_NE(html.find(uri), std::string::npos) << "frame " << th.frame;
  }
  EXPECT_NE(html.find("<figcaption>frame 12, t = 0.05 s</figcaption>"), std::string::npos);
  // The bytes are a real picture: OpenCV decodes them back to the size drawn.
  const cv::Mat back = video::decode_image(r.thumbnails[1].jpeg, cv::IMREAD_COLOR);
  EXPECT_EQ(back.cols, 160);
  EXPECT_EQ(back.rows, 120);
}

TEST(TrackVideoReport, HumanMarksAreDrawnInWorldUnits) {
  auto r = hand_made(true);
  track::Track marks;
  marks.name = "mark";
  marks.points = {{0, 0, 150, 90}, {10, 10 / kVideoFps, 160, 90}};  // pixels, y down
  r.input.marks_px = {marks};
  const auto rep = track_video_report(r);
  const auto figs = video_figures(rep);
  const auto* hx = series_in(*figs[0], "mark: human marks");
  const auto* hy = series_in(*figs[1], "mark: human marks");
  ASSERT_NE(hx, nullptr);
  ASSERT_NE(hy, nullptr);
  // 500 px per m, origin (0, 240) px: x = 150/500 m, y = (240 - 90)/500 m.
  EXPECT_NEAR(hx->y[0], 0.3, 1e-12);
  EXPECT_NEAR(hx->y[1], 0.32, 1e-12);
  EXPECT_NEAR(hy->y[0], 0.3, 1e-12);
  EXPECT_NEAR(hx->x[1], 10 / kVideoFps, 1e-12);
  // Only a track compared with human marks gets them.
  EXPECT_EQ(series_in(*figs[0], "ball: human marks"), nullptr);
}

}  // namespace
}  // namespace tribolab::app
