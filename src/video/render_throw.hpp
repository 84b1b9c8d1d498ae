// Filming a simulated throw (flight, bounce, flight) with known truth: the scene `bounce
// render` writes to a video, the demo tracks back and the tests check trackers against
// (docs/theory.md#rendering). The motion is analysis::simulate_throw's, sampled at any
// sub-frame time; the world -> pixel mapping is the one `track video --scale --origin` inverts.
#pragma once

#include "analysis/bounce_synth.hpp"
#include "track/track.hpp"
#include "video/render.hpp"

#include <opencv2/core.hpp>

#include <string>

namespace tribolab::video {

struct ThrowFilmOptions {
  /// The throw: ball, law, friction, release (height, theta_deg, omega, vx, vy), `after`,
  /// and seed (the phase of the first frame within a frame period). Its fps, noise and
  /// time_factor are not used: the camera is `render`.
  analysis::SynthVideoOptions motion;
  RenderOptions render;        ///< size, fps (default 240), background, shutter, noise, seed
  double scale_m_per_px = 0;   ///< m per px, e.g. 0.002; 0 = fit the whole throw in view
  bool floor_band = true;      ///< a dark band below the floor line
  bool sticker = false;        ///< a 3x3 checker sticker on the ball, half-way to tip B
  std::string validate() const;  ///< empty when valid, else "field: message"
};

/// World (m, y up, origin: the centre's release x on the floor) <-> image (px, y down).
using ThrowView = FilmView;

struct ThrowFilm {
  analysis::ThrowMotion motion;  ///< real time: release at t = 0
  ThrowView view;
  RenderOptions render;          ///< as filmed (floor line, background colour)
  cv::Scalar ball_colour;        ///< BGR, contrasting with the background
  int frames = 0;
  /// Real time of frame 0, s, in [0, 1/fps): frame k is at video time k / fps, which is real
  /// time - t0 (the release happens t0 before frame 0).
  double t0 = 0;
  Scene scene;                   ///< in video time
  /// Truth at each frame's video time, world metres: tracks "ball" (centre), "ball.A" and
  /// "ball.B" (the tips at -a and +a along the major axis, so theta = atan2(B - A)).
  track::TrackSet truth;
  bool ball_in_view = true;      ///< the whole ball stays inside the image in every frame
};

/// Simulates the throw and lays out the camera. Throws InputError for invalid options
/// (naming the field), a ball smaller than 2 px, a floor line outside the image.
ThrowFilm plan_throw_film(const ThrowFilmOptions& options);

}  // namespace tribolab::video
