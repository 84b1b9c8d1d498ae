// Synthetic tracks with known truth for the track-area tests: a ball bouncing on a floor
// (point mass, restitution e), sampled at a frame rate with Gaussian position noise.
#pragma once

#include "numerics/units.hpp"
#include "track/track.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace tribolab::track::testing {

struct Bouncing {
  Track track;
  std::vector<double> contact_times;  ///< exact contact instants, s
};

/// Ball released at height h0 (m) with horizontal speed vx (m/s) at time t_release, bounces
/// with restitution e; sampled at `fps` from t = 0 for `duration` s, noise sd `noise` (m).
inline Bouncing bouncing_ball(double fps, double duration, double h0, double vx, double e,
                              double noise, unsigned seed, double t_release = 0.0123,
                              double g = kDefaultG) {
  Bouncing b;
  // flights: start time, start height, start vertical speed
  struct Flight {
    double t0, y0, v0;
  };
  std::vector<Flight> flights{{t_release, h0, 0}};
  while (flights.back().t0 < duration + 1) {
    const Flight& f = flights.back();
    // y0 + v0 s - g s^2/2 = 0
    const double s = (f.v0 + std::sqrt(f.v0 * f.v0 + 2 * g * f.y0)) / g;
    const double tc = f.t0 + s;
    const double vin = f.v0 - g * s;
    b.contact_times.push_back(tc);
    flights.push_back({tc, 0, -e * vin});
    if (-e * vin < 0.05) break;
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, noise);
  const int frames = static_cast<int>(duration * fps);
  for (int i = 0; i < frames; ++i) {
    const double t = i / fps;
    if (t < t_release) continue;
    std::size_t k = 0;
    while (k + 1 < flights.size() && flights[k + 1].t0 <= t) ++k;
    const Flight& f = flights[k];
    const double s = t - f.t0;
    const double y = f.y0 + f.v0 * s - 0.5 * g * s * s;
    b.track.points.push_back({i, t, vx * (t - t_release) + n(rng), y + n(rng)});
  }
  b.track.name = "ball";
  while (!b.contact_times.empty() && b.contact_times.back() > b.track.points.back().t) {
    b.contact_times.pop_back();
  }
  return b;
}

}  // namespace tribolab::track::testing
