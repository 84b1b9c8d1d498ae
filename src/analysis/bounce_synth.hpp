// Synthetic data with known truth for the bounce analyses (tests and the demo):
//  * a tracked video of one bounce: the two tips of a spinning ellipse in flight, one whole
//    impact (bounce::simulate_impact: the first contact and any further ones before the
//    apex) and flight again, sampled at a frame rate with Gaussian position noise, times optionally multiplied by a slow-motion factor (seed 001: 8);
//  * a table of bounces (incoming and outgoing velocities) from simulate_contact with noise.
// Deterministic for a given seed (std::mt19937_64). docs/theory.md#bounce-synthetic.
#pragma once

#include "analysis/bounce_fit.hpp"
#include "bounce/contact.hpp"
#include "track/track.hpp"
#include "numerics/units.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace tribolab::analysis {

struct SynthVideoOptions {
  bounce::Ball ball;
  bounce::NormalLawSpec law;          ///< default: the seed's Hunt–Crossley fit
  bounce::FrictionModel friction;     ///< default Coulomb mu = 0.5
  double height = 0.8;                ///< centre height at release, m
  double theta_deg = 20;              ///< orientation at release, deg
  double omega = 45;                  ///< spin at release, rad/s (seed: 40-50)
  double vx = 1.5;                    ///< horizontal speed, m/s
  double vy = 0;                      ///< vertical speed at release, m/s
  double after = 0.3;                 ///< s of video after the separation (less if it lands again)
  double fps = 240;                   ///< frames per second of the camera
  double noise = 0.001;               ///< position noise of each tip coordinate, m (sd)
  double time_factor = 8;             ///< file time = real time x this (240 fps played at 30)
  std::uint64_t seed = 1;
  std::string validate() const;
};

/// Truth of a synthetic video, in real time (not multiplied by time_factor).
struct SynthVideoTruth {
  double t_touch = 0, t_separation = 0;  ///< s from the first frame's time origin (first touch, last separation)
  bounce::BodyState touch, separation;   ///< states at first touch and at separation
  double g = kDefaultG;                  ///< m/s^2
  double floor_y = 0;                    ///< m
  double release_apex = 0;               ///< centre height at the pre-impact apex, m
  double post_apex = 0;                  ///< centre height at the post-impact apex, m
  /// Velocity of the free flight before (pre = true) or after the contact, at time t, m/s.
  double vy_flight(bool pre, double t) const;
};

struct SynthVideo {
  track::Track tip_a, tip_b;   ///< named "A" and "B"; times multiplied by time_factor
  SynthVideoTruth truth;
};

/// The simulated throw as a continuous motion in real time (flight, one whole impact, flight):
/// what synth_video samples at its frames and what a renderer samples within an exposure.
struct ThrowMotion {
  bounce::BodyState release;                 ///< state at t = 0 (x = 0, y = height)
  SynthVideoTruth truth;
  std::vector<bounce::ContactSample> contact;  ///< every contact's history, t from first touch
  double t_end = 0;  ///< s: `after` s past the separation, or the next touch if earlier
  /// The ball's state at any time t >= 0, s: free flight before the touch and after the
  /// separation; during the contact a cubic Hermite interpolation of the history's positions
  /// and velocities (x, y, theta with vx, vy, omega), so the pose is smooth at any sub-frame time.
  bounce::BodyState state(double t) const;
};

/// Simulates the throw of `options` (ball, law, friction, release). Throws InputError for
/// invalid options, a release touching the floor, or a contact that does not end.
ThrowMotion simulate_throw(const SynthVideoOptions& options);

/// Throws InputError for invalid options or when the contact does not end.
SynthVideo synth_video(const SynthVideoOptions& options);

struct SynthTableOptions {
  bounce::Ball ball;
  bounce::NormalLawSpec law;
  bounce::FrictionModel friction;
  int rows = 40;                    ///< bounces
  double speed_min = 2, speed_max = 5;  ///< incoming |vy|, m/s
  double vx_max = 2;                ///< incoming vx uniform in [-vx_max, vx_max], m/s
  double omega_max = 50;            ///< incoming omega uniform in [-omega_max, omega_max], rad/s
  double noise_v = 0.02;            ///< noise sd on the outgoing vx, vy, m/s
  double noise_omega = 0.5;         ///< noise sd on the outgoing omega, rad/s
  /// Fraction of rows with a gross error (a mis-tracked bounce): one of vx_out, vy_out,
  /// b omega_out, chosen at random, is off by a size uniform in [outlier_v, 2 outlier_v]
  /// of random sign. 0 (default) draws no extra random numbers: tables as before.
  double outlier_fraction = 0;
  double outlier_v = 0.3;           ///< m/s (omega_out: outlier_v / b rad/s)
  std::uint64_t seed = 1;
  std::string validate() const;
};

std::vector<BounceRow> synth_table(const SynthTableOptions& options);

}  // namespace tribolab::analysis
