// Rendering a known scene (docs/theory.md#rendering). The frame is the background plus, in
// every region where shapes are, the average over `blur_samples` sub-frames of the shapes
// painted at `supersample` x `supersample` sub-pixels and box-filtered down. Only the
// bounding boxes of the shapes (over the whole exposure) are rendered at the supersampled
// resolution; boxes that overlap are merged so that shapes in front occlude those behind.
#include "video/render.hpp"

#include "io/output_path.hpp"
#include "io/temp_files.hpp"
#include "numerics/error.hpp"
#include "video/codec.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>
#include <unistd.h>

namespace tribolab::video {
namespace {

// Sticker cells: dark and light grey (BGR), alternating like a checker board.
const cv::Vec3f kMarkDark(30, 30, 30);
const cv::Vec3f kMarkLight(235, 235, 235);

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser: seeds for distinct streams
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

cv::Mat make_background(const RenderOptions& o) {
  const cv::Vec3f c(static_cast<float>(o.background_colour[0]), static_cast<float>(o.background_colour[1]),
                    static_cast<float>(o.background_colour[2]));
  cv::Mat bg(o.height, o.width, CV_32FC3, cv::Scalar(c[0], c[1], c[2]));
  if (o.background == RenderOptions::Background::gradient) {
    // Light from the top-left: 1.15 x the colour there, 0.7 x at the bottom-right.
    for (int i = 0; i < o.height; ++i) {
      auto* row = bg.ptr<cv::Vec3f>(i);
      for (int j = 0; j < o.width; ++j) {
        const double s = 0.7 * (i + 0.5) / o.height + 0.3 * (j + 0.5) / o.width;
        row[j] = c * static_cast<float>(1.15 - 0.45 * s);
      }
    }
  } else if (o.background == RenderOptions::Background::texture) {
    // Smooth random texture: a coarse grid of random factors (one cell per ~12 px, per
    // channel), interpolated bicubically and slightly blurred, modulating the colour by about
    // +-25 %. (A subtler, mottled texture was tried; the trackers' tests are tuned to this one.)
    cv::RNG rng(mix(o.seed ^ 0x7465787475726555ULL));
    const int gw = std::max(2, o.width / 12 + 2), gh = std::max(2, o.height / 12 + 2);
    cv::Mat grid(gh, gw, CV_32FC3);
    rng.fill(grid, cv::RNG::UNIFORM, cv::Scalar::all(0.75), cv::Scalar::all(1.25));
    cv::Mat up;
    cv::resize(grid, up, cv::Size(o.width, o.height), 0, 0, cv::INTER_CUBIC);
    cv::GaussianBlur(up, up, cv::Size(0, 0), 2.0);
    bg = bg.mul(up);
  }
  if (o.floor_y_px >= 0) {
    // Rows below the edge y = floor_y_px take the floor colour; the row holding the edge (pixel
    // i spans [i - 1/2, i + 1/2]) mixes the two by the fraction of it below the edge.
    const cv::Vec3f fc(static_cast<float>(o.floor_colour[0]), static_cast<float>(o.floor_colour[1]),
                       static_cast<float>(o.floor_colour[2]));
    for (int i = 0; i < o.height; ++i) {
      const double below = std::clamp(i + 0.5 - o.floor_y_px, 0.0, 1.0);
      if (below <= 0) continue;
      auto* row = bg.ptr<cv::Vec3f>(i);
      for (int j = 0; j < o.width; ++j) row[j] = row[j] * static_cast<float>(1 - below) + fc * static_cast<float>(below);
    }
  }
  cv::min(bg, 255.0, bg);
  cv::max(bg, 0.0, bg);
  return bg;
}

// The background depends only on the options, so it is made once per thread and options.
const cv::Mat& background(const RenderOptions& o) {
  using Key = std::tuple<int, int, int, double, double, double, std::uint64_t, double, double, double, double>;
  thread_local std::map<Key, cv::Mat> cache;
  const Key key{o.width, o.height, static_cast<int>(o.background), o.background_colour[0],
                o.background_colour[1], o.background_colour[2],
                o.background == RenderOptions::Background::texture ? o.seed : 0, o.floor_y_px,
                o.floor_colour[0], o.floor_colour[1], o.floor_colour[2]};
  auto it = cache.find(key);
  if (it == cache.end()) {
    if (cache.size() > 8) cache.clear();
    it = cache.emplace(key, make_background(o)).first;
  }
  return it->second;
}

// Half extents of the axis-aligned box around a shape, px.
cv::Rect2d bounds(const ShapePose& s) {
  const double c = std::abs(std::cos(s.angle_rad)), n = std::abs(std::sin(s.angle_rad));
  double ex, ey;
  if (s.kind == ShapePose::Kind::ellipse) {
    ex = std::sqrt(s.a_px * s.a_px * c * c + s.b_px * s.b_px * n * n);
    ey = std::sqrt(s.a_px * s.a_px * n * n + s.b_px * s.b_px * c * c);
  } else {
    ex = s.a_px * c + s.b_px * n;
    ey = s.a_px * n + s.b_px * c;
  }
  return {s.cx_px - ex, s.cy_px - ey, 2 * ex, 2 * ey};
}

// Pixel rectangle (integer, clipped to the image) holding a box, with a one-pixel margin.
cv::Rect pixel_rect(const cv::Rect2d& b, int width, int height) {
  if (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.width) || !std::isfinite(b.height)) {
    return {};
  }
  const double x0 = std::max(-1.0, std::floor(b.x - 1)), y0 = std::max(-1.0, std::floor(b.y - 1));
  const double x1 = std::min<double>(width + 1, std::ceil(b.x + b.width + 2));
  const double y1 = std::min<double>(height + 1, std::ceil(b.y + b.height + 2));
  return cv::Rect(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(std::max(0.0, x1 - x0)),
                  static_cast<int>(std::max(0.0, y1 - y0))) &
         cv::Rect(0, 0, width, height);
}

// Paints one shape into `ss`, the supersampled image of pixel rectangle `region`.
void paint(cv::Mat& ss, const cv::Rect& region, int f, const ShapePose& s) {
  const cv::Rect box = pixel_rect(bounds(s), region.x + region.width, region.y + region.height) & region;
  if (box.empty()) return;
  const cv::Vec3f colour(static_cast<float>(s.colour[0]), static_cast<float>(s.colour[1]),
                         static_cast<float>(s.colour[2]));
  const double cs = std::cos(s.angle_rad), sn = std::sin(s.angle_rad);
  const double inv_a2 = 1 / (s.a_px * s.a_px), inv_b2 = 1 / (s.b_px * s.b_px);
  const double half = s.mark_size_px / 2, cell = s.mark_size_px / 3;
  const bool ellipse = s.kind == ShapePose::Kind::ellipse;
  const int i0 = (box.y - region.y) * f, i1 = (box.y + box.height - region.y) * f;
  const int j0 = (box.x - region.x) * f, j1 = (box.x + box.width - region.x) * f;
  for (int i = i0; i < i1; ++i) {
    // Sub-pixel centre in image coordinates: pixel (i, j) is centred at (j, i) (frame.hpp).
    const double dy = region.y - 0.5 + (i + 0.5) / f - s.cy_px;
    auto* row = ss.ptr<cv::Vec3f>(i);
    for (int j = j0; j < j1; ++j) {
      const double dx = region.x - 0.5 + (j + 0.5) / f - s.cx_px;
      // Body frame: u along the body x-axis at angle_rad counter-clockwise on screen, v
      // 90 degrees further (screen up when angle_rad = 0); image y points down.
      const double u = dx * cs - dy * sn, v = -dx * sn - dy * cs;
      const bool inside = ellipse ? u * u * inv_a2 + v * v * inv_b2 <= 1 : std::abs(u) <= s.a_px && std::abs(v) <= s.b_px;
      if (!inside) continue;
      row[j] = colour;
      if (s.mark && s.mark_size_px > 0) {
        const double mu = u - s.mark_u_px + half, mv = v - s.mark_v_px + half;
        if (mu >= 0 && mv >= 0 && mu < s.mark_size_px && mv < s.mark_size_px) {
          const int ci = static_cast<int>(mu / cell), cj = static_cast<int>(mv / cell);
          row[j] = (ci + cj) % 2 == 0 ? kMarkDark : kMarkLight;
        }
      }
    }
  }
}

struct Placed {
  int sample;
  ShapePose shape;
  cv::Rect box;
};

}  // namespace

cv::Scalar contrasting_colour(const cv::Scalar& bg) {
  const double luma = 0.114 * bg[0] + 0.587 * bg[1] + 0.299 * bg[2];
  return luma > 110 ? cv::Scalar(40, 60, 170) : cv::Scalar(120, 210, 250);
}

std::string RenderOptions::validate() const {
  if (width < kMinSide || width > kMaxSide || height < kMinSide || height > kMaxSide) {
    return "size: width and height must lie in [" + std::to_string(kMinSide) + ", " + std::to_string(kMaxSide) +
           "] px, got " + std::to_string(width) + "x" + std::to_string(height);
  }
  if (!std::isfinite(fps) || fps <= 0 || fps > 1e6) return "fps: must lie in (0, 1e6], got " + std::to_string(fps);
  if (!std::isfinite(shutter_fraction) || shutter_fraction < 0 || shutter_fraction > 1) {
    return "shutter: must lie in [0, 1] (a fraction of the frame period), got " + std::to_string(shutter_fraction);
  }
  if (blur_samples < 1 || blur_samples > 256) {
    return "blur-samples: must lie in [1, 256], got " + std::to_string(blur_samples);
  }
  if (supersample < 1 || supersample > 16) return "supersample: must lie in [1, 16], got " + std::to_string(supersample);
  if (!std::isfinite(noise_sigma) || noise_sigma < 0 || noise_sigma > 100) {
    return "noise: must lie in [0, 100] grey levels, got " + std::to_string(noise_sigma);
  }
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(background_colour[k]) || background_colour[k] < 0 || background_colour[k] > 255) {
      return "background-colour: components must lie in [0, 255]";
    }
    if (!std::isfinite(floor_colour[k]) || floor_colour[k] < 0 || floor_colour[k] > 255) {
      return "floor-colour: components must lie in [0, 255]";
    }
  }
  if (!std::isfinite(floor_y_px)) return "floor-y: must be finite";
  return {};
}

cv::Mat render_frame(const Scene& scene, double t, const RenderOptions& options, int frame_index) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
  const cv::Mat& bg = background(options);
  // Sub-frame times, symmetric about t: t + ((k + 1/2)/n - 1/2) * shutter / fps, so the
  // exposure [t - shutter/(2 fps), t + shutter/(2 fps)] is centred on the frame's time.
  const int n = options.shutter_fraction > 0 ? options.blur_samples : 1;
  const double exposure = options.shutter_fraction / options.fps;
  std::vector<Placed> placed;
  for (int k = 0; k < n; ++k) {
    const double tk = t + ((k + 0.5) / n - 0.5) * exposure;
    for (auto& s : scene(tk)) {
      const cv::Rect box = pixel_rect(bounds(s), options.width, options.height);
      if (!box.empty()) placed.push_back({k, s, box});
    }
  }
  // Regions: the union of overlapping boxes, grown until no two regions overlap.
  std::vector<cv::Rect> regions;
  for (const auto& p : placed) regions.push_back(p.box);
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < regions.size() && !merged; ++a) {
      for (std::size_t b = a + 1; b < regions.size(); ++b) {
        if ((regions[a] & regions[b]).area() > 0) {
          regions[a] |= regions[b];
          regions.erase(regions.begin() + static_cast<std::ptrdiff_t>(b));
          merged = true;
          break;
        }
      }
    }
  }
  cv::Mat frame = bg.clone();
  const int f = options.supersample;
  for (const cv::Rect& region : regions) {
    cv::Mat bg_ss, ss, down;
    cv::resize(bg(region), bg_ss, cv::Size(region.width * f, region.height * f), 0, 0, cv::INTER_NEAREST);
    cv::Mat acc(region.size(), CV_32FC3, cv::Scalar::all(0));
    for (int k = 0; k < n; ++k) {
      bg_ss.copyTo(ss);
      for (const auto& p : placed) {
        if (p.sample == k && (p.box & region).area() > 0) paint(ss, region, f, p.shape);
      }
      // INTER_AREA with an integer factor is the exact box average of the f x f sub-pixels.
      cv::resize(ss, down, region.size(), 0, 0, cv::INTER_AREA);
      acc += down;
    }
    acc.convertTo(frame(region), CV_32FC3, 1.0 / n);
  }
  if (options.noise_sigma > 0) {
    cv::RNG rng(mix(options.seed * 0x100000001b3ULL + static_cast<std::uint64_t>(frame_index)));
    cv::Mat noise(frame.size(), CV_32FC3);
    rng.fill(noise, cv::RNG::NORMAL, cv::Scalar::all(0), cv::Scalar::all(options.noise_sigma));
    frame += noise;
  }
  cv::Mat out;
  frame.convertTo(out, CV_8UC3);  // rounds to nearest and saturates to [0, 255]
  return out;
}

void write_video(const std::string& path, const Scene& scene, int frames, const RenderOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
  if (frames < 1) throw InputError(path, "a video needs at least one frame, got " + std::to_string(frames));
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::string ext = target.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  int code = 0;
  if (ext == ".avi") {
    // FFmpeg's MJPEG encoder (mean error ~1 grey level). Not OpenCV's own CAP_OPENCV_MJPEG:
    // in OpenCV 4.6 it wrote a black 16x16 block into some frames (render_throw_test.cpp).
    code = fourcc('M', 'J', 'P', 'G');
  } else if (ext == ".mp4") {
    code = fourcc('m', 'p', '4', 'v');
  } else {
    throw InputError(path, "unknown video type '" + ext + "' (expected .avi or .mp4)");
  }
  // Written beside the target (symbolic links followed) and renamed when complete: no
  // partial video on failure.
  const fs::path file(io::resolve_file_output(path, "a video is written whole, then renamed into place"));
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  const fs::path tmp = dir / ("." + file.stem().string() + ".tmp" + std::to_string(::getpid()) + ext);
  struct Remove {
    fs::path p;
    io::TempRegistration on_signal{p.string()};  // a signal removes it as well
    bool keep = false;
    ~Remove() {
      std::error_code ec;
      if (!keep) fs::remove(p, ec);
    }
  } guard{tmp};
  {
    // FFmpeg's writer takes no quality property (it rejects VIDEOWRITER_PROP_QUALITY).
    const auto writer = create_video_file(tmp.string(), code, options.fps, cv::Size(options.width, options.height));
    if (!writer) throw InputError(path, "cannot write this video (codec or permissions)");
    for (int i = 0; i < frames; ++i) writer->write(render_frame(scene, i / options.fps, options, i));
    writer->close();
  }
  std::error_code ec;
  if (!fs::exists(tmp, ec) || fs::file_size(tmp, ec) == 0) throw InputError(path, "writing the video failed");
  fs::rename(tmp, file, ec);
  if (ec) throw InputError(path, "cannot write: " + ec.message());
  guard.keep = true;
}

}  // namespace tribolab::video
