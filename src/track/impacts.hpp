// Impacts in a tracked trajectory: abrupt changes of velocity (a bounce reverses vy within one
// frame) located so that derivatives and fits are never smeared across them; the track is
// then split into flight segments. See docs/theory.md#impacts.
//
// Method: for every split between consecutive points k and k+1, a parabola is fitted by least
// squares to the `window` points on each side; the jump of velocity at the midpoint time is
// dv = v_right - v_left, with variance sigma^2 (g_L + g_R) from the fits' covariances and the
// noise sigma estimated robustly from the whole track (median absolute third divided
// difference). A split is an impact when the jump is both significant (|dv|/sd above
// `threshold`, combining x and y) and large (|dv| above `min_jump`); of neighbouring
// candidates the most significant wins. A candidate is dropped when a smooth turning motion
// (uniform translation plus uniform rotation of a point: a mark on a wheel, any arc of
// constant curvature) fits its two windows as well as the two parabolas do (an F test of size
// 0.001): parabolas cannot follow a circle sampled at 20+ degrees per frame, and their
// extrapolations then "jump" by many noise sigmas without any impact.
#pragma once

#include "track/track.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace tribolab::track {

struct ImpactOptions {
  int window = 6;           ///< points fitted on each side of a split (>= 3), e.g. 6
  double threshold = 10;    ///< significance of the jump, in standard deviations, e.g. 10
  double min_jump = 0.3;    ///< smallest velocity jump counted as an impact, m/s, e.g. 0.3
  double min_noise = 1e-6;  ///< floor of the estimated position noise, m (exact synthetic data)
  /// Keep a jump only when a uniformly turning point does not explain its windows as well (a
  /// mark on a wheel is no impact). Off where any departure from a parabola is wanted: the
  /// glitch screen of bounce analyze looks for the jumps out to a hand and back.
  bool veto_smooth_turning = true;
  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
};

/// One detected impact, between points `index` and `index + 1` of the track.
struct Impact {
  std::size_t index = 0;    ///< last point of the incoming segment
  int frame = 0;            ///< frame of that point
  double t = 0;             ///< estimated contact time, s: where the two fitted y parabolas meet
  double dvx = 0;           ///< velocity jump (out - in), m/s
  double dvy = 0;           ///< velocity jump (out - in), m/s, e.g. +5 for a bounce
  double significance = 0;  ///< |dv| in standard deviations (x and y combined)
};

struct ImpactResult {
  std::vector<Impact> impacts;  ///< in time order
  double noise_x = 0;           ///< robust position noise estimate, m, e.g. 0.001
  double noise_y = 0;           ///< robust position noise estimate, m
};

/// Robust estimate of the white position noise of one coordinate: 1.4826 * median of the
/// normalised third divided differences (zero for any parabola, so gravity does not bias it).
/// Returns NaN for fewer than 4 points.
double robust_noise(const std::vector<double>& t, const std::vector<double>& v);

/// Finds the impacts of `track`. Throws InputError for invalid options.
ImpactResult detect_impacts(const Track& track, const ImpactOptions& options = {});

/// A half-open range [begin, end) of point indices.
struct Segment {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t size() const { return end - begin; }
};

/// The flight segments of a track of n points separated by `impacts`.
std::vector<Segment> flight_segments(std::size_t n, const std::vector<Impact>& impacts);

/// The track cut into its flight segments, named "<name>#1", "<name>#2", ...
std::vector<Track> split_track(const Track& track, const std::vector<Impact>& impacts);

}  // namespace tribolab::track
