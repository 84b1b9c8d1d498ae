// Filming a scene that tribolab knows exactly: the truth for every tracking test, the bench
// and `bounce render` (docs/theory.md#video-rendering). A scene is a background plus shapes
// whose pose is a function of time; each frame integrates the shapes over the exposure
// (motion blur: `blur_samples` sub-frames across the shutter time, centred on the frame's time), renders anti-aliased by
// supersampling, adds sensor noise, and is written with FFmpeg (video/codec.hpp).
#pragma once

#include "video/frame.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tribolab::video {

/// A filled ellipse (a rugby ball, a disc, a small ball when a = b), optionally carrying a
/// textured mark (a sticker) at a fixed place in its body frame so its turning is visible.
struct ShapePose {
  enum class Kind { ellipse, rectangle } kind = Kind::ellipse;  ///< rectangle: an occluder (a hand)
  double cx_px = 0, cy_px = 0;  ///< centre, px (image x right, y down)
  double a_px = 10, b_px = 10;  ///< semi-axes (ellipse) or half-sides (rectangle), px
  double angle_rad = 0;         ///< body x-axis from image x-axis, counter-clockwise on screen
  cv::Scalar colour{40, 40, 200};  ///< BGR fill
  bool mark = false;            ///< draw a textured sticker in the body frame
  double mark_u_px = 0, mark_v_px = 0;  ///< sticker centre in the body frame, px
  double mark_size_px = 0;      ///< sticker side, px (3x3 cells, dark (30,30,30) at the centre
                                ///< and corners, light (235,235,235) between; clipped to the body)
};

/// Everything in view at time t (seconds of the video's own time base), back to front.
using Scene = std::function<std::vector<ShapePose>(double t)>;

struct RenderOptions {
  /// The largest frame side, px. Larger ones cannot be made: a float frame costs 12 bytes a
  /// pixel several times over (8000x6000 needed 2 GB), FFmpeg refuses 16384x16384 with its own
  /// log lines, OpenCV ran out of memory at 16000x16000. 4096 is DCI 4K.
  static constexpr int kMaxSide = 4096;
  static constexpr int kMinSide = 8;  ///< the smallest frame side, px
  int width = 640;               ///< px, kMinSide to kMaxSide
  int height = 480;              ///< px, kMinSide to kMaxSide
  double fps = 240;              ///< frames per second of the video's time base
  double shutter_fraction = 0.5; ///< exposure as a fraction of the frame period (0 = no blur)
  int blur_samples = 8;          ///< sub-frames integrated across the exposure (>= 1)
  int supersample = 4;           ///< anti-aliasing factor per axis (>= 1)
  enum class Background { plain, gradient, texture } background = Background::gradient;
  cv::Scalar background_colour{200, 200, 200};  ///< BGR
  double floor_y_px = -1;        ///< a floor band below this image y (anti-aliased edge), px; < 0: none
  cv::Scalar floor_colour{60, 60, 60};  ///< BGR of the floor band
  double noise_sigma = 2;        ///< Gaussian sensor noise, grey levels (0 = none)
  std::uint64_t seed = 1;        ///< random seed of the texture and the noise
  std::string validate() const;
};

/// A camera looking square at a plane: world (m, y up) <-> image (px, x right, y down), the
/// mapping `track video --scale --origin` inverts. Each film says where its world origin is.
struct FilmView {
  double scale_m_per_px = 0.002;  ///< m per px
  double origin_x_px = 0;         ///< image x of the world origin, px
  double origin_y_px = 0;         ///< image y of the world origin, px
  cv::Point2d to_px(double x, double y) const {
    return {origin_x_px + x / scale_m_per_px, origin_y_px - y / scale_m_per_px};
  }
};

/// A body colour that stands out from `background` (BGR): dark red on a light background, pale
/// yellow on a dark one (luma 0.299 R + 0.587 G + 0.114 B above or below 110).
cv::Scalar contrasting_colour(const cv::Scalar& background);

/// The image of `scene` for the frame at time t. The exposure is centred on t
/// ([t - shutter/(2 fps), t + shutter/(2 fps)]), so a blurred object's mean position is its
/// position at t: the frame's time stamp is the middle of its exposure.
cv::Mat render_frame(const Scene& scene, double t, const RenderOptions& options, int frame_index);

/// Writes frames 0..frames-1 to `path` (.avi: MJPG, .mp4: mp4v, both by FFmpeg); throws
/// InputError when the file cannot be written. The video's frame rate is options.fps and
/// frame i is rendered at t = i / fps. The file appears whole or not at all.
void write_video(const std::string& path, const Scene& scene, int frames, const RenderOptions& options);

}  // namespace tribolab::video
