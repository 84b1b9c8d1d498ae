// Filming a disc launched across a rough incline, seen face-on (seed 000, model B), with known
// truth: the scene `incline render` writes to a video and the studio's tests analyse
// (docs/theory.md#rendering). The motion is incline::simulate's (launch along +x from the
// origin, x across the slope, y up it), sampled densely and interpolated at any sub-frame time;
// the world -> pixel mapping is the one `track video --scale --origin` inverts.
#pragma once

#include "incline/params.hpp"
#include "track/track.hpp"
#include "video/render.hpp"

#include <opencv2/core.hpp>

#include <optional>
#include <string>

namespace tribolab::video {

struct InclineFilmOptions {
  /// The launch: mu, phi (rad), v0 (m/s, along +x), g, mu_static. Model B: normal_accel must be 0.
  incline::Parameters launch;
  RenderOptions render;        ///< size, fps (default 240; `incline render` says 60), background, shutter, noise, seed
  double disc_radius = 0.02;   ///< m, e.g. 0.02 (a 4 cm puck)
  std::optional<cv::Scalar> disc_colour;  ///< BGR; unset: contrasting_colour(the background)
  double scale_m_per_px = 0;   ///< m per px, e.g. 0.002; 0 = fit the whole path in view
  /// Launch point (the world origin) in the image, px (x right, y down); unset = laid out so the
  /// whole path is in view, centred.
  std::optional<cv::Point2d> launch_px;
  /// Film length after the launch, s; 0 = until 0.3 s after the stop, or 1.5 s if it never stops.
  double duration = 0;
  /// The launch happens launch_phase / fps before frame 0, in [0, 1) (`incline render` draws it
  /// from the seed, as a real camera's frames fall anywhere in time).
  double launch_phase = 0;
  std::string validate() const;  ///< empty when valid, else "field: message"
};

struct InclineFilm {
  incline::Parameters launch;  ///< as simulated
  FilmView view;               ///< world origin at the launch point
  RenderOptions render;        ///< as filmed (background colour)
  cv::Scalar disc_colour;      ///< BGR, contrasting with the background
  double disc_radius_px = 0;   ///< px
  int frames = 0;
  /// Launch time in the video's clock, s, in (-1/fps, 0]: frame k at video time k / fps is
  /// k / fps - t_launch after the launch.
  double t_launch = 0;
  std::optional<double> t_stop;          ///< first stop, video time, s (none: it never stops)
  std::optional<double> x_stop, y_stop;  ///< m, relative to the launch point
  Scene scene;                 ///< in video time
  /// Truth at each frame's video time, world metres (origin at the launch point): track "disc".
  track::TrackSet truth;
  bool disc_in_view = true;    ///< the whole disc stays inside the image in every frame
};

/// Simulates the launch and lays out the camera. Throws InputError for invalid options (naming
/// the field) and a disc smaller than 2 px.
InclineFilm plan_incline_film(const InclineFilmOptions& options);

}  // namespace tribolab::video
