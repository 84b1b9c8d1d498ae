// Test helpers of the track commands in the application layer: a planar rigid body with known
// motion sampled as two tracked points, written as a tidy CSV that every track command reads.
#pragma once

#include "io/track_csv.hpp"
#include "track/track.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <unistd.h>

namespace tribolab::app::testing {

/// A fresh empty directory for one test's files.
inline std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("tribolab_app_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

/// A body whose centre flies on a parabola (g = 9.8 m/s^2 down) while it turns at a constant
/// rate: point A at centre - L/2 (cos theta, sin theta), B at centre + L/2 (...).
struct SpinningBody {
  double fps = 240;        ///< 1/s
  int frames = 60;
  double x0 = 0.1, y0 = 1.2, vx = 1.5, vy = 2.0;  ///< m, m/s
  double g = 9.8;          ///< m/s^2
  double theta0 = 2.9;     ///< rad (near pi: the atan2 branch cut is crossed at once)
  double omega = 25;       ///< rad/s
  double length = 0.28;    ///< m, A-B distance
  std::function<double(double)> length_of_t;  ///< overrides `length` when set (a drifting scale)
  double noise = 0;        ///< sd of every coordinate, m
  unsigned seed = 7;

  double t(int i) const { return i / fps; }
  double xc(double s) const { return x0 + vx * s; }
  double yc(double s) const { return y0 + vy * s - 0.5 * g * s * s; }
  double theta(double s) const { return theta0 + omega * s; }

  /// Tracks "A" and "B", every frame.
  track::TrackSet tracks() const {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n(0, noise > 0 ? noise : 1);
    const auto e = [&] { return noise > 0 ? n(rng) : 0.0; };
    track::TrackSet set;
    set.tracks = {track::Track{"A", {}}, track::Track{"B", {}}};
    for (int i = 0; i < frames; ++i) {
      const double s = t(i), h = 0.5 * (length_of_t ? length_of_t(s) : length);
      const double c = std::cos(theta(s)), d = std::sin(theta(s));
      set.tracks[0].points.push_back({i, s, xc(s) - h * c + e(), yc(s) - h * d + e()});
      set.tracks[1].points.push_back({i, s, xc(s) + h * c + e(), yc(s) + h * d + e()});
    }
    return set;
  }

  /// Writes the tracks as a tidy CSV (exact numbers) and returns its path.
  std::string write(const std::string& path) const {
    std::ofstream f(path);
    io::write_tidy_csv(f, tracks());
    return path;
  }
};

}  // namespace tribolab::app::testing
