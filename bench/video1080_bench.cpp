// Tracking at 1080p against decoding alone (issue 24's speed bar: tracking one object may add
// at most 25 % to decoding; docs/benchmarks.md#tracking-at-1080p). The video is a rendered
// throw at 1920x1080, 240 fps, textured background, a checker sticker on the ball (the point
// target), written once as H.264 (.mp4, libx264 through OpenCV's FFmpeg backend: what a phone
// records). Every benchmark decodes the whole file; the tracking ones also run the tracker on
// every frame, as `track video` does (each tracker makes the grey image of the windows it reads).
#include "video/codec.hpp"
#include "video/frame.hpp"
#include "video/ellipse_tracker.hpp"
#include "video/path_tracker.hpp"
#include "video/point_tracker.hpp"
#include "video/render.hpp"
#include "video/render_throw.hpp"
#include "video/source.hpp"
#include "video/test_videos.hpp"
#include "video/track_video.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace {

using namespace tribolab;

struct Clip1080 {
  std::string path;
  cv::Point2d ball, sticker;  ///< px in frame 0
  int frames = 0;
  std::vector<cv::Point2d> sticker_at;  ///< the sticker's true centre in each frame, px
  ~Clip1080() { std::filesystem::remove(path); }
};

/// CPU time of the whole process (every thread: FFmpeg decodes on threads of its own), s.
double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Reports the process CPU time per clip (all threads), ms: the load-independent measure of
/// what decoding plus tracking costs, where real time depends on the other processes' load
/// and the main thread's CPU time leaves out the decoder's threads.
struct ProcessCpu {
  benchmark::State& state;
  double t0 = process_cpu_s();
  ~ProcessCpu() {
    state.counters["cpu_all_ms"] =
        benchmark::Counter(1e3 * (process_cpu_s() - t0), benchmark::Counter::kAvgIterations);
  }
};

const Clip1080& clip1080() {
  static const Clip1080 c = [] {
    Clip1080 c;
    video::ThrowFilmOptions o;
    o.render.width = 1920;
    o.render.height = 1080;
    o.render.background = video::RenderOptions::Background::texture;
    o.render.background_colour = cv::Scalar(180, 185, 190);
    o.render.supersample = 2;   // the rendering is set-up only: cheaper, still anti-aliased
    o.render.blur_samples = 4;
    o.sticker = true;
    o.motion.after = 0.05;
    o.motion.omega = 0;  // the sticker does not turn in flight (the benchmark measures the search, not the turning)
    const auto film = video::plan_throw_film(o);
    c.path = (std::filesystem::temp_directory_path() / ("video1080_bench_" + std::to_string(::getpid()) + ".mp4")).string();
    const auto w = video::create_video_file(c.path, video::fourcc('a', 'v', 'c', '1'), o.render.fps,
                                            cv::Size(o.render.width, o.render.height));
    if (!w) throw std::runtime_error("video1080_bench: cannot write H.264 here");
    const int n = std::min(film.frames, 120);
    for (int k = 0; k < n; ++k) w->write(video::render_frame(film.scene, k / o.render.fps, film.render, k));
    c.frames = n;
    for (int k = 0; k < n; ++k) {
      const auto s = film.scene(k / o.render.fps).front();
      c.sticker_at.push_back({s.cx_px + s.mark_u_px * std::cos(s.angle_rad), s.cy_px - s.mark_u_px * std::sin(s.angle_rad)});
    }
    const auto shape = film.scene(0).front();
    c.ball = {shape.cx_px, shape.cy_px};
    c.sticker = {shape.cx_px + shape.mark_u_px * std::cos(shape.angle_rad),
                 shape.cy_px - shape.mark_u_px * std::sin(shape.angle_rad)};
    return c;
  }();
  return c;
}

void BM_Decode1080pH264(benchmark::State& state) {
  const Clip1080& c = clip1080();
  const ProcessCpu cpu{state};
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
BENCHMARK(BM_Decode1080pH264)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Decoding and the grey image of the whole frame (what every tracker was given before the
/// trackers made only their windows' grey image: the reference for that cost).
void BM_DecodeAndGray1080pH264(benchmark::State& state) {
  const Clip1080& c = clip1080();
  const ProcessCpu cpu{state};
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
BENCHMARK(BM_DecodeAndGray1080pH264)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Decoding and the default point tracker (the path tracker) on the sticker.
void BM_DecodeTrackPath1080pH264(benchmark::State& state) {
  const Clip1080& c = clip1080();
  const ProcessCpu cpu{state};
  std::int64_t frames = 0;
  int lost = 0;
  for (auto _ : state) {
    const auto cap = video::open_video_file(c.path);
    video::PathTrackerOptions po;
    po.step_s = 1 / 240.0;  // as track video gives it, from the clip's time base
    video::PathTracker tracker(po);
    video::Frame f;
    bool started = false;
    while (cap->read(f.bgr)) {
      f.t = f.index / 240.0;
      if (!started) {
        benchmark::DoNotOptimize(tracker.start(f, c.sticker.x, c.sticker.y, "sticker"));
        started = true;
      } else {
        tracker.update(f);
      }
      ++f.index;
      ++frames;
    }
    lost = 0;
    for (const auto& o : tracker.finish()) lost += o.lost;
  }
  state.SetItemsProcessed(frames);
  state.counters["lost"] = lost;
}
BENCHMARK(BM_DecodeTrackPath1080pH264)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The path tracker alone on the clip's frames decoded beforehand (held in memory): its own
/// cost per clip, to set against BM_Decode1080pH264's, without the decoder's threads sharing
/// the cores.
void BM_TrackPathDecoded1080p(benchmark::State& state) {
  const Clip1080& c = clip1080();
  static const std::vector<cv::Mat> decoded = [&] {
    std::vector<cv::Mat> v;
    const auto cap = video::open_video_file(c.path);
    cv::Mat m;
    while (cap->read(m)) v.push_back(m.clone());
    return v;
  }();
  const ProcessCpu cpu{state};
  int lost = 0;
  double worst = 0;
  for (auto _ : state) {
    video::PathTrackerOptions po;
    po.step_s = 1 / 240.0;  // as track video gives it, from the clip's time base
    video::PathTracker tracker(po);
    for (std::size_t k = 0; k < decoded.size(); ++k) {
      video::Frame f;
      f.bgr = decoded[k];
      f.index = static_cast<int>(k);
      f.t = f.index / 240.0;
      if (k == 0) {
        benchmark::DoNotOptimize(tracker.start(f, c.sticker.x, c.sticker.y, "sticker"));
      } else {
        tracker.update(f);
      }
    }
    lost = 0;
    worst = 0;
    for (const auto& o : tracker.finish()) {
      lost += o.lost;
      const cv::Point2d truth = c.sticker_at[static_cast<std::size_t>(o.frame)];
      if (!o.lost) worst = std::max(worst, std::hypot(o.x_px - truth.x, o.y_px - truth.y));
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(decoded.size()));
  state.counters["lost"] = lost;
  state.counters["worst_px"] = worst;  // the largest distance of a reported point from the sticker's centre
}
BENCHMARK(BM_TrackPathDecoded1080p)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Decoding and a streaming tracker (answering each frame) started at `at` in frame 0;
/// `lost` reads its answer.
template <class Tracker, class Options, class Lost>
void decode_and_track(benchmark::State& state, const Options& options, cv::Point2d at, const char* name, Lost lost_of) {
  const Clip1080& c = clip1080();
  const ProcessCpu cpu{state};
  std::int64_t frames = 0;
  int lost = 0;
  for (auto _ : state) {
    const auto cap = video::open_video_file(c.path);
    Tracker tracker(options);
    video::Frame f;
    bool started = false;
    lost = 0;
    while (cap->read(f.bgr)) {
      f.t = f.index / 240.0;
      if (!started) {
        benchmark::DoNotOptimize(tracker.start(f, at.x, at.y, name));
        started = true;
      } else {
        lost += lost_of(tracker.update(f));
      }
      ++f.index;
      ++frames;
    }
  }
  state.SetItemsProcessed(frames);
  state.counters["lost"] = lost;
}

/// Decoding and the frame-to-frame point tracker (`--point-tracker frame`) on the sticker.
void BM_DecodeTrackFrame1080pH264(benchmark::State& state) {
  video::PointTrackerOptions o;
  o.step_s = 1 / 240.0;  // as track video gives it from the clip's time base
  decode_and_track<video::PointTracker>(state, o, clip1080().sticker, "sticker",
                                        [](const video::Observation& o) { return o.lost; });
}
BENCHMARK(BM_DecodeTrackFrame1080pH264)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Decoding and the ellipse tracker on the ball.
void BM_DecodeTrackEllipse1080pH264(benchmark::State& state) {
  decode_and_track<video::EllipseTracker>(state, video::EllipseTrackerOptions{}, clip1080().ball, "ball",
                                          [](const video::EllipseObservation& o) { return o.centre.lost; });
}
BENCHMARK(BM_DecodeTrackEllipse1080pH264)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Real film: jmoljana.trz (../shared/data/tracker, not in git), a phone's 1920x1080 H.264 at
/// 30 fps, 150 frames of a swinging ball. range(0) 0: the clip decoded alone (FrameReader, as
/// `track video` reads it); 1: `track video` on its human-marked track from the first mark
/// (the path tracker, the default), decoding included. Skipped without the project.
void BM_RealFilmJmoljana1080p(benchmark::State& state) {
  const std::string path = video::testing::tracker_project_path("jmoljana.trz");
  if (path.empty()) {
    state.SkipWithError("../shared/data/tracker/jmoljana.trz not found");
    return;
  }
  const video::VideoInput input = video::open_input(path, {});
  const ProcessCpu cpu{state};
  std::int64_t frames = 0;
  int lost = 0;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      video::FrameReader reader(input);
      video::Frame f;
      while (reader.next(f)) {
        benchmark::DoNotOptimize(f.bgr.data);
        ++frames;
      }
    } else {
      video::TrackVideoOptions o;
      video::Target t;
      t.name = "mass A";
      t.from_track = "mass A";
      o.targets.push_back(t);
      o.thumbnails = 0;
      const video::TrackVideoResult r = video::track_video(path, o);
      frames += r.frames;
      lost = 0;
      for (const auto& s : r.series)
        for (const auto& [a, b] : s.lost_ranges) lost += b - a + 1;
    }
  }
  state.SetItemsProcessed(frames);
  state.counters["lost"] = lost;
}
BENCHMARK(BM_RealFilmJmoljana1080p)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
