// Video benchmarks (docs/benchmarks.md#video-tracking): frames per second at 640x480 for
// decoding alone and for point and ellipse tracking per frame (frames decoded beforehand, so
// tracking excludes decoding). The video is a rendered throw (bounce render's defaults: 240
// fps, textured background, noise 2, shutter 0.5; a checker sticker on the ball for the point
// tracker), written once to a temporary .avi (MJPG).
#include "video/codec.hpp"
#include "video/correlation.hpp"
#include "video/frame.hpp"
#include "video/ellipse_fit.hpp"
#include "video/ellipse_tracker.hpp"
#include "video/point_tracker.hpp"
#include "video/render_throw.hpp"

#include <benchmark/benchmark.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace tribolab;

/// A throw filmed at `fps` (0: the film's own 240 fps), decoded once; its file is removed at exit.
struct Clip {
  std::string path;
  cv::Point2d ball, sticker;  ///< px in frame 0
  std::vector<video::Frame> frames;
  explicit Clip(double fps);
  Clip(const Clip&) = delete;
  Clip& operator=(const Clip&) = delete;
  ~Clip() { std::filesystem::remove(path); }
};

Clip::Clip(double fps) {
  Clip& c = *this;
  video::ThrowFilmOptions o;
  if (fps > 0) o.render.fps = fps;
  o.render.width = 640;
  o.render.height = 480;
  o.render.background = video::RenderOptions::Background::texture;
  o.render.background_colour = cv::Scalar(180, 185, 190);
  o.sticker = true;
  o.motion.after = 0.1;
  const auto film = video::plan_throw_film(o);
  c.path = (std::filesystem::temp_directory_path() /
            ("video_bench_" + std::to_string(::getpid()) + "_" + std::to_string(static_cast<int>(fps)) + ".avi"))
               .string();
  video::write_video(c.path, film.scene, film.frames, film.render);
  const auto shape = film.scene(0).front();
  c.ball = {shape.cx_px, shape.cy_px};
  // The sticker's centre: mark_u_px along the body x-axis (angle counter-clockwise on screen).
  c.sticker = {shape.cx_px + shape.mark_u_px * std::cos(shape.angle_rad),
               shape.cy_px - shape.mark_u_px * std::sin(shape.angle_rad)};
  const auto cap = video::open_video_file(c.path);
  video::Frame f;
  while (cap->read(f.bgr)) {
    f.t = f.index / film.render.fps;
    video::make_gray(f);
    c.frames.push_back(f);
    f = video::Frame{};
    f.index = static_cast<int>(c.frames.size());
  }
  if (c.frames.empty()) throw std::runtime_error("video_bench: the rendered video does not decode");
}

const Clip& clip(double fps = 0) {
  if (fps == 30) {
    static const Clip c30(30);
    return c30;
  }
  static const Clip c(0);
  return c;
}

void BM_Decode640x480(benchmark::State& state) {
  const Clip& c = clip();
  std::int64_t frames = 0;
  for (auto _ : state) {
    const auto cap = video::open_video_file(c.path);
    cv::Mat m;
    while (cap->read(m)) {
      benchmark::DoNotOptimize(m.data);
      ++frames;
    }
  }
  state.SetItemsProcessed(frames);  // items_per_second = frames per second
}
BENCHMARK(BM_Decode640x480)->Unit(benchmark::kMillisecond);

void BM_DecodeAndGray640x480(benchmark::State& state) {
  const Clip& c = clip();
  std::int64_t frames = 0;
  for (auto _ : state) {
    const auto cap = video::open_video_file(c.path);
    video::Frame f;
    while (cap->read(f.bgr)) {
      video::make_gray(f);
      benchmark::DoNotOptimize(f.gray.data);
      ++frames;
    }
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_DecodeAndGray640x480)->Unit(benchmark::kMillisecond);

void BM_TrackPoint640x480(benchmark::State& state) {
  const Clip& c = clip();
  std::int64_t frames = 0;
  int lost = 0;
  for (auto _ : state) {
    video::PointTracker tracker;
    benchmark::DoNotOptimize(tracker.start(c.frames[0], c.sticker.x, c.sticker.y, "sticker"));
    lost = 0;
    for (std::size_t k = 1; k < c.frames.size(); ++k) lost += tracker.update(c.frames[k]).lost;
    frames += static_cast<std::int64_t>(c.frames.size());
  }
  state.SetItemsProcessed(frames);
  state.counters["lost"] = lost;  // frames of the clip where the sticker was not found
}
BENCHMARK(BM_TrackPoint640x480)->Unit(benchmark::kMillisecond);

// The one-off part alone: the start (reference patch, symmetry check) and the first step's
// wide search (a quarter of the image's smaller side around the start, all rotations).
void BM_TrackPoint640x480StartAndFirstStep(benchmark::State& state) {
  const Clip& c = clip();
  for (auto _ : state) {
    video::PointTracker tracker;
    benchmark::DoNotOptimize(tracker.start(c.frames[0], c.sticker.x, c.sticker.y, "sticker"));
    benchmark::DoNotOptimize(tracker.update(c.frames[1]));
  }
}
BENCHMARK(BM_TrackPoint640x480StartAndFirstStep)->Unit(benchmark::kMillisecond);

// The same clip without the one-off start (template, symmetry check) and first step (a search
// over a quarter of the image): the cost every further frame adds, which is what decides
// whether tracking keeps up with decoding on a long clip.
void BM_TrackPoint640x480Steady(benchmark::State& state) {
  const Clip& c = clip();
  std::int64_t frames = 0;
  for (auto _ : state) {
    state.PauseTiming();
    video::PointTracker tracker;
    benchmark::DoNotOptimize(tracker.start(c.frames[0], c.sticker.x, c.sticker.y, "sticker"));
    benchmark::DoNotOptimize(tracker.update(c.frames[1]));
    state.ResumeTiming();
    for (std::size_t k = 2; k < c.frames.size(); ++k) benchmark::DoNotOptimize(tracker.update(c.frames[k]));
    frames += static_cast<std::int64_t>(c.frames.size()) - 2;
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_TrackPoint640x480Steady)->Unit(benchmark::kMillisecond);

void BM_TrackEllipse640x480(benchmark::State& state) {
  const Clip& c = clip();
  std::int64_t frames = 0;
  for (auto _ : state) {
    video::EllipseTracker tracker;
    benchmark::DoNotOptimize(tracker.start(c.frames[0], c.ball.x, c.ball.y, "ball"));
    for (std::size_t k = 1; k < c.frames.size(); ++k) benchmark::DoNotOptimize(tracker.update(c.frames[k]));
    frames += static_cast<std::int64_t>(c.frames.size());
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_TrackEllipse640x480)->Unit(benchmark::kMillisecond);

// The same throw filmed at 30 fps, where the pass that puts the frames at their time
// (FrameTimePass, fed as the frames come; EllipseTracker::at_frame_time after the last) reads
// the exposure and refits the frames: tracking and the pass together, per frame.
void BM_TrackEllipse640x480At30fps(benchmark::State& state) {
  const Clip& c = clip(30);
  std::int64_t frames = 0;
  std::size_t refitted = 0;
  for (auto _ : state) {
    video::EllipseTracker tracker;
    benchmark::DoNotOptimize(tracker.start(c.frames[0], c.ball.x, c.ball.y, "ball"));
    for (std::size_t k = 1; k < c.frames.size(); ++k) benchmark::DoNotOptimize(tracker.update(c.frames[k]));
    refitted = tracker.at_frame_time().poses.size();
    frames += static_cast<std::int64_t>(c.frames.size());
  }
  state.SetItemsProcessed(frames);
  state.counters["frames"] = static_cast<double>(c.frames.size());
  state.counters["refitted"] = static_cast<double>(refitted);
}
BENCHMARK(BM_TrackEllipse640x480At30fps)->Unit(benchmark::kMillisecond);

// The pass's work for one refitted frame (fit_at_frame_time: each edge point moved by the mean
// crossing of 16 sub-poses, the ellipse refitted, twice), on the edge points of the 30 fps
// throw's fastest frame with its motion.
void BM_FitAtFrameTime(benchmark::State& state) {
  const Clip& c = clip(30);
  video::EllipseTracker tracker;
  std::vector<video::EllipseObservation> seen{tracker.start(c.frames[0], c.ball.x, c.ball.y, "ball")};
  for (std::size_t k = 1; k < c.frames.size(); ++k) seen.push_back(tracker.update(c.frames[k]));
  std::size_t fastest = 1;  // the frame with the largest step from the one before
  const auto step = [&](std::size_t k) {
    return std::hypot(seen[k].centre.x_px - seen[k - 1].centre.x_px, seen[k].centre.y_px - seen[k - 1].centre.y_px);
  };
  for (std::size_t k = 2; k + 1 < seen.size(); ++k) fastest = step(k) > step(fastest) ? k : fastest;
  const video::Observation& o = seen[fastest].centre;
  const video::Ellipse e{o.x_px, o.y_px, o.major_px, o.minor_px, -o.angle_rad};
  const int pad = static_cast<int>(e.a) + 40;
  const cv::Rect roi = cv::Rect(static_cast<int>(e.cx) - pad, static_cast<int>(e.cy) - pad, 2 * pad, 2 * pad) &
                       cv::Rect(0, 0, c.frames[fastest].gray.cols, c.frames[fastest].gray.rows);
  // The tracker's contrast: each pixel's colour distance to the ball's (at its centre).
  const cv::Mat& bgr = c.frames[fastest].bgr;
  const cv::Vec3f ball = bgr.at<cv::Vec3b>(static_cast<int>(e.cy), static_cast<int>(e.cx));
  cv::Mat contrast(roi.size(), CV_32F);
  for (int r = 0; r < roi.height; ++r) {
    for (int k = 0; k < roi.width; ++k) contrast.at<float>(r, k) = static_cast<float>(cv::norm(cv::Vec3f(bgr.at<cv::Vec3b>(roi.y + r, roi.x + k)) - ball));
  }
  video::EdgeFitOptions eo;
  eo.reach_px = 20;
  eo.known_a = e.a, eo.known_b = e.b;
  const video::EdgeFit fit = video::fit_ellipse_edges(contrast, roi.tl(), e, eo);
  video::FrameMotion m;
  m.velocity = {o.x_px - seen[fastest - 1].centre.x_px, o.y_px - seen[fastest - 1].centre.y_px};
  m.acceleration = {0, 1};
  m.turn_rad = -(seen[fastest].centre.angle_rad - seen[fastest - 1].centre.angle_rad);
  video::Ellipse at;
  bool ok = false;
  for (auto _ : state) {
    ok = video::fit_at_frame_time(fit.points, fit.ellipse, e.a, e.b, m, 0.5, at);
    benchmark::DoNotOptimize(at);
  }
  state.counters["points"] = static_cast<double>(fit.points.size());
  state.counters["ok"] = ok;
}
BENCHMARK(BM_FitAtFrameTime)->Unit(benchmark::kMicrosecond);

void BM_RenderFrame640x480(benchmark::State& state) {
  video::ThrowFilmOptions o;
  o.render.background = video::RenderOptions::Background::texture;
  const auto film = video::plan_throw_film(o);
  std::int64_t frames = 0;
  for (auto _ : state) {
    for (int k = 0; k < film.frames; k += 10) {
      benchmark::DoNotOptimize(video::render_frame(film.scene, k / film.render.fps, film.render, k).data);
      ++frames;
    }
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_RenderFrame640x480)->Unit(benchmark::kMillisecond);

/// The trackers' correlation (video::normed_correlation) against OpenCV's matchTemplate
/// (TM_CCOEFF_NORMED) on one core: range(0) x range(0) placements (a search window's union, or
/// a refinement's few) of a template of range(1) px in a textured image; range(2) 0 is OpenCV,
/// 1 ours.
void BM_NormedCorrelation(benchmark::State& state) {
  const int t = static_cast<int>(state.range(1)), side = static_cast<int>(state.range(0)) + t - 1;
  cv::Mat img(side, side, CV_32F);
  cv::RNG rng(1);
  rng.fill(img, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(img, img, cv::Size(0, 0), 1.5);
  const cv::Mat templ = img(cv::Rect((side - t) / 2, (side - t) / 2, t, t)).clone();
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  cv::Mat r;
  for (auto _ : state) {
    if (state.range(2) == 0) {
      cv::matchTemplate(img, templ, r, cv::TM_CCOEFF_NORMED);
    } else {
      video::normed_correlation(img, templ, r);
    }
    benchmark::DoNotOptimize(r.data);
  }
  cv::setNumThreads(threads);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(r.total()));  // placements per second
}
BENCHMARK(BM_NormedCorrelation)
    ->ArgsProduct({{7, 60, 140, 480}, {7, 13, 25}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

/// The half-resolution image of a 1080p path tracker's union (~170 px square, CV_32F):
/// video::half_resolution on the calling thread (0) against cv::pyrDown (1), which OpenCV 4.6
/// splits between its worker threads at any size. CPU time is the calling thread's only: the
/// worker's share (and its spinning afterwards) shows in bench/video1080_bench's cpu_all_ms.
void BM_HalfResolution(benchmark::State& state) {
  cv::Mat img(170, 170, CV_32F);
  cv::RNG rng(2);
  rng.fill(img, cv::RNG::UNIFORM, 0, 255);
  cv::Mat d;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      video::half_resolution(img, d);
    } else {
      cv::pyrDown(img, d);
    }
    benchmark::DoNotOptimize(d.data);
  }
}
BENCHMARK(BM_HalfResolution)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
