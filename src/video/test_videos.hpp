// Tiny videos written at test time (no binary fixtures in git): a textured patch moving at
// constant velocity over a smooth background, and a grey block whose level encodes the frame
// index so a test can check which frame it was given. For the source, workflow and CLI tests.
#pragma once

#include "numerics/source_dir_test_util.hpp"
#include "video/codec.hpp"
#include "video/frame.hpp"
#include "video/render.hpp"

#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace tribolab::video::testing {

struct TestVideo {
  int width = 160, height = 120;  ///< px
  int frames = 20;
  double fps = 25;                ///< 1/s
  double x0 = 40, y0 = 60;        ///< patch centre in frame 0, px
  double vx = 3, vy = -1;         ///< patch velocity, px per frame
  int patch = 15;                 ///< patch side, px (a checker of 3 px cells)
};

/// Grey level of the frame-code block in frame i (distinct for 25 consecutive frames).
inline int code_level(int i) { return 20 + 9 * (i % 25); }

/// Mean grey level of the frame-code block (the top-left 12x12 pixels) of an image.
inline double read_code(const cv::Mat& bgr) {
  cv::Mat g;
  cv::cvtColor(bgr(cv::Rect(2, 2, 8, 8)), g, cv::COLOR_BGR2GRAY);
  return cv::mean(g)[0];
}

/// Patch centre in frame i, px.
inline cv::Point2d patch_centre(const TestVideo& v, int i) { return {v.x0 + v.vx * i, v.y0 + v.vy * i}; }

inline cv::Mat test_frame(const TestVideo& v, int i) {
  cv::Mat img(v.height, v.width, CV_8UC3);
  for (int r = 0; r < v.height; ++r) {
    for (int c = 0; c < v.width; ++c) {  // a smooth background: little texture to lock onto
      const auto g = static_cast<unsigned char>(120 + 40 * c / v.width + 20 * r / v.height);
      img.at<cv::Vec3b>(r, c) = {g, g, g};
    }
  }
  const int level = code_level(i);
  cv::rectangle(img, cv::Rect(0, 0, 12, 12), cv::Scalar(level, level, level), cv::FILLED);
  const cv::Point2d p = patch_centre(v, i);
  const int half = v.patch / 2;
  for (int dy = -half; dy <= half; ++dy) {
    for (int dx = -half; dx <= half; ++dx) {
      const int x = static_cast<int>(std::lround(p.x)) + dx, y = static_cast<int>(std::lround(p.y)) + dy;
      if (x < 0 || y < 0 || x >= v.width || y >= v.height) continue;
      const bool dark = (((dx + half) / 3) + ((dy + half) / 3)) % 2 == 0;
      const unsigned char g = dark ? 30 : 230;
      img.at<cv::Vec3b>(y, x) = {g, static_cast<unsigned char>(dark ? 30 : 200), g};
    }
  }
  return img;
}

/// Writes the video as Motion-JPEG in an .avi (decoded by every FFmpeg build).
inline void write_test_video(const std::string& path, const TestVideo& v) {
  const auto w = create_video_file(path, fourcc('M', 'J', 'P', 'G'), v.fps, cv::Size(v.width, v.height));
  if (!w) throw std::runtime_error("cannot write test video " + path);
  for (int i = 0; i < v.frames; ++i) w->write(test_frame(v, i));
}

/// Frame `index` of `scene` as a tracker receives it: rendered at t = index / fps, grey made.
inline Frame rendered_frame(const Scene& scene, int index, const RenderOptions& o) {
  Frame f;
  f.index = index;
  f.t = index / o.fps;
  f.bgr = render_frame(scene, f.t, o, index);
  make_gray(f);
  return f;
}

/// A real Tracker project with human marks beside the repository (../shared/data/tracker/FILE,
/// not in git; docs/theory.md#tracker-files), or "" when absent.
inline std::string tracker_project_path(const std::string& file) {
  std::string path;
  for (const char* root : {"/../shared", "/../../shared"}) {
    const std::string p = tribolab::test_source_dir() + root + "/data/tracker/" + file;
    if (std::filesystem::exists(p)) path = p;
  }
  return path;
}

/// Tracker's example project BallToss.trz (tracker_project_path), or "" when absent.
inline std::string ball_toss_path() { return tracker_project_path("BallToss.trz"); }

}  // namespace tribolab::video::testing
